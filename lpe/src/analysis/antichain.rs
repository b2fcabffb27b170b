//! Shortest witnesses of one [`Conjunct`] ("a path these operands match and those do
//! not") on the bitset NFA, without determinizing the operands that must match: the
//! antichain search of De Wulf, Doyen, Henzinger and Raskin (CAV 2006) for language
//! inclusion, run forward and breadth-first.
//!
//! A search node is one run position per operand that must match (a single NFA
//! position, as in a product of NFAs), the path-shape state, and the subset of positions
//! of the operands that must not match (as in a subset construction, but of those
//! operands only). A node with the same runs and shape state as a kept node and a
//! superset of its subset is *subsumed*: every continuation that is a witness from it is
//! one from the kept node too (a smaller subset matches less), so it is dropped. On
//! `C.*D.{k}L` against `C.*D.{k}[LO]` the subsets a run position sees have one least
//! element each (the path with one diffuse bounce), so the search keeps `O(k)` nodes per
//! layer where the subset construction of either side has `2^k` states.
//!
//! Layer by layer (breadth-first), a node made in the current layer also *removes* kept
//! nodes of that layer it subsumes strictly (De Wulf et al.'s minimization of the
//! frontier). That keeps the frontier an antichain, which is what makes the example above
//! polynomial, and keeps the first witness a shortest one (a removed node's witnesses are
//! the remover's, from the same layer). It can cost the *first in letter order* among
//! the shortest (the remover may be reached by a later word), which the reports
//! promise; so when a removal happened before the witness's layer, a second search
//! ([`Graph::first_of_length`]) finds the first witness of that length in letter order:
//! a depth-first search in letter order with memoized failures, subsumption again
//! pruning. Without removals the breadth-first order alone gives it: nodes are made in
//! the order of their shortest, first-in-letter-order path, and a node is only dropped
//! for one made earlier.

use super::budget::{Meter, Undecided};
use super::dnf::Conjunct;
use crate::automata::ir::Place;
use crate::automata::nfa::Nfa;
use crate::automata::shape::{Shape, NONE};
use crate::bits;
use crate::fxhash::FxMap;

/// The NFA of a set's operands with what every search on it needs.
pub(super) struct Graph {
    nfa: Nfa,
    /// The letters: a class and the place in the path it stands at, in the order
    /// witnesses are ranked by.
    letters: Vec<(usize, Place)>,
    shape: &'static Shape,
    /// Per operand (hidden AOV), the positions from which one of its final positions can
    /// be reached (its finals included).
    coreach: Vec<Vec<u64>>,
    /// Per operand, its final positions.
    finals: Vec<Vec<u64>>,
}

/// A search node: see the module docs.
#[derive(Clone, Debug)]
struct Node {
    runs: Box<[u32]>,
    shape: u8,
    subset: Box<[u64]>,
}

/// `a ⊆ b`, as bitsets of one width.
fn subset_of(a: &[u64], b: &[u64]) -> bool {
    a.iter().zip(b).all(|(x, y)| x & !y == 0)
}

impl Graph {
    /// The graph of `nfa`, whose final positions end `operands` hidden AOVs, searched on
    /// `letters` in product with `shape`.
    pub(super) fn new(
        nfa: Nfa,
        operands: usize,
        letters: Vec<(usize, Place)>,
        shape: &'static Shape,
    ) -> Graph {
        let n = nfa.positions;
        let words = nfa.words();
        let mut preds: Vec<Vec<u32>> = vec![Vec::new(); n];
        for p in 0..n {
            for q in bits::ones(nfa.follow_of(p).iter().copied()) {
                if q < n {
                    preds[q].push(p as u32);
                }
            }
        }
        let mut finals = vec![vec![0u64; words]; operands];
        for p in 0..n {
            if let Some(a) = nfa.final_aov(p).filter(|&a| a < operands) {
                bits::set(&mut finals[a], p);
            }
        }
        let coreach = finals
            .iter()
            .map(|f| {
                let mut seen = f.clone();
                let mut stack: Vec<usize> = bits::ones(f.iter().copied()).collect();
                while let Some(q) = stack.pop() {
                    for &p in &preds[q] {
                        if !bits::get(&seen, p as usize) {
                            bits::set(&mut seen, p as usize);
                            stack.push(p as usize);
                        }
                    }
                }
                seen
            })
            .collect();
        Graph {
            nfa,
            letters,
            shape,
            coreach,
            finals,
        }
    }

    /// The positions of the operands of `q` that must not match, and their finals.
    fn excluded(&self, q: &Conjunct) -> (Vec<u64>, Vec<u64>) {
        let words = if q.must_not.is_empty() {
            0
        } else {
            self.nfa.words()
        };
        let (mut mask, mut finals) = (vec![0u64; words], vec![0u64; words]);
        for &k in &q.must_not {
            for w in 0..words {
                mask[w] |= self.coreach[k][w];
                finals[w] |= self.finals[k][w];
            }
        }
        (mask, finals)
    }

    fn start(&self, q: &Conjunct, mask: &[u64]) -> Node {
        let mut subset = vec![0u64; mask.len()].into_boxed_slice();
        if !subset.is_empty() {
            subset[0] = 1;
        }
        Node {
            runs: vec![0; q.must.len()].into_boxed_slice(),
            shape: 0,
            subset,
        }
    }

    /// Whether a path ending in `n` is a witness of `q`.
    fn is_witness(&self, q: &Conjunct, n: &Node, excluded_finals: &[u64]) -> bool {
        self.shape.accept[n.shape as usize]
            && n.runs
                .iter()
                .zip(&q.must)
                .all(|(&p, &k)| self.nfa.final_aov(p as usize) == Some(k))
            && n.subset
                .iter()
                .zip(excluded_finals)
                .all(|(s, f)| s & f == 0)
    }

    /// The successors of `n` on letter `l`, in a fixed order, each costing one step.
    fn successors(
        &self,
        q: &Conjunct,
        n: &Node,
        l: usize,
        mask: &[u64],
        meter: &mut Meter,
        out: &mut Vec<Node>,
    ) -> Result<(), Undecided> {
        out.clear();
        let (class, place) = self.letters[l];
        let t = self.shape.next[n.shape as usize][place.index()];
        if t == NONE {
            return Ok(());
        }
        let accept = self.nfa.accept_of(class);
        // Each run's successors: its follow set, read by the letter, still able to end
        // its operand.
        let mut choices: Vec<Vec<u32>> = Vec::with_capacity(n.runs.len());
        for (&p, &k) in n.runs.iter().zip(&q.must) {
            let follow = self.nfa.follow_of(p as usize);
            let next: Vec<u32> = bits::ones(
                follow
                    .iter()
                    .zip(accept)
                    .zip(&self.coreach[k])
                    .map(|((f, a), c)| f & a & c),
            )
            .map(|x| x as u32)
            .collect();
            if next.is_empty() {
                return Ok(());
            }
            choices.push(next);
        }
        let subset: Box<[u64]> = if mask.is_empty() {
            Box::new([])
        } else {
            let mut next = vec![0u64; self.nfa.words()];
            self.nfa.step(&n.subset, class, &mut next);
            next.iter_mut().zip(mask).for_each(|(x, m)| *x &= m);
            next.into_boxed_slice()
        };
        // Every combination of the runs' choices, the last run varying fastest.
        let mut at = vec![0usize; choices.len()];
        loop {
            meter.spend(1)?;
            out.push(Node {
                runs: at.iter().zip(&choices).map(|(&i, c)| c[i]).collect(),
                shape: t,
                subset: subset.clone(),
            });
            let mut k = choices.len();
            loop {
                if k == 0 {
                    return Ok(());
                }
                k -= 1;
                at[k] += 1;
                if at[k] < choices[k].len() {
                    break;
                }
                at[k] = 0;
            }
        }
    }

    /// A shortest witness of `q` as letter indices, the first in letter order among the
    /// shortest; `None` if there is none.
    ///
    /// A layer is a list of groups, a group the kept nodes one word reaches (one subset:
    /// the subset depends on the word alone), in the order of their words; a group and
    /// a letter make the next layer's group of the word one letter longer. Nodes are
    /// thus made in the order of their words, shortest first, then in letter order,
    /// which a list of nodes expanded one by one does not give (two nodes of one word,
    /// expanded apart, interleave their continuations).
    pub(super) fn shortest(
        &self,
        q: &Conjunct,
        meter: &mut Meter,
    ) -> Result<Option<Vec<u32>>, Undecided> {
        let (mask, excluded_finals) = self.excluded(q);
        // Kept nodes with their parent and letter.
        let mut nodes: Vec<(Node, u32, u32)> = vec![(self.start(q, &mask), u32::MAX, 0)];
        let mut removed: Vec<bool> = vec![false];
        // Per (runs, shape state), the kept nodes not subsumed by a later one: an
        // antichain of subsets.
        let mut kept: FxMap<(Box<[u32]>, u8), Vec<u32>> = FxMap::default();
        kept.insert((nodes[0].0.runs.clone(), 0), vec![0]);
        let mut layer: Vec<Vec<u32>> = vec![vec![0]];
        let mut reordered = false;
        let mut succ = Vec::new();
        while !layer.is_empty() {
            let first_of_layer = nodes.len() as u32;
            let mut removed_here = false;
            let mut next_layer = Vec::new();
            for group in &layer {
                let members: Vec<(u32, Node)> = group
                    .iter()
                    .filter(|&&id| !removed[id as usize])
                    .map(|&id| (id, nodes[id as usize].0.clone()))
                    .collect();
                for l in 0..self.letters.len() {
                    let mut next_group = Vec::new();
                    for (id, parent) in &members {
                        self.successors(q, parent, l, &mask, meter, &mut succ)?;
                        for n in succ.drain(..) {
                            let key = (n.runs.clone(), n.shape);
                            let list = kept.entry(key).or_default();
                            meter.spend(list.len())?;
                            if list
                                .iter()
                                .any(|&k| subset_of(&nodes[k as usize].0.subset, &n.subset))
                            {
                                continue;
                            }
                            list.retain(|&k| {
                                // Not a subset of `n` (checked above): a strict superset.
                                let sup = subset_of(&n.subset, &nodes[k as usize].0.subset);
                                if sup && k >= first_of_layer {
                                    removed[k as usize] = true;
                                    removed_here = true;
                                }
                                !sup
                            });
                            let new = nodes.len() as u32;
                            list.push(new);
                            let witness = self.is_witness(q, &n, &excluded_finals);
                            nodes.push((n, *id, l as u32));
                            removed.push(false);
                            next_group.push(new);
                            if witness {
                                let mut path = Vec::new();
                                let mut i = new;
                                while nodes[i as usize].1 != u32::MAX {
                                    path.push(nodes[i as usize].2);
                                    i = nodes[i as usize].1;
                                }
                                path.reverse();
                                if !reordered {
                                    return Ok(Some(path));
                                }
                                return Ok(Some(self.first_in_order(q, path, meter)));
                            }
                        }
                    }
                    if !next_group.is_empty() {
                        next_layer.push(next_group);
                    }
                }
            }
            reordered |= removed_here;
            layer = next_layer;
        }
        Ok(None)
    }

    /// The first witness of `q` in letter order of the length of `found` (a witness):
    /// [`Graph::first_of_length`] on at most half the steps left, else `found`.
    fn first_in_order(&self, q: &Conjunct, found: Vec<u32>, meter: &mut Meter) -> Vec<u32> {
        let mut sub = meter.share(meter.left() / 2);
        let first = self.first_of_length(q, found.len(), &mut sub);
        meter.absorb(&sub);
        match first {
            Ok(Some(w)) => w,
            _ => found,
        }
    }

    /// The first witness of `q` of exactly `len` letters in letter order, if any: a
    /// depth-first search in letter order over the groups of nodes one word reaches. A
    /// node that has no witness continuation of `r` more letters is remembered (by runs,
    /// shape state and `r`), and so is, by subsumption, every node with a superset of
    /// its subset.
    pub(super) fn first_of_length(
        &self,
        q: &Conjunct,
        len: usize,
        meter: &mut Meter,
    ) -> Result<Option<Vec<u32>>, Undecided> {
        let (mask, excluded_finals) = self.excluded(q);
        if len == 0 {
            return Ok(None);
        }
        // A frame: the nodes of one word and the next letter to try.
        struct Frame {
            nodes: Vec<Node>,
            next: usize,
        }
        type Failed = FxMap<(Box<[u32]>, u8, usize), Vec<Box<[u64]>>>;
        let mut failed: Failed = FxMap::default();
        let mut succ = Vec::new();
        let mut stack = vec![Frame {
            nodes: vec![self.start(q, &mask)],
            next: 0,
        }];
        let mut path: Vec<u32> = Vec::new();
        while !stack.is_empty() {
            let depth = stack.len();
            let Some(top) = stack.last_mut() else { break };
            if top.next == self.letters.len() {
                // No letter led on: every node of the word fails with `len - depth`
                // letters left.
                if let Some(frame) = stack.pop() {
                    let left = len - stack.len();
                    for n in frame.nodes {
                        let list = failed.entry((n.runs, n.shape, left)).or_default();
                        list.retain(|s| !subset_of(&n.subset, s));
                        list.push(n.subset);
                    }
                }
                path.pop();
                continue;
            }
            let l = top.next;
            top.next += 1;
            let left = len - depth;
            let mut child: Vec<Node> = Vec::new();
            for n in &top.nodes {
                self.successors(q, n, l, &mask, meter, &mut succ)?;
                for c in succ.drain(..) {
                    // One word, one subset: nodes differ by runs and shape state.
                    if child.iter().any(|x| x.runs == c.runs && x.shape == c.shape) {
                        continue;
                    }
                    if let Some(list) = failed.get(&(c.runs.clone(), c.shape, left)) {
                        meter.spend(list.len())?;
                        if list.iter().any(|s| subset_of(s, &c.subset)) {
                            continue;
                        }
                    }
                    child.push(c);
                }
            }
            if child.is_empty() {
                continue;
            }
            if left == 0 {
                if child
                    .iter()
                    .any(|c| self.is_witness(q, c, &excluded_finals))
                {
                    path.push(l as u32);
                    return Ok(Some(path));
                }
                continue;
            }
            path.push(l as u32);
            stack.push(Frame {
                nodes: child,
                next: 0,
            });
        }
        Ok(None)
    }
}

#[cfg(test)]
mod tests {
    use super::super::budget::{AnalysisBudget, Meter};
    use super::super::dnf::Conjunct;
    use super::super::problem::Problem;
    use super::super::search::analysis_options;
    use crate::renderman::{self, RenderMan};

    /// The letter-order search of [`Graph::first_in_order`] gets half the steps left, no
    /// more: given exactly the steps that search takes, it stops at half of them and the
    /// witness it was handed stands, half the steps charged; given twice as many, it
    /// finishes and its own witness replaces the one handed in. Fault caught: `left() /
    /// 2` as `* 2` (the search gets every step left and finishes in the first case).
    #[test]
    fn the_letter_order_search_gets_half_the_steps_left() {
        let aovs = [("a".to_string(), renderman::parse("C<RD>L").unwrap())];
        let problem = Problem::<RenderMan>::new(&aovs, &analysis_options()).unwrap();
        let q = Conjunct {
            must: vec![0],
            must_not: vec![],
        };
        // The steps of the letter-order search for a witness of 3 letters: the camera,
        // a diffuse reflection, a light.
        let plenty = 1 << 20;
        let mut probe = Meter::new(&AnalysisBudget::steps(plenty));
        let first = problem.graph.first_of_length(&q, 3, &mut probe).unwrap();
        let first = first.expect("C<RD>L has paths of 3 vertices");
        let cost = plenty - probe.left();
        assert!(cost >= 2, "{cost}");
        // A stand-in for the breadth-first search's witness, no path at all, so that
        // which of the two comes back shows.
        let handed = vec![u32::MAX; 3];
        let mut meter = Meter::new(&AnalysisBudget::steps(cost));
        assert_eq!(
            problem.graph.first_in_order(&q, handed.clone(), &mut meter),
            handed
        );
        assert_eq!(meter.left(), cost - cost / 2);
        let mut meter = Meter::new(&AnalysisBudget::steps(2 * cost));
        assert_eq!(problem.graph.first_in_order(&q, handed, &mut meter), first);
        assert_eq!(meter.left(), cost);
    }

    /// The failures the letter-order search remembers are keyed by the letters left
    /// after the node: `C<RD>?<RS><TS>L` and `C<RS>?<RD><TS>L` each have one word of 5
    /// vertices with the optional bounce taken, and whichever of `<RD>`, `<RS>` comes
    /// first in letter order, one of the two searches reaches the bounce after the
    /// optional one first after 2 letters (the optional one skipped), where it fails
    /// with 3 left, and then after 3 letters, where the word goes on with 2. Both find their word of 5 and none of 6.
    /// Fault caught: the letters left at a failure as `len / depth` instead of `len -
    /// depth` (a failure with 3 left is taken for one with 2: the word is missed, the
    /// search runs out and, popping its root, divides by zero).
    #[test]
    fn a_failure_is_remembered_with_the_letters_left_after_it() {
        let aovs = [
            (
                "a".to_string(),
                renderman::parse("C<RD>?<RS><TS>L").unwrap(),
            ),
            (
                "b".to_string(),
                renderman::parse("C<RS>?<RD><TS>L").unwrap(),
            ),
        ];
        let problem = Problem::<RenderMan>::new(&aovs, &analysis_options()).unwrap();
        for operand in [0, 1] {
            let q = Conjunct {
                must: vec![operand],
                must_not: vec![],
            };
            let budget = AnalysisBudget::steps(1 << 20);
            let found = |len| {
                problem
                    .graph
                    .first_of_length(&q, len, &mut Meter::new(&budget))
                    .unwrap()
            };
            assert_eq!(found(5).map(|w| w.len()), Some(5), "{operand}");
            assert_eq!(found(6), None, "{operand}");
        }
    }
}
