//! The lazy DFA: sets whose eager DFA would pass its budget determinize on demand, one
//! transition at a time, as paths reach them.
//!
//! Two layers, because a renderer keeps thousands of paths in flight:
//! - the set owns a **registry** of the NFA states (position subsets) paths have reached,
//!   each under a `u32` id that is never reused. A [`State`] of a lazy set is such an id,
//!   so it is as small as a DFA state and stays valid for the life of the set: whatever
//!   happens to a cache, a path's state can always be re-derived from the registry. The
//!   registry is a memo behind a lock (the set's answers never change), consulted only
//!   when a cache misses; it grows by one subset per distinct NFA state reached, at most
//!   `2^positions` and in practice the few hundred to few thousand states that sampled
//!   paths reach. That growth is the price of states that survive a clear; the
//!   alternatives (a generation check that invalidates in-flight states, or a state that
//!   carries its subset) either lose paths or undo the register-sized state. A subset is
//!   as wide as the NFA needs (one bit per position, any number of positions), interned
//!   once and shared by the id map and the list.
//! - each thread owns a bounded [`Cache`] of transition rows over registry ids, like
//!   regex-automata's hybrid DFA: a hit is two dependent loads (the state's row, then the
//!   transition), a miss steps the bitset NFA and interns the result. When the rows pass
//!   the cache's budget, every row is dropped and the cache refills; states in flight are
//!   untouched, since they name registry entries, not rows.

use std::cell::RefCell;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, PoisonError, RwLock};

use crate::automata::mask::{AovMask, Class, State, NFA_STATE_WORDS};
use crate::automata::nfa::Nfa;
use crate::automata::visible::Visible;
use crate::fxhash::FxMap;

/// A subset of NFA positions: [`Nfa::words`] words, shared by the registry's map and list.
type Subset = Arc<[u64]>;

/// Marks "no row yet" in [`Cache::row_of`] and "not computed" in [`Cache::trans`].
const NONE: u32 = u32::MAX;

/// Fewest rows a cache holds whatever its budget, so a step can always store its
/// transition.
const MIN_ROWS: usize = 2;

/// Tells sets apart for caches: a cache filled for one set must not answer for another.
static NEXT_OWNER: AtomicU64 = AtomicU64::new(1);

thread_local! {
    /// The cache of the `State` API, per thread. Initialized as a constant, so that an
    /// access is an address computation and a registration check that inline into the
    /// step: with a lazy initializer, every step called out to the thread-local's
    /// accessor, and the state went through memory on the way.
    static LOCAL: RefCell<Cache> = const { RefCell::new(Cache::empty()) };
}

/// `hit` on this thread's cache, if it is free: the hit path alone inside the
/// thread-local access, so that the access inlines into the step (with the miss path in
/// it, it stayed a call, and the state went through memory into it).
#[inline(always)]
fn local_hit<T>(hit: impl FnOnce(&Cache) -> Option<T>) -> Option<T> {
    LOCAL.with(|cache| hit(&*cache.try_borrow().ok()?))
}

/// NFA states reached so far, by id. Id 0 is the empty subset (the dead state), id 1 the
/// start (position 0 alone).
#[derive(Clone, Debug)]
struct Registry {
    ids: FxMap<Subset, u32>,
    subsets: Vec<Subset>,
}

impl Registry {
    /// The dead state and the start, as subsets of `words` words.
    fn new(words: usize) -> Registry {
        let mut r = Registry {
            ids: FxMap::default(),
            subsets: Vec::new(),
        };
        let mut start = vec![0u64; words];
        start[0] = 1;
        for s in [vec![0u64; words], start] {
            let s: Subset = s.into();
            r.ids.insert(s.clone(), r.subsets.len() as u32);
            r.subsets.push(s);
        }
        r
    }
}

/// A set stepped lazily: its NFA, the shared registry and the size of per-thread caches.
#[derive(Debug)]
pub(crate) struct Lazy {
    nfa: Nfa,
    /// With set algebra, the visible masks over the NFA's hidden ones.
    visible: Option<Visible>,
    classes: usize,
    /// `log2` of the row stride (class count rounded up to a power of two).
    shift: u32,
    /// Bytes of one cache's rows; 0 disables caching (every step runs the NFA).
    cache_budget: usize,
    owner: u64,
    registry: RwLock<Registry>,
}

impl Clone for Lazy {
    /// The clone gets its own registry (a copy) and owner id: ids of the two diverge
    /// from here on, so their caches must not be shared.
    fn clone(&self) -> Lazy {
        let registry = self
            .registry
            .read()
            .unwrap_or_else(PoisonError::into_inner)
            .clone();
        Lazy {
            nfa: self.nfa.clone(),
            visible: self.visible.clone(),
            classes: self.classes,
            shift: self.shift,
            cache_budget: self.cache_budget,
            owner: NEXT_OWNER.fetch_add(1, Ordering::Relaxed),
            registry: RwLock::new(registry),
        }
    }
}

impl Lazy {
    /// The lazy DFA over `nfa`, of any number of positions.
    pub(crate) fn new(
        nfa: Nfa,
        classes: usize,
        cache_budget: usize,
        visible: Option<Visible>,
    ) -> Lazy {
        let words = nfa.words().max(1);
        Lazy {
            nfa,
            visible,
            classes,
            shift: classes.next_power_of_two().trailing_zeros(),
            cache_budget,
            owner: NEXT_OWNER.fetch_add(1, Ordering::Relaxed),
            registry: RwLock::new(Registry::new(words)),
        }
    }

    pub(crate) fn nfa(&self) -> &Nfa {
        &self.nfa
    }

    /// The subset of state `s`; an id this set never gave out reads as the dead state
    /// (id 0).
    fn subset(&self, s: State) -> Subset {
        let r = self.registry.read().unwrap_or_else(PoisonError::into_inner);
        r.subsets.get(s.0 as usize).unwrap_or(&r.subsets[0]).clone()
    }

    fn intern(&self, sub: &[u64]) -> State {
        if let Some(&id) = self
            .registry
            .read()
            .unwrap_or_else(PoisonError::into_inner)
            .ids
            .get(sub)
        {
            return State(id);
        }
        let mut r = self
            .registry
            .write()
            .unwrap_or_else(PoisonError::into_inner);
        // Another thread may have interned it between the two locks.
        if let Some(&id) = r.ids.get(sub) {
            return State(id);
        }
        let id = r.subsets.len() as u32;
        let sub: Subset = sub.into();
        r.ids.insert(sub.clone(), id);
        r.subsets.push(sub);
        State(id)
    }

    /// One step on the NFA, no cache: the registry only. A state that fits
    /// [`NFA_STATE_WORDS`] words is stepped on the stack; a wider one in a buffer of its
    /// width.
    pub(crate) fn step_uncached(&self, s: State, c: Class) -> State {
        let cur = self.subset(s);
        let w = cur.len();
        let mut small = [0u64; NFA_STATE_WORDS];
        let mut wide = Vec::new();
        let next: &mut [u64] = if w <= NFA_STATE_WORDS {
            &mut small[..w]
        } else {
            wide.resize(w, 0);
            &mut wide
        };
        self.nfa.step(&cur, c.index(), next);
        self.intern(next)
    }

    pub(crate) fn matches_uncached(&self, s: State) -> AovMask {
        let hidden = self.nfa.matches(&self.subset(s));
        self.visible.as_ref().map_or(hidden, |v| v.mask(hidden))
    }

    /// Distinct NFA states reached so far.
    pub(crate) fn registered(&self) -> usize {
        self.registry
            .read()
            .unwrap_or_else(PoisonError::into_inner)
            .subsets
            .len()
    }

    /// Bytes of the NFA and the registry (caches are the caller's).
    pub(crate) fn memory_bytes(&self) -> usize {
        // A registry entry: the subset's words and its shared allocation's two counts,
        // two pointers to it (the list and the map key), the id, and about one control
        // byte of the map.
        let words = self.nfa.words().max(1);
        let entry = 8 * words + 16 + 2 * std::mem::size_of::<Subset>() + 4 + 1;
        self.nfa.memory_bytes() + self.registered() * entry
    }

    /// A cache for this set.
    pub(crate) fn cache(&self) -> Cache {
        let mut c = Cache::empty();
        c.adopt(self);
        c
    }

    /// One step through this thread's cache (for callers without a [`Cache`] of their
    /// own: the `State` API and [`crate::PathMatcher`]) if it holds the transition: two
    /// loads. Else [`Lazy::step_local_miss`] steps. One cache per thread, adopted by the
    /// set stepped last: a thread alternating between two lazy sets refills it.
    #[inline]
    pub(crate) fn step_local_hit(&self, s: State, c: Class) -> Option<State> {
        local_hit(|cache| self.cached(cache, s, c))
    }

    /// [`Lazy::step_local_hit`], else [`Lazy::step_local_miss`], for each pair of a batch
    /// (pairs past the shorter slice left alone), with this thread's cache borrowed once
    /// for the whole batch rather than once a step.
    pub(crate) fn step_batch_local(&self, states: &mut [State], classes: &[Class]) {
        self.with_local(|mut cache| {
            for (s, &c) in states.iter_mut().zip(classes) {
                *s = self.step_in(cache.as_deref_mut(), *s, c);
            }
        })
    }

    /// The step [`Lazy::step_local_hit`] does not have: through this thread's cache,
    /// filling it.
    #[inline(never)]
    pub(crate) fn step_local_miss(&self, s: State, c: Class) -> State {
        self.with_local(|cache| self.step_in(cache, s, c))
    }

    /// One step through `cache`, or on the NFA alone without one.
    #[inline]
    fn step_in(&self, cache: Option<&mut Cache>, s: State, c: Class) -> State {
        match cache {
            Some(cache) => self.step(cache, s, c),
            None => self.step_uncached(s, c),
        }
    }

    /// `f` with this thread's cache, or with none when caching is off (or the cache is
    /// already borrowed, which a step never leaves it).
    fn with_local<T>(&self, f: impl FnOnce(Option<&mut Cache>) -> T) -> T {
        if self.cache_budget == 0 {
            return f(None);
        }
        LOCAL.with(|cache| match cache.try_borrow_mut() {
            Ok(mut cache) => f(Some(&mut cache)),
            Err(_) => f(None),
        })
    }

    /// The row of `s` in `cache`, if it has one.
    #[inline(always)]
    fn cached_row(&self, cache: &Cache, s: State) -> Option<u32> {
        if cache.owner != self.owner {
            return None;
        }
        let row = *cache.row_of.get(s.0 as usize)?;
        (row != NONE).then_some(row)
    }

    /// The transition from `s` on `c` if `cache` holds it: two loads.
    #[inline(always)]
    fn cached(&self, cache: &Cache, s: State, c: Class) -> Option<State> {
        let row = self.cached_row(cache, s)?;
        let n = *cache.trans.get(row as usize + c.0 as usize)?;
        (n != NONE).then_some(State(n))
    }

    /// [`Lazy::matches`] through this thread's cache.
    #[inline]
    pub(crate) fn matches_local(&self, s: State) -> AovMask {
        match local_hit(|cache| self.cached_mask(cache, s)) {
            Some(m) => m,
            None => self.matches_local_miss(s),
        }
    }

    #[inline(never)]
    fn matches_local_miss(&self, s: State) -> AovMask {
        self.with_local(|cache| match cache {
            Some(cache) => self.matches(cache, s),
            None => self.matches_uncached(s),
        })
    }

    /// The AOVs matching in `s` if `cache` has a row for it.
    #[inline(always)]
    fn cached_mask(&self, cache: &Cache, s: State) -> Option<AovMask> {
        let row = self.cached_row(cache, s)?;
        cache.masks.get((row >> self.shift) as usize).copied()
    }

    /// One step through `cache`: two loads on a hit.
    #[inline]
    pub(crate) fn step(&self, cache: &mut Cache, s: State, c: Class) -> State {
        match self.cached(cache, s, c) {
            Some(n) => n,
            None => self.fill(cache, s, c),
        }
    }

    /// The miss path, out of line so that the hit path inlines into the caller's loop.
    #[inline(never)]
    fn fill(&self, cache: &mut Cache, s: State, c: Class) -> State {
        let next = self.step_uncached(s, c);
        if !self.cacheable(s) || c.index() >= self.classes {
            return next;
        }
        let row = self.row(cache, s);
        cache.trans[row as usize + c.index()] = next.0;
        next
    }

    /// The AOVs matching in `s`, through `cache`.
    #[inline]
    pub(crate) fn matches(&self, cache: &mut Cache, s: State) -> AovMask {
        match self.cached_mask(cache, s) {
            Some(m) => m,
            None => self.matches_fill(cache, s),
        }
    }

    #[inline(never)]
    fn matches_fill(&self, cache: &mut Cache, s: State) -> AovMask {
        if !self.cacheable(s) {
            return self.matches_uncached(s);
        }
        let row = self.row(cache, s);
        cache.masks[(row >> self.shift) as usize]
    }

    /// Whether `s` may get a cache row: caching is on and `s` is a registry id (a state
    /// of another set could be any `u32`, and `row_of` is indexed by id).
    fn cacheable(&self, s: State) -> bool {
        self.cache_budget > 0 && (s.0 as usize) < self.registered()
    }

    /// The row of `s` in `cache`, made (clearing a full cache first) if it has none.
    fn row(&self, cache: &mut Cache, s: State) -> u32 {
        if cache.owner != self.owner {
            cache.adopt(self);
        }
        let id = s.0 as usize;
        if let Some(&row) = cache.row_of.get(id) {
            if row != NONE {
                return row;
            }
        }
        if cache.masks.len() >= cache.max_rows {
            cache.clear();
        }
        if cache.row_of.len() <= id {
            cache.row_of.resize(id + 1, NONE);
        }
        let row = (cache.masks.len() << self.shift) as u32;
        cache.row_of[id] = row;
        cache.with_rows.push(s.0);
        cache
            .trans
            .resize(cache.trans.len() + (1 << self.shift), NONE);
        cache.masks.push(self.matches_uncached(s));
        row
    }
}

/// A per-thread cache of a lazily stepped set's transitions, owned by the caller (make
/// one per render thread with [`crate::aov::AovSet::cache`]). Bounded by
/// [`crate::aov::Options::lazy_cache`] bytes of rows, cleared whole when full; states
/// in flight stay valid across clears. A cache made for one set and handed to another
/// starts over for it. For sets with an eager DFA it is unused.
#[derive(Clone, Debug)]
pub struct Cache {
    owner: u64,
    /// Per registry id, the premultiplied row of its transitions, or `NONE`.
    row_of: Vec<u32>,
    /// Next registry id per `(row, class)`, or `NONE`.
    trans: Vec<u32>,
    /// The AOVs matching in each row's state.
    masks: Vec<AovMask>,
    /// Registry ids that have a row, to reset `row_of` on a clear.
    with_rows: Vec<u32>,
    max_rows: usize,
    clears: usize,
}

impl Cache {
    /// A cache for no set (the first step adopts one).
    pub(crate) const fn empty() -> Cache {
        Cache {
            owner: 0,
            row_of: Vec::new(),
            trans: Vec::new(),
            masks: Vec::new(),
            with_rows: Vec::new(),
            max_rows: MIN_ROWS,
            clears: 0,
        }
    }

    fn adopt(&mut self, set: &Lazy) {
        self.clear();
        self.row_of = Vec::new();
        self.owner = set.owner;
        let row_bytes = (4usize << set.shift) + std::mem::size_of::<AovMask>() + 8;
        self.max_rows = (set.cache_budget / row_bytes).max(MIN_ROWS);
        self.clears = 0;
    }

    fn clear(&mut self) {
        for &id in &self.with_rows {
            self.row_of[id as usize] = NONE;
        }
        self.with_rows.clear();
        self.trans.clear();
        self.masks.clear();
        self.clears += 1;
    }

    /// How often the cache was cleared because it was full (a cache that clears often is
    /// too small for the set's working states).
    pub fn clears(&self) -> usize {
        self.clears
    }

    /// States with a row now.
    pub fn rows(&self) -> usize {
        self.masks.len()
    }

    /// Bytes held.
    pub fn memory_bytes(&self) -> usize {
        (self.row_of.len() + self.trans.len() + self.with_rows.len()) * 4
            + self.masks.len() * std::mem::size_of::<AovMask>()
    }
}
