//! The seam between engines and the tools that run them.
//!
//! Each engine compiles a *set* of expressions (a single expression is a set of one) and
//! then answers, per path, which of them match. An engine that cannot build a set (a
//! size limit) says so with an [`EngineError`]; callers count such skips and report
//! them, never hide them.
//!
//! Two dialects share the seam: [`Engine::compile`] takes RenderMan expressions and gives
//! a [`Matcher`] over [`lpe::renderman::Path`], [`Engine::compile_osl`] takes OSL expressions and
//! gives a `Matcher<lpe::osl::Path>`. An engine written for one dialect only keeps the
//! default `compile_osl`, which refuses with [`EngineError::Unsupported`].

use lpe::osl::{self, Registered};
use lpe::renderman::{Lpe, Path};
use lpe::DialectName;

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
    /// The engine does not speak this dialect.
    #[error("cannot build: this engine does not support the {0} dialect")]
    Unsupported(DialectName),
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

/// A compiled expression set over paths of type `P` (RenderMan's [`Path`] unless
/// named). `Send`, so a multi-threaded caller (the renderer's `converge`) can keep one
/// per thread; not `Sync`, since matchers may keep a mutable cache.
pub trait Matcher<P = Path>: Send {
    /// For each compiled expression, in order, whether it matches the whole path.
    fn which(&self, path: &P) -> Vec<bool>;
}

/// A matching engine.
pub trait Engine: Sync {
    /// Short name, as given to `--engine`.
    fn name(&self) -> &'static str;
    /// Compiles a set of expressions.
    fn compile(&self, exprs: &[Lpe]) -> Result<Box<dyn Matcher + '_>, EngineError>;
    /// Compiles a set of OSL expressions, parsed with `registered` user labels.
    fn compile_osl(
        &self,
        exprs: &[osl::Lpe],
        registered: &Registered,
    ) -> Result<Box<dyn Matcher<osl::Path> + '_>, EngineError> {
        let _ = (exprs, registered);
        Err(EngineError::Unsupported(DialectName::Osl))
    }
}
