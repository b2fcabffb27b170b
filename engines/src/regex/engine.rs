//! The `oracle` engine itself, the same for every dialect: a dialect's [`Translation`]
//! (patterns, one per operand, and the [`Encoder`] of its paths, from
//! [`OracleDialect::oracle`]) compiled into one multi-pattern automaton, searched once
//! per path, and each expression's set algebra evaluated over the patterns that match.
//!
//! Two forms of the same automaton: a lazy (hybrid) DFA, which determinizes only the
//! states the searched paths visit, and an eager dense DFA. The registered engine
//! ([`LAZY`]) is lazy because the harness compiles a new set for every case and runs
//! only a few paths on it, where eager determinization took 90% of the time; a
//! [`RegexEngine`] with `eager: true` ([`EAGER`]) builds the dense DFA first and falls
//! back to the lazy one when the dense DFA exceeds its size limit.
//!
//! Size limits are explicit (regex-automata has none by default). When even the NFA is
//! over its limit the engine refuses the set with a [`BuildError`], which the harness
//! counts as a skip.

use std::cell::RefCell;

use lpe::algebra::{formulas, Algebra};
use lpe::{AovMask, Dialect};
use regex_automata::dfa::{dense, Automaton};
use regex_automata::hybrid;
use regex_automata::nfa::thompson::{self, WhichCaptures, NFA};
use regex_automata::{Anchored, Input, MatchKind, PatternSet};
use regex_syntax::hir::Hir;

use crate::dialect::{Encoder, OracleDialect, Translation};
use crate::engine::{fits_mask, Engine, Matcher};
use crate::error::{BuildError, EngineError};

/// Limits on what one compile may allocate.
#[derive(Clone, Copy, Debug)]
pub struct SizeLimits {
    /// Thompson NFA heap size.
    pub nfa: usize,
    /// Dense DFA size, and the determinizer's working memory.
    pub dfa: usize,
    /// Lazy DFA cache.
    pub lazy_cache: usize,
}

impl SizeLimits {
    /// The defaults: generous for real AOVs, small enough that a refusal is quick.
    pub const DEFAULT: SizeLimits = SizeLimits {
        nfa: 8 << 20,
        dfa: 4 << 20,
        lazy_cache: 2 << 20,
    };
}

impl Default for SizeLimits {
    fn default() -> Self {
        SizeLimits::DEFAULT
    }
}

/// The regex-automata engine.
#[derive(Clone, Copy, Debug, Default)]
pub struct RegexEngine {
    /// Size limits for every compile.
    pub limits: SizeLimits,
    /// Build the dense DFA up front (falling back to the lazy DFA over the limit).
    pub eager: bool,
}

/// The lazy engine with default limits, registered as `oracle` in [`crate::all`].
pub static LAZY: RegexEngine = RegexEngine {
    limits: SizeLimits::DEFAULT,
    eager: false,
};

/// The engine building dense DFAs eagerly (same name, `oracle`; not registered).
pub static EAGER: RegexEngine = RegexEngine {
    limits: SizeLimits::DEFAULT,
    eager: true,
};

/// The compiled automaton: dense when it fits, lazy otherwise.
enum Searcher {
    Dense(Box<dense::DFA<Vec<u32>>>),
    Lazy(Box<(hybrid::dfa::DFA, RefCell<hybrid::dfa::Cache>)>),
}

/// One multi-pattern automaton over an encoded path, whatever the dialect's encoding:
/// which patterns match the whole byte string.
struct Program {
    patterns: usize,
    dfa: Searcher,
}

impl Program {
    /// Which patterns match all of `bytes`; `path` only names the input in a panic.
    fn which(&self, bytes: &[u8], path: &dyn std::fmt::Display) -> Vec<bool> {
        let input = Input::new(bytes).anchored(Anchored::Yes);
        let mut set = PatternSet::new(self.patterns);
        let searched = match &self.dfa {
            Searcher::Dense(d) => d.try_which_overlapping_matches(&input, &mut set),
            Searcher::Lazy(lazy) => {
                let (d, cache) = &**lazy;
                d.try_which_overlapping_matches(&mut cache.borrow_mut(), &input, &mut set)
            }
        };
        // Neither automaton has quit bytes, and the lazy one never gives up, so a
        // search error is a bug in this engine's configuration.
        if let Err(e) = searched {
            panic!("regex-automata search failed on `{path}`: {e}");
        }
        (0..self.patterns)
            .map(|i| set.contains(regex_automata::PatternID::new_unchecked(i)))
            .collect()
    }
}

/// A compiled set: the path encoding, the automaton over it, and how operands combine.
struct RegexMatcher<D: Dialect> {
    encoder: Box<dyn Encoder<D>>,
    /// One pattern per operand.
    program: Program,
    /// Per expression, its set algebra over pattern ids (a plain expression is one).
    formulas: Vec<Algebra<usize>>,
}

impl RegexEngine {
    fn build<D: OracleDialect>(&self, exprs: &[D::Lpe]) -> Result<RegexMatcher<D>, EngineError> {
        fits_mask(exprs.len())?;
        let Translation { encoder, hirs } = D::oracle(exprs)?;
        Ok(RegexMatcher {
            encoder,
            program: self.program(&hirs)?,
            formulas: formulas(exprs),
        })
    }

    /// One automaton for all of `hirs` (each anchored at the start by the search and at
    /// the end by its own `$`).
    fn program(&self, hirs: &[Hir]) -> Result<Program, BuildError> {
        let nfa: NFA = thompson::Compiler::new()
            .configure(
                thompson::Config::new()
                    .utf8(false)
                    .which_captures(WhichCaptures::None)
                    .nfa_size_limit(Some(self.limits.nfa)),
            )
            .build_many_from_hir(hirs)
            .map_err(|e| BuildError::Nfa(Box::new(e)))?;
        let dense = if self.eager {
            dense::Builder::new()
                .configure(
                    dense::Config::new()
                        .match_kind(MatchKind::All)
                        .start_kind(regex_automata::dfa::StartKind::Anchored)
                        .dfa_size_limit(Some(self.limits.dfa))
                        .determinize_size_limit(Some(self.limits.dfa)),
                )
                .build_from_nfa(&nfa)
                .map(Some)
        } else {
            Ok(None)
        };
        let dfa = match dense {
            Ok(Some(d)) => Searcher::Dense(Box::new(d)),
            Ok(None) => self.lazy(nfa)?,
            Err(e) if e.is_size_limit_exceeded() => self.lazy(nfa)?,
            Err(e) => return Err(BuildError::Dfa(Box::new(e))),
        };
        Ok(Program {
            patterns: hirs.len(),
            dfa,
        })
    }
}

impl RegexEngine {
    fn lazy(&self, nfa: NFA) -> Result<Searcher, BuildError> {
        let lazy = hybrid::dfa::Builder::new()
            .configure(
                hybrid::dfa::Config::new()
                    .match_kind(MatchKind::All)
                    .cache_capacity(self.limits.lazy_cache)
                    .skip_cache_capacity_check(true)
                    // Never give up: a slow answer beats no answer for a checking engine.
                    .minimum_cache_clear_count(None),
            )
            .build_from_nfa(nfa)
            .map_err(|e| BuildError::LazyDfa(Box::new(e)))?;
        let cache = RefCell::new(lazy.create_cache());
        Ok(Searcher::Lazy(Box::new((lazy, cache))))
    }
}

impl<D: Dialect> Matcher<D> for RegexMatcher<D> {
    fn which(&self, path: &D::Path) -> AovMask {
        let operands = self.program.which(&self.encoder.encode(path), path);
        combine(&self.formulas, &operands)
    }
}

/// Set algebra combines the per-operand answers: per expression, its formula over
/// pattern ids.
fn combine(formulas: &[Algebra<usize>], operands: &[bool]) -> AovMask {
    formulas
        .iter()
        .enumerate()
        .filter(|(_, f)| f.eval(&mut |&i| operands[i]))
        .map(|(i, _)| i)
        .collect()
}

// The registration is in the parsed trees (RenderMan's macros expanded, OSL's eaters'
// exclusions), which is all a translation reads.
impl<D: OracleDialect> Engine<D> for RegexEngine {
    fn name(&self) -> &'static str {
        "oracle"
    }

    fn compile(
        &self,
        exprs: &[D::Lpe],
        _: &D::Registration,
    ) -> Result<Box<dyn Matcher<D> + '_>, EngineError> {
        Ok(Box::new(self.build::<D>(exprs)?))
    }
}

/// Whether one expression matches the whole path (`Err` if the engine cannot build it).
pub fn is_match<D: OracleDialect>(lpe: &D::Lpe, path: &D::Path) -> Result<bool, EngineError> {
    let m = LAZY.build::<D>(std::slice::from_ref(lpe))?;
    Ok(m.which(path).contains(0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use lpe::renderman::{Lpe, Parser, Path, RenderMan};

    /// `engine`'s RenderMan matcher for `exprs`.
    fn compile<'e>(
        engine: &'e RegexEngine,
        exprs: &[Lpe],
    ) -> Result<Box<dyn Matcher<RenderMan> + 'e>, EngineError> {
        Engine::<RenderMan>::compile(engine, exprs, &Parser::default())
    }

    /// The answers to `n` expressions.
    fn answers(m: &dyn Matcher<RenderMan>, path: &Path, n: usize) -> Vec<bool> {
        crate::engine::bits(m.which(path), n)
    }

    fn is_match(lpe: &Lpe, path: &Path) -> Result<bool, EngineError> {
        super::is_match::<RenderMan>(lpe, path)
    }

    /// Whether `engine` built the dense form for `exprs`.
    fn dense(engine: &RegexEngine, exprs: &[Lpe]) -> bool {
        matches!(
            engine.build::<RenderMan>(exprs).unwrap().program.dfa,
            Searcher::Dense(_)
        )
    }

    /// The lazy and the eager automaton's answer, which must be the same.
    fn m(expr: &str, path: &str) -> bool {
        let lpe = lpe::renderman::parse(expr).unwrap();
        let path: Path = path.parse().unwrap();
        let lazy = is_match(&lpe, &path).unwrap();
        // The eager build falls back to the lazy DFA silently; without this the
        // comparison below could be the lazy DFA against itself.
        assert!(dense(&EAGER, std::slice::from_ref(&lpe)), "{lpe}");
        assert!(!dense(&LAZY, std::slice::from_ref(&lpe)), "{lpe}");
        let eager = compile(&EAGER, std::slice::from_ref(&lpe)).unwrap();
        assert_eq!(answers(&*eager, &path, 1), [lazy], "{lpe} on {path}");
        lazy
    }

    // Expected values come from the semantics table (docs/language.md), written by hand.
    #[test]
    fn design_table_cases() {
        assert!(m("C<RD>[<L.>O]", "C RD2 L'key'"));
        assert!(m("C<RD>[<L.>O]", "C RD1 O"));
        assert!(!m("C<RD>[<L.>O]", "C TD1 L"));
        assert!(!m("C<RD>[<L.>O]", "C RD1 RD1 L"));
        assert!(m("C.L", "C TS8'x' L"));
        assert!(!m("C.L", "C RU3 L"), "user lobes match only explicitly");
        assert!(m("CUL", "C RU3 L"));
        assert!(m("CU3L", "C TU3 L"));
        assert!(!m("CU3L", "C TU4 L"));
        assert!(!m("C[^D]L", "C RU1 L"), "negated class is `.` minus items");
        assert!(m("C[^D]L", "C RS2 L"));
        assert!(m("C<R.[^'foo']>L", "C RD L"), "no label is not foo");
        assert!(!m("C<R.[^'foo']>L", "C RD'foo' L"));
        assert!(m("C<R.[^'foo']>L", "C RD'bar' L"));
        assert!(m("CD|(SD)L", "C RS1 RD1 L"));
        assert!(m("CD|(SD)L", "C RD L"));
        assert!(m("C<L.'key'>", "C L'key'"));
        assert!(!m("C<L.'key'>", "C L'fill'"));
        assert!(!m("C<L.'key'>", "C L"));
        assert!(m("C'floor'L", "C RD'floor' L"));
        assert!(!m("C'floor'L", "C RU1'floor' L"));
        assert!(m("C.{0}L", "C L"));
        assert!(m("C.{2,3}L", "C RD RD RD L"));
        assert!(!m("C.{2,3}L", "C RD RD RD RD L"));
        assert!(m("C<.[^D]>L", "C RS3 L"));
        assert!(!m("C<.[^D]>L", "C RU3 L"));
        assert!(m("C<[^R]>L", "C TD L"));
        assert!(!m("C<[^R]>L", "C RD L"));
        // A label no expression mentions shares the "other" byte: it is not 'a', and
        // it is a label (so `<L.'a'>` and `'a'` do not match it).
        assert!(m("C<R.[^'a']>L", "C RD'zzz' L"));
        assert!(!m("C'a'L", "C RD'zzz' L"));
        assert!(!m("C<L.'a'>", "C L'zzz'"));
        assert!(m("C<L.[^'a']>", "C L"));
        // Event position `.` on an emitter means "no event": `<L.>` matches a light.
        assert!(m("C<L.>", "C L'k'"));
        assert!(!m("C<LD>", "C L"));
    }

    #[test]
    fn set_algebra_combines_the_operand_patterns() {
        assert!(m("C.*L - C.*DL", "C RS L"));
        assert!(!m("C.*L - C.*DL", "C RS RD L"));
        assert!(m("^C.*L", "C RD O"));
        assert!(!m("^C.*L", "C RD L"));
        assert!(m("C.*L & C<RD>.*L", "C RD RS L"));
        assert!(!m("C.*L & C<RD>.*L", "C RS RD L"));
        // Two expressions after one with two operands: pattern ids shift by operand.
        let exprs: Vec<Lpe> = ["C.*L - CL", "CL", "^CL"]
            .iter()
            .map(|s| lpe::renderman::parse(s).unwrap())
            .collect();
        let m = compile(&LAZY, &exprs).unwrap();
        assert_eq!(
            answers(&*m, &"C L".parse().unwrap(), 3),
            [false, true, false]
        );
        assert_eq!(
            answers(&*m, &"C RD L".parse().unwrap(), 3),
            [true, false, true]
        );
    }

    #[test]
    fn aov_set_is_one_automaton_answering_each_pattern() {
        let exprs: Vec<Lpe> = lpe::renderman::macros::BASIC
            .iter()
            .map(|(_, s)| lpe::renderman::parse(s).unwrap())
            .collect();
        assert!(dense(&EAGER, &exprs));
        assert!(!dense(&LAZY, &exprs));
        for engine in [&LAZY, &EAGER] {
            let m = compile(engine, &exprs).unwrap();
            let p: Path = "C RD RS RD L".parse().unwrap();
            assert_eq!(
                answers(&*m, &p, 7),
                [false, true, false, false, false, false, false]
            );
            let p: Path = "C O".parse().unwrap();
            assert_eq!(
                answers(&*m, &p, 7),
                [false, false, false, false, false, false, true]
            );
            // The pattern set is fresh per search: a second path does not inherit answers.
            let p: Path = "C TS8 L".parse().unwrap();
            assert_eq!(
                answers(&*m, &p, 7),
                [false, false, false, false, false, true, false]
            );
        }
    }

    #[test]
    fn huge_counts_are_a_typed_refusal_not_a_hang() {
        let lpe = lpe::renderman::parse("C(.{0,200}){200}L").unwrap();
        let r = compile(&LAZY, std::slice::from_ref(&lpe));
        assert!(matches!(r, Err(EngineError::Regex(BuildError::Nfa(_)))));
    }

    #[test]
    fn dfa_blowup_falls_back_to_the_lazy_dfa() {
        // "the 20th vertex from the end is diffuse": exponential for any DFA.
        let lpe = lpe::renderman::parse("C.*D.{20}L").unwrap();
        assert!(!dense(&EAGER, std::slice::from_ref(&lpe)));
        let m = compile(&EAGER, std::slice::from_ref(&lpe)).unwrap();
        let mut text = String::from("C RS RD");
        for _ in 0..20 {
            text.push_str(" RS");
        }
        text.push_str(" L");
        assert_eq!(answers(&*m, &text.parse().unwrap(), 1), [true]);
        assert_eq!(
            answers(&*m, &text.replace("RD", "RS").parse().unwrap(), 1),
            [false]
        );
    }
}
