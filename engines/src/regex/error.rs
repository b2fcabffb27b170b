//! The `oracle` engine's build error, in a file of its own: the engine seam
//! ([`crate::engine::EngineError`]) carries it, and the engine implements that seam, so
//! the error cannot live beside the engine without the two files importing each other.

use regex_automata::dfa::dense;
use regex_automata::hybrid;
use regex_automata::nfa::thompson;

/// Why the regex-automata engine cannot build a set. regex-automata's errors are boxed:
/// they are large, and every `compile` result carries this type.
#[derive(Clone, Debug, thiserror::Error)]
pub enum BuildError {
    /// The set mentions more distinct labels than the label byte can number.
    #[error("{labels} distinct labels, the byte encoding holds {max}")]
    TooManyLabels {
        /// Distinct labels the set mentions.
        labels: usize,
        /// Most the encoding holds ([`super::encode::MAX_LABELS`], or [`super::osl::MAX_SYMBOLS`]
        /// for an OSL set).
        max: usize,
    },
    /// The Thompson NFA is over [`super::SizeLimits::nfa`] (or otherwise unbuildable).
    #[error("NFA: {0}")]
    Nfa(Box<thompson::BuildError>),
    /// The dense DFA failed for a reason other than its size limit (over the limit,
    /// the eager engine falls back to the lazy DFA).
    #[error("DFA: {0}")]
    Dfa(Box<dense::BuildError>),
    /// The lazy DFA could not be configured.
    #[error("lazy DFA: {0}")]
    LazyDfa(Box<hybrid::BuildError>),
}
