//! The film: per-pixel sums for beauty and every AOV, in f64.
//!
//! f64 accumulation keeps `sum of 10^7 samples of mixed magnitude` within about 1e-9
//! relative of the exact sum, far inside the 1e-5 partition tolerance (f32 would drift by
//! ~1e-3 at that count). Issue 6 compares against f32 and compensated sums; the
//! accumulation is isolated here ([`PixelSums`]) so another accumulator can replace it.

use glam::DVec3;

/// How a film adds samples into its pixel sums (issue 6 compares them).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub enum Accumulation {
    /// f64 sums: the renderer's film.
    #[default]
    F64,
    /// A naive f32 film: every running sum is rounded to f32 after each addition (stored
    /// in the f64 buffer, where an f32 value is exact), to show what f64 buys.
    F32,
}

impl Accumulation {
    /// `sum + x` as this film stores it.
    #[inline]
    pub fn add(self, sum: DVec3, x: DVec3) -> DVec3 {
        match self {
            Accumulation::F64 => sum + x,
            Accumulation::F32 => (sum.as_vec3() + x.as_vec3()).as_dvec3(),
        }
    }
}

/// Sums for one pixel: layer 0 is beauty, layer `1 + i` is AOV `i`.
pub type PixelSums = [DVec3];

/// Accumulated samples for an image.
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    pub width: usize,
    pub height: usize,
    pub spp: u32,
    /// `1 + number of AOVs`.
    pub layers: usize,
    /// Pixel-major: pixel `(x, y)` holds `layers` consecutive sums.
    pub(crate) data: Vec<DVec3>,
    /// AOVs whose pixel holds the last value written, not a sum (`overwrite;`).
    pub(crate) overwrite: Vec<bool>,
    /// Samples rejected for beauty and every AOV because light transport was not finite.
    pub rejected: u64,
    /// AOV-only values (unoccluded, shadows, nothruput) dropped as non-finite.
    pub aov_rejected: u64,
}

impl Film {
    pub fn new(width: usize, height: usize, spp: u32, overwrite: Vec<bool>) -> Film {
        let layers = overwrite.len() + 1;
        Film {
            width,
            height,
            spp,
            layers,
            data: vec![DVec3::ZERO; width * height * layers],
            overwrite,
            rejected: 0,
            aov_rejected: 0,
        }
    }

    /// The estimate at pixel `(x, y)` of `layer` (0 = beauty, `1 + i` = AOV `i`): the
    /// mean over all samples (rejected samples count as zero), or the last value for
    /// `overwrite;` AOVs.
    pub fn pixel(&self, x: usize, y: usize, layer: usize) -> DVec3 {
        let s = self.data[(y * self.width + x) * self.layers + layer];
        if layer > 0 && self.overwrite[layer - 1] {
            s
        } else {
            s / self.spp as f64
        }
    }

    /// A whole layer, row-major.
    pub fn layer(&self, layer: usize) -> Vec<DVec3> {
        (0..self.height)
            .flat_map(|y| (0..self.width).map(move |x| (x, y)))
            .map(|(x, y)| self.pixel(x, y, layer))
            .collect()
    }

    /// Bitwise equality of one layer with another film's (determinism checks).
    pub fn layer_bits_equal(&self, layer: usize, other: &Film, other_layer: usize) -> bool {
        self.width == other.width
            && self.height == other.height
            && (0..self.width * self.height).all(|p| {
                let a = self.data[p * self.layers + layer];
                let b = other.data[p * other.layers + other_layer];
                a.to_array().map(f64::to_bits) == b.to_array().map(f64::to_bits)
            })
    }
}
