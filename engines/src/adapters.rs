//! The workspace's own matchers behind [`Engine`]: the backtracking reference and lpe's
//! AOV set in its two stepping modes.

use lpe::{AovSet, Lpe, Options, Path};

use crate::engine::{Engine, EngineError, Matcher};

/// The backtracking reference matcher, one expression at a time.
pub struct Reference;

/// Crate-visible so the harness's planted-bug engine (differential tests) answers like
/// the reference on its rewritten expressions without a copy of this type.
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

pub(crate) fn compile_set(exprs: &[Lpe], opts: &Options) -> Result<Box<dyn Matcher>, EngineError> {
    let aovs: Vec<(String, Lpe)> = exprs
        .iter()
        .enumerate()
        .map(|(i, e)| (i.to_string(), e.clone()))
        .collect();
    let set = AovSet::compile_with(&aovs, opts)?;
    Ok(Box::new(AovSetMatcher(set)))
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
