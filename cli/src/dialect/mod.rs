//! What the subcommands ask of an expression language beyond [`lpe::Dialect`] and
//! [`LintDialect`]: [`CliDialect`], implemented on `lpe`'s dialect markers in
//! [`renderman`] and [`osl`]. Each subcommand is one function generic over it,
//! dispatched once on `--dialect` with [`lpe::with_dialect!`].

pub mod osl;
pub mod renderman;

use std::path::Path;

use lpe_lint::check::dialect::LintDialect;

use crate::error::InputError;

/// An expression language as the command line reads and reports it.
pub trait CliDialect: LintDialect {
    /// Whether the dialect reads `rendermn.ini` files (their macros and lobe mappings);
    /// `lint` then reads them with the other files, not as [`CliDialect::registration`].
    const READS_INI: bool;

    /// The registration the arguments give (`--ini` or `--register`); the flag the
    /// dialect does not take is an error.
    fn registration(
        ini: Option<&Path>,
        register: Option<&str>,
    ) -> Result<Self::Registration, InputError>;

    /// The registration and lobe mappings once `lint` has read its ini files into
    /// `config`, from the registration the arguments gave.
    fn configured(
        registration: Self::Registration,
        config: &lpe::renderman::Config,
    ) -> (Self::Registration, Self::Lobes);

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

    /// The warnings `parse` prints on stderr for an expression that parsed.
    fn parse_warnings(lpe: &Self::Lpe) -> Vec<String> {
        let _ = lpe;
        Vec::new()
    }
}
