//! The dialects this crate implements, by name: [`DialectName`] and
//! [`with_dialect!`](crate::with_dialect), where a run-time choice becomes a type.
//! Adding a dialect to the crate adds one variant, one arm of the macro, and its folder.

use std::error::Error;
use std::fmt;
use std::str::FromStr;

use crate::dialect::Dialect;

/// The dialects this crate implements, by name: what `--dialect` and the C ABI choose
/// from at run time. [`with_dialect!`](crate::with_dialect) turns one into a type.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum DialectName {
    /// RenderMan's dialect (docs/language.md §1–§7): [`crate::renderman::RenderMan`].
    #[default]
    RenderMan,
    /// OSL's dialect (docs/language.md, the OSL chapter): [`crate::osl::Osl`].
    Osl,
}

/// Runs `$body` with `$d` naming the dialect type of `$name` (a [`DialectName`]): the one
/// place a tool turns a run-time dialect into generic code.
///
/// ```
/// use lpe::{with_dialect, Dialect, DialectName};
///
/// fn universe(name: DialectName) -> &'static str {
///     with_dialect!(name, D => D::DEFAULT_UNIVERSE)
/// }
/// assert_eq!(universe(DialectName::Osl), "C<[RT][DGS]>*[LO]");
/// ```
#[macro_export]
macro_rules! with_dialect {
    ($name:expr, $d:ident => $body:expr) => {
        match $name {
            $crate::DialectName::RenderMan => {
                type $d = $crate::renderman::RenderMan;
                $body
            }
            $crate::DialectName::Osl => {
                type $d = $crate::osl::Osl;
                $body
            }
        }
    };
}

impl DialectName {
    /// Every dialect, in their `FromStr` spelling order.
    pub const ALL: [DialectName; 2] = [DialectName::RenderMan, DialectName::Osl];

    /// The name `FromStr` accepts and `Display` prints: the dialect's [`Dialect::NAME`].
    pub fn name(self) -> &'static str {
        with_dialect!(self, D => D::NAME)
    }

    /// The name of dialect `D`, if this crate implements it.
    pub fn of<D: Dialect>() -> Option<DialectName> {
        DialectName::ALL.into_iter().find(|d| d.name() == D::NAME)
    }
}

impl fmt::Display for DialectName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// An unknown dialect name.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownDialect(pub String);

impl fmt::Display for UnknownDialect {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let known: Vec<String> = DialectName::ALL.iter().map(|d| format!("`{d}`")).collect();
        write!(
            f,
            "unknown dialect `{}` (expected {})",
            self.0,
            known.join(" or ")
        )
    }
}

impl Error for UnknownDialect {}

impl FromStr for DialectName {
    type Err = UnknownDialect;

    fn from_str(s: &str) -> Result<DialectName, UnknownDialect> {
        DialectName::ALL
            .into_iter()
            .find(|d| d.name() == s)
            .ok_or_else(|| UnknownDialect(s.to_string()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_unknown_names_fail() {
        assert_eq!("osl".parse::<DialectName>(), Ok(DialectName::Osl));
        assert_eq!(
            "renderman".parse::<DialectName>(),
            Ok(DialectName::RenderMan)
        );
        assert_eq!(DialectName::Osl.to_string(), "osl");
        assert_eq!(DialectName::RenderMan.to_string(), "renderman");
        let e = "OSL".parse::<DialectName>().unwrap_err();
        assert_eq!(e, UnknownDialect("OSL".into()));
        assert_eq!(
            e.to_string(),
            "unknown dialect `OSL` (expected `renderman` or `osl`)"
        );
        assert_eq!(DialectName::of::<crate::osl::Osl>(), Some(DialectName::Osl));
    }
}
