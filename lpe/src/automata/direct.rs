//! Matching a whole path without building an automaton: each expression tree evaluated
//! on the path, node by node, as a set of positions (bit `i`: the first `i` vertices are
//! read). What a set asked about a single path needs: compiling is one walk of the tree,
//! where the Glushkov NFA unrolls every counted repetition (`.{150}` is 150 positions,
//! here one node) and the DFA determinizes it.
//!
//! A node maps the set of positions it may start at to the set it may end at:
//! - an atom reads one vertex: `(S & accepted) << 1`, `accepted` the positions whose
//!   vertex the atom accepts, asked of the dialect only at the positions some `S` has
//!   reached (and once each): `C[…40 items…]*L` on a path whose second vertex none of
//!   the items accepts asks 40 questions, not 40 per vertex;
//! - a sequence applies its parts in turn, an alternation unites its alternatives;
//! - `e{n,m}` unites `T_n ..= T_m`, where `T_0 = S` and `T_(k+1)` is `e` applied to
//!   `T_k` ([`Eval::repeat`] says why that stops within `len + 2` applications).
//!
//! The expression matches the path when the root, started at `{0}`, can end at `len`.

use std::hash::Hash;

use crate::automata::ir::{Node, Regex, Repetition};
use crate::automata::mask::AovMask;
use crate::fxhash::FxMap;

/// The trees of a set's hidden AOVs, flattened in preorder so that evaluating a path
/// walks a slice, with each distinct atom numbered in first-seen order.
#[derive(Clone, Debug)]
pub(crate) struct Program {
    ops: Vec<Op>,
    /// Per hidden AOV, the index of its root in `ops`.
    roots: Vec<u32>,
    /// How many distinct atoms the `Op::Atom`s number.
    atoms: usize,
}

/// One node of a flattened tree. `end` is the index just past the node's subtree, so
/// the children of a sequence or an alternation are found by jumping from one `end` to
/// the next.
#[derive(Clone, Copy, Debug)]
enum Op {
    Atom(u32),
    Concat {
        end: u32,
    },
    Alt {
        end: u32,
    },
    /// The body is the next node.
    Repeat {
        rep: Repetition,
        end: u32,
    },
    Empty,
}

impl Program {
    /// The program of `exprs`, one hidden AOV each, in order, and their distinct atoms in
    /// first-seen order.
    pub(crate) fn new<'a, E: Regex>(exprs: &[&'a E]) -> (Program, Vec<&'a E::Atom>)
    where
        E::Atom: Eq + Hash,
    {
        let mut flat = Flatten {
            ops: Vec::new(),
            atoms: Vec::new(),
            index: FxMap::default(),
        };
        let roots = exprs
            .iter()
            .map(|e| {
                let root = flat.ops.len() as u32;
                flat.push(*e);
                root
            })
            .collect();
        let program = Program {
            ops: flat.ops,
            roots,
            atoms: flat.atoms.len(),
        };
        (program, flat.atoms)
    }

    /// The hidden AOVs matching the whole path of `len` vertices, where distinct atom `a`
    /// accepts vertex `i` when `accepts(a, i)`.
    pub(crate) fn matches(&self, len: usize, accepts: impl Fn(usize, usize) -> bool) -> AovMask {
        if len < u64::BITS as usize {
            self.matches_on::<u64>(len, accepts)
        } else {
            self.matches_on::<Wide>(len, accepts)
        }
    }

    fn matches_on<P: Positions>(
        &self,
        len: usize,
        accepts: impl Fn(usize, usize) -> bool,
    ) -> AovMask {
        let mut eval = Eval {
            ops: &self.ops,
            len,
            accepted: vec![P::none(len); self.atoms],
            asked: vec![P::none(len); self.atoms],
            accepts,
        };
        let mut start = P::none(len);
        start.insert(0);
        self.roots
            .iter()
            .enumerate()
            .filter(|(_, &root)| eval.run(root as usize, &start).0.contains(len))
            .map(|(hidden, _)| hidden)
            .collect()
    }

    /// Bytes held.
    pub(crate) fn memory_bytes(&self) -> usize {
        self.ops.capacity() * std::mem::size_of::<Op>() + self.roots.capacity() * 4
    }
}

/// The flattening walk of [`Program::new`].
struct Flatten<'a, A> {
    ops: Vec<Op>,
    atoms: Vec<&'a A>,
    index: FxMap<&'a A, u32>,
}

impl<'a, A: Eq + Hash> Flatten<'a, A> {
    fn push<E: Regex<Atom = A>>(&mut self, e: &'a E) {
        match e.node() {
            Node::Atom(a) => {
                let next = self.atoms.len() as u32;
                let id = *self.index.entry(a).or_insert(next);
                if id == next {
                    self.atoms.push(a);
                }
                self.ops.push(Op::Atom(id));
            }
            Node::Empty => self.ops.push(Op::Empty),
            Node::Concat(es) => self.push_parent(es, |end| Op::Concat { end }),
            Node::Alt(es) => self.push_parent(es, |end| Op::Alt { end }),
            Node::Repeat(body, rep) => {
                self.push_parent(std::slice::from_ref(body), |end| Op::Repeat { rep, end })
            }
        }
    }

    /// A node over `children`, written once they are (`op` gets the index past them).
    fn push_parent<E: Regex<Atom = A>>(&mut self, children: &'a [E], op: impl Fn(u32) -> Op) {
        let at = self.ops.len();
        self.ops.push(Op::Empty);
        for e in children {
            self.push(e);
        }
        self.ops[at] = op(self.ops.len() as u32);
    }
}

/// One path's evaluation: the program and, per distinct atom, the positions whose
/// vertex it accepts among those asked so far.
struct Eval<'p, P, F> {
    ops: &'p [Op],
    /// The path's vertices.
    len: usize,
    accepted: Vec<P>,
    asked: Vec<P>,
    /// Whether distinct atom `a` accepts vertex `i`.
    accepts: F,
}

impl<P: Positions, F: Fn(usize, usize) -> bool> Eval<'_, P, F> {
    /// The positions of `start` whose vertex atom `a` accepts (before each, the vertex
    /// asked about unless it was before).
    fn accepted(&mut self, a: usize, start: &P) -> &P {
        let fresh = start.minus(&self.asked[a]);
        fresh.each(self.len, |i| {
            if (self.accepts)(a, i) {
                self.accepted[a].insert(i);
            }
        });
        self.asked[a].union(&fresh);
        &self.accepted[a]
    }

    /// Where the node at `at` may end when started anywhere in `start`, and the index
    /// past its subtree.
    fn run(&mut self, at: usize, start: &P) -> (P, usize) {
        match self.ops[at] {
            Op::Atom(a) => (start.read(self.accepted(a as usize, start)), at + 1),
            Op::Empty => (start.clone(), at + 1),
            Op::Concat { end } => {
                let end = end as usize;
                let mut s = start.clone();
                let mut child = at + 1;
                while child < end {
                    // Every later part reads from nowhere once nothing is left.
                    if s.is_empty() {
                        return (s, end);
                    }
                    (s, child) = self.run(child, &s);
                }
                (s, end)
            }
            Op::Alt { end } => {
                let end = end as usize;
                let mut out = P::none_like(start);
                let mut child = at + 1;
                while child < end {
                    let (s, next) = self.run(child, start);
                    out.union(&s);
                    child = next;
                }
                (out, end)
            }
            Op::Repeat { rep, end } => (self.repeat(at + 1, rep, start), end as usize),
        }
    }

    /// `e{n,m}` on `start`: the union of `T_n ..= T_m`, `T_0 = start`, `T_(k+1)` the body
    /// `e` applied to `T_k`. It stops early, and within `len + 2` applications of the
    /// body whatever `n` and `m` are (so `.{100000}` costs what `.{len + 1}` does):
    /// - Below `n`: at an empty `T_k` (every later one is empty), or at `T_(k+1) = T_k`
    ///   (every later one is the same set, so the union is that set). One of the two
    ///   comes within `len + 1` steps: a body that cannot match the empty sequence moves
    ///   the first position of `T_k` forward at every step, so `T_k` is empty by
    ///   `k = len + 1`; one that can keeps every position (`T_k` within `T_(k+1)`), so
    ///   the sets grow until they stop growing, at most `len + 1` times.
    /// - From `n` on: at a `T_k` inside the union `U` so far (`T_n ..= T_(k-1)`). Every
    ///   later set is then inside `U` too: `T_(k+1)` is the body applied to `T_k`, which
    ///   is within the body applied to `U`, that is `T_(n+1) ..= T_k`, within `U`. Each
    ///   step that does not stop adds a position to `U`, of which there are `len + 1`.
    ///
    /// `m < n` repeats `n` times, as the NFA builds it.
    fn repeat(&mut self, body: usize, rep: Repetition, start: &P) -> P {
        let mut t = start.clone();
        let mut k = 0u32;
        while k < rep.min {
            let (next, _) = self.run(body, &t);
            k += 1;
            if next.is_empty() || next == t {
                return next;
            }
            t = next;
        }
        let max = rep.max.map(|m| m.max(rep.min));
        let mut out = t.clone();
        while max.is_none_or(|m| k < m) {
            let (next, _) = self.run(body, &t);
            k += 1;
            if next.is_subset(&out) {
                break;
            }
            out.union(&next);
            t = next;
        }
        out
    }
}

/// A set of positions `0..=len` of a path of `len` vertices.
trait Positions: Clone + PartialEq {
    /// The empty set, for a path of `len` vertices.
    fn none(len: usize) -> Self;
    /// The empty set, of the width of `like`.
    fn none_like(like: &Self) -> Self;
    fn insert(&mut self, i: usize);
    fn contains(&self, i: usize) -> bool;
    fn is_empty(&self) -> bool;
    fn is_subset(&self, of: &Self) -> bool;
    fn union(&mut self, other: &Self);
    /// The positions of `self` not in `other`.
    fn minus(&self, other: &Self) -> Self;
    /// Calls `f` on each position below `len`, in order.
    fn each(&self, len: usize, f: impl FnMut(usize));
    /// Reads one vertex: the positions after the ones of `self` whose vertex is in
    /// `accepted`.
    fn read(&self, accepted: &Self) -> Self;
}

/// A path of fewer than 64 vertices: its `len + 1` positions fit a word.
impl Positions for u64 {
    fn none(_: usize) -> Self {
        0
    }
    fn none_like(_: &Self) -> Self {
        0
    }
    fn insert(&mut self, i: usize) {
        *self |= 1 << i;
    }
    fn contains(&self, i: usize) -> bool {
        self >> i & 1 == 1
    }
    fn is_empty(&self) -> bool {
        *self == 0
    }
    fn is_subset(&self, of: &Self) -> bool {
        self & !of == 0
    }
    fn union(&mut self, other: &Self) {
        *self |= other;
    }
    fn minus(&self, other: &Self) -> Self {
        self & !other
    }
    fn each(&self, len: usize, mut f: impl FnMut(usize)) {
        let mut rest = *self;
        while rest != 0 {
            let i = rest.trailing_zeros() as usize;
            if i >= len {
                break;
            }
            f(i);
            rest &= rest - 1;
        }
    }
    fn read(&self, accepted: &Self) -> Self {
        // No position past `len` is ever set: `accepted` has bits below `len` only
        // (`each` stops there).
        (self & accepted) << 1
    }
}

/// A longer path: a word per 64 positions.
#[derive(Clone, PartialEq, Debug)]
struct Wide(Vec<u64>);

impl Positions for Wide {
    fn none(len: usize) -> Self {
        Wide(vec![0; (len + 1).div_ceil(64)])
    }
    fn none_like(like: &Self) -> Self {
        Wide(vec![0; like.0.len()])
    }
    fn insert(&mut self, i: usize) {
        self.0[i / 64] |= 1 << (i % 64);
    }
    fn contains(&self, i: usize) -> bool {
        self.0[i / 64] >> (i % 64) & 1 == 1
    }
    fn is_empty(&self) -> bool {
        self.0.iter().all(|&w| w == 0)
    }
    fn is_subset(&self, of: &Self) -> bool {
        self.0.iter().zip(&of.0).all(|(a, b)| a & !b == 0)
    }
    fn union(&mut self, other: &Self) {
        for (a, b) in self.0.iter_mut().zip(&other.0) {
            *a |= b;
        }
    }
    fn minus(&self, other: &Self) -> Self {
        Wide(self.0.iter().zip(&other.0).map(|(a, b)| a & !b).collect())
    }
    fn each(&self, len: usize, mut f: impl FnMut(usize)) {
        for (w, &word) in self.0.iter().enumerate() {
            let mut rest = word;
            while rest != 0 {
                let i = w * 64 + rest.trailing_zeros() as usize;
                if i >= len {
                    return;
                }
                f(i);
                rest &= rest - 1;
            }
        }
    }
    fn read(&self, accepted: &Self) -> Self {
        let mut carry = 0;
        let words = self
            .0
            .iter()
            .zip(&accepted.0)
            .map(|(s, a)| {
                let w = s & a;
                let shifted = w << 1 | carry;
                carry = w >> 63;
                shifted
            })
            .collect();
        Wide(words)
    }
}

#[cfg(test)]
mod tests {
    //! The evaluation's own accounting, with answers and counts worked out by hand (the
    //! answers themselves are tested through [`crate::DirectSet`]).

    use std::cell::Cell;

    use crate::renderman::parse;

    use super::{Op, Program};

    /// The bytes held: the capacity of the ops (not their number) and four bytes a
    /// root. Caught: the sum's `+` as `-` or `*`, either `*` as `+` or `/`, the whole
    /// as 0 or 1.
    #[test]
    fn memory_counts_the_ops_and_four_bytes_a_root() {
        let p = Program {
            ops: Vec::with_capacity(10),
            roots: Vec::with_capacity(3),
            atoms: 0,
        };
        assert_eq!((p.ops.capacity(), p.roots.capacity()), (10, 3));
        assert_eq!(p.memory_bytes(), 10 * std::mem::size_of::<Op>() + 3 * 4);
    }

    /// The dialect is asked about an atom on a vertex only where some set reaches it,
    /// and once: `C<RD>*<RD>*L` (atoms `C`, `<RD>`, `L`) on `C`, `n` diffuse vertices,
    /// `L` asks `C` about vertex 0, `<RD>` about vertices 1 to `n + 1` (the first loop
    /// stops at the light; the second reaches nothing new), `L` about the same `n + 1`:
    /// `2n + 3` questions, on one word (`n` = 3) and on two (`n` = 68). Caught: the
    /// positions still to ask taken as `start | !asked` (every vertex not yet asked,
    /// on either width), and as `start ^ !asked`.
    #[test]
    fn each_atom_is_asked_once_about_each_vertex_it_reaches() {
        let lpe = parse("C<RD>*<RD>*L").unwrap();
        let (program, atoms) = Program::new(&[&lpe.expr]);
        let names: Vec<String> = atoms.iter().map(|a| a.to_string()).collect();
        assert_eq!(names, ["C", "<RD>", "L"]);
        for n in [3, 68] {
            let len = n + 2;
            let asked = Cell::new(0);
            let hit = program.matches(len, |a, i| {
                asked.set(asked.get() + 1);
                match a {
                    0 => i == 0,
                    1 => (1..=n).contains(&i),
                    _ => i == n + 1,
                }
            });
            assert_eq!(hit.iter().collect::<Vec<_>>(), [0], "n = {n}");
            assert_eq!(asked.get(), 2 * n + 3, "n = {n}");
        }
    }
}
