//! AOV sets: many expressions compiled into one automaton, stepped once per vertex.
//!
//! [`AovSet::compile`] builds, for a list of `(name, expression)` pairs:
//! 1. the dialect's vertex classes ([`Dialect::classes`]; RenderMan's compressed alphabet
//!    is `renderman::alphabet`): vertices grouped into [`Class`]es;
//! 2. one bitset Glushkov NFA holding every AOV's positions (module `automata::nfa`);
//! 3. a minimized dense DFA over it (module `automata::dfa`), unless that would exceed
//!    [`Options::dfa_budget`]; then the set is a lazy DFA (module [`crate::automata::lazy`]):
//!    determinized on demand into per-thread [`Cache`]s. Both give the same answers (the
//!    `fast` and `nfa` engines of the differential harness check that).
//!
//! A [`State`] is one `u32` either way. Sets over the DFA budget step fastest through a
//! caller-owned [`Cache`] per thread ([`AovSet::cache`], [`AovSet::step_with`],
//! [`AovSet::matches_with`]); the plain `State` API uses a per-thread cache of its own.
//! A RenderMan set can intern labels once ([`AovSet::label_id`]) so that classifying a
//! vertex is index arithmetic ([`AovSet::classify_interned`]).
//!
//! A renderer compiles once, shares the set across threads (`AovSet` is `Send + Sync`,
//! immutable, lock-free), and per path calls [`AovSet::start`], then [`AovSet::step`] (or
//! [`AovSet::step_class`] on classes computed once per material lobe at scene load) per
//! vertex, reads [`AovSet::matches`] at the emitter and may stop early once
//! [`AovSet::is_dead`]. Stepping never allocates.
//!
//! ```
//! use lpe::aov::AovSet;
//! use lpe::renderman::macros::BASIC;
//! use lpe::renderman::{parse, Event, EventKind, Lpe, Vertex, VertexType};
//!
//! let aovs: Vec<(String, Lpe)> = BASIC
//!     .iter()
//!     .map(|(name, src)| (name.to_string(), parse(src).unwrap()))
//!     .collect();
//! let set = AovSet::compile(&aovs).unwrap();
//!
//! // Scene load: classify each material lobe once.
//! let floor = Vertex::scatter(VertexType::R, Event::new(EventKind::D, 2).unwrap(), Some("floor"));
//! let floor_class = set.classify(&floor);
//!
//! // Per path: one table step per vertex.
//! let mut s = set.start();
//! s = set.step(s, &Vertex::camera());
//! s = set.step_class(s, floor_class);
//! s = set.step_class(s, floor_class);
//! assert!(!set.is_dead(s));
//! s = set.step(s, &Vertex::light(Some("key")));
//! let hits: Vec<&str> = set.matches(s).iter().map(|i| set.names()[i].as_str()).collect();
//! assert_eq!(hits, ["indirectDiffuse"]);
//! ```

use crate::algebra::SetExpr;
use std::ops::Deref;

pub use crate::automata::automaton::Automaton;
use crate::automata::emptiness::{self, Warning};
pub use crate::automata::error::CompileError;
use crate::automata::ir::VertexClasses;
pub use crate::automata::lazy::Cache;
use crate::automata::mask::{AovMask, Class, State, MAX_AOVS};
use crate::automata::nfa::{Builder, Nfa};
pub use crate::automata::options::Options;
use crate::automata::visible::Visible;
pub use crate::automata::wide::NfaMatcher;
use crate::dialect::{Dialect, DialectLpe};

/// The hidden AOVs of a set: every operand of set algebra is one, a plain AOV is one
/// operand.
pub(crate) struct Hidden<'a, E> {
    pub(crate) operands: Vec<&'a E>,
    /// Per hidden AOV, the name of the AOV it belongs to.
    names: Vec<String>,
    /// With set algebra: the visible masks as formulas over the hidden ones.
    pub(crate) visible: Option<Visible>,
}

impl<'a, E> Hidden<'a, E> {
    pub(crate) fn of<L: SetExpr<Operand = E>>(
        aovs: &'a [(String, L)],
    ) -> Result<Self, CompileError> {
        if aovs.len() > MAX_AOVS {
            return Err(CompileError::TooManyAovs(aovs.len()));
        }
        let operands: Vec<&E> = aovs.iter().flat_map(|(_, l)| l.operands()).collect();
        if operands.len() > MAX_AOVS {
            return Err(CompileError::TooManyOperands {
                aovs: aovs.len(),
                hidden: operands.len(),
            });
        }
        let visible = aovs
            .iter()
            .any(|(_, l)| l.algebra().is_some())
            .then(|| Visible::new(crate::algebra::formulas(aovs.iter().map(|(_, l)| l))));
        let names = aovs
            .iter()
            .flat_map(|(n, l)| std::iter::repeat_n(n.clone(), l.operands().len()))
            .collect();
        Ok(Hidden {
            operands,
            names,
            visible,
        })
    }

    /// The emptiness warnings of the plain AOVs, renumbered from hidden AOVs: the NFA
    /// alone answers for them, while an AOV with set algebra needs a search of the set's
    /// states (`analysis::warnings`).
    fn plain_warnings<L: SetExpr<Operand = E>>(
        aovs: &[(String, L)],
        hidden: &[Warning],
    ) -> Vec<Warning> {
        let mut out = Vec::new();
        let mut first = 0;
        for (i, (_, l)) in aovs.iter().enumerate() {
            if l.algebra().is_none() {
                if let Some(w) = hidden.iter().find(|w| w.aov == first) {
                    out.push(Warning {
                        aov: i,
                        ..w.clone()
                    });
                }
            }
            first += l.operands().len();
        }
        out
    }
}

/// A compiled AOV set of dialect `D`: the dialect's vertex classes in front of the
/// [`Automaton`] every dialect steps, which the set dereferences to (`set.start()`,
/// `set.step_class(s, c)`, `set.matches(s)`, …). See the [module docs](self).
///
/// A set is of one dialect by type: another dialect's vertex does not classify.
///
/// ```compile_fail
/// use lpe::AovSet;
///
/// let set = AovSet::compile(&[("d".to_string(), lpe::renderman::parse("C<RD>L").unwrap())]).unwrap();
/// let osl_vertex: lpe::osl::Vertex = "C,_".parse().unwrap();
/// set.classify(&osl_vertex);
/// ```
#[derive(Clone, Debug)]
pub struct AovSet<D: Dialect> {
    names: Vec<String>,
    lpes: Vec<D::Lpe>,
    registration: D::Registration,
    classes: D::Classes,
    automaton: Automaton,
    warnings: Vec<Warning>,
}

impl<D: Dialect> Deref for AovSet<D> {
    type Target = Automaton;

    #[inline(always)]
    fn deref(&self) -> &Automaton {
        &self.automaton
    }
}

impl<D: Dialect> AovSet<D> {
    /// Compiles with default [`Options`] and the dialect's default registration (the
    /// dialect is the expressions').
    pub fn compile<L>(aovs: &[(String, L)]) -> Result<AovSet<D>, CompileError>
    where
        L: DialectLpe<Dialect = D>,
        D: Dialect<Lpe = L>,
    {
        Self::compile_under(aovs, &D::Registration::default(), &Options::default())
    }

    /// Compiles with explicit options.
    pub fn compile_with<L>(aovs: &[(String, L)], opts: &Options) -> Result<AovSet<D>, CompileError>
    where
        L: DialectLpe<Dialect = D>,
        D: Dialect<Lpe = L>,
    {
        Self::compile_under(aovs, &D::Registration::default(), opts)
    }

    /// Compiles expressions parsed under `registration` (OSL's user labels, RenderMan's
    /// macros: the set keeps it for [`AovSet::registration`]) with explicit options. The
    /// eager DFA is attempted within the smaller of [`Options::dfa_budget`] and
    /// [`Dialect::DFA_ATTEMPT_BUDGET`].
    ///
    /// ```
    /// use lpe::osl::{self, Osl, Registered};
    /// use lpe::{AovSet, Options};
    ///
    /// let reg = Registered::none();
    /// let aovs = vec![("diffuse".to_string(), osl::parse("C<RD>L", &reg).unwrap())];
    /// let set = AovSet::compile_under(&aovs, &reg, &Options::default()).unwrap();
    /// let hit = set.match_path(&"C,_ R,D,floor L,_".parse().unwrap());
    /// assert!(hit.contains(0));
    /// assert!(set.match_path(&"C,_ R,D,G L,_".parse().unwrap()).is_empty());
    /// ```
    pub fn compile_under<L>(
        aovs: &[(String, L)],
        registration: &D::Registration,
        opts: &Options,
    ) -> Result<AovSet<D>, CompileError>
    where
        L: DialectLpe<Dialect = D>,
        D: Dialect<Lpe = L>,
    {
        Self::compile_lpes(aovs, registration, opts)
    }

    fn compile_lpes(
        aovs: &[(String, D::Lpe)],
        registration: &D::Registration,
        opts: &Options,
    ) -> Result<AovSet<D>, CompileError> {
        let Hidden {
            operands,
            names: hidden_names,
            visible,
        } = Hidden::of(aovs)?;
        let (classes, nfa, atoms) = Self::build_nfa(&operands, opts)?;
        // A set for a few paths is asked for answers, not findings: the emptiness
        // search (four searches and a message for an AOV that matches nothing) would
        // cost a third of its compile.
        let warnings = if opts.few_paths {
            Vec::new()
        } else {
            Hidden::plain_warnings(
                aovs,
                &emptiness::empty_aovs(&nfa, &classes, D::SHAPE, &atoms, &hidden_names, &operands),
            )
        };
        let attempt = Options {
            dfa_budget: opts.dfa_budget.min(D::DFA_ATTEMPT_BUDGET),
            ..opts.clone()
        };
        let automaton = Automaton::build(nfa, classes.class_count(), &attempt, visible)?;
        Ok(AovSet {
            names: aovs.iter().map(|(n, _)| n.clone()).collect(),
            lpes: aovs.iter().map(|(_, l)| l.clone()).collect(),
            registration: registration.clone(),
            classes,
            automaton,
            warnings,
        })
    }

    /// The vertex classes and NFA of `aovs`' operands (hidden AOVs, numbered as
    /// [`crate::algebra::formulas`] numbers them) with each AOV's formula over them, under
    /// the checks and limits of a compile but without the DFA: what the analyses search.
    #[allow(clippy::type_complexity)]
    pub(crate) fn operand_nfa(
        aovs: &[(String, D::Lpe)],
        opts: &Options,
    ) -> Result<(D::Classes, Nfa, Vec<crate::algebra::Algebra<usize>>), CompileError> {
        let hidden = Hidden::of(aovs)?;
        let (classes, nfa, _) = Self::build_nfa(&hidden.operands, opts)?;
        let formulas = crate::algebra::formulas(aovs.iter().map(|(_, l)| l));
        Ok((classes, nfa, formulas))
    }

    /// Whether the NFA of the hidden AOVs `exprs` fits [`Options::nfa_budget`], counted
    /// without building it.
    pub(crate) fn check_positions(exprs: &[&D::Expr], opts: &Options) -> Result<(), CompileError> {
        let positions = exprs.iter().fold(1u64, |n, e| {
            n.saturating_add(D::positions(e, opts.max_path_len))
        });
        Self::check_nfa_budget(positions, opts)
    }

    /// One follow row per position is the least an NFA needs: `positions^2 / 8` bytes.
    fn check_nfa_budget(positions: u64, opts: &Options) -> Result<(), CompileError> {
        let rows = positions
            .checked_mul(positions.div_ceil(64))
            .and_then(|r| r.checked_mul(8));
        if rows.is_none_or(|r| r > opts.nfa_budget as u64) {
            return Err(CompileError::NfaOverBudget {
                positions,
                bytes: rows,
                budget: opts.nfa_budget,
            });
        }
        Ok(())
    }

    /// The vertex classes and NFA of the hidden AOVs `exprs`, and their distinct atoms
    /// (the NFA's atom indices refer to them).
    #[allow(clippy::type_complexity)]
    pub(crate) fn build_nfa<'a>(
        exprs: &[&'a D::Expr],
        opts: &Options,
    ) -> Result<(D::Classes, Nfa, Vec<&'a D::Atom>), CompileError> {
        Self::check_positions(exprs, opts)?;
        let (builder, parts) = Builder::of_all(exprs.iter().copied(), opts.max_path_len);
        let classes = D::classes(&builder.atoms, exprs)?;
        // Borrowed from `aovs`: the analysis outlives the builder, which the NFA consumes.
        let atoms = builder.atoms.clone();
        let nfa = Nfa::new(builder, parts, &classes, opts);
        Ok((classes, nfa, atoms))
    }

    /// The class of a vertex: compute it once per material lobe and step with
    /// [`AovSet::step_class`].
    #[inline]
    pub fn classify(&self, v: &D::Vertex) -> Class {
        self.classes.classify(v)
    }

    /// One vertex.
    #[inline]
    pub fn step(&self, s: State, v: &D::Vertex) -> State {
        self.step_class(s, self.classify(v))
    }

    /// The bitset NFA of a lazy set, stepped on its wide state without registry or
    /// cache; `None` for a set with a DFA (which drops its NFA) and for a set of more
    /// positions than an [`crate::NfaState`] holds (`64 * NFA_STATE_WORDS`: such a set
    /// steps its lazy DFA, whose states are registry ids of any width).
    pub fn nfa(&self) -> Option<NfaMatcher<'_, D::Classes>> {
        let (nfa, visible, empty_is_dead) = self.automaton.lazy_nfa()?;
        Some(NfaMatcher {
            nfa,
            classes: &self.classes,
            visible,
            empty_is_dead,
        })
    }

    /// Steps a whole path from the start.
    pub fn match_path(&self, path: &D::Path) -> AovMask {
        let s = D::vertices(path)
            .iter()
            .fold(self.start(), |s, v| self.step(s, v));
        self.matches(s)
    }

    /// [`AovSet::match_path`] through a caller-owned `cache` ([`AovSet::cache`]) instead
    /// of the thread's: a caller that takes turns between sets on one thread (a batch
    /// whose lines alternate expressions) keeps each set's transitions, where the
    /// thread's cache, holding one set at a time, would start over at every switch.
    pub fn match_path_with(&self, cache: &mut Cache, path: &D::Path) -> AovMask {
        let s = D::vertices(path).iter().fold(self.start(), |s, v| {
            self.step_with(cache, s, self.classify(v))
        });
        self.matches_with(cache, s)
    }

    /// The name of the set's dialect ([`Dialect::NAME`]).
    pub fn dialect(&self) -> &'static str {
        D::NAME
    }

    /// What the set's expressions were parsed under.
    pub fn registration(&self) -> &D::Registration {
        &self.registration
    }

    /// Number of AOVs.
    pub fn len(&self) -> usize {
        self.names.len()
    }

    /// A set of no AOVs.
    pub fn is_empty(&self) -> bool {
        self.names.is_empty()
    }

    /// The AOV names, in compile order (bit `i` of an [`AovMask`] is `names()[i]`).
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The AOV expressions, in compile order (RenderMan's prefixes tell the renderer what
    /// to accumulate).
    pub fn lpes(&self) -> &[D::Lpe] {
        &self.lpes
    }

    /// AOVs that can match no path, with the reason, found at compile time on the NFA
    /// alone. Set-algebra AOVs need a search of the set's states:
    /// [`crate::analysis::warnings`] covers every AOV.
    pub fn warnings(&self) -> &[Warning] {
        &self.warnings
    }

    /// A shortest vertex of class `c` (`0..class_count()`) at the first place of the
    /// dialect's path shape where the class occurs; `None` for a class out of range.
    /// Every class has one, so stepping over these visits every state of the set.
    pub fn class_vertex(&self, c: usize) -> Option<D::Vertex> {
        if c >= self.classes.class_count() {
            return None;
        }
        D::SHAPE
            .places()
            .iter()
            .find_map(|&p| self.classes.representative(c, p))
    }

    /// Number of vertex classes.
    pub fn class_count(&self) -> usize {
        self.classes.class_count()
    }

    /// Bytes held by the automaton the set steps and by the class tables.
    pub fn memory_bytes(&self) -> usize {
        self.classes.memory_bytes() + self.automaton.memory_bytes()
    }

    /// The automaton the set steps (what it dereferences to).
    pub fn automaton(&self) -> &Automaton {
        &self.automaton
    }

    /// The set's vertex classes.
    pub(crate) fn classes(&self) -> &D::Classes {
        &self.classes
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::renderman::{parse, Lpe, Path, RenderMan, Vertex};

    fn lpe(s: &str) -> Lpe {
        parse(s).unwrap()
    }

    fn set(srcs: &[&str], opts: &Options) -> AovSet<RenderMan> {
        let aovs: Vec<(String, Lpe)> = srcs
            .iter()
            .map(|s| (s.to_string(), parse(s).unwrap()))
            .collect();
        AovSet::compile_with(&aovs, opts).unwrap()
    }

    fn nfa_only() -> Options {
        Options {
            dfa_budget: 0,
            ..Options::default()
        }
    }

    #[test]
    fn set_is_send_and_sync() {
        fn check<T: Send + Sync>() {}
        check::<AovSet<RenderMan>>();
        check::<AovSet<crate::osl::Osl>>();
    }

    #[test]
    fn emptiness_warning_for_camera_star() {
        let set = AovSet::compile(&[("c".into(), lpe("C.*")), ("ok".into(), lpe("C.*L"))]).unwrap();
        let w = set.warnings();
        assert_eq!(w.len(), 1, "{w:?}");
        assert_eq!(w[0].aov, 0);
        assert!(
            w[0].message.contains("never reaches an emitter"),
            "{}",
            w[0]
        );
    }

    #[test]
    fn emptiness_reasons() {
        let cases = [
            ("C<CD>L", "matches no vertex"),
            ("RDL", "other than the camera"),
            ("CLRDL", "in the middle"),
        ];
        for (src, needle) in cases {
            let set = AovSet::compile(&[("x".into(), lpe(src))]).unwrap();
            let w = set.warnings();
            assert_eq!(w.len(), 1, "{src}: {w:?}");
            assert!(w[0].message.contains(needle), "{src}: {}", w[0]);
        }
    }

    #[test]
    fn dead_state_is_reached_early() {
        for opts in [Options::default(), nfa_only()] {
            let s = set(&["C<RD>L"], &opts);
            let mut st = s.start();
            st = s.step(st, &Vertex::camera());
            assert!(!s.is_dead(st));
            st = s.step(st, &Vertex::light(None));
            assert!(s.matches(st).is_empty());
            assert!(s.is_dead(st));
        }
    }

    #[test]
    fn atoms_matching_nothing_make_the_state_dead_in_both_modes() {
        for opts in [Options::default(), nfa_only()] {
            let s = set(&["CR<CD>L", "C<L.'a'>"], &opts);
            let st = s.step(s.start(), &Vertex::camera());
            assert!(!s.is_dead(st));
            // After `C R`, only `<CD>` could follow, and it matches no vertex.
            let p: Path = "C RD L".parse().unwrap();
            let st = s.step(st, &p.vertices()[1]);
            assert!(s.is_dead(st));
        }
    }

    #[test]
    fn over_budget_falls_back_to_the_nfa() {
        // 2^21 subsets: far over a 1 MiB budget.
        let s = set(
            &["C.*D.{20}[LO]"],
            &Options {
                dfa_budget: 1 << 20,
                ..Options::default()
            },
        );
        assert!(!s.uses_dfa());
        let mut p = "C RD".to_string();
        p.push_str(&" RS".repeat(20));
        p.push_str(" L");
        assert!(s.match_path(&p.parse().unwrap()).contains(0));
    }

    #[test]
    fn empty_sets_and_foreign_states_do_not_panic() {
        let empty = AovSet::<RenderMan>::compile(&[] as &[(String, Lpe)]).unwrap();
        assert!(empty.is_empty());
        assert!(empty.match_path(&"C L".parse().unwrap()).is_empty());
        // A state and class from a larger set, stepped in a smaller one: some state,
        // never a panic.
        let big = set(&["C.*D.{12}[LO]", "C<RD'a'><TS'b'>L"], &Options::default());
        for opts in [Options::default(), nfa_only()] {
            let small = set(&["CL"], &opts);
            let p: Path = "C RD'a' TS'b' RD RS RD L".parse().unwrap();
            let s = p.vertices()[..6]
                .iter()
                .fold(big.start(), |s, v| big.step(s, v));
            let c = big.classify(&Vertex::light(Some("zz")));
            let t = small.step_class(s, c);
            let _ = (small.matches(t), small.is_dead(t));
        }
    }

    #[test]
    fn sets_too_large_for_step_tables_still_get_a_dfa() {
        // 302 positions: 5-word states, too wide for the inlined wide step and so given
        // no step tables (they would take 400 KiB, over a 256 KiB NFA budget, while the
        // follow rows take 12 KiB); the DFA (a chain) is built by stepping rows.
        let opts = Options {
            nfa_budget: 256 << 10,
            ..Options::default()
        };
        let s = set(&["C(.{100}){3}L"], &opts);
        assert!(s.uses_dfa());
        // The set keeps only its DFA: ask the construction it came from.
        let nfa_of = |opts: &Options| {
            let e = parse("C(.{100}){3}L").unwrap().expr;
            AovSet::<RenderMan>::build_nfa(&[&e], opts).unwrap().1
        };
        assert!(!nfa_of(&opts).has_step_tables());
        assert!(!nfa_of(&Options::default()).has_step_tables());
        for (n, want) in [(300, true), (299, false), (301, false)] {
            let p: Path = format!("C{} L", " RD".repeat(n)).parse().unwrap();
            assert_eq!(s.match_path(&p).contains(0), want, "{n}");
        }
    }

    /// Two lazy sets taking turns, each through its own cache, answer as worked out by
    /// hand (`C<RD>+L`: diffuse bounces only; `C.*<RS>L`: a specular last bounce), and
    /// each cache keeps its rows across the turns. Caught: `match_path_with` stepping
    /// the thread's cache (2 rows each: the end states alone), or reading matches from
    /// the start state.
    #[test]
    fn a_set_stepped_through_its_own_cache_keeps_it_between_turns() {
        let diffuse = set(&["C<RD>+L"], &nfa_only());
        let specular = set(&["C.*<RS>L"], &nfa_only());
        assert!(!diffuse.uses_dfa() && !specular.uses_dfa());
        let (mut a, mut b) = (diffuse.cache(), specular.cache());
        let p = |t: &str| -> Path { t.parse().unwrap() };
        for _ in 0..2 {
            assert!(diffuse.match_path_with(&mut a, &p("C RD RD L")).contains(0));
            assert!(!specular
                .match_path_with(&mut b, &p("C RD RD L"))
                .contains(0));
            assert!(!diffuse.match_path_with(&mut a, &p("C RD RS L")).contains(0));
            assert!(specular
                .match_path_with(&mut b, &p("C RD RS L"))
                .contains(0));
        }
        // The steps are stored, not only the two end states whose matches are read.
        assert!(a.rows() > 2 && b.rows() > 2, "{} {}", a.rows(), b.rows());
        assert_eq!((a.clears(), b.clears()), (0, 0));
    }

    fn few_paths() -> Options {
        Options {
            dfa_budget: 0,
            few_paths: true,
            ..Options::default()
        }
    }

    /// A compile for a few paths builds no per-byte step tables: `C.{199}[LO]` keeps 202
    /// positions (four 64-bit words a state), whose tables take `16 KiB * 4^2` = 256 KiB,
    /// while its follow rows take 202 * 4 * 8 bytes (6.3 KiB). Caught when planted:
    /// `Nfa::new` taking the table budget from `nfa_budget` whatever `few_paths` says
    /// (the few-paths set held 266 KiB).
    #[test]
    fn a_few_paths_compile_builds_no_step_tables() {
        let tables = 256 << 10;
        let lazy = set(&["C.{199}[LO]"], &nfa_only());
        let few = set(&["C.{199}[LO]"], &few_paths());
        assert_eq!((lazy.nfa_positions(), few.nfa_positions()), (202, 202));
        assert!(lazy.memory_bytes() >= tables, "{}", lazy.memory_bytes());
        assert!(few.memory_bytes() < tables / 16, "{}", few.memory_bytes());
        // Tables or not, the same answers: exactly 199 scattering vertices between.
        for (n, want) in [(199, true), (198, false), (200, false)] {
            let p: Path = format!("C{} L", " RD".repeat(n)).parse().unwrap();
            for s in [&lazy, &few] {
                assert_eq!(s.match_path(&p).contains(0), want, "{n}");
            }
        }
    }

    /// A compile for a few paths keeps positions always active together apart, and
    /// searches for no empty AOV: `C<RD>L` and `C<RD>O` share their `C<RD>` positions
    /// (merged: the start, `C`, `<RD>`, `L`, `O`: 5; apart: 7), `C.*` adds its `C`
    /// (which ends it, so merges with no other) and `.`, and it (never an emitter) warns
    /// only in a full compile. Caught when planted: merging whatever
    /// `few_paths` says (5 positions), and the warnings searched for anyway.
    #[test]
    fn a_few_paths_compile_merges_nothing_and_searches_no_warnings() {
        let srcs = ["C<RD>L", "C<RD>O", "C.*"];
        let full = set(&srcs, &nfa_only());
        let few = set(&srcs, &few_paths());
        assert_eq!((full.nfa_positions(), few.nfa_positions()), (7, 9));
        assert_eq!(full.warnings().len(), 1, "{:?}", full.warnings());
        assert!(few.warnings().is_empty(), "{:?}", few.warnings());
    }

    /// Every way of compiling answers alike, with and without `few_paths` (expected
    /// answers worked by hand): plain AOVs sharing a prefix, a counted repetition, set
    /// algebra (a complement that matches where its operand does not) and a set wider
    /// than the NFA's wide state (303 positions), on the DFA, the lazy DFA with and
    /// without a cache, and the NFA's wide state ([`AovSet::nfa`]). Caught when planted:
    /// `Adjacency::new`'s counting sort not advancing past a written target (a position
    /// kept one successor of several).
    #[test]
    fn answers_are_the_same_with_few_paths_on_and_off() {
        let srcs = [
            "C<RD>L",
            "C<RD>.*O",
            "C.{2}[LO]",
            "C.*L - C<RD>L",
            "C(.{100}){3}L",
        ];
        let cases: [(&str, [bool; 5]); 7] = [
            ("C RD L", [true, false, false, false, false]),
            ("C RD RS O", [false, true, true, false, false]),
            ("C RD O", [false, true, false, false, false]),
            ("C RS RD L", [false, false, true, true, false]),
            ("C RS L", [false, false, false, true, false]),
            ("C L", [false, false, false, true, false]),
            ("C RD RD L", [false, false, true, true, false]),
        ];
        let long: Path = format!("C{} L", " RS".repeat(300)).parse().unwrap();
        let base = [
            Options::default(),
            nfa_only(),
            Options {
                lazy_cache: 0,
                ..nfa_only()
            },
        ];
        for opts in base.iter().flat_map(|o| {
            [
                o.clone(),
                Options {
                    few_paths: true,
                    ..o.clone()
                },
            ]
        }) {
            let s = set(&srcs, &opts);
            for (p, want) in &cases {
                let got = s.match_path(&p.parse().unwrap());
                assert_eq!(
                    (0..5).map(|i| got.contains(i)).collect::<Vec<_>>(),
                    want,
                    "{p} {opts:?}"
                );
            }
            assert_eq!(
                (0..5)
                    .map(|i| s.match_path(&long).contains(i))
                    .collect::<Vec<_>>(),
                [false, false, false, true, true],
                "{opts:?}"
            );
            // The narrower sets on the NFA's wide state, as the few-paths engine steps them.
            let narrow = set(&srcs[..4], &opts);
            if let Some(nfa) = narrow.nfa() {
                for (p, want) in &cases {
                    let path: Path = p.parse().unwrap();
                    let got = crate::PathMatcher::match_vertices(&nfa, path.vertices());
                    assert_eq!(
                        (0..4).map(|i| got.contains(i)).collect::<Vec<_>>(),
                        want[..4],
                        "{p} {opts:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn too_large_is_an_error_not_a_hang() {
        let e = parse("C(.{256}){200}L").unwrap();
        let err = AovSet::compile(&[("big".into(), e)]).unwrap_err();
        assert!(err.to_string().contains("NFA budget"), "{err}");
        assert!(
            matches!(err, CompileError::NfaOverBudget { positions, bytes: Some(b), budget }
                if positions > 50_000 && b > budget as u64 && budget == 16 << 20),
            "{err:?}"
        );
        // 303 positions (the start included) are five words, more than an `NfaState`
        // holds: with no DFA the set steps its lazy DFA, whose states are of any width.
        let e = parse("C(.{100}){3}L").unwrap();
        let wide = AovSet::compile_with(&[("wide".into(), e)], &nfa_only()).unwrap();
        assert!(!wide.uses_dfa() && wide.nfa().is_none());
        assert_eq!(wide.nfa_positions(), 303);
        for (n, want) in [(300, true), (299, false), (301, false)] {
            let p: Path = format!("C{} L", " RD".repeat(n)).parse().unwrap();
            assert_eq!(wide.match_path(&p).contains(0), want, "{n}");
        }
        let many: Vec<(String, Lpe)> = (0..=MAX_AOVS)
            .map(|i| (i.to_string(), parse("CL").unwrap()))
            .collect();
        assert_eq!(
            AovSet::compile(&many).unwrap_err(),
            CompileError::TooManyAovs(MAX_AOVS + 1)
        );
    }

    #[test]
    fn set_algebra_combines_operands_in_both_modes() {
        let srcs = ["C.*L - C.*DL", "^C<RD>L", "C.*L & C.+<L.'key'>", "CL"];
        for opts in [Options::default(), nfa_only()] {
            let s = set(&srcs, &opts);
            let hits = |p: &str| s.match_path(&p.parse().unwrap()).iter().collect::<Vec<_>>();
            assert_eq!(hits("C RS L"), [0, 1]);
            assert_eq!(hits("C RS RD L"), [1]);
            assert_eq!(hits("C RD L"), Vec::<usize>::new());
            assert_eq!(hits("C RD L'key'"), [2]);
            assert_eq!(hits("C L"), [0, 1, 3]);
            assert_eq!(hits("C RD O"), [1]);
        }
    }

    #[test]
    fn a_complement_keeps_states_alive_after_its_operand_died() {
        for opts in [Options::default(), nfa_only()] {
            let s = set(&["^C<RD>L"], &opts);
            let p: Path = "C RS RS L".parse().unwrap();
            let mut st = s.start();
            for v in p.vertices() {
                st = s.step(st, v);
                // The operand died at `RS`: from then on every continuation matches.
                assert!(!s.is_dead(st));
            }
            assert!(s.matches(st).contains(0));
            // Minus a plain AOV that died: dead as before.
            let s = set(&["C<RD>L - C<RD>L'x'", "C<RS>L"], &opts);
            let st = s.step(s.step(s.start(), &Vertex::camera()), &Vertex::light(None));
            assert!(s.is_dead(st), "{opts:?}");
        }
        // A DFA without any dead state still answers `is_dead` with false.
        let s = set(&["^CL"], &Options::default());
        assert!(s.uses_dfa());
        assert!(!s.is_dead(s.start()));
    }

    #[test]
    fn operands_count_toward_the_aov_limit() {
        // The parser's operand limit is the set's: one expression always fits a set.
        assert_eq!(crate::algebra::MAX_OPERANDS, MAX_AOVS);
        let one = parse("C.*L - C.*DL - C.*SL").unwrap();
        let aovs: Vec<(String, Lpe)> = (0..MAX_AOVS / 3 + 1)
            .map(|i| (i.to_string(), one.clone()))
            .collect();
        let err = AovSet::compile(&aovs).unwrap_err();
        assert_eq!(
            err,
            CompileError::TooManyOperands {
                aovs: MAX_AOVS / 3 + 1,
                hidden: 3 * (MAX_AOVS / 3 + 1)
            }
        );
        assert!(err.to_string().contains("hidden AOVs"), "{err}");
    }
}
