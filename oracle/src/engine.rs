//! The engines `lpe-check` and the differential harness run, behind one trait.
//!
//! Each engine compiles a *set* of expressions (a single expression is a set of one) and
//! then answers, per path, which of them match. An engine that cannot build a set (a
//! size limit) says so with [`EngineError::CannotBuild`]; callers count such skips and
//! report them, never hide them.

use std::fmt;

use lpe::{Lpe, Path};

/// Why an engine produced no matcher.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum EngineError {
    /// The engine refuses this input (e.g. an automaton over its size limit).
    CannotBuild(String),
}

impl fmt::Display for EngineError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            EngineError::CannotBuild(why) => write!(f, "cannot build: {why}"),
        }
    }
}

impl std::error::Error for EngineError {}

/// A compiled expression set.
pub trait Matcher {
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

/// The backtracking reference matcher, one expression at a time.
pub struct Reference;

struct ReferenceMatcher(Vec<Lpe>);

impl Matcher for ReferenceMatcher {
    fn which(&self, path: &Path) -> Vec<bool> {
        self.0
            .iter()
            .map(|e| reference::is_match(e, path))
            .collect()
    }
}

impl Engine for Reference {
    fn name(&self) -> &'static str {
        "reference"
    }

    fn compile(&self, exprs: &[Lpe]) -> Result<Box<dyn Matcher + '_>, EngineError> {
        Ok(Box::new(ReferenceMatcher(exprs.to_vec())))
    }
}

/// Every available engine, reference first.
pub fn all() -> Vec<&'static dyn Engine> {
    vec![&Reference, &crate::regex_oracle::ORACLE]
}

/// The engine called `name`, if available.
pub fn by_name(name: &str) -> Option<&'static dyn Engine> {
    all().into_iter().find(|e| e.name() == name)
}
