//! Where every generator's decisions come from: [`Choices`], over a seeded
//! [`SplitMix64`] (deterministic runs, e.g. `lpe-check diff --seed`) or a fuzzer's
//! `arbitrary::Unstructured` (so a fuzzer's mutations steer the structure, and an
//! exhausted input still yields a small, valid value).

use lpe::rng::SplitMix64;

/// A source of decisions.
pub trait Choices {
    /// A number in `0..n`; `n >= 1`. Never fails: a source that runs dry answers 0.
    fn below(&mut self, n: usize) -> usize;

    /// True with probability `percent`/100.
    fn chance(&mut self, percent: usize) -> bool {
        self.below(100) < percent
    }

    /// One element of a non-empty slice.
    fn pick<'s, T>(&mut self, xs: &'s [T]) -> &'s T {
        &xs[self.below(xs.len())]
    }
}

impl Choices for SplitMix64 {
    fn below(&mut self, n: usize) -> usize {
        SplitMix64::below(self, n)
    }
}

impl Choices for arbitrary::Unstructured<'_> {
    fn below(&mut self, n: usize) -> usize {
        if n <= 1 {
            return 0;
        }
        self.int_in_range(0..=n - 1).unwrap_or(0)
    }
}
