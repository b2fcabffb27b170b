//! What the subcommands ask of an expression language beyond [`lpe::Dialect`] and
//! [`LintDialect`]: [`CliDialect`] (its registration read from and written back to
//! arguments, how its errors print), implemented on `lpe`'s dialect markers in
//! [`renderman`] and [`osl`]. Each subcommand is one function generic over it,
//! dispatched once on `--dialect` with [`lpe::with_dialect!`].

pub mod osl;
pub mod renderman;

use std::path::Path;

use lpe_lint::check::dialect::LintDialect;

use crate::error::InputError;

/// An expression language as the command line reads and reports it.
pub trait CliDialect: LintDialect + lpe_profile::ProfileDialect {
    /// The registration the arguments give (`--ini` or `--register`); the flag the
    /// dialect does not take is an error.
    fn registration(
        ini: Option<&Path>,
        register: Option<&str>,
    ) -> Result<Self::Registration, InputError>;

    /// Parses an expression argument as a file would declare it (a leading `lpe:`
    /// included).
    fn parse_arg(
        src: &str,
        registration: &Self::Registration,
    ) -> Result<Self::Lpe, Self::ParseError>;

    /// A parse error of `src` with its caret, as `parse` and `explain` print it.
    fn show_error(src: &str, e: &Self::ParseError) -> String;

    /// A parse error of `src` as `equiv` and `partition` print it, a line starting
    /// `error:`.
    fn error_line(src: &str, e: &Self::ParseError) -> String {
        Self::show_error(src, e)
    }

    /// A path argument's error, as `explain` prints it after `error: `.
    fn path_error(text: &str, e: &Self::PathError) -> String;

    /// The arguments that give `registration` back (what [`CliDialect::registration`]
    /// reads), as a replay command writes them; none, the default, for the default
    /// registration.
    fn registration_args(registration: &Self::Registration) -> Vec<String> {
        let _ = registration;
        Vec::new()
    }
}
