//! AOV sets: many expressions compiled into one automaton, stepped once per vertex.
//!
//! [`AovSet::compile`] builds, for a list of `(name, expression)` pairs:
//! 1. the compressed alphabet (module `automata::alphabet`): vertices grouped into [`Class`]es;
//! 2. one bitset Glushkov NFA holding every AOV's positions (module `automata::nfa`);
//! 3. a minimized dense DFA over it (module `automata::dfa`), unless that would exceed
//!    [`Options::dfa_budget`]; then the set steps the NFA instead. Both give the same
//!    answers (the `fast` and `nfa` engines of the differential harness check that).
//!
//! A renderer compiles once, shares the set across threads (`AovSet` is `Send + Sync`,
//! immutable, lock-free), and per path calls [`AovSet::start`], then [`AovSet::step`] (or
//! [`AovSet::step_class`] on classes computed once per material lobe at scene load) per
//! vertex, reads [`AovSet::matches`] at the emitter and may stop early once
//! [`AovSet::is_dead`]. Stepping never allocates.
//!
//! ```
//! use lpe::aov::AovSet;
//! use lpe::macros::BASIC;
//! use lpe::{parse, Event, EventKind, Vertex, VertexType};
//!
//! let aovs: Vec<(String, lpe::Lpe)> = BASIC
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

use std::fmt;

use crate::ast::Atom;
use crate::automata::alphabet::Alphabet;
use crate::automata::dfa::Dfa;
use crate::automata::emptiness::{self, Warning};
use crate::automata::mask::{AovMask, Class, State, MAX_AOVS, NFA_STATE_WORDS};
use crate::automata::nfa::{Builder, Nfa};
use crate::osl;
use crate::path::{Path, Vertex};
use crate::{Dialect, Lpe};

/// Compile-time knobs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Options {
    /// Most bytes the DFA may take (transition table, per-state masks and construction
    /// scratch). Over it, the set steps the bitset NFA. Default 16 MiB. `0` forces the
    /// NFA.
    pub dfa_budget: usize,
    /// Most bytes the NFA may take. It needs one follow row per position
    /// (`positions^2 / 8` bytes; over the budget, compilation fails: about 11 000
    /// positions at the default), and steps fast with per-byte tables of `16 KiB *
    /// words^2` for states of `words` 64-bit words, built when they fit (about 2 000
    /// positions); without them it only serves to build the DFA. Default 16 MiB.
    pub nfa_budget: usize,
    /// The longest path the caller will ever step, in vertices, if known. With it,
    /// `e{n,m}` with `m >= max_path_len` compiles as `e{n,}` (fewer positions, smaller
    /// automata); answers for longer paths are then unspecified. Default `None`: exact
    /// on every path.
    pub max_path_len: Option<u32>,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            dfa_budget: 16 << 20,
            nfa_budget: 16 << 20,
            max_path_len: None,
        }
    }
}

/// Why a set did not compile.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CompileError {
    /// More than [`MAX_AOVS`] expressions.
    TooManyAovs(usize),
    /// The NFA's follow sets alone (one row per position: `positions^2 / 8` bytes) would
    /// exceed [`Options::nfa_budget`].
    NfaOverBudget {
        /// NFA positions the set unrolls to, the start included.
        positions: u64,
        /// Bytes the follow sets would take; `None` when that overflows `u64`.
        bytes: Option<u64>,
        /// [`Options::nfa_budget`].
        budget: usize,
    },
    /// An OSL set's vertex patterns need more states than
    /// [`osl::MAX_VERTEX_STATES`] to classify a vertex.
    TooManyVertexStates {
        /// [`osl::MAX_VERTEX_STATES`].
        max: usize,
    },
    /// The DFA exceeds [`Options::dfa_budget`], and the NFA has more positions than a
    /// [`State`] holds, so the set cannot step the NFA instead either.
    TooManyPositions {
        /// NFA positions, the start included.
        positions: usize,
        /// Most positions a stepping state holds (`64 * NFA_STATE_WORDS`).
        max: usize,
        /// [`Options::dfa_budget`].
        dfa_budget: usize,
    },
}

impl fmt::Display for CompileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CompileError::TooManyAovs(n) => {
                write!(
                    f,
                    "{n} AOVs in one set, over the limit of {MAX_AOVS}: split the set"
                )
            }
            CompileError::NfaOverBudget {
                positions,
                bytes,
                budget,
            } => {
                let need = bytes.map_or("more than 2^64 bytes".into(), |b| {
                    format!("{} MiB", b >> 20)
                });
                write!(
                    f,
                    "the set unrolls to {positions} NFA positions; its follow sets would need \
                     {need}, over the NFA budget of {} MiB (lower the repetition counts, \
                     or set `max_path_len` so long bounded repeats compile as unbounded)",
                    budget >> 20
                )
            }
            CompileError::TooManyVertexStates { max } => write!(
                f,
                "the set's vertex patterns need more than {max} states to classify a vertex \
                 (many long `<...>` groups with negations): split the set"
            ),
            CompileError::TooManyPositions {
                positions,
                max,
                dfa_budget,
            } => write!(
                f,
                "the set's DFA exceeds the budget of {} MiB and its NFA has {positions} \
                 positions, more than the {max} a stepping state holds: raise `dfa_budget`, \
                 or split the set",
                dfa_budget >> 20
            ),
        }
    }
}

impl std::error::Error for CompileError {}

/// A compiled AOV set. See the [module docs](self).
#[derive(Clone, Debug)]
pub struct AovSet {
    names: Vec<String>,
    lpes: Vec<Lpe>,
    alphabet: Alphabet,
    engine: Engine,
    /// NFA positions (the start included), kept for reporting once the NFA is dropped.
    nfa_positions: usize,
    warnings: Vec<Warning>,
    /// The OSL side of a set compiled with [`AovSet::compile_osl`] (its `alphabet` is
    /// then an empty RenderMan one).
    osl: Option<Box<osl::Compiled>>,
}

/// What a set steps. The NFA only serves to build the DFA, so a set with a DFA drops it
/// (with its follow tables, often the larger of the two).
#[derive(Clone, Debug)]
enum Engine {
    Dfa(Dfa),
    /// Over the DFA budget.
    Nfa(Nfa),
}

impl AovSet {
    /// Compiles with default [`Options`].
    pub fn compile(aovs: &[(String, Lpe)]) -> Result<AovSet, CompileError> {
        Self::compile_with(aovs, &Options::default())
    }

    /// Compiles with explicit options.
    pub fn compile_with(aovs: &[(String, Lpe)], opts: &Options) -> Result<AovSet, CompileError> {
        if aovs.len() > MAX_AOVS {
            return Err(CompileError::TooManyAovs(aovs.len()));
        }
        let (alphabet, nfa, atoms) = Self::build_nfa(aovs, opts)?;
        let names: Vec<String> = aovs.iter().map(|(n, _)| n.clone()).collect();
        let lpes: Vec<Lpe> = aovs.iter().map(|(_, l)| l.clone()).collect();
        let warnings = emptiness::empty_aovs(&nfa, &alphabet, &atoms, &names, &lpes);
        let nfa_positions = nfa.positions;
        let engine = Self::engine(nfa, alphabet.class_count(), opts)?;
        Ok(AovSet {
            names,
            lpes,
            alphabet,
            engine,
            nfa_positions,
            warnings,
            osl: None,
        })
    }

    /// Compiles OSL-dialect expressions (parsed with [`osl::parse`] under `registered`)
    /// into a set stepped exactly like a RenderMan one, on OSL vertex classes
    /// ([`AovSet::classify_osl`]). The eager DFA is attempted within the smaller of
    /// [`Options::dfa_budget`] and [`osl::DFA_ATTEMPT_BUDGET`].
    ///
    /// ```
    /// use lpe::osl::{self, Registered};
    /// use lpe::{AovSet, Options};
    ///
    /// let reg = Registered::none();
    /// let aovs = vec![("diffuse".to_string(), osl::parse("C<RD>L", &reg).unwrap())];
    /// let set = AovSet::compile_osl(&aovs, &reg, &Options::default()).unwrap();
    /// let hit = set.match_osl_path(&"C,_ R,D,floor L,_".parse().unwrap());
    /// assert!(hit.contains(0));
    /// assert!(set.match_osl_path(&"C,_ R,D,G L,_".parse().unwrap()).is_empty());
    /// ```
    pub fn compile_osl(
        aovs: &[(String, osl::Lpe)],
        registered: &osl::Registered,
        opts: &Options,
    ) -> Result<AovSet, CompileError> {
        if aovs.len() > MAX_AOVS {
            return Err(CompileError::TooManyAovs(aovs.len()));
        }
        let positions = aovs
            .iter()
            .fold(1u64, |n, (_, l)| n.saturating_add(l.expr.positions()));
        Self::check_nfa_budget(positions, opts)?;
        let names: Vec<String> = aovs.iter().map(|(n, _)| n.clone()).collect();
        let (compiled, nfa, warnings) =
            osl::Compiled::build(aovs, &names, registered, opts.max_path_len, opts.nfa_budget)
                .map_err(
                    |osl::TooManyVertexStates| CompileError::TooManyVertexStates {
                        max: osl::MAX_VERTEX_STATES,
                    },
                )?;
        let nfa_positions = nfa.positions;
        // OSL sets have several times RenderMan's classes, so a blow-up reaches a large
        // budget slowly (OSL's own ReDoS expression: a second for 16 MiB): attempt the
        // eager DFA within a smaller budget, and step the NFA past it.
        let attempt = Options {
            dfa_budget: opts.dfa_budget.min(osl::DFA_ATTEMPT_BUDGET),
            ..opts.clone()
        };
        let engine = Self::engine(nfa, compiled.class_count(), &attempt)?;
        Ok(AovSet {
            names,
            lpes: Vec::new(),
            alphabet: Alphabet::new(&[], Vec::new()),
            engine,
            nfa_positions,
            warnings,
            osl: Some(Box::new(compiled)),
        })
    }

    /// The automaton a set steps: its DFA when it fits [`Options::dfa_budget`], else the
    /// NFA (which must then fit a [`State`]).
    fn engine(nfa: Nfa, classes: usize, opts: &Options) -> Result<Engine, CompileError> {
        let dfa = if opts.dfa_budget > 0 {
            Dfa::build(&nfa, classes, opts.dfa_budget)
        } else {
            None
        };
        if dfa.is_none() && nfa.words() > NFA_STATE_WORDS {
            return Err(CompileError::TooManyPositions {
                positions: nfa.positions,
                max: 64 * NFA_STATE_WORDS,
                dfa_budget: opts.dfa_budget,
            });
        }
        Ok(dfa.map_or(Engine::Nfa(nfa), Engine::Dfa))
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

    /// The alphabet and NFA of `aovs`, and their distinct atoms (the NFA's atom indices
    /// refer to them).
    fn build_nfa<'a>(
        aovs: &'a [(String, Lpe)],
        opts: &Options,
    ) -> Result<(Alphabet, Nfa, Vec<&'a Atom>), CompileError> {
        let positions = aovs.iter().fold(1u64, |n, (_, l)| {
            n.saturating_add(l.expr.positions_with(opts.max_path_len))
        });
        Self::check_nfa_budget(positions, opts)?;
        let (builder, parts) =
            Builder::of_all(aovs.iter().map(|(_, l)| &l.expr), opts.max_path_len);
        // Duplicates across AOVs are fine: the alphabet's label table deduplicates.
        let labels: Vec<String> = aovs.iter().flat_map(|(_, l)| l.expr.labels()).collect();
        let alphabet = Alphabet::new(&builder.atoms, labels);
        // Borrowed from `aovs`: the analysis outlives the builder, which the NFA consumes.
        let atoms = builder.atoms.clone();
        let nfa = Nfa::new(builder, parts, &alphabet, opts.nfa_budget);
        Ok((alphabet, nfa, atoms))
    }

    /// The state before any vertex.
    #[inline]
    pub fn start(&self) -> State {
        match &self.engine {
            Engine::Dfa(d) => State::id(d.start()),
            // The NFA start: position 0 alone, bit 0 of word 0.
            Engine::Nfa(_) => State::id(1),
        }
    }

    /// The class of a vertex: compute it once per material lobe and step with
    /// [`AovSet::step_class`]. On an OSL set the answer is unspecified: use
    /// [`AovSet::classify_osl`].
    #[inline]
    pub fn classify(&self, v: &Vertex) -> Class {
        self.alphabet.classify(v)
    }

    /// One vertex.
    #[inline]
    pub fn step(&self, s: State, v: &Vertex) -> State {
        self.step_class(s, self.classify(v))
    }

    /// One vertex, already classified. A class or state from another set gives an
    /// unspecified state, never a panic.
    #[inline]
    pub fn step_class(&self, s: State, c: Class) -> State {
        match &self.engine {
            Engine::Dfa(d) => State::id(d.next(s.0[0] as u32, c.0)),
            Engine::Nfa(n) => Self::step_nfa(n, s, c),
        }
    }

    /// Out of line so that the DFA step above stays small enough to inline into the
    /// caller's loop.
    #[inline(never)]
    fn step_nfa(nfa: &Nfa, s: State, c: Class) -> State {
        let mut next = [0u64; NFA_STATE_WORDS];
        nfa.step(&s.0, c.index(), &mut next);
        State(next)
    }

    /// The AOVs that match a path ending in state `s`.
    #[inline]
    pub fn matches(&self, s: State) -> AovMask {
        match &self.engine {
            Engine::Dfa(d) => d.matches(s.0[0] as u32),
            Engine::Nfa(n) => n.matches(&s.0),
        }
    }

    /// No continuation of the path can match any AOV.
    #[inline]
    pub fn is_dead(&self, s: State) -> bool {
        match &self.engine {
            Engine::Dfa(_) => s.0[0] == 0,
            Engine::Nfa(_) => s.0 == [0; NFA_STATE_WORDS],
        }
    }

    /// The class of a whole OSL vertex, read once (one table load per symbol): compute
    /// it once per material lobe and step with [`AovSet::step_class`]. On a RenderMan set
    /// every vertex gets a class one past the set's last, which steps to the dead state.
    #[inline]
    pub fn classify_osl(&self, v: &osl::Vertex) -> Class {
        match &self.osl {
            Some(o) => o.classify(v),
            None => Class(self.alphabet.class_count() as u32),
        }
    }

    /// Steps a whole OSL path from the start (only meaningful on an OSL set).
    pub fn match_osl_path(&self, p: &osl::Path) -> AovMask {
        let s = p.vertices.iter().fold(self.start(), |s, v| {
            self.step_class(s, self.classify_osl(v))
        });
        self.matches(s)
    }

    /// The dialect the set was compiled from.
    pub fn dialect(&self) -> Dialect {
        if self.osl.is_some() {
            Dialect::Osl
        } else {
            Dialect::RenderMan
        }
    }

    /// The OSL expressions of an OSL set, in compile order (empty for a RenderMan set,
    /// whose expressions are [`AovSet::lpes`]).
    pub fn osl_lpes(&self) -> &[osl::Lpe] {
        self.osl.as_ref().map_or(&[], |o| o.lpes())
    }

    /// The labels an OSL set was compiled under.
    pub fn osl_registered(&self) -> Option<&osl::Registered> {
        self.osl.as_ref().map(|o| o.registered())
    }

    pub(crate) fn osl_compiled(&self) -> Option<&osl::Compiled> {
        self.osl.as_deref()
    }

    /// Steps a whole path from the start.
    pub fn match_path(&self, path: &Path) -> AovMask {
        let s = path
            .vertices()
            .iter()
            .fold(self.start(), |s, v| self.step(s, v));
        self.matches(s)
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

    /// The AOV expressions, in compile order (prefixes tell the renderer what to
    /// accumulate); empty for an OSL set ([`AovSet::osl_lpes`]).
    pub fn lpes(&self) -> &[Lpe] {
        &self.lpes
    }

    /// AOVs that can match no path, with the reason, found at compile time.
    pub fn warnings(&self) -> &[Warning] {
        &self.warnings
    }

    /// Number of vertex classes.
    pub fn class_count(&self) -> usize {
        match &self.osl {
            Some(o) => o.class_count(),
            None => self.alphabet.class_count(),
        }
    }

    /// Whether the set steps a DFA (else the bitset NFA: over the DFA budget).
    pub fn uses_dfa(&self) -> bool {
        matches!(self.engine, Engine::Dfa(_))
    }

    /// DFA states (dead state included), if the set has a DFA.
    pub fn dfa_states(&self) -> Option<usize> {
        match &self.engine {
            Engine::Dfa(d) => Some(d.state_count()),
            Engine::Nfa(_) => None,
        }
    }

    /// NFA positions (the start included).
    pub fn nfa_positions(&self) -> usize {
        self.nfa_positions
    }

    /// Bytes held by the automaton the set steps and by the alphabet tables.
    pub fn memory_bytes(&self) -> usize {
        self.alphabet.memory_bytes()
            + self.osl.as_ref().map_or(0, |o| o.memory_bytes())
            + match &self.engine {
                Engine::Dfa(d) => d.memory_bytes(),
                Engine::Nfa(n) => n.memory_bytes(),
            }
    }

    pub(crate) fn alphabet(&self) -> &Alphabet {
        &self.alphabet
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse;

    fn lpe(s: &str) -> Lpe {
        parse(s).unwrap()
    }

    fn set(srcs: &[&str], opts: &Options) -> AovSet {
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
        check::<AovSet>();
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
        let empty = AovSet::compile(&[]).unwrap();
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
        // 302 positions: 5-word states, whose step tables (400 KiB) are over a 256 KiB
        // NFA budget while the follow rows (12 KiB) fit; the DFA (a chain) is built by
        // stepping rows instead.
        let opts = Options {
            nfa_budget: 256 << 10,
            ..Options::default()
        };
        let s = set(&["C(.{100}){3}L"], &opts);
        assert!(s.uses_dfa());
        // The set keeps only its DFA: ask the construction it came from.
        let nfa_of = |opts: &Options| {
            let aovs = [("a".to_string(), parse("C(.{100}){3}L").unwrap())];
            AovSet::build_nfa(&aovs, opts).unwrap().1
        };
        assert!(!nfa_of(&opts).has_step_tables());
        assert!(nfa_of(&Options::default()).has_step_tables());
        for (n, want) in [(300, true), (299, false), (301, false)] {
            let p: Path = format!("C{} L", " RD".repeat(n)).parse().unwrap();
            assert_eq!(s.match_path(&p).contains(0), want, "{n}");
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
        // 303 positions (the start included) are five words, one more than a stepping
        // state holds: without a DFA the set cannot step.
        let e = parse("C(.{100}){3}L").unwrap();
        let err = AovSet::compile_with(&[("wide".into(), e)], &nfa_only()).unwrap_err();
        assert_eq!(
            err,
            CompileError::TooManyPositions {
                positions: 303,
                max: 256,
                dfa_budget: 0
            }
        );
        assert!(err.to_string().contains("raise `dfa_budget`"), "{err}");
        let many: Vec<(String, Lpe)> = (0..=MAX_AOVS)
            .map(|i| (i.to_string(), parse("CL").unwrap()))
            .collect();
        assert_eq!(
            AovSet::compile(&many).unwrap_err(),
            CompileError::TooManyAovs(MAX_AOVS + 1)
        );
    }
}
