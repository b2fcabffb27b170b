//! OSL's open alphabet: symbols, the built-in labels, and the user labels a renderer
//! registers before it parses its rules.

use std::fmt;
use std::str::FromStr;

/// One symbol of OSL's open alphabet: a label (any string) or NONE (OSL's null ustring,
/// `x` in an expression, `~` in path text). STOP is not a symbol: it is implied at the end
/// of every vertex.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Symbol {
    /// NONE: the null label (an event or scattering slot left empty).
    None,
    /// A label.
    Label(String),
}

impl Symbol {
    /// The label `s`.
    pub fn label(s: impl Into<String>) -> Symbol {
        Symbol::Label(s.into())
    }
}

/// The built-in event labels (slot 0), in OSL's order.
pub const EVENT_LABELS: [&str; 7] = ["C", "L", "B", "V", "T", "R", "O"];
/// The built-in scattering labels (slot 1).
pub const SCATTERING_LABELS: [&str; 4] = ["D", "G", "S", "s"];
/// The label OSL ends every vertex with. Never a [`Symbol`]; the OSL front end rejects it
/// in expressions.
pub const STOP_LABEL: &str = "__stop__";

/// Which slot a known label belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LabelKind {
    /// An event type (slot 0): built in or registered with `events=`.
    Event,
    /// A scattering type (slot 1): built in or registered with `scatters=`.
    Scattering,
}

/// What a renderer registers before it reads its rules: user labels (OSL's
/// `AccumAutomata::addEventType` / `addScatteringType`), in registration order, and what
/// a renderer built on OSL reads around an expression (its prefixes and named AOVs, from
/// its profile). Registered labels change how other expressions match: they join the
/// basic set the eater excludes. Prefixes and built-in names only change how an AOV
/// source reads ([`crate::osl::parse_source`]); the text form (`events=…;scatters=…`)
/// carries the labels alone.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct Registered {
    /// Extra event types (slot 0).
    pub events: Vec<String>,
    /// Extra scattering types (slot 1).
    pub scatters: Vec<String>,
    /// The prefixes a renderer reads before an AOV source (`unoccluded` for
    /// `unoccluded;C.*L`), without their `;`. `None`: plain OSL, which reads no prefix.
    pub prefixes: Option<Vec<String>>,
    /// The AOVs a renderer defines by name, usable as a whole source (Arnold's
    /// `diffuse_direct`): name and expression, in this dialect.
    pub builtins: Vec<(String, String)>,
}

impl Registered {
    /// Nothing registered.
    pub fn none() -> Registered {
        Registered::default()
    }

    /// The basic set: every built-in and registered label, plus NONE. The eater of a
    /// vertex pattern skips only symbols outside it (STOP is implied).
    pub fn basic_labels(&self) -> Vec<Symbol> {
        let mut out: Vec<Symbol> = EVENT_LABELS
            .iter()
            .chain(&SCATTERING_LABELS)
            .map(|l| Symbol::label(*l))
            .chain(self.events.iter().chain(&self.scatters).map(Symbol::label))
            .collect();
        out.push(Symbol::None);
        out.sort();
        out.dedup();
        out
    }

    /// The slot of a known label (built in or registered); a later registration wins, as
    /// in OSL, where registering overwrites the label's position.
    pub fn kind_of(&self, label: &str) -> Option<LabelKind> {
        let registered = |list: &[String]| list.iter().any(|l| l == label);
        if registered(&self.scatters) {
            Some(LabelKind::Scattering)
        } else if registered(&self.events) {
            Some(LabelKind::Event)
        } else if SCATTERING_LABELS.contains(&label) {
            Some(LabelKind::Scattering)
        } else if EVENT_LABELS.contains(&label) {
            Some(LabelKind::Event)
        } else {
            None
        }
    }
}

/// Why a registration text did not parse.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RegisteredError {
    /// Byte offset of the bad part.
    pub pos: usize,
    /// The part that is neither `events=…` nor `scatters=…`.
    pub part: String,
}

impl fmt::Display for RegisteredError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "at byte {}: `{}` is neither `events=A,B` nor `scatters=Y` (or `-` for none)",
            self.pos, self.part
        )
    }
}

impl std::error::Error for RegisteredError {}

impl FromStr for Registered {
    type Err = RegisteredError;

    /// `-` (nothing registered) or `events=A,B;scatters=Y`, either part optional, in any
    /// order; labels are separated by commas and hold no `,`, `;` or `=`.
    fn from_str(s: &str) -> Result<Registered, RegisteredError> {
        let mut out = Registered::default();
        if s == "-" {
            return Ok(out);
        }
        let mut pos = 0;
        for part in s.split(';') {
            let bad = || RegisteredError {
                pos,
                part: part.to_string(),
            };
            let (key, list) = part.split_once('=').ok_or_else(bad)?;
            let target = match key {
                "events" => &mut out.events,
                "scatters" => &mut out.scatters,
                _ => return Err(bad()),
            };
            if list.contains('=') {
                return Err(bad());
            }
            if !list.is_empty() {
                target.extend(list.split(',').map(str::to_string));
            }
            pos += part.len() + 1;
        }
        Ok(out)
    }
}

impl fmt::Display for Registered {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let parts: Vec<String> = [("events", &self.events), ("scatters", &self.scatters)]
            .into_iter()
            .filter(|(_, l)| !l.is_empty())
            .map(|(k, l)| format!("{k}={}", l.join(",")))
            .collect();
        if parts.is_empty() {
            f.write_str("-")
        } else {
            f.write_str(&parts.join(";"))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn registration_text_round_trips() {
        let r: Registered = "events=U;scatters=Y".parse().unwrap();
        assert_eq!(r.events, ["U"]);
        assert_eq!(r.scatters, ["Y"]);
        assert_eq!(r.to_string(), "events=U;scatters=Y");
        let r: Registered = "scatters=Y,Z;events=A,B".parse().unwrap();
        assert_eq!(r.events, ["A", "B"]);
        assert_eq!(r.scatters, ["Y", "Z"]);
        assert_eq!(r.to_string(), "events=A,B;scatters=Y,Z");
        let r: Registered = "-".parse().unwrap();
        assert_eq!(r, Registered::none());
        assert_eq!(r.to_string(), "-");
        let r: Registered = "scatters=Y".parse().unwrap();
        assert_eq!(r.to_string(), "scatters=Y");
    }

    #[test]
    fn bad_registration_text_names_the_part() {
        let e = "events=U;colors=Y".parse::<Registered>().unwrap_err();
        assert_eq!(e.pos, 9);
        assert_eq!(e.part, "colors=Y");
        assert_eq!("U".parse::<Registered>().unwrap_err().pos, 0);
        assert!("".parse::<Registered>().is_err());
        assert!("events=A=B".parse::<Registered>().is_err());
        assert_eq!(
            e.to_string(),
            "at byte 9: `colors=Y` is neither `events=A,B` nor `scatters=Y` (or `-` for none)"
        );
    }

    #[test]
    fn basic_labels_include_registered_and_none() {
        let r: Registered = "events=U;scatters=Y".parse().unwrap();
        let b = r.basic_labels();
        assert_eq!(b.len(), 7 + 4 + 2 + 1);
        for l in [
            "C", "L", "B", "V", "T", "R", "O", "D", "G", "S", "s", "U", "Y",
        ] {
            assert!(b.contains(&Symbol::label(l)), "{l}");
        }
        assert!(b.contains(&Symbol::None));
        assert!(!b.contains(&Symbol::label("x")));
    }

    #[test]
    fn kinds_of_labels() {
        let r: Registered = "events=U;scatters=Y".parse().unwrap();
        assert_eq!(r.kind_of("C"), Some(LabelKind::Event));
        assert_eq!(r.kind_of("s"), Some(LabelKind::Scattering));
        assert_eq!(r.kind_of("U"), Some(LabelKind::Event));
        assert_eq!(r.kind_of("Y"), Some(LabelKind::Scattering));
        assert_eq!(r.kind_of("E"), None);
        assert_eq!(Registered::none().kind_of("U"), None);
    }
}
