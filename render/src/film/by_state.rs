//! Plain AOVs summed per final matcher state.
//!
//! A plain AOV (no prefix that changes a contribution's value, not `overwrite;`, not
//! `noinfinitecheck;`) receives exactly beauty's value of every contribution whose path
//! it matches, and which AOVs match depends only on the matcher state the path ended in.
//! So the film need not route each contribution into each matching AOV: it sums
//! contributions per final state and expands a state's sum into its AOVs once, when the
//! pixel is done (f64 film) or the sample is (f32 films, which model a renderer adding
//! every sample to an f32 pixel). A pixel's paths end in few distinct states (about 3
//! per 8-sample pixel of the Cornell box with 32 AOVs, against 15 contributions routed
//! into 4 AOVs each), which is what keeps AOV tracking near free.

use glam::DVec3;

use crate::aov::matcher::AovMask;

/// A pixel's beauty-valued contributions with the final state `K` of their path, in
/// arrival order, summed per state when the pixel is done.
///
/// A contribution only appends `(state, value)`; committing a sample only moves a mark;
/// a rejected sample's entries are cut off at that mark. The per-state sums are formed
/// once per pixel, over the committed entries in arrival order, which adds the same
/// values in the same order as summing each committed sample into the state's sum
/// would: the result does not depend on when the merge happens.
#[derive(Clone, Debug)]
pub(super) struct ByState<K> {
    arrivals: Vec<(K, DVec3)>,
    /// `arrivals[..committed]` belong to committed samples, the rest to the sample
    /// being traced.
    committed: usize,
    /// The per-state sums while a pixel is expanded (kept for its allocation).
    sums: Vec<(K, DVec3)>,
}

impl<K> Default for ByState<K> {
    fn default() -> Self {
        ByState {
            arrivals: Vec::new(),
            committed: 0,
            sums: Vec::new(),
        }
    }
}

impl<K: Copy + PartialEq> ByState<K> {
    /// Notes `v` for state `k` in the current sample.
    #[inline]
    pub(super) fn push(&mut self, k: K, v: DVec3) {
        self.arrivals.push((k, v));
    }

    /// The current sample's entries join the pixel.
    #[inline]
    pub(super) fn commit_sample(&mut self) {
        self.committed = self.arrivals.len();
    }

    /// Forgets the current sample's entries (a rejected sample).
    #[inline]
    pub(super) fn drop_sample(&mut self) {
        self.arrivals.truncate(self.committed);
    }

    /// Hands each of the current sample's entries to every AOV of `plain` its state
    /// matches (`matches`, the matcher's answer for a state), in arrival order then AOV
    /// order, and forgets them: the f32 films, which add every sample to the pixel.
    pub(super) fn expand_sample(
        &mut self,
        plain: &AovMask,
        matches: impl Fn(K) -> AovMask,
        mut to: impl FnMut(usize, DVec3),
    ) {
        for &(k, v) in &self.arrivals[self.committed..] {
            for i in (matches(k) & *plain).iter() {
                to(i, v);
            }
        }
        self.drop_sample();
    }

    /// Sums the committed entries per state (states in order of first arrival, each
    /// sum in arrival order), hands each sum to every AOV of `plain` its state matches,
    /// in state order then AOV order, and empties the table.
    pub(super) fn expand(
        &mut self,
        plain: &AovMask,
        matches: impl Fn(K) -> AovMask,
        mut to: impl FnMut(usize, DVec3),
    ) {
        let sums = &mut self.sums;
        for &(k, v) in &self.arrivals[..self.committed] {
            // A linear scan, a pixel's few states beat any hashing; without an early
            // exit, so that which state an entry has costs no mispredicted branch.
            let mut at = sums.len();
            for (j, (s, _)) in sums.iter().enumerate() {
                if *s == k {
                    at = j;
                }
            }
            match sums.get_mut(at) {
                Some((_, sum)) => *sum += v,
                None => sums.push((k, v)),
            }
        }
        for (k, v) in sums.drain(..) {
            for i in (matches(k) & *plain).iter() {
                to(i, v);
            }
        }
        self.arrivals.clear();
        self.committed = 0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// States stand for themselves: state `k` matches the AOVs of the mask `k`.
    fn mask(ids: &[usize]) -> AovMask {
        ids.iter().copied().collect()
    }

    fn expanded(t: &mut ByState<AovMask>, plain: &[usize]) -> Vec<(usize, DVec3)> {
        let mut out = Vec::new();
        t.expand(&mask(plain), |k| k, |i, v| out.push((i, v)));
        out
    }

    fn sample(t: &mut ByState<AovMask>, entries: &[(AovMask, f64)]) {
        for &(k, v) in entries {
            t.push(k, DVec3::splat(v));
        }
    }

    #[test]
    fn expand_sums_per_state_in_arrival_order_and_routes_each_sum_to_its_plain_aovs() {
        let (a, b) = (mask(&[0, 2]), mask(&[1, 2, 3]));
        let mut t = ByState::default();
        sample(&mut t, &[(a, 1.0), (b, 10.0)]);
        t.commit_sample();
        sample(&mut t, &[(a, 2.0)]);
        t.commit_sample();
        // AOV 3 is not plain (routed per contribution elsewhere): it gets nothing here.
        assert_eq!(
            expanded(&mut t, &[0, 1, 2]),
            [
                (0, DVec3::splat(3.0)),
                (2, DVec3::splat(3.0)),
                (1, DVec3::splat(10.0)),
                (2, DVec3::splat(10.0)),
            ]
        );
        assert!(expanded(&mut t, &[0, 1, 2]).is_empty(), "expand empties");
    }

    #[test]
    fn a_dropped_sample_leaves_no_entry_and_uncommitted_entries_are_not_expanded() {
        let (a, b) = (mask(&[0]), mask(&[1]));
        let mut t = ByState::default();
        sample(&mut t, &[(a, 1.0)]);
        t.commit_sample();
        // Rejected: neither its value for a known state nor its new state survive.
        sample(&mut t, &[(a, 100.0), (b, 100.0)]);
        t.drop_sample();
        sample(&mut t, &[(b, 4.0)]);
        t.commit_sample();
        // Traced but never committed: not part of the pixel.
        sample(&mut t, &[(a, 1000.0)]);
        assert_eq!(
            expanded(&mut t, &[0, 1]),
            [(0, DVec3::splat(1.0)), (1, DVec3::splat(4.0))]
        );
    }

    #[test]
    fn sums_add_in_arrival_order() {
        // 1 + 2^-53 + 2^-53 rounds to 1 added left to right (each addition is a tie to
        // even); any other association gives 1 + 2^-52: the pixel's sum must be the
        // one the samples would have built one after the other.
        let a = mask(&[0]);
        let tiny = 2f64.powi(-53);
        let mut t = ByState::default();
        for v in [1.0, tiny, tiny] {
            sample(&mut t, &[(a, v)]);
            t.commit_sample();
        }
        assert_eq!(expanded(&mut t, &[0]), [(0, DVec3::splat(1.0))]);
    }

    #[test]
    fn expand_sample_routes_only_the_current_sample_entry_by_entry() {
        let (a, b) = (mask(&[0]), mask(&[0, 1]));
        let mut t = ByState::default();
        sample(&mut t, &[(a, 1.0), (b, 2.0), (a, 4.0)]);
        let mut out = Vec::new();
        t.expand_sample(&mask(&[0, 1]), |k| k, |i, v| out.push((i, v)));
        assert_eq!(
            out,
            [
                (0, DVec3::splat(1.0)),
                (0, DVec3::splat(2.0)),
                (1, DVec3::splat(2.0)),
                (0, DVec3::splat(4.0)),
            ],
            "entries stay apart, in arrival order"
        );
        assert!(
            expanded(&mut t, &[0, 1]).is_empty(),
            "expand_sample forgets them"
        );
    }
}
