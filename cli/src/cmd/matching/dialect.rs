//! What `lpe-check match` needs of a dialect beyond the engines' view of it
//! ([`EngineDialect`]): [`MatchDialect`], implemented in [`super::renderman`] and
//! [`super::osl`].

use lpe_engines::{Engine, EngineDialect};

use super::answer::{Args, LineOutcome};

/// A dialect as `lpe-check match` reads its arguments and batch lines.
pub trait MatchDialect: EngineDialect {
    /// A path shown in the error for a missing path argument.
    const EXAMPLE_PATH: &'static str;

    /// What the expression argument (or every batch line, unless a line brings its own)
    /// is read under, from the arguments; the full error message if they are bad.
    fn registration(args: &Args) -> Result<Self::Registration, String>;

    /// The expression argument, or the full error message (printed as it is). Warnings
    /// go to stderr.
    fn parse_arg(src: &str, registration: &Self::Registration) -> Result<Self::Lpe, String>;

    /// Answers one batch line (not blank, not a comment).
    fn batch_line(
        engines: &[&dyn Engine<Self>],
        registration: &Self::Registration,
        line: &str,
    ) -> LineOutcome;
}
