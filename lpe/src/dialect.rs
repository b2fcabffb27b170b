//! Which surface syntax an expression is written in.

use std::fmt;
use std::str::FromStr;

/// A dialect of light path expressions: RenderMan's (the [`crate::syntax`] front end) or
/// Open Shading Language's (the [`crate::osl`] front end, which Arnold, Karma, MoonRay and
/// appleseed derive from).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Dialect {
    /// RenderMan's dialect (docs/language.md §1–§7).
    #[default]
    RenderMan,
    /// OSL's dialect (docs/language.md, the OSL chapter).
    Osl,
}

impl Dialect {
    /// Both dialects, in their `FromStr` spelling order.
    pub const ALL: [Dialect; 2] = [Dialect::RenderMan, Dialect::Osl];

    /// The name `FromStr` accepts and `Display` prints.
    pub fn name(self) -> &'static str {
        match self {
            Dialect::RenderMan => "renderman",
            Dialect::Osl => "osl",
        }
    }
}

impl fmt::Display for Dialect {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// An unknown dialect name.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownDialect(pub String);

impl fmt::Display for UnknownDialect {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "unknown dialect `{}` (expected `renderman` or `osl`)",
            self.0
        )
    }
}

impl std::error::Error for UnknownDialect {}

impl FromStr for Dialect {
    type Err = UnknownDialect;

    fn from_str(s: &str) -> Result<Dialect, UnknownDialect> {
        Dialect::ALL
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
        assert_eq!("osl".parse::<Dialect>(), Ok(Dialect::Osl));
        assert_eq!("renderman".parse::<Dialect>(), Ok(Dialect::RenderMan));
        assert_eq!(Dialect::Osl.to_string(), "osl");
        assert_eq!(Dialect::RenderMan.to_string(), "renderman");
        let e = "OSL".parse::<Dialect>().unwrap_err();
        assert_eq!(e, UnknownDialect("OSL".into()));
        assert!(e.to_string().contains("`OSL`"));
    }
}
