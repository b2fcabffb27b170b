//! The bitset NFA: a Glushkov (position) automaton over alphabet classes, stepped
//! bit-parallel.
//!
//! Every atom occurrence of every compiled expression (after unrolling counted
//! repetition) is a *position*; position 0 is the shared start. The automaton has no
//! epsilon moves, and every transition into position `q` reads `q`'s atom, so one step is
//!
//! ```text
//! next = Follow(state) & Accept[class]
//! ```
//!
//! where `Follow(state)` is the union of the follow sets of the active positions. It is
//! tabulated per 8-bit chunk of the state (Navarro & Raffinot): one table row per
//! `(chunk, byte value)`, so a step is one load-and-OR per byte of state, whatever the
//! number of active positions. The tables cost `16 KiB * words^2` (`words` = 64-position
//! words); [`crate::aov::Options::nfa_budget`] bounds them. A set too large for tables
//! (thousands of positions) keeps only one follow row per position and ORs the rows of
//! the active positions: slower, and used only to build its DFA. So does a set compiled
//! for a few paths ([`crate::aov::Options::few_paths`]): building the tables would cost
//! more than all the steps they save (a 200-position set's take 256 KiB).
//!
//! Many AOVs share one automaton, and a final position names the AOV it ends
//! ([`Nfa::matches`]). Positions that are always active together (the `C<RD>` that
//! begins several AOVs) are kept once (`coactive`; not for a few paths), and positions no
//! path can use are dropped, so a set's position count is what its automaton needs, not
//! its source's atom count.

use std::hash::Hash;

use crate::fxhash::FxMap;

use crate::automata::coactive;
use crate::automata::ir::{Node, Regex, Repetition, VertexClasses};
use crate::automata::mask::{AovMask, NFA_STATE_WORDS};
use crate::automata::options::Options;
use crate::bits::{self, set};

/// What the Glushkov construction computes for one subexpression.
struct Frag {
    first: Vec<u32>,
    last: Vec<u32>,
    nullable: bool,
}

impl Frag {
    fn empty() -> Frag {
        Frag {
            first: Vec::new(),
            last: Vec::new(),
            nullable: true,
        }
    }
}

/// The Glushkov construction: positions, their atoms and follow edges.
pub(crate) struct Builder<'a, A> {
    /// Distinct atoms, in first-seen order; positions refer to them by index.
    pub atoms: Vec<&'a A>,
    atom_ids: FxMap<&'a A, u32>,
    atom_of: Vec<u32>,
    /// `(p, q)`: `q` may follow `p` (duplicates allowed). One list for all positions,
    /// not a list per position: a compile for a few paths is mostly allocation, and a
    /// list per position was one allocation per position.
    edges: Vec<(u32, u32)>,
    /// First and last lists of finished fragments, emptied, for the next ones: a chain
    /// of atoms (`.{199}`) then allocates none per atom.
    spare: Vec<Vec<u32>>,
    /// The path length repetitions are [`Repetition::bounded`] by.
    max_path_len: Option<u32>,
}

impl<'a, A: Eq + Hash> Builder<'a, A> {
    pub(crate) fn new(max_path_len: Option<u32>) -> Builder<'a, A> {
        Builder {
            atoms: Vec::new(),
            atom_ids: FxMap::default(),
            // Position 0: the start, reading no atom.
            atom_of: vec![u32::MAX],
            edges: Vec::new(),
            spare: Vec::new(),
            max_path_len,
        }
    }

    fn position(&mut self, atom: &'a A) -> u32 {
        let next = self.atoms.len() as u32;
        let a = *self.atom_ids.entry(atom).or_insert(next);
        if a == next {
            self.atoms.push(atom);
        }
        self.atom_of.push(a);
        (self.atom_of.len() - 1) as u32
    }

    fn link(&mut self, from: &[u32], to: &[u32]) {
        for &p in from {
            self.edges.extend(to.iter().map(|&q| (p, q)));
        }
    }

    /// The list `[p]`, in a spare list if there is one.
    fn single(&mut self, p: u32) -> Vec<u32> {
        let mut v = self.spare.pop().unwrap_or_default();
        v.push(p);
        v
    }

    /// Keeps `v`'s allocation for a later [`Builder::single`].
    fn recycle(&mut self, mut v: Vec<u32>) {
        if v.capacity() > 0 {
            v.clear();
            self.spare.push(v);
        }
    }

    fn concat(&mut self, a: Frag, b: Frag) -> Frag {
        self.link(&a.last, &b.first);
        let mut first = a.first;
        if a.nullable {
            first.extend_from_slice(&b.first);
        }
        self.recycle(b.first);
        let mut last = b.last;
        if b.nullable {
            last.extend_from_slice(&a.last);
        }
        self.recycle(a.last);
        Frag {
            first,
            last,
            nullable: a.nullable && b.nullable,
        }
    }

    fn build<E: Regex<Atom = A>>(&mut self, e: &'a E) -> Frag {
        match e.node() {
            Node::Atom(a) => {
                let p = self.position(a);
                Frag {
                    first: self.single(p),
                    last: self.single(p),
                    nullable: false,
                }
            }
            Node::Empty => Frag::empty(),
            Node::Concat(es) => es.iter().fold(Frag::empty(), |acc, e| {
                let f = self.build(e);
                self.concat(acc, f)
            }),
            Node::Alt(es) => {
                let mut out = Frag {
                    first: Vec::new(),
                    last: Vec::new(),
                    nullable: false,
                };
                for e in es {
                    let f = self.build(e);
                    out.first.extend_from_slice(&f.first);
                    out.last.extend_from_slice(&f.last);
                    out.nullable |= f.nullable;
                    self.recycle(f.first);
                    self.recycle(f.last);
                }
                out
            }
            Node::Repeat(body, r) => {
                let Repetition { min, max } = r.bounded(self.max_path_len);
                let mut acc = Frag::empty();
                for _ in 0..min {
                    let f = self.build(body);
                    acc = self.concat(acc, f);
                }
                let tail = match max {
                    None => {
                        let mut f = self.build(body);
                        self.link(&f.last, &f.first);
                        f.nullable = true;
                        f
                    }
                    Some(m) => self.optional_chain(body, m.saturating_sub(min)),
                };
                self.concat(acc, tail)
            }
        }
    }

    /// `(e(e(e)?)?)?` with `k` copies: nested optionals keep Follow linear in `k`, where
    /// `e?e?e?` would link every copy to every later one.
    fn optional_chain<E: Regex<Atom = A>>(&mut self, body: &'a E, k: u32) -> Frag {
        if k == 0 {
            return Frag::empty();
        }
        let head = self.build(body);
        let rest = self.optional_chain(body, k - 1);
        let mut f = self.concat(head, rest);
        f.nullable = true;
        f
    }
}

/// The compiled bitset NFA.
#[derive(Clone, Debug)]
pub(crate) struct Nfa {
    /// Positions, including the start (after dropping useless ones).
    pub positions: usize,
    /// `[(chunk * 256 + byte) * words ..][..words]`: union of the follow sets of the
    /// positions set in `byte` of chunk `chunk`. Empty when over the table budget.
    follow: Vec<u64>,
    /// `[p * words ..][..words]`: the follow set of position `p`.
    rows: Vec<u64>,
    /// `[class * words ..][..words]`: positions whose atom accepts the class.
    accept: Vec<u64>,
    /// Positions that end some AOV.
    finals: Vec<u64>,
    /// The AOV each position belongs to.
    aov_of: Vec<u32>,
    /// AOVs that match the empty sequence (reported for the start state).
    start_matches: AovMask,
    /// Per position, the distinct-atom index (`u32::MAX` for the start).
    pub atom_of: Vec<u32>,
}

/// Glushkov output before tabulation, for [`Nfa::new`].
pub(crate) struct Parts {
    pub aov_first: Vec<Vec<u32>>,
    pub aov_last: Vec<Vec<u32>>,
    pub aov_nullable: Vec<bool>,
}

impl<'a, A: Eq + Hash> Builder<'a, A> {
    /// The construction of `exprs`, one AOV each, in order.
    pub(crate) fn of_all<E: Regex<Atom = A> + 'a>(
        exprs: impl IntoIterator<Item = &'a E>,
        max_path_len: Option<u32>,
    ) -> (Builder<'a, A>, Parts) {
        let mut builder = Builder::new(max_path_len);
        let mut parts = Parts {
            aov_first: Vec::new(),
            aov_last: Vec::new(),
            aov_nullable: Vec::new(),
        };
        for e in exprs {
            builder.add(e, &mut parts);
        }
        (builder, parts)
    }

    /// Adds one AOV's expression.
    pub(crate) fn add<E: Regex<Atom = A>>(&mut self, e: &'a E, parts: &mut Parts) {
        let f = self.build(e);
        parts.aov_first.push(f.first);
        parts.aov_last.push(f.last);
        parts.aov_nullable.push(f.nullable);
    }
}

/// Positions and predecessor edges merging co-active positions may visit (rounds times
/// both) before it gives up and keeps every position. Refining from blocks of equal
/// depth takes 1 to 31 rounds on the sets of `lpe-check bench` (`nested` needs 31); a
/// set of 1 437 positions that merges nothing took 475 rounds, so the refinement also
/// stops after [`MERGE_ROUNDS`] rounds: its cost stays linear in the NFA's size.
const MERGE_BUDGET: usize = 1 << 20;

/// Most refinement rounds merging co-active positions may take.
const MERGE_ROUNDS: usize = 64;

/// Edges grouped by their source: one list of all targets and where each source's begin,
/// two allocations for any number of positions.
struct Adjacency {
    /// `starts[p]..starts[p + 1]` are `p`'s targets in `targets`.
    starts: Vec<u32>,
    targets: Vec<u32>,
}

impl Adjacency {
    /// The edges `(from, to)` over positions `0..n`, by a counting sort on `from`.
    fn new(n: usize, edges: impl Iterator<Item = (u32, u32)> + Clone) -> Adjacency {
        let mut starts = vec![0u32; n + 1];
        for (p, _) in edges.clone() {
            starts[p as usize + 1] += 1;
        }
        for p in 0..n {
            starts[p + 1] += starts[p];
        }
        let mut next = starts.clone();
        let mut targets = vec![0u32; starts[n] as usize];
        for (p, q) in edges {
            targets[next[p as usize] as usize] = q;
            next[p as usize] += 1;
        }
        Adjacency { starts, targets }
    }

    /// The targets of the edges from `p`.
    fn of(&self, p: usize) -> &[u32] {
        &self.targets[self.starts[p] as usize..self.starts[p + 1] as usize]
    }
}

/// Bytes of follow tables for a state of `words` words.
pub(crate) fn table_bytes(words: usize) -> usize {
    words * 8 * 256 * words * 8
}

impl Nfa {
    /// Tabulates a finished construction. Positions that cannot be reached from the start
    /// or cannot reach a final position are dropped: they never change an answer, and
    /// dropping them makes [`Nfa::is_dead`] exact and the DFA smaller.
    ///
    /// Its per-byte step tables are built when they fit [`Options::nfa_budget`], and
    /// positions always active together are merged, unless [`Options::few_paths`] says
    /// that the steps to come would not repay either.
    pub(crate) fn new<A>(
        builder: Builder<'_, A>,
        parts: Parts,
        alphabet: &impl VertexClasses,
        opts: &Options,
    ) -> Nfa {
        let table_budget = if opts.few_paths { 0 } else { opts.nfa_budget };
        let Builder {
            atoms,
            atom_of,
            mut edges,
            ..
        } = builder;
        let n = atom_of.len();
        for first in &parts.aov_first {
            edges.extend(first.iter().map(|&q| (0, q)));
        }
        let mut aov_of = vec![u32::MAX; n];
        for (i, last) in parts.aov_last.iter().enumerate() {
            for &p in last {
                aov_of[p as usize] = i as u32;
            }
        }
        // `[a * classes + c]`: whether distinct atom `a` accepts class `c`, asked once per
        // atom rather than per position (a chain `.{199}` has one atom).
        let classes = alphabet.class_count();
        let accepts: Vec<bool> = (0..atoms.len())
            .flat_map(|a| (0..classes).map(move |c| (a, c)))
            .map(|(a, c)| alphabet.accepts(c, a))
            .collect();
        let accepts_of = |a: u32| &accepts[a as usize * classes..][..classes];
        // Keep positions reachable from the start and co-reachable to a final.
        // A position whose atom accepts no vertex (`<CD>`) is never entered: leave it
        // out of the search, so that every kept position can really lead to a match and
        // the empty set is the only dead state, minimized or not.
        let live_pos: Vec<bool> = atom_of
            .iter()
            .map(|&a| a != u32::MAX && accepts_of(a).contains(&true))
            .collect();
        let live = |q: u32| live_pos[q as usize];
        let succs = Adjacency::new(n, edges.iter().copied());
        let mut reach = vec![false; n];
        reach[0] = true;
        let mut stack = vec![0usize];
        while let Some(p) = stack.pop() {
            for &q in succs.of(p) {
                if live(q) && !std::mem::replace(&mut reach[q as usize], true) {
                    stack.push(q as usize);
                }
            }
        }
        let preds = Adjacency::new(n, edges.iter().map(|&(p, q)| (q, p)));
        let mut coreach = vec![false; n];
        let mut stack: Vec<usize> = (1..n)
            .filter(|&p| aov_of[p] != u32::MAX && live(p as u32))
            .collect();
        for &p in &stack {
            coreach[p] = true;
        }
        while let Some(q) = stack.pop() {
            for &p in preds.of(q) {
                if (p == 0 || live(p)) && !std::mem::replace(&mut coreach[p as usize], true) {
                    stack.push(p as usize);
                }
            }
        }
        let mut renumber = vec![u32::MAX; n];
        let mut kept = vec![0usize];
        renumber[0] = 0;
        for p in 1..n {
            if reach[p] && coreach[p] {
                renumber[p] = kept.len() as u32;
                kept.push(p);
            }
        }
        // Edges between kept positions, renumbered.
        let kept_edges = || {
            edges.iter().filter_map(|&(p, q)| {
                let (p, q) = (renumber[p as usize], renumber[q as usize]);
                (p != u32::MAX && q != u32::MAX).then_some((p, q))
            })
        };
        // One position per block of positions always active together: same atom, same
        // AOV ended (a position names one), predecessors in the same blocks.
        let block = if opts.few_paths {
            (0..kept.len() as u32).collect()
        } else {
            let key: Vec<(u32, u32)> = kept
                .iter()
                .map(|&old| (atom_of[old], aov_of[old]))
                .collect();
            let mut preds = vec![Vec::new(); kept.len()];
            for (p, q) in kept_edges() {
                preds[q as usize].push(p);
            }
            let edges: usize = preds.iter().map(Vec::len).sum();
            let budget = MERGE_BUDGET.min(MERGE_ROUNDS * (kept.len() + edges + 1));
            coactive::co_active_blocks(&key, &preds, budget)
                .unwrap_or_else(|| (0..kept.len() as u32).collect())
        };
        let positions = block.iter().max().map_or(0, |&b| b as usize + 1);
        let words = positions.div_ceil(64);
        let mut rows = vec![0u64; positions * words];
        for (p, q) in kept_edges() {
            let (p, q) = (block[p as usize] as usize, block[q as usize] as usize);
            set(&mut rows[p * words..][..words], q);
        }
        // Chunk tables: entry `b` is entry `b` without its lowest bit, plus that bit's row.
        // Every chunk of every word, those past the last position too: the inlined wide
        // step then reads a row per byte with no check of where the positions end
        // (tables for the used chunks only, with that check, made it 1.6-1.9x slower:
        // `lpe-check bench`, bitset NFA row). The chunks past the last position hold no
        // position, so their rows stay zero and are not filled: a compile, which the
        // fuzz targets do per case, writes only the used chunks.
        // Only a state the wide step holds by value reads them (`Nfa::step`); a wider NFA
        // steps by rows.
        let chunks = if words <= NFA_STATE_WORDS && table_bytes(words) <= table_budget {
            words * 8
        } else {
            0
        };
        let mut table = vec![0u64; chunks * 256 * words];
        for chunk in 0..chunks.min(positions.div_ceil(8)) {
            for b in 1..256usize {
                let p = chunk * 8 + b.trailing_zeros() as usize;
                let (dst, src) = (
                    (chunk * 256 + b) * words,
                    (chunk * 256 + (b & (b - 1))) * words,
                );
                for k in 0..words {
                    let row = if p < positions {
                        rows[p * words + k]
                    } else {
                        0
                    };
                    table[dst + k] = table[src + k] | row;
                }
            }
        }
        let mut accept = vec![0u64; classes * words];
        let mut finals = vec![0u64; words];
        let mut new_atom_of = vec![u32::MAX; positions];
        let mut new_aov_of = vec![u32::MAX; positions];
        for (&new, &old) in block.iter().zip(&kept).skip(1) {
            let new = new as usize;
            let a = atom_of[old];
            new_atom_of[new] = a;
            new_aov_of[new] = aov_of[old];
            if aov_of[old] != u32::MAX {
                set(&mut finals, new);
            }
            for (c, _) in accepts_of(a).iter().enumerate().filter(|(_, &yes)| yes) {
                set(&mut accept[c * words..][..words], new);
            }
        }
        let mut start_matches = AovMask::EMPTY;
        for (i, &nullable) in parts.aov_nullable.iter().enumerate() {
            if nullable {
                start_matches.insert(i);
            }
        }
        Nfa {
            positions,
            follow: table,
            rows,
            accept,
            finals,
            aov_of: new_aov_of,
            start_matches,
            atom_of: new_atom_of,
        }
    }

    /// Whether the per-byte follow tables fit the budget (else steps OR the rows of the
    /// active positions).
    pub(crate) fn has_step_tables(&self) -> bool {
        !self.follow.is_empty()
    }

    /// 64-bit words per state.
    #[inline]
    pub(crate) fn words(&self) -> usize {
        self.positions.div_ceil(64)
    }

    /// `next = Follow(cur) & Accept[class]`. `cur` and `next` hold [`Nfa::words`] words.
    #[inline]
    pub(crate) fn step(&self, cur: &[u64], class: usize, next: &mut [u64]) {
        let w = self.words();
        if w <= NFA_STATE_WORDS && self.has_step_tables() {
            let mut wide = [0u64; NFA_STATE_WORDS];
            wide[..w].copy_from_slice(&cur[..w]);
            next[..w].copy_from_slice(&self.step_wide(wide, class)[..w]);
        } else {
            self.step_rows(cur, class, next);
        }
    }

    /// [`Nfa::step`] on a state of at most [`NFA_STATE_WORDS`] words held by value (words
    /// past [`Nfa::words`] are ignored and come back zero). Inlined whole, with the word
    /// count a constant in each arm and the state passed by value, so that in a caller's
    /// loop the state stays in registers: out of line, it went through memory at every
    /// step, a store-forwarding stall each way.
    #[inline(always)]
    pub(crate) fn step_wide(
        &self,
        cur: [u64; NFA_STATE_WORDS],
        class: usize,
    ) -> [u64; NFA_STATE_WORDS] {
        let tabled = self.has_step_tables();
        match self.words() {
            1 if tabled => {
                let [a] = self.step_tabled([cur[0]], class);
                [a, 0, 0, 0]
            }
            2 if tabled => {
                let [a, b] = self.step_tabled([cur[0], cur[1]], class);
                [a, b, 0, 0]
            }
            3 if tabled => {
                let [a, b, c] = self.step_tabled([cur[0], cur[1], cur[2]], class);
                [a, b, c, 0]
            }
            4 if tabled => self.step_tabled(cur, class),
            // The words go by value: a pointer to the caller's state would keep it in
            // memory in the caller's loop.
            _ => self.step_rows_wide(cur[0], cur[1], cur[2], cur[3], class),
        }
    }

    /// [`Nfa::step_wide`] without tables, out of line.
    #[inline(never)]
    fn step_rows_wide(&self, w0: u64, w1: u64, w2: u64, w3: u64, class: usize) -> [u64; 4] {
        let cur = [w0, w1, w2, w3];
        let mut next = [0u64; NFA_STATE_WORDS];
        let w = self.words();
        // Never stepped on a wide state: a lazy set's NFA fits one.
        if w <= NFA_STATE_WORDS {
            self.step_rows(&cur[..w], class, &mut next[..w]);
        }
        next
    }

    /// One step through the per-byte tables on a state of `W` words: one row load per
    /// byte, zero bytes and bytes past the last position included (their rows are
    /// empty; a load is cheaper than a branch that mispredicts), in loops of constant
    /// length that unroll, ORed into two accumulators so that the ORs of a wide state
    /// do not form one long chain.
    #[inline(always)]
    fn step_tabled<const W: usize>(&self, cur: [u64; W], class: usize) -> [u64; W] {
        // One bounds check for the whole table: each row index below is provably in it.
        let follow = &self.follow[..8 * W * 256 * W];
        let row = |chunk: usize, b: u64| -> &[u64] {
            &follow[(chunk * 256 + (b & 0xff) as usize) * W..][..W]
        };
        let (mut even, mut odd) = ([0u64; W], [0u64; W]);
        for (i, &word) in cur.iter().enumerate() {
            for pair in 0..4 {
                let lo = row(i * 8 + 2 * pair, word >> (16 * pair));
                let hi = row(i * 8 + 2 * pair + 1, word >> (16 * pair + 8));
                for k in 0..W {
                    even[k] |= lo[k];
                    odd[k] |= hi[k];
                }
            }
        }
        match self.accept.get(class * W..(class + 1) * W) {
            Some(acc) => std::array::from_fn(|k| (even[k] | odd[k]) & acc[k]),
            // A class of another set: no position accepts it.
            None => [0; W],
        }
    }

    /// [`Nfa::step`] without the per-byte tables: the rows of the active positions.
    fn step_rows(&self, cur: &[u64], class: usize, next: &mut [u64]) {
        let w = self.words();
        let (cur, next) = (&cur[..w], &mut next[..w]);
        next.fill(0);
        for p in bits::ones(cur.iter().copied()) {
            let row = self.rows.get(p * w..(p + 1) * w).unwrap_or(&[]);
            for (n, r) in next.iter_mut().zip(row) {
                *n |= r;
            }
        }
        match self.accept.get(class * w..(class + 1) * w) {
            Some(acc) => next.iter_mut().zip(acc).for_each(|(n, a)| *n &= a),
            // A class of another set: no position accepts it.
            None => next.fill(0),
        }
    }

    /// [`Nfa::matches`] on a state held by value (words past [`Nfa::words`] ignored),
    /// inlined for the reason [`Nfa::step_wide`] is.
    #[inline(always)]
    pub(crate) fn matches_wide(&self, cur: [u64; NFA_STATE_WORDS]) -> AovMask {
        self.matches(&cur)
    }

    /// The AOVs that match when the path ends in state `cur` (words past
    /// [`Nfa::words`] ignored: the finals have no more).
    #[inline(always)]
    pub(crate) fn matches(&self, cur: &[u64]) -> AovMask {
        let mut m = if cur[0] & 1 == 1 {
            self.start_matches
        } else {
            AovMask::EMPTY
        };
        for p in bits::ones(cur.iter().zip(&self.finals).map(|(a, f)| a & f)) {
            m.insert(self.aov_of[p] as usize);
        }
        m
    }

    /// The follow set of one position.
    pub(crate) fn follow_of(&self, p: usize) -> &[u64] {
        &self.rows[p * self.words()..][..self.words()]
    }

    /// The positions whose atom accepts `class` (empty for a class of another set): with
    /// [`Nfa::follow_of`], one position's successors, for searches that follow a single
    /// run instead of a subset.
    pub(crate) fn accept_of(&self, class: usize) -> &[u64] {
        let w = self.words();
        self.accept.get(class * w..(class + 1) * w).unwrap_or(&[])
    }

    /// The AOV position `p` ends, if it is final.
    pub(crate) fn final_aov(&self, p: usize) -> Option<usize> {
        (p != 0 && self.aov_of[p] != u32::MAX).then(|| self.aov_of[p] as usize)
    }

    pub(crate) fn memory_bytes(&self) -> usize {
        (self.follow.len() + self.rows.len() + self.accept.len() + self.finals.len()) * 8
            + (self.aov_of.len() + self.atom_of.len()) * 4
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::renderman::alphabet::Alphabet;
    use crate::renderman::parse;
    use crate::rng::SplitMix64;

    /// `Options::default().nfa_budget`, spelled out so that the tests do not depend on
    /// the default.
    const DEFAULT_NFA_BUDGET: usize = 16 << 20;

    /// The NFA of `srcs` with the given table budget, and its class count.
    fn nfa(srcs: &[&str], table_budget: usize) -> (Nfa, usize) {
        let opts = Options {
            nfa_budget: table_budget,
            ..Options::default()
        };
        nfa_with(srcs, &opts)
    }

    /// The NFA of `srcs` compiled with `opts`, and its class count.
    fn nfa_with(srcs: &[&str], opts: &Options) -> (Nfa, usize) {
        let lpes: Vec<_> = srcs.iter().map(|s| parse(s).unwrap()).collect();
        let (builder, parts) = Builder::of_all(lpes.iter().map(|l| &l.expr), None);
        let labels = lpes.iter().flat_map(|l| l.expr.labels()).collect();
        let alphabet = Alphabet::new(&builder.atoms, labels);
        let classes = alphabet.class_count();
        (Nfa::new(builder, parts, &alphabet, opts), classes)
    }

    #[test]
    fn steps_with_and_without_tables_agree() {
        let sets: [&[&str]; 7] = [
            &["C<RD>[<L.>O]", "C<RS>+<TD'glass'>?L", "CD*L"],
            &["C.*D.{20}[LO]", "C[^'a' S]{2,5}<L.'key'>"],
            // Two, three and four words: each width of the inlined wide step.
            &["C.*D.{70}[LO]", "C<RD'a'>*<TS'b'>L"],
            &["C.{140}L", "C<RD'a'>*<TS'b'>L"],
            &["C.*D.{200}[LO]", "C[^'a' S]{2,5}<L.'key'>"],
            // 302 positions: five-word states, stepped by rows with or without a
            // table budget (no tables: only the inlined wide step reads them).
            &["C(.{100}){3}L", "C<RD'a'>*<TS'b'>L"],
            &["CR<CD>L", "C<L.'a'>", "C(U|S2)+O"],
        ];
        let mut rng = SplitMix64::new(7);
        let mut widths = Vec::new();
        for srcs in sets {
            let (tabled, classes) = nfa(srcs, DEFAULT_NFA_BUDGET);
            let (rows_only, _) = nfa(srcs, 0);
            assert_eq!(
                tabled.has_step_tables(),
                tabled.words() <= NFA_STATE_WORDS,
                "{srcs:?}"
            );
            widths.push(tabled.words());
            assert!(!rows_only.has_step_tables(), "{srcs:?}");
            assert!(rows_only.follow.is_empty());
            assert_eq!(tabled.positions, rows_only.positions);
            let w = tabled.words();
            let mut cur = vec![0u64; w];
            let (mut a, mut b) = (vec![0u64; w], vec![0u64; w]);
            for i in 0..2000 {
                // Dense, sparse and single-position states; bits past the last position
                // included, since a state from another set may carry them.
                for x in cur.iter_mut() {
                    *x = match i % 3 {
                        0 => rng.next_u64(),
                        1 => rng.next_u64() & rng.next_u64() & rng.next_u64(),
                        _ => 0,
                    };
                }
                if i % 3 == 2 {
                    set(&mut cur, rng.next_u64() as usize % tabled.positions);
                }
                // Every class, and one past the end (a class of another set).
                let class = rng.next_u64() as usize % (classes + 1);
                tabled.step(&cur, class, &mut a);
                rows_only.step(&cur, class, &mut b);
                assert_eq!(a, b, "{srcs:?}: state {cur:x?}, class {class}");
                assert_eq!(tabled.matches(&a), rows_only.matches(&b));
                if w <= NFA_STATE_WORDS {
                    // The wide step and mask, with and without tables, on the same state
                    // padded with words that must be ignored.
                    let mut wide = [rng.next_u64(); NFA_STATE_WORDS];
                    wide[..w].copy_from_slice(&cur);
                    for nfa in [&tabled, &rows_only] {
                        let next = nfa.step_wide(wide, class);
                        assert_eq!(next[..w], a[..], "{srcs:?}: state {cur:x?}, class {class}");
                        assert!(next[w..].iter().all(|&x| x == 0), "{next:x?}");
                        assert_eq!(nfa.matches_wide(wide), tabled.matches(&cur));
                    }
                }
            }
        }
        assert_eq!(widths, [1, 1, 2, 3, 4, 5, 1]);
    }
}
