//! Does a lobe sample directions with the density its `eval` reports? Pearson's
//! chi-square test over a grid on the sphere, as in pbrt-v4's and Mitsuba's BSDF tests:
//! histogram many sampled directions, integrate the reported pdf over each cell for the
//! expected counts, pool cells expecting fewer than 5, and reject at significance
//! `alpha` (callers Sidak-correct it for the number of tests they run).
//!
//! Two grids share the histogram, quadrature and statistic:
//!
//! - [`SphereGrid`]: equal-area cells in `(cos theta, phi)` around the normal. Fine for
//!   diffuse lobes and GGX down to alpha ~0.05; below that a lobe falls into a handful of
//!   cells and the test sees nothing.
//! - [`HalfVectorGrid`]: cells in the half vector `h = normalize(wo + wi)` of a
//!   reflection, with the polar angle warped by the roughness (`s = tan^2 / (tan^2 +
//!   alpha^2)`, the GGX CDF) so the lobe covers every radial bin at any alpha. It is used
//!   instead of a grid around the mirror direction because at grazing incidence the
//!   reflected lobe collapses to a curve (the out-of-plane width scales with `cos theta_o`,
//!   1e-6), which no azimuthal binning around the mirror direction resolves, while in `h`
//!   it is the same disk at every angle of incidence. Rows are clipped analytically to the
//!   directions above the surface, so no quadrature node straddles the pdf's jump there.
//!
//! The honest limit is the f32 direction. Next to the mirror direction `r`, each
//! component `r_k` of a sampled direction is quantized to `ulp(r_k)`, an angular step of
//! `ulp(r_k) sqrt(1 - r_k^2)` ([`f32_lattice`]): ~3e-8 at `cos theta_o` 0.9, ~1e-13 at
//! grazing (the large component is ~1 and moves the direction by only `1e-6 ulp`), ~0 at
//! normal incidence (the tangential components are tiny and exact). A lobe a few lattice
//! steps wide is a lattice, not a density, and a test resolving it rejects correctly but
//! uselessly; [`resolvable`] accepts a case when alpha spans at least
//! [`LATTICE_MARGIN`] steps.

use glam::{DVec3, Vec2, Vec3};
use std::f64::consts::PI;

use super::stats::chi2_sf;
use crate::material::Lobe;
use crate::rng::Rng;

/// Cells in `cos(theta)` (equal area) and in `phi`.
pub const COS_BINS: usize = 20;
pub const PHI_BINS: usize = 40;
/// Simpson subintervals per cell and axis for the expected counts: 16 leave a quadrature
/// error that a GGX lobe of alpha 0.05 at grazing incidence already shows as a false
/// rejection (p ~ 0 with 400k samples); 64 do not.
const QUAD: usize = 64;
/// Lattice steps a lobe's alpha must span to be tested (see the module docs). Measured
/// with 400k samples on the half-vector grid, the lattice alone starts failing tests
/// around 100-200 steps: alpha 1e-6 at `cos theta_o` 0.9 (37 steps) gives p = 0, at 0.1
/// (135 steps) p = 1e-7, alpha 1e-5 at 0.5 (194 steps) p = 0.02, while 373 steps (1e-5 at
/// 0.9) and 860 (1e-7 at 1e-3) give p 0.1 and 0.16. 1000 leaves a factor 5.
pub const LATTICE_MARGIN: f64 = 1000.0;

/// A parametrization of (part of) the sphere of directions by `(u, v)` in `[0, 1)^2`,
/// cut into a uniform grid of cells.
pub trait Grid {
    /// Cells along `u` and along `v`.
    fn bins(&self) -> (usize, usize);
    /// The grid coordinates of a sampled direction; `None` where the pdf is zero by
    /// construction (a sample there is a disagreement between sampler and pdf).
    fn locate(&self, w: Vec3) -> Option<(f64, f64)>;
    /// The direction at `(u, v)` and the solid angle per unit `du dv` there.
    fn point(&self, u: f64, v: f64) -> (DVec3, f64);
    /// Values of `u` across which a row's integrand is not smooth: the quadrature splits
    /// cells there.
    fn breaks(&self) -> Vec<f64> {
        Vec::new()
    }
    /// The part `[lo, hi]` of row `u` where the pdf may be nonzero (`None`: nowhere); the
    /// quadrature integrates over it only, so the jump at its ends is never straddled.
    fn row(&self, _u: f64) -> Option<(f64, f64)> {
        Some((0.0, 1.0))
    }
}

/// The whole sphere in `(cos theta, phi)` around the normal: `u = (cos + 1) / 2`,
/// `v = phi / 2 pi`; the horizon is the cell edge `u = 1/2`.
pub struct SphereGrid;

impl Grid for SphereGrid {
    fn bins(&self) -> (usize, usize) {
        (COS_BINS, PHI_BINS)
    }

    fn locate(&self, w: Vec3) -> Option<(f64, f64)> {
        let w = w.as_dvec3().normalize();
        let phi = w.y.atan2(w.x).rem_euclid(2.0 * PI);
        Some(((w.z + 1.0) * 0.5, phi / (2.0 * PI)))
    }

    fn point(&self, u: f64, v: f64) -> (DVec3, f64) {
        let c = 2.0 * u - 1.0;
        let s = (1.0 - c * c).max(0.0).sqrt();
        let p = 2.0 * PI * v;
        (DVec3::new(s * p.cos(), s * p.sin(), c), 4.0 * PI)
    }

    fn breaks(&self) -> Vec<f64> {
        vec![0.5]
    }
}

/// Reflections of `wo` (for reflection lobes only) parametrized by their half vector
/// `h`, on `wo`'s side of the surface: `u = s = tan^2 theta_h / (tan^2 theta_h +
/// alpha^2)`, `v` = the azimuth of `h` measured from `wo`'s tangential direction, shifted
/// by `pi` so the part of a row that reflects above the surface is one interval centred
/// on `v = 1/2`.
///
/// In these coordinates a GGX lobe of roughness `alpha` sampled from `D cos theta_h` is
/// uniform (`h`'s solid angle per `ds dphi` is `1 / (2 pi D cos theta_h)`), masked where the
/// reflection goes below the surface: a row at `theta_h` reflects above it where
/// `cos phi > -(cos theta_o / sin theta_o) cot 2 theta_h`.
pub struct HalfVectorGrid {
    wo: DVec3,
    alpha: f64,
    /// The normal on `wo`'s side, and `wo`'s tangential direction and its complement.
    n: DVec3,
    t1: DVec3,
    t2: DVec3,
    /// `cos theta_o` (> 0) and `sin theta_o` (>= 0).
    cos_o: f64,
    sin_o: f64,
}

impl HalfVectorGrid {
    /// `wo` must not lie in the surface (`wo.z != 0`).
    pub fn new(wo: Vec3, alpha: f32) -> HalfVectorGrid {
        let wo = wo.as_dvec3().normalize();
        let n = DVec3::Z * wo.z.signum();
        let tangential = wo - wo.dot(n) * n;
        let sin_o = tangential.length();
        let t1 = if sin_o > 0.0 {
            tangential / sin_o
        } else {
            DVec3::X
        };
        HalfVectorGrid {
            wo,
            alpha: alpha as f64,
            n,
            t1,
            t2: n.cross(t1),
            cos_o: wo.dot(n),
            sin_o,
        }
    }

    /// `tan theta_h` of row `s`.
    fn tan(&self, s: f64) -> f64 {
        self.alpha * (s / (1.0 - s)).sqrt()
    }

    fn s_of_tan(&self, t: f64) -> f64 {
        t * t / (t * t + self.alpha * self.alpha)
    }
}

impl Grid for HalfVectorGrid {
    fn bins(&self) -> (usize, usize) {
        (COS_BINS, PHI_BINS)
    }

    fn locate(&self, w: Vec3) -> Option<(f64, f64)> {
        let w = w.as_dvec3().normalize();
        if w.dot(self.n) <= 0.0 {
            return None;
        }
        // Both unit in f64: at grazing the in-plane part of `h` is ~1e-13 and only
        // survives the sum because neither direction is left at f32 length.
        let h = self.wo + w;
        let (hn, h1, h2) = (h.dot(self.n), h.dot(self.t1), h.dot(self.t2));
        let t2 = h1 * h1 + h2 * h2;
        let s = t2 / (t2 + self.alpha * self.alpha * hn * hn);
        let v = (h2.atan2(h1) + PI) / (2.0 * PI);
        Some((s, v))
    }

    fn point(&self, s: f64, v: f64) -> (DVec3, f64) {
        let t = self.tan(s);
        let phi = 2.0 * PI * v - PI;
        let h = (self.n + t * (phi.cos() * self.t1 + phi.sin() * self.t2)).normalize();
        let wo_h = self.wo.dot(h);
        let wi = 2.0 * wo_h * h - self.wo;
        // d omega_h / (ds dphi) from tan^2 = alpha^2 s / (1 - s), times the reflection's
        // d omega_i / d omega_h = 4 (wo.h) and d phi / dv = 2 pi.
        let a2 = self.alpha * self.alpha;
        let d_omega_h = a2 / (2.0 * (1.0 - s).sqrt() * ((1.0 - s) + a2 * s).powf(1.5));
        (wi, 2.0 * PI * d_omega_h * 4.0 * wo_h)
    }

    fn breaks(&self) -> Vec<f64> {
        // Where a row starts to be cut by the horizon (`tan theta_h` solving
        // `(cos_o / sin_o) cot 2 theta_h = 1`) and where it is gone (`= -1`), written
        // without cancellation.
        let (a, b) = (self.cos_o, self.sin_o);
        let r = (a * a + b * b).sqrt();
        vec![self.s_of_tan(a / (r + b)), self.s_of_tan((b + r) / a)]
    }

    fn row(&self, s: f64) -> Option<(f64, f64)> {
        let t = self.tan(s);
        // cot 2 theta_h = (1 - tan^2) / (2 tan).
        let cot2 = (1.0 - t * t) / (2.0 * t);
        let bound = if self.sin_o > 0.0 {
            -self.cos_o / self.sin_o * cot2
        } else if cot2 > 0.0 {
            -2.0
        } else {
            2.0
        };
        // `!(< 1)`: also the row `s = 1` (rounded up from just below), at `tan = inf`.
        if !(bound < 1.0) {
            return None;
        }
        let half = bound.max(-1.0).acos() / (2.0 * PI);
        Some((0.5 - half, 0.5 + half))
    }
}

/// Angular step of the f32 lattice of directions within `2 alpha` of `r` (see the module
/// docs): the largest over components of `ulp` times the component's lever arm on the
/// direction, `sqrt(1 - r_k^2)`.
pub fn f32_lattice(r: Vec3, alpha: f32) -> f64 {
    let unit = r.as_dvec3().normalize();
    (0..3)
        .map(|k| {
            let x = r[k].abs() + 2.0 * alpha;
            let ulp = f32::from_bits(x.to_bits() + 1) - x;
            ulp as f64 * (1.0 - unit[k] * unit[k]).max(0.0).sqrt()
        })
        .fold(0.0, f64::max)
}

/// Whether a reflection lobe of roughness `alpha` for outgoing `wo` is wide enough on
/// the f32 lattice around its mirror direction to be tested as a density.
pub fn resolvable(wo: Vec3, alpha: f32) -> bool {
    let r = Vec3::new(-wo.x, -wo.y, wo.z);
    alpha as f64 >= LATTICE_MARGIN * f32_lattice(r, alpha)
}

/// The outcome of one test.
#[derive(Clone, Debug)]
pub struct ChiSquare {
    pub statistic: f64,
    pub dof: usize,
    /// Probability of a statistic at least this large if sampling matches the pdf.
    pub p_value: f64,
    /// Samples where the grid says the pdf is zero, or in cells where it integrates to
    /// zero (must be none).
    pub outside: u64,
    /// Samples whose weight was not finite and non-negative (must be none).
    pub bad_weights: u64,
}

impl ChiSquare {
    pub fn passes(&self, alpha: f64) -> bool {
        self.outside == 0 && self.bad_weights == 0 && self.p_value >= alpha
    }
}

/// `n` samples of `sample(u) -> (direction, weight)` (`None`: no direction, still
/// counted in `n`), binned on `grid`, against `n` times the integral of `pdf` over each
/// cell.
pub fn test(
    grid: &dyn Grid,
    n: u64,
    seed: u64,
    mut sample: impl FnMut(Vec2) -> Option<(Vec3, Vec3)>,
    pdf: impl Fn(Vec3) -> f64,
) -> ChiSquare {
    let (nu, nv) = grid.bins();
    let mut observed = vec![0u64; nu * nv];
    let (mut bad_weights, mut outside) = (0, 0);
    let mut rng = Rng::for_sample(seed, 0, 0);
    for _ in 0..n {
        let Some((wi, weight)) = sample(rng.vec2()) else {
            continue;
        };
        if !(weight.is_finite() && weight.min_element() >= 0.0) {
            bad_weights += 1;
        }
        match grid.locate(wi) {
            Some((u, v)) => {
                let iu = ((u * nu as f64) as usize).min(nu - 1);
                let iv = ((v * nv as f64) as usize).min(nv - 1);
                observed[iu * nv + iv] += 1;
            }
            None => outside += 1,
        }
    }
    let breaks = grid.breaks();
    let expected: Vec<f64> = (0..nu * nv)
        .map(|k| n as f64 * cell_integral(grid, &breaks, k / nv, k % nv, &pdf))
        .collect();
    if std::env::var_os("LPE_CHI2_DEBUG").is_some() {
        debug_report(&observed, &expected, nv, n);
    }
    let (mut stat, mut dof) = (0.0, 0usize);
    let (mut pooled_o, mut pooled_e) = (0.0, 0.0);
    for (o, e) in observed.iter().zip(&expected) {
        let o = *o as f64;
        if *e == 0.0 {
            // Samples where the pdf is zero: the sampler and the pdf disagree.
            outside += o as u64;
        } else if *e < 5.0 {
            pooled_o += o;
            pooled_e += e;
        } else {
            stat += (o - e) * (o - e) / e;
            dof += 1;
        }
    }
    if pooled_e > 0.0 {
        stat += (pooled_o - pooled_e).powi(2) / pooled_e;
        dof += 1;
    }
    let dof = dof.saturating_sub(1).max(1);
    ChiSquare {
        statistic: stat,
        dof,
        p_value: chi2_sf(stat, dof as f64),
        outside,
        bad_weights,
    }
}

/// The cells contributing most to the statistic, for `LPE_CHI2_DEBUG`.
fn debug_report(observed: &[u64], expected: &[f64], nv: usize, n: u64) {
    let mut dev: Vec<(f64, usize, u64, f64)> = observed
        .iter()
        .zip(expected)
        .enumerate()
        .filter(|(_, (_, e))| **e > 0.0)
        .map(|(k, (o, e))| ((*o as f64 - e).powi(2) / e, k, *o, *e))
        .collect();
    dev.sort_by(|a, b| b.0.total_cmp(&a.0));
    eprintln!(
        "total expected {} observed {}",
        expected.iter().sum::<f64>() / n as f64,
        observed.iter().sum::<u64>() as f64 / n as f64
    );
    for d in dev.iter().take(12) {
        eprintln!(
            "cell u{} v{}: obs {} exp {:.1} chi {:.1}",
            d.1 / nv,
            d.1 % nv,
            d.2,
            d.3,
            d.0
        );
    }
}

/// The chi-square test of a lobe's `sample` against its `eval` pdf, for outgoing `wo`.
pub fn test_lobe(grid: &dyn Grid, lobe: &Lobe, wo: Vec3, n: u64, seed: u64) -> ChiSquare {
    test(
        grid,
        n,
        seed,
        |u| lobe.sample(wo, u).map(|s| (s.wi, s.weight)),
        |wi| lobe.eval(wo, wi).1 as f64,
    )
}

/// Composite Simpson over `[a, b]`.
fn simpson(a: f64, b: f64, mut f: impl FnMut(f64) -> f64) -> f64 {
    let mut sum = 0.0;
    for i in 0..=QUAD {
        let weight = match i {
            0 => 1.0,
            i if i == QUAD => 1.0,
            i if i % 2 == 1 => 4.0,
            _ => 2.0,
        };
        sum += weight * f(a + (b - a) * (i as f64 / QUAD as f64));
    }
    sum * (b - a) / (3.0 * QUAD as f64)
}

/// Integral of `pdf` (solid-angle density) over cell `(iu, iv)` of `grid`: Simpson over
/// each smooth piece of the cell in `u`, and over the row's part in the support in `v`.
fn cell_integral(
    grid: &dyn Grid,
    breaks: &[f64],
    iu: usize,
    iv: usize,
    pdf: &impl Fn(Vec3) -> f64,
) -> f64 {
    let (nu, nv) = grid.bins();
    let (u0, u1) = (iu as f64 / nu as f64, (iu + 1) as f64 / nu as f64);
    let (v0, v1) = (iv as f64 / nv as f64, (iv + 1) as f64 / nv as f64);
    let mut cuts = vec![u0];
    cuts.extend(breaks.iter().copied().filter(|b| *b > u0 && *b < u1));
    cuts.push(u1);
    cuts.sort_by(f64::total_cmp);
    let row = |u: f64| match grid.row(u) {
        Some((lo, hi)) if lo.max(v0) < hi.min(v1) => {
            let (lo, hi) = (lo.max(v0), hi.min(v1));
            // End nodes are nudged inside: the pdf jumps where a row is clipped (the
            // horizon), and an end node must take the inside value.
            let nudge = 1e-6 * (hi - lo);
            simpson(lo, hi, |v| {
                let (w, jacobian) = grid.point(u, v.clamp(lo + nudge, hi - nudge));
                pdf(w.as_vec3()) * jacobian
            })
        }
        _ => 0.0,
    };
    // Across rows the integrand has square-root ends: where the horizon starts or stops
    // cutting rows (the cut length goes like `acos` near +-1) and, on the half-vector
    // grid, at `s = 1` (`d omega / ds ~ 1 / sqrt(1 - s)`). The substitution
    // `u = a + (b - a)(3t^2 - 2t^3)` makes both smooth in `t`, and its vanishing
    // derivative at the ends keeps the nodes off the piece ends, where the horizon (a
    // cell edge `u = 1/2` of the sphere grid) or `s = 1` would be evaluated.
    cuts.windows(2)
        .map(|p| {
            let (a, b) = (p[0], p[1]);
            simpson(0.0, 1.0, |t| {
                let du_dt = (b - a) * 6.0 * t * (1.0 - t);
                if du_dt > 0.0 {
                    row(a + (b - a) * t * t * (3.0 - 2.0 * t)) * du_dt
                } else {
                    0.0
                }
            })
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn total(grid: &dyn Grid, pdf: impl Fn(Vec3) -> f64) -> f64 {
        let (nu, nv) = grid.bins();
        let breaks = grid.breaks();
        (0..nu * nv)
            .map(|k| cell_integral(grid, &breaks, k / nv, k % nv, &pdf))
            .sum()
    }

    #[test]
    fn uniform_sphere_integrates_to_one_over_the_grid() {
        let t = total(&SphereGrid, |_| 1.0 / (4.0 * PI));
        assert!((t - 1.0).abs() < 1e-12, "{t}");
    }

    fn wo(cos: f32) -> Vec3 {
        Vec3::new((1.0 - cos * cos).max(0.0).sqrt(), 0.0, cos)
    }

    #[test]
    fn cosine_hemisphere_integrates_to_one_over_the_half_vector_grid() {
        // Checks the Jacobian, the horizon clipping and the breaks at every angle of
        // incidence. Only for alpha near 1: the grid resolves densities of angular scale
        // alpha, and at alpha 1e-2 the whole hemisphere is in its last row.
        for cos in [1.0f32, 0.9, 0.5, 0.1, 1e-3, 1e-6, -0.5, -1e-6] {
            for alpha in [1.0, 0.5, 0.3] {
                let grid = HalfVectorGrid::new(wo(cos), alpha);
                let t = total(&grid, |w| (w.z * cos.signum()).max(0.0) as f64 / PI);
                assert!((t - 1.0).abs() < 1e-4, "cos {cos} alpha {alpha}: {t}");
            }
        }
        let grid = HalfVectorGrid::new(Vec3::Z, 1.0);
        let t = total(&grid, |w| if w.z > 0.0 { 0.5 / PI } else { 0.0 });
        assert!((t - 1.0).abs() < 1e-9, "{t}");
    }

    fn ggx(alpha: f32) -> Lobe {
        Lobe::white_ggx(alpha, &lpe::renderman::LobeMap::default())
    }

    #[test]
    fn ggx_at_normal_incidence_integrates_to_its_unmasked_fraction_at_any_alpha() {
        // At normal incidence the reflection stays above the surface iff tan theta_h < 1,
        // which D cos theta_h gives probability 1 / (1 + alpha^2).
        for alpha in [0.1f32, 1e-3, 1e-7] {
            let lobe = ggx(alpha);
            let grid = HalfVectorGrid::new(Vec3::Z, alpha);
            let t = total(&grid, |w| lobe.eval(Vec3::Z, w).1 as f64);
            let want = 1.0 / (1.0 + (alpha as f64).powi(2));
            assert!((t - want).abs() < 1e-6, "alpha {alpha}: {t} vs {want}");
        }
    }

    #[test]
    fn both_grids_agree_on_an_oblique_ggx_lobe() {
        for cos in [0.5f32, 0.1, -0.5] {
            let lobe = ggx(0.3);
            let pdf = |w: Vec3| lobe.eval(wo(cos), w).1 as f64;
            let sphere = total(&SphereGrid, pdf);
            let half = total(&HalfVectorGrid::new(wo(cos), 0.3), pdf);
            assert!(
                (sphere - half).abs() < 1e-6,
                "cos {cos}: {sphere} vs {half}"
            );
        }
    }

    #[test]
    fn a_sample_lands_in_the_cell_its_grid_point_came_from() {
        let wo = Vec3::new(0.6, 0.0, 0.8);
        let grid = HalfVectorGrid::new(wo, 0.01);
        for (u, v) in [(0.01, 0.5), (0.5, 0.3), (0.9, 0.7), (0.3, 0.52)] {
            let (w, _) = grid.point(u, v);
            let (u2, v2) = grid.locate(w.as_vec3()).unwrap();
            assert!(
                (u - u2).abs() < 1e-4 && (v - v2).abs() < 1e-4,
                "{u} {v}: {u2} {v2}"
            );
        }
    }

    #[test]
    fn the_lattice_rule_admits_normal_and_grazing_incidence_and_not_tiny_oblique_lobes() {
        let wo = |c: f32| Vec3::new((1.0 - c * c).max(0.0).sqrt(), 0.0, c);
        assert!(resolvable(Vec3::Z, 1e-7));
        assert!(resolvable(wo(1e-6), 1e-7));
        assert!(resolvable(wo(0.9), 1e-4));
        assert!(!resolvable(wo(0.9), 1e-5));
        // ~3e-8 rad next to (-0.436, 0, 0.9).
        let l = f32_lattice(Vec3::new(-wo(0.9).x, 0.0, 0.9), 1e-5);
        assert!(l > 2e-8 && l < 4e-8, "{l}");
    }
}
