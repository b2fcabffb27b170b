//! `rendermn.ini`-style configuration: user macros and lobe mappings.
//!
//! ```text
//! # comments and blank lines are ignored, so are keys outside /prman/lpe/
//! /prman/lpe/macro/myDiffuse   C<RD>[<L.>O]
//! /prman/lpe/diffuse2          Diffuse,HairDiffuse
//! /prman/lpe/specular4         Clearcoat
//! /prman/lpe/user2             Albedo,DiffuseAlbedo
//! ```
//!
//! Every macro is parsed once at load (after all lines are read, so macros may name
//! macros defined later), so a broken macro is reported with its line, not at first use.

use std::fmt;

use crate::renderman::lobes::{LobeCategory, LobeError, LobeMap};
use crate::renderman::macros::MacroTable;
use crate::renderman::syntax::{Error, Limits, Parser};

/// Macros and lobe mappings, from defaults plus an optional ini file.
#[derive(Clone, Debug, Default)]
pub struct Config {
    /// Built-in plus user macros.
    pub macros: MacroTable,
    /// Named lobe -> LPE lobe.
    pub lobes: LobeMap,
    /// Parse limits.
    pub limits: Limits,
}

/// A problem in an ini file: which line, and what.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct IniError {
    /// One-based line number.
    pub line: usize,
    /// What is wrong.
    pub kind: IniErrorKind,
}

/// What is wrong with one line of an ini file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum IniErrorKind {
    /// `/prman/lpe/macro/NAME` with a name that is not letters, digits and `_`.
    BadMacroName(String),
    /// A macro defined with no expression.
    EmptyMacro(String),
    /// A key under `/prman/lpe/` that is neither a macro nor a lobe mapping.
    UnknownKey(String),
    /// A lobe mapping that names no lobes.
    NoLobeNames(String),
    /// A lobe mapping outside its category's range.
    Lobe(LobeError),
    /// A macro whose expression does not parse.
    Macro(Box<Error>),
}

impl fmt::Display for IniErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            IniErrorKind::BadMacroName(name) => {
                write!(f, "macro name `{name}` must be letters, digits and `_`")
            }
            IniErrorKind::EmptyMacro(name) => write!(f, "macro `{name}` has no expression"),
            IniErrorKind::UnknownKey(key) => write!(
                f,
                "unknown key `{key}`: expected /prman/lpe/macro/NAME, /prman/lpe/diffuseN, \
                 /prman/lpe/specularN or /prman/lpe/userN"
            ),
            IniErrorKind::NoLobeNames(key) => write!(f, "`{key}` lists no lobe names"),
            IniErrorKind::Lobe(e) => write!(f, "{e}"),
            IniErrorKind::Macro(e) => f.write_str(&e.one_line()),
        }
    }
}

impl fmt::Display for IniError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}: {}", self.line, self.kind)
    }
}

impl std::error::Error for IniError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match &self.kind {
            IniErrorKind::Lobe(e) => Some(e),
            IniErrorKind::Macro(e) => Some(e.as_ref()),
            _ => None,
        }
    }
}

impl Config {
    /// The defaults updated by the lines of an ini file.
    pub fn from_ini(text: &str) -> Result<Config, IniError> {
        let mut config = Config::default();
        config.load_ini(text)?;
        Ok(config)
    }

    /// Applies the lines of an ini file on top of this configuration.
    pub fn load_ini(&mut self, text: &str) -> Result<(), IniError> {
        let mut defined = Vec::new();
        for (n, raw) in text.lines().enumerate() {
            let line = n + 1;
            let err = |kind: IniErrorKind| IniError { line, kind };
            let trimmed = raw.trim();
            if trimmed.is_empty() || trimmed.starts_with('#') {
                continue;
            }
            let (key, value) = match trimmed.split_once(char::is_whitespace) {
                Some((k, v)) => (k, v.trim()),
                None => (trimmed, ""),
            };
            let Some(rest) = key.strip_prefix("/prman/lpe/") else {
                continue;
            };
            if let Some(name) = rest.strip_prefix("macro/") {
                if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
                    return Err(err(IniErrorKind::BadMacroName(name.to_string())));
                }
                if value.is_empty() {
                    return Err(err(IniErrorKind::EmptyMacro(name.to_string())));
                }
                self.macros.define(name, value);
                defined.push((line, name.to_string()));
                continue;
            }
            let category = LobeCategory::ALL.into_iter().find(|c| {
                rest.strip_prefix(c.ini_name())
                    .is_some_and(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()))
            });
            let Some(category) = category else {
                return Err(err(IniErrorKind::UnknownKey(key.to_string())));
            };
            let lobe: u8 = rest[category.ini_name().len()..].parse().unwrap_or(0);
            let names: Vec<&str> = value
                .split(',')
                .map(str::trim)
                .filter(|s| !s.is_empty())
                .collect();
            if names.is_empty() {
                return Err(err(IniErrorKind::NoLobeNames(key.to_string())));
            }
            self.lobes
                .assign(category, lobe, names)
                .map_err(|e| err(IniErrorKind::Lobe(e)))?;
        }
        let parser = self.parser();
        for (line, name) in defined {
            parser.parse(&name).map_err(|e| IniError {
                line,
                kind: IniErrorKind::Macro(Box::new(e)),
            })?;
        }
        Ok(())
    }

    /// A parser using these macros and limits.
    pub fn parser(&self) -> Parser {
        Parser::new(self.limits.clone(), self.macros.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::renderman::path::{Event, EventKind};

    #[test]
    fn loads_macros_and_lobes() {
        let c = Config::from_ini(
            "# studio settings\n\
             /prman/lpe/macro/myDiffuse  C<RD>[<L.>O]\n\
             /prman/lpe/macro/alias myDiffuse\n\
             /prman/lpe/specular4 Sheen, Clearcoat\n\
             /prman/lpe/user5 Cryptomatte\n\
             /prman/other/setting 3\n",
        )
        .unwrap();
        let p = c.parser();
        assert_eq!(
            p.parse("myDiffuse").unwrap(),
            p.parse("C<RD>[<L.>O]").unwrap()
        );
        assert_eq!(
            p.parse("alias_key").unwrap(),
            p.parse("C<RD>[<L.'key'>O]").unwrap()
        );
        assert_eq!(
            c.lobes.event(LobeCategory::Specular, "Sheen"),
            Event::new(EventKind::S, 4).unwrap()
        );
        assert_eq!(
            c.lobes.event(LobeCategory::User, "Cryptomatte"),
            Event::new(EventKind::U, 5).unwrap()
        );
    }

    #[test]
    fn errors_name_the_line() {
        let cases = [
            ("/prman/lpe/macro/bad C<DR>L", 1, "event"),
            ("\n/prman/lpe/diffuse5 X", 2, "1 to 4"),
            ("/prman/lpe/specular Glass", 1, "unknown key"),
            ("/prman/lpe/user2", 1, "no lobe names"),
            ("/prman/lpe/macro/x", 1, "no expression"),
            (
                "/prman/lpe/macro/a b\n/prman/lpe/macro/b a",
                1,
                "nests deeper",
            ),
            ("/prman/lpe/glossy2 X", 1, "unknown key"),
        ];
        for (text, line, needle) in cases {
            let e = Config::from_ini(text).expect_err(text);
            assert_eq!(e.line, line, "{text}: {e}");
            assert!(e.to_string().contains(needle), "{text}: {e}");
        }
    }
    #[test]
    fn set_algebra_operands_are_macros_with_groups_and_prefixes() {
        // A macro operand with a light group, and a macro whose body is itself algebra.
        let config =
            Config::from_ini("/prman/lpe/macro/rest unoccluded;C.*[<L.>O] - directDiffuse\n")
                .unwrap();
        let parser = config.parser();
        let l = parser.parse("rest_key & C<RD>.*L").unwrap();
        assert!(l.prefixes.contains(crate::renderman::Prefix::Unoccluded));
        assert_eq!(
            l.to_string(),
            "unoccluded;C.*[<L.'key'>O] - C<RD>[<L.'key'>O] & C<RD>.*L"
        );
        let plain = crate::renderman::parse("directDiffuse_key").unwrap();
        assert!(plain.algebra.is_none());
    }

    #[test]
    fn set_algebra_macros_expand_and_stop_at_the_operand_limit() {
        // Macros that multiply operands hit the operand limit, not the memory: `m4` has
        // 2 * 3^4 = 162 operands, `m4 & m4` 324, and a macro `m5` fails when loaded.
        let mut ini = String::from("/prman/lpe/macro/m0 CL - CL\n");
        for i in 1..5 {
            ini.push_str(&format!(
                "/prman/lpe/macro/m{i} m{p} - m{p} - m{p}\n",
                p = i - 1
            ));
        }
        let config = Config::from_ini(&ini).unwrap();
        assert_eq!(config.parser().parse("m4").unwrap().operands().len(), 162);
        let e = config.parser().parse("m4 & m4").unwrap_err();
        assert_eq!(
            (e.kind(), e.span().start),
            (crate::renderman::ErrorKind::Limit, 5),
            "{e}"
        );
        assert!(e.message().contains("operands"), "{e}");
        ini.push_str("/prman/lpe/macro/m5 m4 - m4 - m4\n");
        let e = Config::from_ini(&ini).unwrap_err();
        assert_eq!(e.line, 6, "{e:?}");
    }
}
