//! The seam between engines and the tools that run them.
//!
//! Each engine compiles a *set* of expressions (a single expression is a set of one) and
//! then answers, per path, which of them match. An engine that cannot build a set (a
//! size limit) says so with an [`EngineError`]; callers count such skips and report
//! them, never hide them.

use lpe::{Lpe, Path};

use crate::regex::BuildError;

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

/// A compiled expression set. `Send`, so a multi-threaded caller (the renderer's
/// `converge`) can keep one per thread; not `Sync`, since matchers may keep a mutable
/// cache.
pub trait Matcher: Send {
    /// For each compiled expression, in order, whether it matches the whole path.
    fn which(&self, path: &Path) -> Vec<bool>;
}

/// A matching engine.
pub trait Engine: Sync {
    /// Short name, as given to `--engine`.
    fn name(&self) -> &'static str;
    /// Compiles a set of expressions.
    fn compile(&self, exprs: &[Lpe]) -> Result<Box<dyn Matcher + '_>, EngineError>;
}
