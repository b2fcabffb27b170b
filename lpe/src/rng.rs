//! SplitMix64 (Steele, Lea, Flood 2014): the one small deterministic generator the
//! workspace shares. Same seed, same sequence, on every platform, which the generators'
//! and tests' seeds rely on. Not for cryptography.

/// The SplitMix64 generator: a 64-bit counter stepped by the golden ratio, each value
/// passed through [`SplitMix64::mix`].
#[derive(Clone, Debug)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// The counter increment: 2^64 divided by the golden ratio, made odd.
    pub const GOLDEN_GAMMA: u64 = 0x9E37_79B9_7F4A_7C15;

    /// A generator for `seed`.
    pub fn new(seed: u64) -> SplitMix64 {
        SplitMix64(seed)
    }

    /// The next 64 random bits.
    #[inline]
    pub fn next_u64(&mut self) -> u64 {
        let z = Self::mix(self.0);
        self.0 = self.0.wrapping_add(Self::GOLDEN_GAMMA);
        z
    }

    /// A uniform index in `0..n` (0 when `n` is 0), by multiply-high: no division, and a
    /// bias of at most `n / 2^64`.
    #[inline]
    pub fn below(&mut self, n: usize) -> usize {
        ((u128::from(self.next_u64()) * n.max(1) as u128) >> 64) as usize
    }

    /// The output a generator seeded with `z` gives first: a bijective avalanche mix of
    /// 64 bits, also useful alone to derive independent seeds from counters.
    #[inline]
    pub fn mix(z: u64) -> u64 {
        let mut z = z.wrapping_add(Self::GOLDEN_GAMMA);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matches_the_published_sequence() {
        // The reference implementation's first outputs for seed 0 (as in the Java
        // SplittableRandom and the xoshiro authors' splitmix64.c).
        let mut r = SplitMix64::new(0);
        assert_eq!(r.next_u64(), 0xE220_A839_7B1D_CDAF);
        assert_eq!(r.next_u64(), 0x6E78_9E6A_A1B9_65F4);
        assert_eq!(r.next_u64(), 0x06C4_5D18_8009_454F);
        assert_eq!(SplitMix64::mix(0), 0xE220_A839_7B1D_CDAF);
    }

    #[test]
    fn below_stays_in_range() {
        let mut r = SplitMix64::new(7);
        assert!((0..1000).all(|_| r.below(13) < 13));
        assert_eq!(r.below(0), 0);
    }
}
