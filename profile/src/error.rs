//! Why a profile could not be had: an unknown name, an unreadable or malformed file, or
//! a rule the checks refuse, each naming the file, line and key.

use std::fmt;

/// A profile that did not load.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ProfileError {
    /// `--renderer` named no shipped profile.
    UnknownRenderer {
        /// The name given.
        name: String,
        /// The shipped names.
        known: Vec<String>,
        /// The nearest of them, if one is close.
        nearest: Option<String>,
    },
    /// The file could not be read.
    Read {
        /// The file.
        file: String,
        /// Why.
        message: String,
    },
    /// The file is not a profile: TOML that does not parse, a missing or unknown key, a
    /// value of the wrong type, or a rule the checks refuse.
    Invalid {
        /// The file (`data/karma.toml` for a shipped one).
        file: String,
        /// The line, counting from 1, when the error has a place.
        line: Option<usize>,
        /// The key at fault (`events[1].letter`), when known.
        key: Option<String>,
        /// What is wrong.
        message: String,
    },
}

impl fmt::Display for ProfileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ProfileError::UnknownRenderer {
                name,
                known,
                nearest,
            } => {
                write!(f, "unknown renderer `{name}`")?;
                if let Some(n) = nearest {
                    write!(f, " (did you mean `{n}`?)")?;
                }
                write!(f, "; known renderers: {}", known.join(", "))?;
                f.write_str("; an in-house renderer's profile loads with --profile FILE")
            }
            ProfileError::Read { file, message } => write!(f, "{file}: {message}"),
            ProfileError::Invalid {
                file,
                line,
                key,
                message,
            } => {
                f.write_str(file)?;
                if let Some(line) = line {
                    write!(f, ":{line}")?;
                }
                if let Some(key) = key {
                    write!(f, ": `{key}`")?;
                }
                write!(f, ": {message}")
            }
        }
    }
}

impl std::error::Error for ProfileError {}

/// The line (from 1) of byte `offset` in `text`.
pub(crate) fn line_of(text: &str, offset: usize) -> usize {
    let end = offset.min(text.len());
    text.as_bytes()[..end]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}
