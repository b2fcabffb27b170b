//! Why an engine produced no matcher: [`EngineError`]. In a file of its own (importing
//! only the oracle's error type), so that the seam ([`crate::engine`]) and the
//! dialects' trait ([`crate::dialect`]), which both name it, do not import each other.

use lpe::Dialect;

use crate::regex::error::BuildError;

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
