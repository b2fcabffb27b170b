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

/// Beauty-valued contributions keyed by the final state `K` of their path.
#[derive(Clone, Debug)]
pub(super) struct ByState<K> {
    sums: Vec<(K, DVec3)>,
}

impl<K> Default for ByState<K> {
    fn default() -> Self {
        ByState { sums: Vec::new() }
    }
}

impl<K: Copy + PartialEq> ByState<K> {
    /// Appends `v` for state `k`, keeping the order contributions arrived in.
    #[inline]
    pub(super) fn push(&mut self, k: K, v: DVec3) {
        self.sums.push((k, v));
    }

    /// Adds `v` to state `k`'s sum (a new entry for a state not seen yet). A linear
    /// scan: a pixel's few states beat any hashing.
    #[inline]
    pub(super) fn merge(&mut self, k: K, v: DVec3) {
        match self.sums.iter_mut().find(|(s, _)| *s == k) {
            Some((_, sum)) => *sum += v,
            None => self.sums.push((k, v)),
        }
    }

    /// Adds every entry of `other` into this one by state, and empties `other`.
    pub(super) fn merge_from(&mut self, other: &mut ByState<K>) {
        for (k, v) in other.sums.drain(..) {
            self.merge(k, v);
        }
    }

    pub(super) fn clear(&mut self) {
        self.sums.clear();
    }

    /// Hands each entry's sum to every AOV of `plain` its state matches (`matches`, the
    /// matcher's answer for a state), in entry order then AOV order, and empties the
    /// table.
    pub(super) fn expand(
        &mut self,
        plain: &AovMask,
        matches: impl Fn(K) -> AovMask,
        mut to: impl FnMut(usize, DVec3),
    ) {
        for (k, v) in self.sums.drain(..) {
            for i in matches(k).iter().filter(|&i| plain.contains(i)) {
                to(i, v);
            }
        }
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

    #[test]
    fn merge_sums_per_state_and_expand_routes_each_sum_to_the_plain_aovs_it_matches() {
        let (a, b) = (mask(&[0, 2]), mask(&[1, 2, 3]));
        let mut t = ByState::default();
        t.merge(a, DVec3::splat(1.0));
        t.merge(b, DVec3::splat(10.0));
        t.merge(a, DVec3::splat(2.0));
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
    fn push_keeps_arrival_order_and_merge_from_folds_it_in_by_state() {
        let (a, b) = (mask(&[0]), mask(&[1]));
        let mut sample = ByState::default();
        sample.push(a, DVec3::splat(1.0));
        sample.push(a, DVec3::splat(2.0));
        sample.push(b, DVec3::splat(4.0));
        let mut pixel = ByState::default();
        pixel.merge(b, DVec3::splat(8.0));
        pixel.merge_from(&mut sample);
        assert!(sample.sums.is_empty());
        assert_eq!(
            expanded(&mut pixel, &[0, 1]),
            [(1, DVec3::splat(12.0)), (0, DVec3::splat(3.0))]
        );
        let mut sample = ByState::default();
        sample.push(a, DVec3::splat(1.0));
        sample.push(a, DVec3::splat(2.0));
        assert_eq!(
            expanded(&mut sample, &[0]),
            [(0, DVec3::splat(1.0)), (0, DVec3::splat(2.0))],
            "pushed entries stay apart"
        );
    }
}
