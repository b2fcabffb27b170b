//! The workspace's own matchers behind [`Engine`]: the backtracking reference and lpe's
//! AOV set in its two stepping modes, each written once for every dialect.

use std::cell::RefCell;

use lpe::{AovMask, AovSet, Cache, Dialect, DirectSet, Options};

use crate::dialect::ReferenceDialect;
use crate::engine::{fits_mask, Engine, EngineError, Matcher};

/// The backtracking reference matcher ([`ReferenceDialect::reference`]) on the trees of the
/// reference's own front end, one expression at a time.
pub struct Reference;

/// Crate-visible so the harness's planted-bug engines (differential tests) answer like
/// the reference on their rewritten expressions without a copy of this type.
pub(crate) struct ReferenceMatcher<D: ReferenceDialect>(pub(crate) Vec<D::ReferenceTree>);

impl<D: ReferenceDialect> ReferenceMatcher<D> {
    /// Every expression read by the reference's own front end
    /// ([`ReferenceDialect::reference_tree`]).
    pub(crate) fn new(
        exprs: &[D::Lpe],
        registration: &D::Registration,
    ) -> Result<ReferenceMatcher<D>, EngineError> {
        let trees = exprs
            .iter()
            .map(|e| D::reference_tree(e, registration))
            .collect::<Result<_, _>>()?;
        Ok(ReferenceMatcher(trees))
    }
}

impl<D: ReferenceDialect> Matcher<D> for ReferenceMatcher<D> {
    fn which(&self, path: &D::Path) -> AovMask {
        self.0
            .iter()
            .enumerate()
            .filter(|(_, e)| D::reference(e, path))
            .map(|(i, _)| i)
            .collect()
    }
}

impl<D: ReferenceDialect> Engine<D> for Reference {
    fn name(&self) -> &'static str {
        "reference"
    }

    /// Each expression read again by the reference's own front end, under the
    /// registration (see [`ReferenceDialect::reference_tree`]).
    fn compile(
        &self,
        exprs: &[D::Lpe],
        registration: &D::Registration,
    ) -> Result<Box<dyn Matcher<D> + '_>, EngineError> {
        fits_mask(exprs.len())?;
        Ok(Box::new(ReferenceMatcher::<D>::new(exprs, registration)?))
    }
}

/// lpe's fast matcher: the AOV set's minimized DFA, or bitset-NFA stepping when the
/// DFA is over the default budget. Exact on every path (no `max_path_len`).
pub struct Fast;

/// lpe's bitset NFA alone (DFA budget 0), so the NFA stepping is checked on every case
/// and not only on sets whose DFA is too large.
pub struct BitsetNfa;

struct AovSetMatcher<D: Dialect>(AovSet<D>);

impl<D: Dialect> Matcher<D> for AovSetMatcher<D> {
    fn which(&self, path: &D::Path) -> AovMask {
        self.0.match_path(path)
    }
}

/// A lazy set stepped through a cache of its own ([`AovSet::match_path_with`]), not the
/// thread's, which a batch whose lines take turns between expressions would hand from
/// set to set.
struct OwnCacheMatcher<D: Dialect>(AovSet<D>, RefCell<Cache>);

impl<D: Dialect> Matcher<D> for OwnCacheMatcher<D> {
    fn which(&self, path: &D::Path) -> AovMask {
        self.0.match_path_with(&mut self.1.borrow_mut(), path)
    }
}

/// A set that answers a few paths on the expression trees themselves ([`DirectSet`]).
struct DirectMatcher<D: Dialect>(DirectSet<D>);

impl<D: Dialect> Matcher<D> for DirectMatcher<D> {
    fn which(&self, path: &D::Path) -> AovMask {
        self.0.match_path(path)
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

/// lpe's AOV set of `exprs` under `registration`, compiled with `opts`.
pub(crate) fn compile_set<D: Dialect>(
    exprs: &[D::Lpe],
    registration: &D::Registration,
    opts: &Options,
) -> Result<Box<dyn Matcher<D>>, EngineError> {
    let set = AovSet::<D>::compile_under(&numbered(exprs), registration, opts)?;
    Ok(Box::new(AovSetMatcher(set)))
}

/// Every step on the bitset NFA: no DFA, and no lazy cache to remember transitions.
pub(crate) fn nfa_only() -> Options {
    Options {
        dfa_budget: 0,
        lazy_cache: 0,
        ..Options::default()
    }
}

/// The lazy-DFA cache of a set compiled for some paths: a batch keeps up to 1 024
/// expressions compiled, each with its own cache, so 64 MiB at most in all.
pub const SOME_PATHS_CACHE: usize = 64 << 10;

impl<D: Dialect> Engine<D> for Fast {
    fn name(&self) -> &'static str {
        "fast"
    }

    fn compile(
        &self,
        exprs: &[D::Lpe],
        registration: &D::Registration,
    ) -> Result<Box<dyn Matcher<D> + '_>, EngineError> {
        compile_set(exprs, registration, &Options::default())
    }

    /// The expression trees evaluated on each path ([`DirectSet`]): compiling is one
    /// walk of the tree and the vertex classes, where the NFA unrolls every counted
    /// repetition (`.{150}` is 150 positions) and the DFA determinizes it, which a batch
    /// line whose expression does not repeat would pay for one path.
    fn compile_for_few_paths(
        &self,
        exprs: &[D::Lpe],
        _: &D::Registration,
    ) -> Result<Box<dyn Matcher<D> + '_>, EngineError> {
        // The full compile's NFA budget, so that a batch refuses such an expression on
        // every line alike.
        let set = DirectSet::<D>::compile_within(&numbered(exprs), &Options::default())?;
        Ok(Box::new(DirectMatcher(set)))
    }

    /// The lazy DFA over the bare NFA ([`Options::few_paths`], `dfa_budget` 0): the NFA
    /// without its step tables compiles in microseconds, and the lazy DFA's cache makes
    /// the steps of the paths after the first few table reads; the minimized DFA of a
    /// 40-item alternation costs a quarter of a millisecond, which a few hundred lines do
    /// not repay. The cache is the matcher's own, of at most [`SOME_PATHS_CACHE`] bytes.
    fn compile_for_some_paths(
        &self,
        exprs: &[D::Lpe],
        registration: &D::Registration,
    ) -> Result<Box<dyn Matcher<D> + '_>, EngineError> {
        Ok(Box::new(some_paths_matcher(exprs, registration)?))
    }
}

/// What [`Fast`] compiles for some paths, as its own type (for the tests, which look
/// at the automaton and the cache).
fn some_paths_matcher<D: Dialect>(
    exprs: &[D::Lpe],
    registration: &D::Registration,
) -> Result<OwnCacheMatcher<D>, EngineError> {
    let opts = Options {
        dfa_budget: 0,
        few_paths: true,
        lazy_cache: SOME_PATHS_CACHE,
        ..Options::default()
    };
    let set = AovSet::<D>::compile_under(&numbered(exprs), registration, &opts)?;
    let cache = RefCell::new(set.cache());
    Ok(OwnCacheMatcher(set, cache))
}

impl<D: Dialect> Engine<D> for BitsetNfa {
    fn name(&self) -> &'static str {
        "nfa"
    }

    fn compile(
        &self,
        exprs: &[D::Lpe],
        registration: &D::Registration,
    ) -> Result<Box<dyn Matcher<D> + '_>, EngineError> {
        compile_set(exprs, registration, &nfa_only())
    }
}

#[cfg(test)]
mod tests {
    //! The fast engine's compiles for a few and for some paths against the reference on
    //! generated cases, in both dialects: the differential runs compare
    //! [`Engine::compile`] only. Caught when planted: the direct set's atom accepting
    //! nothing (both dialects disagree).

    use lpe::osl::Osl;
    use lpe::renderman::RenderMan;

    use super::*;
    use crate::differential::{run_cases, Generate, Run};

    /// [`Fast`] as it compiles for a few paths or for some paths, through
    /// [`Engine::compile`] so that the differential run asks it.
    enum FastFor {
        FewPaths,
        SomePaths,
    }

    impl<D: Dialect> Engine<D> for FastFor {
        fn name(&self) -> &'static str {
            match self {
                FastFor::FewPaths => "fast-few-paths",
                FastFor::SomePaths => "fast-some-paths",
            }
        }

        fn compile(
            &self,
            exprs: &[D::Lpe],
            registration: &D::Registration,
        ) -> Result<Box<dyn Matcher<D> + '_>, EngineError> {
            match self {
                FastFor::FewPaths => Fast.compile_for_few_paths(exprs, registration),
                FastFor::SomePaths => Fast.compile_for_some_paths(exprs, registration),
            }
        }
    }

    /// The some-paths set is what [`Fast::compile_for_some_paths`] promises: a lazy DFA
    /// (no minimized DFA built) over an NFA without its step tables (the 16 positions of
    /// `C.*<RD>.{11}L` make a one-word state, whose per-byte tables take up to 16 KiB:
    /// [`Options::nfa_budget`]; with them the set takes more), stepped through a 64 KiB
    /// cache of its own. That expression's lazy DFA has a state per
    /// choice of which of the last 12 vertices were diffuse (4 096), and a path of 20 000
    /// pseudo-random diffuse and specular bounces visits most of them: more rows than 64
    /// KiB holds, so the cache is cleared, where the default 2 MiB would hold them all.
    /// The path ends in a diffuse bounce, 11 specular ones and the light: it matches.
    /// Caught: the cache's size 64 << 10 as 64 >> 10 (no caching: no rows), and each of
    /// `dfa_budget`, `few_paths` and `lazy_cache` left at its default (the DFA built,
    /// the step tables built, the cache never cleared).
    #[test]
    fn the_some_paths_set_is_lazy_over_a_bare_nfa_with_a_small_cache_of_its_own() {
        let lpe = lpe::renderman::parse("C.*<RD>.{11}L").unwrap();
        let m = some_paths_matcher::<RenderMan>(&[lpe], &Default::default()).unwrap();
        assert!(!m.0.automaton().uses_dfa());
        assert!(m.0.memory_bytes() < 16 << 10, "{}", m.0.memory_bytes());
        let mut x = 12345u64;
        let mut text = String::from("C");
        for _ in 0..20_000 {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            text.push_str(if x >> 63 == 1 { " RD" } else { " RS" });
        }
        text.push_str(" RD");
        text.push_str(&" RS".repeat(11));
        text.push_str(" L");
        let path: lpe::renderman::Path = text.parse().unwrap();
        assert_eq!(m.which(&path).iter().collect::<Vec<_>>(), [0]);
        let cache = m.1.borrow();
        assert!(
            cache.rows() > 0 && cache.clears() > 0,
            "rows {}, clears {}",
            cache.rows(),
            cache.clears()
        );
    }

    fn agrees<D: Generate>(cases: u64, max_size: usize) {
        let args = Run {
            cases,
            seed: 3,
            first: 0,
            max_size,
            paths: 4,
            max_failures: 1,
        };
        let t = run_cases::<D>(
            &args,
            &[&Reference, &FastFor::FewPaths, &FastFor::SomePaths],
        );
        if let Some((i, c)) = t.failures.first() {
            panic!("case {i}:\n{c}");
        }
        assert_eq!(t.uncompared, 0, "{:?}", t.skips);
        assert!(
            t.matched > 0 && t.matched < t.pairs,
            "{} of {}",
            t.matched,
            t.pairs
        );
    }

    #[test]
    fn few_paths_answers_as_the_reference() {
        agrees::<RenderMan>(300, 10);
    }

    #[test]
    fn few_paths_answers_as_the_reference_in_the_osl_dialect() {
        agrees::<Osl>(400, 8);
    }
}
