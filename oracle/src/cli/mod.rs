//! Subcommands of `lpe-check`, one module each; the binary only dispatches.

pub mod bench;
pub mod diff;
pub mod equiv;
pub mod matching;
pub mod parse;
pub mod partition;
pub mod witness;

use crate::engine::{self, Engine};

/// Reports bad input (an argument, a file, an expression) on stderr: exit status 2.
pub fn bad_input(message: impl std::fmt::Display) -> std::process::ExitCode {
    eprintln!("{message}");
    std::process::ExitCode::from(2)
}

/// `--engine` values: one engine name, or `all`.
pub fn select_engines(name: &str) -> Result<Vec<&'static dyn Engine>, String> {
    if name == "all" {
        return Ok(engine::all());
    }
    engine::by_name(name).map(|e| vec![e]).ok_or_else(|| {
        let names: Vec<&str> = engine::all().iter().map(|e| e.name()).collect();
        format!(
            "unknown engine `{name}`: available engines are {}, or `all`",
            names.join(", ")
        )
    })
}

/// The parser for the built-in macros, or for those plus an ini file's.
pub fn load_parser(ini: Option<&std::path::Path>) -> Result<lpe::Parser, String> {
    let Some(path) = ini else {
        return Ok(lpe::Parser::default());
    };
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("error: cannot read {}: {e}", path.display()))?;
    lpe::Config::from_ini(&text)
        .map(|c| c.parser())
        .map_err(|e| format!("error: {}: {e}", path.display()))
}
