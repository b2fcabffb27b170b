//! The DFA: subset construction over the bitset NFA into a dense `u32` table, then
//! minimized.
//!
//! Layout: one row of `stride` entries per state (`stride` = class count rounded up to a
//! power of two), and state ids are *premultiplied* row offsets, so a step is
//! `table[state + class]`: one add and one dependent load. State 0 is the dead state
//! (every transition leads back to it, no AOV matches), so `is_dead` is a compare with 0.
//! Minimization (Moore's partition refinement) merges every state that can no longer
//! reach a match into the dead state, so a renderer can stop a path as soon as it dies.
//!
//! Construction stops as soon as the table would pass the memory budget or
//! [`MAX_EAGER_STATES`] (the DFA of a set can be exponential in its NFA: `C.*D.{k}[LO]`
//! needs `2^(k+1)` states); the caller then steps the lazy DFA instead.

use crate::fxhash::FxMap;

use crate::automata::mask::AovMask;
use crate::automata::nfa::Nfa;
use crate::automata::visible::Visible;

/// Most states the subset construction builds before it gives up and leaves the set to
/// the lazy DFA, whatever the budget (when the set can step lazily at all; the caller
/// passes it to [`Dfa::build`]): a DFA this large takes milliseconds to build
/// (`C.*D.{12}[LO]`, 8 195 states, fits), and a blow-up set such as `C.*D.{20}[LO]`
/// (2^21 states) must not spend a budget's worth of construction before going lazy.
pub(crate) const MAX_EAGER_STATES: usize = 1 << 14;

/// Hashing work (state x class visits) minimization may spend before giving up.
const MAX_MINIMIZE_WORK: usize = 20_000_000;

/// Which states reach a non-empty mask, by a backward search over `trans` (`classes`
/// entries per state).
fn live_states(trans: &[u32], masks: &[AovMask], classes: usize) -> Vec<bool> {
    let n = masks.len();
    // Predecessor lists in one array: `start[t]..start[t + 1]` are the states with an
    // edge into `t`.
    let mut start = vec![0u32; n + 1];
    for &t in trans {
        start[t as usize + 1] += 1;
    }
    for i in 0..n {
        start[i + 1] += start[i];
    }
    let mut fill = start.clone();
    let mut preds = vec![0u32; trans.len()];
    for (e, &t) in trans.iter().enumerate() {
        preds[fill[t as usize] as usize] = (e / classes) as u32;
        fill[t as usize] += 1;
    }
    let mut live: Vec<bool> = masks.iter().map(|m| !m.is_empty()).collect();
    let mut stack: Vec<usize> = (0..n).filter(|&s| live[s]).collect();
    while let Some(t) = stack.pop() {
        for &p in &preds[start[t] as usize..start[t + 1] as usize] {
            if !std::mem::replace(&mut live[p as usize], true) {
                stack.push(p as usize);
            }
        }
    }
    live
}

/// A dense, minimized DFA.
#[derive(Clone, Debug)]
pub(crate) struct Dfa {
    /// `table[state + class]`, with premultiplied state ids.
    table: Vec<u32>,
    /// `log2(stride)`.
    shift: u32,
    /// The AOVs that match in each state, by state index (`id >> shift`).
    masks: Vec<AovMask>,
    start: u32,
}

impl Dfa {
    /// Bytes one state costs during and after construction, for the budget.
    fn state_cost(stride: usize, words: usize) -> usize {
        stride * 4 + std::mem::size_of::<AovMask>() + 2 * words * 8 + 32
    }

    /// Determinizes `nfa` over `classes` classes, or `None` if the DFA would exceed
    /// `budget` bytes or `max_states` states, or its construction `max_work` NFA row
    /// reads (each step of a state reads one row of `words` words per active position). With set algebra, `visible` turns the
    /// NFA's hidden masks into the states' visible masks, once per state.
    pub(crate) fn build(
        nfa: &Nfa,
        classes: usize,
        budget: usize,
        visible: Option<&Visible>,
        max_states: usize,
        max_work: usize,
    ) -> Option<Dfa> {
        let stride = classes.next_power_of_two();
        let cost = Self::state_cost(stride, nfa.words());
        // Premultiplied ids must fit a `u32`.
        let max_states = (budget / cost)
            .min(u32::MAX as usize / stride)
            .min(max_states);
        let w = nfa.words();
        // Subset construction. Index 0 is the empty set: the dead state.
        let mut sets: Vec<Box<[u64]>> = vec![vec![0u64; w].into_boxed_slice()];
        let mut ids: FxMap<Box<[u64]>, u32> = FxMap::default();
        ids.insert(sets[0].clone(), 0);
        // The start state: position 0 alone.
        let mut start = vec![0u64; w].into_boxed_slice();
        start[0] = 1;
        ids.insert(start.clone(), 1);
        sets.push(start);
        if max_states < 2 {
            return None;
        }
        let mut trans: Vec<u32> = Vec::new();
        let mut next = vec![0u64; w];
        let mut i = 0;
        let mut work = 0usize;
        while i < sets.len() {
            let active: usize = sets[i].iter().map(|x| x.count_ones() as usize).sum();
            work = work.saturating_add(classes.saturating_mul(active.max(1) * w));
            if work > max_work {
                return None;
            }
            for c in 0..classes {
                nfa.step(&sets[i], c, &mut next);
                let id = match ids.get(&next[..]) {
                    Some(&id) => id,
                    None => {
                        if sets.len() >= max_states {
                            return None;
                        }
                        let id = sets.len() as u32;
                        let key: Box<[u64]> = next.clone().into_boxed_slice();
                        ids.insert(key.clone(), id);
                        sets.push(key);
                        id
                    }
                };
                trans.push(id);
            }
            i += 1;
        }
        let masks: Vec<AovMask> = sets
            .iter()
            .map(|s| visible.map_or(nfa.matches(s), |v| v.mask(nfa.matches(s))))
            .collect();
        drop(ids);
        Some(Self::minimize(&trans, &masks, classes, stride))
    }

    /// Moore's algorithm: start from "same AOV mask", split blocks by the blocks their
    /// successors fall in, until nothing splits. Then lay the blocks out with the dead
    /// state's block at id 0.
    fn minimize(trans: &[u32], masks: &[AovMask], classes: usize, stride: usize) -> Dfa {
        let n = masks.len();
        let mut block: Vec<u32> = {
            let mut by_mask: FxMap<AovMask, u32> = FxMap::default();
            masks
                .iter()
                .map(|m| {
                    let next = by_mask.len() as u32;
                    *by_mask.entry(*m).or_insert(next)
                })
                .collect()
        };
        let mut count = block.iter().max().map_or(0, |&b| b + 1);
        let mut sig = Vec::with_capacity(classes + 1);
        // Moore's algorithm takes as many rounds as the longest chain of states it must
        // tell apart (`C.{2000}L` needs 2 000 rounds over 2 000 states). Past this much
        // work, keep the DFA unminimized: it is as correct, only larger, and the dead
        // state stays exact because the NFA keeps only positions that can lead to a match.
        let mut work = 0usize;
        loop {
            work += n * (classes + 1);
            if work > MAX_MINIMIZE_WORK {
                block = (0..n as u32).collect();
                count = n as u32;
                break;
            }
            let mut by_sig: FxMap<Vec<u32>, u32> = FxMap::default();
            let refined: Vec<u32> = (0..n)
                .map(|s| {
                    sig.clear();
                    sig.push(block[s]);
                    sig.extend(
                        trans[s * classes..][..classes]
                            .iter()
                            .map(|&t| block[t as usize]),
                    );
                    // Look up before inserting: a key is allocated only for a new block.
                    match by_sig.get(&sig[..]) {
                        Some(&b) => b,
                        None => {
                            let next = by_sig.len() as u32;
                            by_sig.insert(sig.clone(), next);
                            next
                        }
                    }
                })
                .collect();
            let refined_count = by_sig.len() as u32;
            block = refined;
            if refined_count == count {
                break;
            }
            count = refined_count;
        }
        // The dead block goes first. Without set algebra the empty subset (index 0) is
        // dead; with a complement `^A` it matches, and a set may have no dead state at
        // all (then an unreachable one is added so that id 0 still means dead). Dead
        // states are those that reach no non-empty mask; Moore's algorithm already put
        // them in one block, except in the unminimized fallback.
        let live = live_states(trans, masks, classes);
        let dead = match live.iter().position(|&l| !l) {
            Some(s) => block[s],
            None => {
                count += 1;
                count - 1
            }
        };
        for (b, _) in block.iter_mut().zip(&live).filter(|(_, &l)| !l) {
            *b = dead;
        }
        let mut order = vec![u32::MAX; count as usize];
        order[dead as usize] = 0;
        let mut next_id = 1;
        for &b in &block {
            if order[b as usize] == u32::MAX {
                order[b as usize] = next_id;
                next_id += 1;
            }
        }
        let shift = stride.trailing_zeros();
        let count = next_id;
        let mut table = vec![0u32; count as usize * stride];
        let mut out_masks = vec![AovMask::EMPTY; count as usize];
        for s in 0..n {
            let b = order[block[s] as usize] as usize;
            out_masks[b] = masks[s];
            for c in 0..classes {
                let t = order[block[trans[s * classes + c] as usize] as usize];
                table[b * stride + c] = t << shift;
            }
        }
        Dfa {
            table,
            shift,
            masks: out_masks,
            start: order[block[1] as usize] << shift,
        }
    }

    /// The start state id.
    #[inline]
    pub(crate) fn start(&self) -> u32 {
        self.start
    }

    /// One transition; `None` for out-of-range input (a state or class of another set,
    /// or any input of the empty DFA a lazy set carries), so that the caller's one branch
    /// covers both.
    #[inline]
    pub(crate) fn next(&self, state: u32, class: u32) -> Option<u32> {
        let i = state.wrapping_add(class) as usize;
        self.table.get(i).copied()
    }

    /// The whole table: `table()[state + class]` is [`Dfa::next`] where in range.
    #[inline]
    pub(crate) fn table(&self) -> &[u32] {
        &self.table
    }

    /// The AOVs matching in `state`; `None` out of range, as for [`Dfa::next`].
    #[inline]
    pub(crate) fn matches(&self, state: u32) -> Option<AovMask> {
        let i = (state >> self.shift) as usize;
        self.masks.get(i).copied()
    }

    /// [`Dfa::matches`] by reference.
    #[inline]
    pub(crate) fn mask_ref(&self, state: u32) -> Option<&AovMask> {
        self.masks.get((state >> self.shift) as usize)
    }

    /// No states: every step misses. What a lazy set carries in place of a DFA.
    pub(crate) fn empty() -> Dfa {
        Dfa {
            table: Vec::new(),
            shift: 0,
            masks: Vec::new(),
            start: 0,
        }
    }

    /// Number of states, dead state included.
    pub(crate) fn state_count(&self) -> usize {
        self.masks.len()
    }

    pub(crate) fn memory_bytes(&self) -> usize {
        self.table.len() * 4 + self.masks.len() * std::mem::size_of::<AovMask>()
    }
}
