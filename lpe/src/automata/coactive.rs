//! Positions that are always active together, found so that the NFA can keep one of each.
//!
//! In a Glushkov automaton a position is active after a vertex exactly when its atom
//! accepts the vertex's class and one of its predecessors was active before. Two
//! positions with the same atom and the same predecessors are therefore active together
//! on every path, and more generally so are the positions of a block of a partition in
//! which every block's positions share an atom and have predecessors in the same blocks
//! (a backward bisimulation; by induction on the path length, with the start alone in
//! its block). Many AOVs of one set begin alike (`C<RD>…` in every diffuse AOV,
//! `C<RS>…` in every specular one), so merging such positions often halves the NFA, and
//! the bitset step's cost grows with the state's words.
//!
//! The coarsest such partition comes from refining: start from the blocks of equal keys,
//! split each block by the set of blocks its positions' predecessors lie in, repeat until
//! no block splits. Positions always active together are first active after the same
//! number of vertices, so the start's partition also splits by that depth: the result is
//! the same, and a chain (`C.{250}L`), which would otherwise split one position a round,
//! is stable at once.

use std::hash::Hash;

use crate::fxhash::FxMap;

/// The block of each position in the coarsest partition where positions of a block have
/// equal `key`s and predecessors (`preds`) in the same blocks; blocks numbered in the
/// order of their first position. Position 0 is the start (alone at depth 0). `None`
/// when refining would visit more than `budget` positions and predecessor edges, summed
/// over its rounds (then no merging: one block per position is always sound).
///
/// The caller keys each position by what must not merge (its atom, the AOV it ends);
/// a position whose key no other has stays alone.
pub(crate) fn co_active_blocks<K: Hash + Eq + Copy>(
    key: &[K],
    preds: &[Vec<u32>],
    budget: usize,
) -> Option<Vec<u32>> {
    let n = key.len();
    let edges: usize = preds.iter().map(Vec::len).sum();
    let depth = depths(preds);
    let mut ids: FxMap<(K, u32), u32> = FxMap::default();
    let mut block: Vec<u32> = key
        .iter()
        .zip(&depth)
        .map(|(&k, &d)| {
            let next = ids.len() as u32;
            *ids.entry((k, d)).or_insert(next)
        })
        .collect();
    let mut count = ids.len();
    let mut spent = 0usize;
    // Each round's signatures, one after another (`bounds[p]..bounds[p + 1]` is
    // position `p`'s), so that the round's map borrows them instead of owning a copy each.
    let mut signatures: Vec<u32> = Vec::with_capacity(edges);
    let mut bounds: Vec<usize> = Vec::with_capacity(n + 1);
    loop {
        // A round reads every position and edge once (and counts one more, so that
        // rounds end even on nothing); the rounds are at most one per block.
        spent = spent.saturating_add(n + edges + 1);
        if spent > budget {
            return None;
        }
        signatures.clear();
        bounds.clear();
        bounds.push(0);
        for ps in preds {
            let start = signatures.len();
            signatures.extend(ps.iter().map(|&q| block[q as usize]));
            let sig = &mut signatures[start..];
            sig.sort_unstable();
            let len = dedup_sorted(sig);
            signatures.truncate(start + len);
            bounds.push(signatures.len());
        }
        let mut ids: FxMap<(u32, &[u32]), u32> = FxMap::default();
        let next: Vec<u32> = (0..n)
            .map(|p| {
                let fresh = ids.len() as u32;
                let sig = &signatures[bounds[p]..bounds[p + 1]];
                *ids.entry((block[p], sig)).or_insert(fresh)
            })
            .collect();
        // The new partition refines the old (a block is part of the signature), so an
        // unchanged count means an unchanged partition: every block is stable.
        let stable = ids.len() == count;
        count = ids.len();
        drop(ids);
        block = next;
        if stable {
            return Some(block);
        }
    }
}

/// Moves the distinct values of sorted `xs` to its front; returns how many there are.
fn dedup_sorted(xs: &mut [u32]) -> usize {
    let mut len = 0;
    for i in 0..xs.len() {
        if len == 0 || xs[len - 1] != xs[i] {
            xs[len] = xs[i];
            len += 1;
        }
    }
    len
}

/// Per position, the fewest steps from position 0 to it (`u32::MAX` if none), by a
/// breadth-first search over the edges `preds` lists.
fn depths(preds: &[Vec<u32>]) -> Vec<u32> {
    let n = preds.len();
    let mut succs = vec![Vec::new(); n];
    for (q, ps) in preds.iter().enumerate() {
        for &p in ps {
            succs[p as usize].push(q as u32);
        }
    }
    let mut depth = vec![u32::MAX; n];
    let mut queue = std::collections::VecDeque::new();
    if n > 0 {
        depth[0] = 0;
        queue.push_back(0u32);
    }
    while let Some(p) = queue.pop_front() {
        for &q in &succs[p as usize] {
            if depth[q as usize] == u32::MAX {
                depth[q as usize] = depth[p as usize] + 1;
                queue.push_back(q);
            }
        }
    }
    depth
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Enough for every case below, and finite, so that a refinement that never saw
    /// itself stable would fail rather than loop.
    const BUDGET: usize = 1 << 20;

    /// Preds lists from an edge list over `n` positions.
    fn preds(n: usize, edges: &[(u32, u32)]) -> Vec<Vec<u32>> {
        let mut p = vec![Vec::new(); n];
        for &(from, to) in edges {
            p[to as usize].push(from);
        }
        p
    }

    #[test]
    fn equal_prefixes_merge_and_different_ones_do_not() {
        // 0 -> 1(a) -> 2(b) and 0 -> 3(a) -> 4(b): the two branches merge pairwise;
        // 0 -> 5(a) -> 6(c): 5 joins them, 6 (another atom) stays alone.
        let key = [9, 1, 2, 1, 2, 1, 3];
        let p = preds(7, &[(0, 1), (1, 2), (0, 3), (3, 4), (0, 5), (5, 6)]);
        assert_eq!(
            co_active_blocks(&key, &p, BUDGET),
            Some(vec![0, 1, 2, 1, 2, 1, 3])
        );
    }

    #[test]
    fn a_shared_atom_after_different_predecessors_stays_apart() {
        // 1(a) and 2(b) after the start, then 3(c) after 1 and 4(c) after 2: 3 and 4
        // read the same atom but are active after different vertices.
        let key = [9, 1, 2, 3, 3];
        let p = preds(5, &[(0, 1), (0, 2), (1, 3), (2, 4)]);
        assert_eq!(
            co_active_blocks(&key, &p, BUDGET),
            Some(vec![0, 1, 2, 3, 4])
        );
    }

    #[test]
    fn loops_merge_when_they_loop_alike() {
        // Two copies of `a b*`: 1(a) -> 2(b) -> 2 and 3(a) -> 4(b) -> 4. Each loop's only
        // outside predecessor is a merged `a`, so the coarsest partition merges the
        // loops too (the least one, growing merges from single positions, would not).
        let key = [9, 1, 2, 1, 2];
        let p = preds(5, &[(0, 1), (1, 2), (2, 2), (0, 3), (3, 4), (4, 4)]);
        assert_eq!(
            co_active_blocks(&key, &p, BUDGET),
            Some(vec![0, 1, 2, 1, 2])
        );
    }

    #[test]
    fn a_chain_is_told_apart_by_depth_at_once() {
        // 0 -> 1 -> 2 -> ... -> 9, all the same atom: every position is alone, and the
        // depths say so before any round (without them, one position split a round).
        let n = 10;
        let key: Vec<u64> = (0..n).map(|p| u64::from(p > 0)).collect();
        let p = preds(n, &(1..n as u32).map(|q| (q - 1, q)).collect::<Vec<_>>());
        // Ten positions, nine edges and one a round, one round to confirm: 20.
        assert!(co_active_blocks(&key, &p, 20).is_some());
        assert_eq!(co_active_blocks(&key, &p, 19), None);
        let alone: Vec<u32> = (0..n as u32).collect();
        assert_eq!(co_active_blocks(&key, &p, BUDGET), Some(alone));
    }

    #[test]
    fn no_positions_make_no_blocks() {
        assert_eq!(co_active_blocks::<u64>(&[], &[], BUDGET), Some(vec![]));
        assert_eq!(co_active_blocks::<u64>(&[], &[], 0), None);
        assert_eq!(depths(&[]), Vec::<u32>::new());
    }

    #[test]
    fn refinement_splits_what_depth_does_not() {
        // 1(a) and 2(b) after the start, then 3(c) after 1 and 4(c) after 2, then 5(d)
        // after 3 and 6(d) after 4: 3 and 4 share key and depth but not predecessors,
        // and 5 and 6 split only once 3 and 4 have (a second round, then one to confirm).
        let key = [9, 1, 2, 3, 3, 4, 4];
        let p = preds(7, &[(0, 1), (0, 2), (1, 3), (2, 4), (3, 5), (4, 6)]);
        // Seven positions, six edges and one a round, three rounds: 42.
        assert!(co_active_blocks(&key, &p, 42).is_some());
        assert_eq!(co_active_blocks(&key, &p, 41), None);
        let alone: Vec<u32> = (0..7).collect();
        assert_eq!(co_active_blocks(&key, &p, BUDGET), Some(alone));
    }

    #[test]
    fn depth_is_the_fewest_steps_from_the_start() {
        // 0 -> 1 -> 2 -> 3 and 0 -> 3, 3 -> 3, and 4 unreachable.
        let p = preds(5, &[(0, 1), (1, 2), (2, 3), (0, 3), (3, 3)]);
        assert_eq!(depths(&p), [0, 1, 2, 1, u32::MAX]);
    }
}
