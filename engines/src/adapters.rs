//! The workspace's own matchers behind [`Engine`]: the backtracking reference and lpe's
//! AOV set in its two stepping modes.

use lpe::osl::{self, Registered};
use lpe::renderman::{Lpe, Path};
use lpe::{AovSet, Dialect, Options};

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
            .map(|e| lpe_reference::is_match(e, path))
            .collect()
    }
}

/// The OSL reference matcher (symbol stream with STOP), one expression at a time.
/// Crate-visible for the same reason as [`ReferenceMatcher`].
pub(crate) struct OslReferenceMatcher(pub(crate) Vec<osl::Lpe>);

impl Matcher<osl::Path> for OslReferenceMatcher {
    fn which(&self, path: &osl::Path) -> Vec<bool> {
        self.0
            .iter()
            .map(|e| lpe_reference::osl::is_match(e, path))
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

    // The registration is already in the parsed trees (the eaters' exclusions).
    fn compile_osl(
        &self,
        exprs: &[osl::Lpe],
        _: &Registered,
    ) -> Result<Box<dyn Matcher<osl::Path> + '_>, EngineError> {
        Ok(Box::new(OslReferenceMatcher(exprs.to_vec())))
    }
}

/// lpe's fast matcher: the AOV set's minimized DFA, or bitset-NFA stepping when the
/// DFA is over the default budget. Exact on every path (no `max_path_len`).
pub struct Fast;

/// lpe's bitset NFA alone (DFA budget 0), so the NFA stepping is checked on every case
/// and not only on sets whose DFA is too large.
pub struct BitsetNfa;

struct AovSetMatcher<D: Dialect>(AovSet<D>);

impl<D: Dialect> Matcher<D::Path> for AovSetMatcher<D> {
    fn which(&self, path: &D::Path) -> Vec<bool> {
        let m = self.0.match_path(path);
        (0..self.0.len()).map(|i| m.contains(i)).collect()
    }
}

/// The expressions as AOVs named by their index.
fn numbered<T: Clone>(exprs: &[T]) -> Vec<(String, T)> {
    exprs
        .iter()
        .enumerate()
        .map(|(i, e)| (i.to_string(), e.clone()))
        .collect()
}

pub(crate) fn compile_set(exprs: &[Lpe], opts: &Options) -> Result<Box<dyn Matcher>, EngineError> {
    let set = AovSet::compile_with(&numbered(exprs), opts)?;
    Ok(Box::new(AovSetMatcher(set)))
}

fn compile_osl_set(
    exprs: &[osl::Lpe],
    registered: &Registered,
    opts: &Options,
) -> Result<Box<dyn Matcher<osl::Path>>, EngineError> {
    let set = AovSet::compile_under(&numbered(exprs), registered, opts)?;
    Ok(Box::new(AovSetMatcher(set)))
}

/// Every step on the bitset NFA: no DFA, and no lazy cache to remember transitions.
fn nfa_only() -> Options {
    Options {
        dfa_budget: 0,
        lazy_cache: 0,
        ..Options::default()
    }
}

impl Engine for Fast {
    fn name(&self) -> &'static str {
        "fast"
    }

    fn compile(&self, exprs: &[Lpe]) -> Result<Box<dyn Matcher + '_>, EngineError> {
        compile_set(exprs, &Options::default())
    }

    fn compile_osl(
        &self,
        exprs: &[osl::Lpe],
        registered: &Registered,
    ) -> Result<Box<dyn Matcher<osl::Path> + '_>, EngineError> {
        compile_osl_set(exprs, registered, &Options::default())
    }
}

impl Engine for BitsetNfa {
    fn name(&self) -> &'static str {
        "nfa"
    }

    fn compile(&self, exprs: &[Lpe]) -> Result<Box<dyn Matcher + '_>, EngineError> {
        compile_set(exprs, &nfa_only())
    }

    fn compile_osl(
        &self,
        exprs: &[osl::Lpe],
        registered: &Registered,
    ) -> Result<Box<dyn Matcher<osl::Path> + '_>, EngineError> {
        compile_osl_set(exprs, registered, &nfa_only())
    }
}
