//! Sampling routines and the shading frame.

use glam::{Vec2, Vec3};
use std::f32::consts::PI;

/// An orthonormal basis around a normal, for working in a local frame where `n = +z`.
#[derive(Clone, Copy, Debug)]
pub struct Frame {
    pub s: Vec3,
    pub t: Vec3,
    pub n: Vec3,
}

impl Frame {
    /// Duff et al. 2017, "Building an Orthonormal Basis, Revisited": branchless and
    /// continuous except at one pole.
    pub fn from_normal(n: Vec3) -> Frame {
        let sign = 1.0f32.copysign(n.z);
        let a = -1.0 / (sign + n.z);
        let b = n.x * n.y * a;
        Frame {
            s: Vec3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x),
            t: Vec3::new(b, sign + n.y * n.y * a, -n.y),
            n,
        }
    }

    pub fn to_local(&self, v: Vec3) -> Vec3 {
        Vec3::new(v.dot(self.s), v.dot(self.t), v.dot(self.n))
    }

    pub fn to_world(&self, v: Vec3) -> Vec3 {
        self.s * v.x + self.t * v.y + self.n * v.z
    }
}

/// Cosine-weighted direction on the `+z` hemisphere; pdf `cos(theta) / pi`.
pub fn cosine_hemisphere(u: Vec2) -> Vec3 {
    let r = u.x.sqrt();
    let phi = 2.0 * PI * u.y;
    Vec3::new(r * phi.cos(), r * phi.sin(), (1.0 - u.x).max(0.0).sqrt())
}

/// Uniform direction on the unit sphere; pdf `1 / (4 pi)`.
pub fn uniform_sphere(u: Vec2) -> Vec3 {
    let z = 1.0 - 2.0 * u.x;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = 2.0 * PI * u.y;
    Vec3::new(r * phi.cos(), r * phi.sin(), z)
}

/// Uniform direction in the cone of half-angle `theta_max` around `+z`, given
/// `one_minus_cos_max = 1 - cos(theta_max)` (see [`one_minus_cos_from_sin2`]); pdf
/// `1 / (2 pi one_minus_cos_max)`. Works in `1 - cos` throughout: a cone of 1e-6 rad has
/// `cos = 1` in f32, and `sin = sqrt(1 - cos^2)` would put every sample on the axis.
pub fn uniform_cone(u: Vec2, one_minus_cos_max: f32) -> Vec3 {
    let one_minus_cos = u.x * one_minus_cos_max;
    let cos = 1.0 - one_minus_cos;
    let sin = (one_minus_cos * (2.0 - one_minus_cos)).max(0.0).sqrt();
    let phi = 2.0 * PI * u.y;
    Vec3::new(sin * phi.cos(), sin * phi.sin(), cos)
}

/// `1 - cos(theta)` from `sin^2(theta)` for `theta <= pi/2`, without cancellation:
/// `sin^2 / (1 + cos)`, which is `sin^2 / 2` to f32 precision for tiny angles.
pub fn one_minus_cos_from_sin2(sin2: f32) -> f32 {
    let sin2 = sin2.clamp(0.0, 1.0);
    sin2 / (1.0 + (1.0 - sin2).sqrt())
}

/// Veach's power heuristic (beta = 2) for strategy `a` against `b`. Written as
/// `1 / (1 + (b/a)^2)` so huge pdfs do not overflow; a zero or non-finite `a` weighs 0
/// unless `b` is zero too.
pub fn power_heuristic(a: f32, b: f32) -> f32 {
    if !(a > 0.0) {
        return if b > 0.0 { 0.0 } else { 1.0 };
    }
    if a.is_infinite() {
        // Two infinite densities (two delta-like strategies) share the weight.
        return if b.is_infinite() { 0.5 } else { 1.0 };
    }
    let r = b / a;
    1.0 / (1.0 + r * r)
}

/// Largest component: Russian roulette and clamping act on it.
pub fn max_component(v: Vec3) -> f32 {
    v.x.max(v.y).max(v.z)
}

/// Rec. 709 luminance.
pub fn luminance(v: Vec3) -> f32 {
    0.2126 * v.x + 0.7152 * v.y + 0.0722 * v.z
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_is_orthonormal() {
        for n in [
            Vec3::Z,
            -Vec3::Z,
            Vec3::new(1.0, 2.0, -3.0).normalize(),
            Vec3::X,
        ] {
            let f = Frame::from_normal(n);
            assert!(f.s.dot(f.t).abs() < 1e-6 && f.s.dot(n).abs() < 1e-6);
            assert!((f.s.length() - 1.0).abs() < 1e-6 && (f.t.length() - 1.0).abs() < 1e-6);
            let v = Vec3::new(0.3, -0.2, 0.9);
            assert!((f.to_local(f.to_world(v)) - v).length() < 1e-5);
        }
    }

    #[test]
    fn power_heuristic_weights_sum_to_one() {
        for (a, b) in [(1.0, 2.0), (1e-30, 1e30), (3.0, 0.0), (0.5, 0.5)] {
            let s = power_heuristic(a, b) + power_heuristic(b, a);
            assert!((s - 1.0).abs() < 1e-6, "{a} {b}: {s}");
        }
    }
}
