//! Why an engine produced no matcher: [`EngineError`], and the `oracle` engine's own
//! reasons, [`BuildError`]. A leaf of the crate (it imports nothing of it): the engine
//! seam ([`crate::engine`]), the dialects' traits ([`crate::dialect`]) and the engines
//! all name these types, and none of them may sit below the others for it.

use lpe::Dialect;
use regex_automata::dfa::dense;
use regex_automata::hybrid;
use regex_automata::nfa::thompson;

/// Why an engine produced no matcher. Displayed as `cannot build: <why>`.
#[derive(Clone, Debug, thiserror::Error)]
pub enum EngineError {
    /// lpe's compiler refused the set (the `fast` and `nfa` engines): too many AOVs, or
    /// an automaton over a limit.
    #[error("cannot build: {0}")]
    Compile(lpe::CompileError),
    /// The regex-automata translation refused the set (the `oracle` engine).
    #[error("cannot build: {0}")]
    Regex(BuildError),
    /// The reference front end refused lpe's canonical print of the expression (a
    /// front-end disagreement: lpe accepted it).
    #[error("cannot build: the reference front end refuses `{text}`: {why}")]
    Reference {
        /// The printed expression.
        text: String,
        /// The reference's error.
        why: String,
    },
    /// The engine does not speak this dialect (its name, [`Dialect::NAME`]: a name
    /// rather than a `DialectName`, so that a dialect outside the registry can be
    /// refused too).
    #[error("cannot build: this engine does not support the {0} dialect")]
    Unsupported(&'static str),
}

impl EngineError {
    /// The refusal of dialect `D`.
    pub fn unsupported<D: Dialect>() -> EngineError {
        EngineError::Unsupported(D::NAME)
    }
}

// Written out rather than `#[from]`, which would also make the inner error the
// `source()`: its text is already in the message, and error-chain printers would show
// it twice.
impl From<lpe::CompileError> for EngineError {
    fn from(e: lpe::CompileError) -> Self {
        EngineError::Compile(e)
    }
}

impl From<BuildError> for EngineError {
    fn from(e: BuildError) -> Self {
        EngineError::Regex(e)
    }
}

/// Why the regex-automata engine cannot build a set. regex-automata's errors are boxed:
/// they are large, and every `compile` result carries this type.
#[derive(Clone, Debug, thiserror::Error)]
pub enum BuildError {
    /// The set mentions more distinct labels than the label byte can number.
    #[error("{labels} distinct labels, the byte encoding holds {max}")]
    TooManyLabels {
        /// Distinct labels the set mentions.
        labels: usize,
        /// Most the encoding holds (`regex::renderman::encode::MAX_LABELS`, or
        /// `regex::osl::MAX_SYMBOLS` for an OSL set).
        max: usize,
    },
    /// The Thompson NFA is over [`crate::regex::SizeLimits::nfa`] (or otherwise unbuildable).
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
