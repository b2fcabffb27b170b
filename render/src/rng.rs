//! Deterministic random numbers, seeded per pixel and per sample (pbrt-v4 style).
//!
//! Every camera sample owns an independent stream derived by hashing `(seed, pixel,
//! sample)`, so an image does not depend on how rows are scheduled across threads, and a
//! path that stops early (Russian roulette, a dead matcher state) cannot shift the random
//! numbers of any other sample.

/// PCG32 (O'Neill): small state, good statistical quality, fast.
#[derive(Clone, Debug)]
pub struct Rng {
    state: u64,
    inc: u64,
}

/// The workspace's SplitMix64 finaliser: a bijective avalanche mix that derives each
/// sample's stream seed from `(seed, pixel, sample)`.
fn mix64(z: u64) -> u64 {
    lpe::rng::SplitMix64::mix(z)
}

impl Rng {
    const MULT: u64 = 6_364_136_223_846_793_005;

    /// The stream of sample `sample` of pixel `pixel` for the render seed `seed`.
    pub fn for_sample(seed: u64, pixel: u64, sample: u64) -> Rng {
        let a = mix64(seed ^ mix64(pixel.wrapping_mul(0xD1B5_4A32_D192_ED03)));
        let b = mix64(a ^ mix64(sample.wrapping_add(0x8CB9_2BA7_2F3D_8DD7)));
        let mut r = Rng {
            state: 0,
            inc: (mix64(b ^ 0x5851_F42D_4C95_7F2D) << 1) | 1,
        };
        r.next_u32();
        r.state = r.state.wrapping_add(b);
        r.next_u32();
        r
    }

    /// The next 32 random bits.
    pub fn next_u32(&mut self) -> u32 {
        let old = self.state;
        self.state = old.wrapping_mul(Self::MULT).wrapping_add(self.inc);
        let xorshifted = (((old >> 18) ^ old) >> 27) as u32;
        let rot = (old >> 59) as u32;
        xorshifted.rotate_right(rot)
    }

    /// Uniform in `[0, 1)`: 24 random mantissa bits, so 1.0 is never returned.
    pub fn f32(&mut self) -> f32 {
        (self.next_u32() >> 8) as f32 * (1.0 / (1u32 << 24) as f32)
    }

    /// Two uniforms in `[0, 1)`.
    pub fn vec2(&mut self) -> glam::Vec2 {
        let x = self.f32();
        glam::Vec2::new(x, self.f32())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn streams_differ_and_repeat() {
        let a: Vec<u32> = (0..4)
            .map({
                let mut r = Rng::for_sample(1, 2, 3);
                move |_| r.next_u32()
            })
            .collect();
        let mut again = Rng::for_sample(1, 2, 3);
        assert!(a.iter().all(|&x| x == again.next_u32()));
        let mut other = Rng::for_sample(1, 2, 4);
        assert_ne!(a[0], other.next_u32());
    }

    #[test]
    fn uniform_mean_is_a_half() {
        // Mean of n uniforms has standard deviation 1/sqrt(12 n); 6 sigma is a safe bound.
        let n = 100_000;
        let mut r = Rng::for_sample(7, 0, 0);
        let mean: f64 = (0..n).map(|_| r.f32() as f64).sum::<f64>() / n as f64;
        let sigma = (1.0 / (12.0 * n as f64)).sqrt();
        assert!((mean - 0.5).abs() < 6.0 * sigma, "mean {mean}");
    }
}
