//! OSL's dialect on the command line: `--register` declares user labels, `--ini` is
//! refused (its macros and lobe mappings are RenderMan's), and parse errors print in
//! OSL's words with the expression and a caret under the character.

use std::path::Path;

use lpe::osl::{self, Error, Osl, PathError, Registered};

use super::CliDialect;
use crate::error::InputError;

impl CliDialect for Osl {
    /// `--register` absent is `-`: nothing registered.
    fn registration(ini: Option<&Path>, register: Option<&str>) -> Result<Registered, InputError> {
        if ini.is_some() {
            return Err(InputError::IniWithOsl);
        }
        register
            .unwrap_or("-")
            .parse()
            .map_err(InputError::Register)
    }

    /// `--register`, unless nothing is registered (`-`, the default).
    fn registration_args(registered: &Registered) -> Vec<String> {
        if *registered == Registered::none() {
            Vec::new()
        } else {
            vec!["--register".into(), registered.to_string()]
        }
    }

    fn parse_arg(src: &str, registered: &Registered) -> Result<osl::Lpe, Error> {
        osl::parse_source(src, registered)
    }

    /// OSL's error counts characters: the caret goes under the character at `pos`.
    fn show_error(src: &str, e: &Error) -> String {
        let col = src.get(..e.pos).map_or(e.pos, |s| s.chars().count());
        format!("error: {e}\n  {src}\n  {}^", " ".repeat(col))
    }

    fn path_error(text: &str, e: &PathError) -> String {
        format!("path `{text}`: {e}")
    }
}
