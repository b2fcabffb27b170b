//! The engines `lpe-check` and the differential harness run, behind one trait.
//!
//! Each engine compiles a *set* of expressions (a single expression is a set of one) and
//! then answers, per path, which of them match. An engine that cannot build a set (a
//! size limit) says so with [`EngineError::CannotBuild`]; callers count such skips and
//! report them, never hide them.

use std::fmt;

use lpe::aov::{AovSet, Options};
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

/// The backtracking reference matcher, one expression at a time.
pub struct Reference;

/// Crate-visible so the harness's planted-bug engine (differential.rs tests) answers
/// like the reference on its rewritten expressions without a copy of this type.
pub(crate) struct ReferenceMatcher(pub(crate) Vec<Lpe>);

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

/// lpe's fast matcher: the AOV set's minimized DFA, or bitset-NFA stepping when the
/// DFA is over the default budget. Exact on every path (no `max_path_len`).
pub struct Fast;

/// lpe's bitset NFA alone (DFA budget 0), so the NFA stepping is checked on every case
/// and not only on sets whose DFA is too large.
pub struct BitsetNfa;

struct AovSetMatcher(AovSet);

impl Matcher for AovSetMatcher {
    fn which(&self, path: &Path) -> Vec<bool> {
        let m = self.0.match_path(path);
        (0..self.0.len()).map(|i| m.contains(i)).collect()
    }
}

fn compile_set(exprs: &[Lpe], opts: &Options) -> Result<Box<dyn Matcher>, EngineError> {
    let aovs: Vec<(String, Lpe)> = exprs
        .iter()
        .enumerate()
        .map(|(i, e)| (i.to_string(), e.clone()))
        .collect();
    AovSet::compile_with(&aovs, opts)
        .map(|set| Box::new(AovSetMatcher(set)) as Box<dyn Matcher>)
        .map_err(|e| EngineError::CannotBuild(e.to_string()))
}

impl Engine for Fast {
    fn name(&self) -> &'static str {
        "fast"
    }

    fn compile(&self, exprs: &[Lpe]) -> Result<Box<dyn Matcher + '_>, EngineError> {
        compile_set(exprs, &Options::default())
    }
}

impl Engine for BitsetNfa {
    fn name(&self) -> &'static str {
        "nfa"
    }

    fn compile(&self, exprs: &[Lpe]) -> Result<Box<dyn Matcher + '_>, EngineError> {
        compile_set(
            exprs,
            &Options {
                dfa_budget: 0,
                ..Options::default()
            },
        )
    }
}

/// Every available engine, reference first.
pub fn all() -> Vec<&'static dyn Engine> {
    vec![&Reference, &crate::regex_oracle::ORACLE, &Fast, &BitsetNfa]
}

/// The engine called `name`, if available.
pub fn by_name(name: &str) -> Option<&'static dyn Engine> {
    all().into_iter().find(|e| e.name() == name)
}
