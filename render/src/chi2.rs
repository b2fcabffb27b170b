//! Does a lobe sample directions with the density its `eval` reports? Pearson's
//! chi-square test over a grid on the sphere, as in pbrt-v4's and Mitsuba's BSDF tests:
//! histogram many sampled directions, integrate the reported pdf over each cell for the
//! expected counts, pool cells expecting fewer than 5, and reject at significance
//! `alpha` (callers Sidak-correct it for the number of tests they run).

use glam::Vec3;
use std::f64::consts::PI;

use crate::material::Lobe;
use crate::rng::Rng;

/// Cells in `cos(theta)` (equal area) and in `phi`.
pub const COS_BINS: usize = 20;
pub const PHI_BINS: usize = 40;
/// Simpson subintervals per cell and axis for the expected counts: 16 leave a quadrature
/// error that a GGX lobe of alpha 0.05 at grazing incidence already shows as a false
/// rejection (p ~ 0 with 400k samples); 64 do not.
const QUAD: usize = 64;

/// The outcome of one test.
#[derive(Clone, Debug)]
pub struct ChiSquare {
    pub statistic: f64,
    pub dof: usize,
    /// Probability of a statistic at least this large if sampling matches the pdf.
    pub p_value: f64,
    /// Samples falling in cells where the pdf integrates to zero (must be none).
    pub outside: u64,
    /// Samples whose weight was not finite and non-negative (must be none).
    pub bad_weights: u64,
}

impl ChiSquare {
    pub fn passes(&self, alpha: f64) -> bool {
        self.outside == 0 && self.bad_weights == 0 && self.p_value >= alpha
    }
}

fn cell(w: Vec3) -> usize {
    let c = ((w.z as f64 + 1.0) * 0.5 * COS_BINS as f64) as usize;
    let phi = (w.y as f64).atan2(w.x as f64).rem_euclid(2.0 * PI);
    let p = (phi / (2.0 * PI) * PHI_BINS as f64) as usize;
    c.min(COS_BINS - 1) * PHI_BINS + p.min(PHI_BINS - 1)
}

/// `n` samples of `sample(u) -> (direction, weight)`, binned, against the integral of
/// `pdf` over each cell.
pub fn test(
    n: u64,
    seed: u64,
    mut sample: impl FnMut(glam::Vec2) -> Option<(Vec3, Vec3)>,
    pdf: impl Fn(Vec3) -> f64,
) -> ChiSquare {
    let cells = COS_BINS * PHI_BINS;
    let mut observed = vec![0u64; cells];
    let mut bad_weights = 0;
    let mut rng = Rng::for_sample(seed, 0, 0);
    for _ in 0..n {
        if let Some((wi, weight)) = sample(rng.vec2()) {
            if !(weight.is_finite() && weight.min_element() >= 0.0) {
                bad_weights += 1;
            }
            observed[cell(wi)] += 1;
        }
    }
    let expected: Vec<f64> = (0..cells)
        .map(|k| n as f64 * cell_integral(k, &pdf))
        .collect();
    if std::env::var_os("LPE_CHI2_DEBUG").is_some() {
        let mut dev: Vec<(f64, usize, u64, f64)> = observed
            .iter()
            .zip(&expected)
            .enumerate()
            .filter(|(_, (_, e))| **e > 0.0)
            .map(|(k, (o, e))| ((*o as f64 - e).powi(2) / e, k, *o, *e))
            .collect();
        dev.sort_by(|a, b| b.0.total_cmp(&a.0));
        eprintln!("total expected {}", expected.iter().sum::<f64>() / n as f64);
        for d in dev.iter().take(12) {
            eprintln!(
                "cell c{} p{}: obs {} exp {:.1} chi {:.1}",
                d.1 / PHI_BINS,
                d.1 % PHI_BINS,
                d.2,
                d.3,
                d.0
            );
        }
    }
    let mut outside = 0;
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

/// The chi-square test of a lobe's `sample` against its `eval` pdf, for outgoing `wo`.
pub fn test_lobe(lobe: &Lobe, wo: Vec3, n: u64, seed: u64) -> ChiSquare {
    test(
        n,
        seed,
        |u| lobe.sample(wo, u).map(|s| (s.wi, s.weight)),
        |wi| lobe.eval(wo, wi).1 as f64,
    )
}

/// Integral of `pdf` over cell `k` in `(cos theta, phi)` coordinates (where the solid
/// angle element is `d cos d phi`), by composite Simpson.
fn cell_integral(k: usize, pdf: &impl Fn(Vec3) -> f64) -> f64 {
    let (ci, pi) = (k / PHI_BINS, k % PHI_BINS);
    let dc = 2.0 / COS_BINS as f64;
    let dp = 2.0 * PI / PHI_BINS as f64;
    let (c0, p0) = (-1.0 + ci as f64 * dc, pi as f64 * dp);
    let simpson = |i: usize| match i {
        0 => 1.0,
        i if i == QUAD => 1.0,
        i if i % 2 == 1 => 4.0,
        _ => 2.0,
    };
    let mut sum = 0.0;
    for i in 0..=QUAD {
        // Nodes on a cell's edge are nudged inside it: pdfs jump at the horizon
        // (cos = 0 is a cell edge), and the edge node must take the inside value.
        let c = c0 + dc * (i as f64 / QUAD as f64).clamp(1e-6, 1.0 - 1e-6);
        let s = (1.0 - c * c).max(0.0).sqrt();
        for j in 0..=QUAD {
            let p = p0 + dp * j as f64 / QUAD as f64;
            let w = Vec3::new((s * p.cos()) as f32, (s * p.sin()) as f32, c as f32);
            sum += simpson(i) * simpson(j) * pdf(w);
        }
    }
    sum * (dc / QUAD as f64 / 3.0) * (dp / QUAD as f64 / 3.0)
}

/// Upper tail of the chi-square distribution with `k` degrees of freedom:
/// `Q(k/2, x/2)`, the regularized upper incomplete gamma function.
pub fn chi2_sf(x: f64, k: f64) -> f64 {
    if !(x > 0.0) {
        return 1.0;
    }
    gamma_q(0.5 * k, 0.5 * x)
}

/// `ln Gamma(a)`, Lanczos (g = 7, n = 9), relative error ~1e-15 for `a > 0`.
fn ln_gamma(a: f64) -> f64 {
    const C: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    let x = a - 1.0;
    let t = x + 7.5;
    let s: f64 = C[0] + (1..9).map(|i| C[i] / (x + i as f64)).sum::<f64>();
    0.5 * (2.0 * PI).ln() + (x + 0.5) * t.ln() - t + s.ln()
}

/// Regularized upper incomplete gamma `Q(a, x)`: series for `x < a + 1`, Lentz's
/// continued fraction otherwise (Numerical Recipes' `gammq`).
fn gamma_q(a: f64, x: f64) -> f64 {
    let lead = (-x + a * x.ln() - ln_gamma(a)).exp();
    if x < a + 1.0 {
        let (mut sum, mut term, mut ap) = (1.0 / a, 1.0 / a, a);
        for _ in 0..10_000 {
            ap += 1.0;
            term *= x / ap;
            sum += term;
            if term.abs() < sum.abs() * 1e-16 {
                break;
            }
        }
        (1.0 - sum * lead).max(0.0)
    } else {
        let tiny = 1e-300;
        let mut b = x + 1.0 - a;
        let mut c = 1.0 / tiny;
        let mut d = 1.0 / b;
        let mut h = d;
        for i in 1..10_000 {
            let an = -(i as f64) * (i as f64 - a);
            b += 2.0;
            d = an * d + b;
            if d.abs() < tiny {
                d = tiny;
            }
            c = b + an / c;
            if c.abs() < tiny {
                c = tiny;
            }
            d = 1.0 / d;
            let delta = d * c;
            h *= delta;
            if (delta - 1.0).abs() < 1e-16 {
                break;
            }
        }
        lead * h
    }
}

/// Per-test significance that keeps the family-wise rate at `alpha` over `m` independent
/// tests (Sidak).
pub fn sidak(alpha: f64, m: usize) -> f64 {
    1.0 - (1.0 - alpha).powf(1.0 / m as f64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chi2_tail_matches_tables() {
        // Critical values from standard chi-square tables.
        assert!((chi2_sf(3.841459, 1.0) - 0.05).abs() < 1e-6);
        assert!((chi2_sf(23.209251, 10.0) - 0.01).abs() < 1e-6);
        assert!((chi2_sf(124.342113, 100.0) - 0.05).abs() < 1e-6);
        assert!((chi2_sf(2.0, 2.0) - (-1.0f64).exp()).abs() < 1e-12);
    }

    #[test]
    fn uniform_sphere_integrates_to_one_over_the_grid() {
        let total: f64 = (0..COS_BINS * PHI_BINS)
            .map(|k| cell_integral(k, &|_| 1.0 / (4.0 * PI)))
            .sum();
        assert!((total - 1.0).abs() < 1e-12, "{total}");
    }
}
