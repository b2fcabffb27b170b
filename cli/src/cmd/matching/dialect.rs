//! What `lpe-check match` needs of a dialect beyond the engines' view of it
//! ([`EngineDialect`]) and the command line's ([`CliDialect`]): [`MatchDialect`],
//! implemented in [`super::renderman`] and [`super::osl`].

use lpe_engines::EngineDialect;

use super::answer::{Args, BatchCache, LineOutcome};
use crate::dialect::CliDialect;

/// A dialect as `lpe-check match` reads its arguments and batch lines.
pub trait MatchDialect: EngineDialect + CliDialect {
    /// A path shown in the error for a missing path argument.
    const EXAMPLE_PATH: &'static str;

    /// What the expression argument (or every batch line, unless a line brings its own)
    /// is read under, from `--ini` or `--register` ([`CliDialect::registration`]); the
    /// full error message if they are bad.
    fn from_args(args: &Args) -> Result<Self::Registration, String> {
        args.lang
            .registration::<Self>(args.ini.as_deref())
            .map_err(|e| format!("error: {e}"))
    }

    /// The expression argument ([`CliDialect::parse_arg`]), or its error as the dialect
    /// shows it ([`CliDialect::show_error`]); warnings go to stderr.
    fn read_arg(src: &str, registration: &Self::Registration) -> Result<Self::Lpe, String> {
        let lpe = Self::parse_arg(src, registration).map_err(|e| Self::show_error(src, &e))?;
        for w in Self::parse_warnings(&lpe) {
            eprintln!("warning: {w}");
        }
        Ok(lpe)
    }

    /// Answers one batch line (not blank, not a comment) with the engines of `cache`,
    /// parsing its expression only if `cache` does not hold it yet.
    fn batch_line<'e>(
        registration: &Self::Registration,
        line: &str,
        cache: &mut BatchCache<'e, Self>,
    ) -> LineOutcome;
}
