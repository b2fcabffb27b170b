//! RenderMan's dialect on the command line: `--ini` adds macros and lobe mappings,
//! `--register` is refused, and parse errors print as the parser shows them (a caret
//! under the span, the hint).

use std::path::Path;

use lpe::renderman::{Config, Error, Lpe, Parser, PathError, RenderMan};

use super::CliDialect;
use crate::error::InputError;

impl CliDialect for RenderMan {
    fn registration(ini: Option<&Path>, register: Option<&str>) -> Result<Parser, InputError> {
        if register.is_some() {
            return Err(InputError::RegisterWithoutOsl);
        }
        let Some(path) = ini else {
            return Ok(Parser::default());
        };
        let text = std::fs::read_to_string(path).map_err(|error| InputError::ReadIni {
            path: path.to_path_buf(),
            error,
        })?;
        Config::from_ini(&text)
            .map(|c| c.parser())
            .map_err(|error| InputError::Ini {
                path: path.to_path_buf(),
                error,
            })
    }

    fn parse_arg(src: &str, parser: &Parser) -> Result<Lpe, Error> {
        parser.parse(src)
    }

    fn show_error(_: &str, e: &Error) -> String {
        e.to_string()
    }

    /// The error already starts `error at byte N:`; these two subcommands have always
    /// put `error: ` before it, and scripts may read it.
    fn error_line(_: &str, e: &Error) -> String {
        format!("error: {e}")
    }

    fn path_error(_: &str, e: &PathError) -> String {
        e.to_string()
    }
}
