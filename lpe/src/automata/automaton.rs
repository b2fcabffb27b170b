//! The automaton a set steps, whatever its dialect: a minimized DFA when it fits its
//! budget, else a lazy DFA over the bitset NFA, with the visible masks of set algebra.
//! [`crate::AovSet`] is a dialect's vertex classes in front of one (it dereferences to
//! it), so every stepping method is written once, here; the C ABI holds a set of either
//! dialect and steps this.

use crate::automata::dfa::{Dfa, MAX_EAGER_STATES};
use crate::automata::error::CompileError;
use crate::automata::lazy::{Cache, Lazy};
use crate::automata::mask::{AovMask, Class, State, NFA_STATE_WORDS};
use crate::automata::nfa::Nfa;
use crate::automata::options::Options;
use crate::automata::visible::Visible;

/// NFA row reads (of one word each) the eager DFA of an NFA wider than
/// [`NFA_STATE_WORDS`] words may spend before the set goes lazy: about 2 ms.
const WIDE_DFA_WORK: usize = 1 << 20;

/// A compiled set's automaton: one `u32` [`State`] per path, one table step per vertex.
#[derive(Clone, Debug)]
pub struct Automaton {
    /// The eager DFA; empty (no states) for a lazy set, so that a step of a lazy set
    /// misses the table and takes the lazy path: the DFA step has no other branch.
    dfa: Dfa,
    /// Over the DFA budget: the lazy DFA. Boxed because its registry's lock is interior
    /// mutability: held inline it would make `&Automaton` a reference to mutable memory,
    /// and the compiler would reload the DFA's table pointer and length after every call
    /// in a caller's loop (the out-of-line miss path) instead of keeping them in
    /// registers.
    lazy: Option<Box<Lazy>>,
    /// The DFA's start, or the registry's id of the NFA start (position 0 alone).
    start: State,
    /// NFA positions (the start included), kept for reporting once the NFA is dropped.
    nfa_positions: usize,
    /// With set algebra: the visible masks as formulas over the operands, which the
    /// automata hold as hidden AOVs. `None`: every AOV is its own hidden AOV.
    visible: Option<Visible>,
    /// State 0 is dead: always with a DFA; on a lazy set, where it is the NFA state with
    /// no active position, unless a complement then matches.
    empty_is_dead: bool,
}

impl Automaton {
    /// The automaton of `nfa` over `classes` vertex classes: its eager DFA when it fits
    /// [`Options::dfa_budget`] and [`MAX_EAGER_STATES`], else a lazy DFA over the NFA.
    /// With set algebra, `visible` gives the visible masks.
    pub(crate) fn build(
        nfa: Nfa,
        classes: usize,
        opts: &Options,
        visible: Option<Visible>,
    ) -> Result<Automaton, CompileError> {
        let dfa = Self::engine(&nfa, classes, opts, visible.as_ref())?;
        let nfa_positions = nfa.positions;
        // The NFA only serves to build the DFA, so a set with a DFA drops it (with its
        // follow tables, often the larger of the two).
        let start = dfa.as_ref().map_or(State(1), |d| State(d.start()));
        let lazy = dfa
            .is_none()
            .then(|| Box::new(Lazy::new(nfa, classes, opts.lazy_cache, visible.clone())));
        let empty_is_dead = Self::empty_is_dead(lazy.as_deref(), visible.as_ref());
        Ok(Automaton {
            dfa: dfa.unwrap_or_else(Dfa::empty),
            lazy,
            start,
            nfa_positions,
            visible,
            empty_is_dead,
        })
    }

    /// The eager DFA of `nfa` when it fits [`Options::dfa_budget`] and
    /// [`MAX_EAGER_STATES`]; `None` when the lazy DFA steps instead, which it can for an
    /// NFA of any width. With set algebra, `visible` gives the visible masks.
    fn engine(
        nfa: &Nfa,
        classes: usize,
        opts: &Options,
        visible: Option<&Visible>,
    ) -> Result<Option<Dfa>, CompileError> {
        if opts.dfa_budget == 0 {
            return Ok(None);
        }
        // A state wider than the wide step holds is stepped by rows, one per active
        // position and class: its subset construction is bounded by that work, so that
        // a set of thousands of positions gives up on the eager DFA within milliseconds
        // (the lazy DFA determinizes only the states paths reach).
        let max_work = if nfa.words() <= NFA_STATE_WORDS {
            usize::MAX
        } else {
            WIDE_DFA_WORK
        };
        Ok(Dfa::build(
            nfa,
            classes,
            opts.dfa_budget,
            visible,
            MAX_EAGER_STATES,
            max_work,
        ))
    }

    /// A DFA's state 0 is always dead (`Dfa::build`); a lazy set's state 0 is the NFA
    /// state with no active position, where a complement `^A` still matches.
    fn empty_is_dead(lazy: Option<&Lazy>, visible: Option<&Visible>) -> bool {
        lazy.is_none() || visible.is_none_or(|v| v.none().is_empty())
    }

    /// The state before any vertex.
    #[inline]
    pub fn start(&self) -> State {
        self.start
    }

    /// One vertex, already classified. A class or state from another set gives an
    /// unspecified state, never a panic. On a lazy set (no DFA) this goes through a
    /// per-thread cache; [`Automaton::step_with`] with a [`Cache`] of the caller's is faster.
    #[inline]
    pub fn step_class(&self, s: State, c: Class) -> State {
        match self.dfa.next(s.0, c.0) {
            Some(n) => State(n),
            None => self.step_off_table(s, c),
        }
    }

    /// A state or class out of the DFA's table, which on a lazy set is every step: the
    /// lazy DFA's cache hit inline, the rest out of line and cold. Cold, so that a DFA
    /// set's loop keeps its registers: with the call on an ordinary branch, the caller
    /// spilled the table's pointer and the path's bounds around it, and a renderer-shaped
    /// loop stepped at 1.3-1.75x the bare chain of table loads (`lpe-check bench`), 1.1x
    /// with the whole off-table step cold. The lazy hit stays inline (1.2-1.3x), since
    /// with it in the cold call a lazy set paid that call's spills at every step.
    #[inline(always)]
    fn step_off_table(&self, s: State, c: Class) -> State {
        if let Some(n) = self.lazy.as_ref().and_then(|l| l.step_local_hit(s, c)) {
            return n;
        }
        self.step_miss(s, c)
    }

    /// The eager DFA's transitions, for callers that inline the step into their own
    /// loop (the C ABI's `lpe_step_view`): for any state `s` and class `c`, when
    /// `i = s.to_u32().wrapping_add(c.index() as u32)` is below the table's length,
    /// [`Automaton::step_class`]`(s, c)` is `State::from_u32(table[i])`; otherwise (always
    /// on a lazy set, whose table is empty) step with [`Automaton::step_class`]. Immutable
    /// for the set's life.
    ///
    /// ```
    /// use lpe::AovSet;
    /// use lpe::renderman::{parse, Vertex};
    ///
    /// let set = AovSet::compile(&[("d".to_string(), parse("C<RD>L").unwrap())]).unwrap();
    /// let (s, c) = (set.start(), set.classify(&Vertex::camera()));
    /// let i = s.to_u32().wrapping_add(c.index() as u32) as usize;
    /// assert_eq!(set.step_table()[i], set.step_class(s, c).to_u32());
    /// ```
    #[inline]
    pub fn step_table(&self) -> &[u32] {
        self.dfa.table()
    }

    /// The AOVs that match a path ending in state `s`.
    #[inline]
    pub fn matches(&self, s: State) -> AovMask {
        let missed;
        let m = match self.dfa.mask_ref(s.0) {
            Some(m) => m,
            None => {
                missed = self.matches_miss(s);
                &missed
            }
        };
        *m
    }

    /// No continuation of the path can match any AOV. Exact on a DFA, where the dead
    /// state is state 0. On a lazy set, state 0 is the NFA state with no active position:
    /// dead unless a complement (`^A`) matches from there on; and a state whose operands
    /// can still match but whose set algebra never will (`A & B` after `B` died) is not
    /// flagged.
    #[inline]
    pub fn is_dead(&self, s: State) -> bool {
        s == State::DEAD && self.empty_is_dead
    }

    /// One step of many independent paths, for wavefront renderers: `states[i]` steps on
    /// `classes[i]` (pairs past the shorter slice are left alone). On a DFA the loads of
    /// different paths overlap, where one path's steps wait on each other.
    #[inline]
    pub fn step_batch(&self, states: &mut [State], classes: &[Class]) {
        match &self.lazy {
            // The table alone, no call in the loop: what is off the table is another
            // set's state or class, which `step_class` takes to the dead state too.
            None => {
                for (s, c) in states.iter_mut().zip(classes) {
                    *s = self.dfa.next(s.0, c.0).map_or(State::DEAD, State);
                }
            }
            // The lazy DFA borrows this thread's cache once for the batch.
            Some(l) => l.step_batch_local(states, classes),
        }
    }

    /// A cache for stepping this set with [`Automaton::step_with`]: one per thread. Sized by
    /// [`Options::lazy_cache`]; holds nothing for a set with a DFA.
    pub fn cache(&self) -> Cache {
        match &self.lazy {
            None => Cache::empty(),
            Some(l) => l.cache(),
        }
    }

    /// [`Automaton::step_class`] through the caller's cache: on a lazy set, two loads when
    /// the transition is cached. A cache of another set is reset for this one.
    #[inline]
    pub fn step_with(&self, cache: &mut Cache, s: State, c: Class) -> State {
        match (self.dfa.next(s.0, c.0), &self.lazy) {
            (Some(n), _) => State(n),
            (None, Some(l)) => l.step(cache, s, c),
            (None, None) => State::DEAD,
        }
    }

    /// [`Automaton::matches`] through the caller's cache.
    #[inline]
    pub fn matches_with(&self, cache: &mut Cache, s: State) -> AovMask {
        match (self.dfa.matches(s.0), &self.lazy) {
            (Some(m), _) => m,
            (None, Some(l)) => l.matches(cache, s),
            (None, None) => AovMask::EMPTY,
        }
    }

    /// A state or class out of the DFA's table that this thread's lazy cache does not
    /// hold: the lazy DFA's step, or (a state or class of another set) the dead state.
    #[cold]
    #[inline(never)]
    fn step_miss(&self, s: State, c: Class) -> State {
        match &self.lazy {
            Some(l) => l.step_local_miss(s, c),
            None => State::DEAD,
        }
    }

    #[cold]
    #[inline(never)]
    fn matches_miss(&self, s: State) -> AovMask {
        match &self.lazy {
            Some(l) => l.matches_local(s),
            None => AovMask::EMPTY,
        }
    }

    /// Whether the set steps an eager DFA (else a lazy one: over the DFA budget).
    pub fn uses_dfa(&self) -> bool {
        self.lazy.is_none()
    }

    /// DFA states (dead state included), if the set has a DFA.
    pub fn dfa_states(&self) -> Option<usize> {
        self.lazy.is_none().then(|| self.dfa.state_count())
    }

    /// NFA states a lazy set has determinized so far (dead and start included), across
    /// all threads; `None` for a set with a DFA.
    pub fn lazy_states(&self) -> Option<usize> {
        self.lazy.as_deref().map(Lazy::registered)
    }

    /// NFA positions (the start included), after keeping once the positions that are
    /// always active together and dropping those no path can use: at most the atoms of
    /// the expressions after unrolling, plus one.
    pub fn nfa_positions(&self) -> usize {
        self.nfa_positions
    }

    /// The lazy DFA's NFA when its state fits an [`crate::NfaState`] ([`NFA_STATE_WORDS`]
    /// words), for [`crate::AovSet::nfa`]: with the visible masks and whether no active
    /// position is dead.
    pub(crate) fn lazy_nfa(&self) -> Option<(&Nfa, Option<&Visible>, bool)> {
        self.lazy
            .as_ref()
            .filter(|l| l.nfa().words() <= NFA_STATE_WORDS)
            .map(|l| (l.nfa(), self.visible.as_ref(), self.empty_is_dead))
    }

    /// Bytes held by the DFA or the lazy DFA.
    pub fn memory_bytes(&self) -> usize {
        self.dfa.memory_bytes()
            + match &self.lazy {
                None => 0,
                Some(l) => l.memory_bytes(),
            }
    }
}
