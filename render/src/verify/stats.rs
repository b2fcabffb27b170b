//! Distribution tails and estimators the statistical checks share. The tails come from
//! `statrs`; the tests pin them to table values.

use statrs::distribution::{ChiSquared, ContinuousCDF, Normal};

/// Standard normal upper tail `P(Z > z)`.
pub fn normal_tail(z: f64) -> f64 {
    Normal::standard().sf(z)
}

/// The two-sided critical value: `|Z| > z` with probability `alpha`.
pub fn critical_z(alpha: f64) -> f64 {
    Normal::standard().inverse_cdf(1.0 - 0.5 * alpha)
}

/// Upper tail of the chi-square distribution with `k` degrees of freedom (1 for `x <= 0`
/// or NaN, so a degenerate statistic never rejects).
pub fn chi2_sf(x: f64, k: f64) -> f64 {
    if !(x > 0.0) {
        return 1.0;
    }
    match ChiSquared::new(k) {
        Ok(d) => d.sf(x),
        Err(_) => f64::NAN,
    }
}

/// Per-test significance that keeps the family-wise rate at `alpha` over `m` independent
/// tests (Sidak).
pub fn sidak(alpha: f64, m: usize) -> f64 {
    1.0 - (1.0 - alpha).powf(1.0 / m as f64)
}

/// Mean of `x` and its standard error `s / sqrt(n)` (`s` the sample standard deviation;
/// 0 for fewer than two values).
pub fn mean_and_se(x: &[f64]) -> (f64, f64) {
    let n = x.len() as f64;
    let mean = x.iter().sum::<f64>() / n;
    let var = x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0);
    (mean, (var / n).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normal_tail_matches_known_quantiles() {
        // Table values of the standard normal distribution.
        assert!((normal_tail(0.0) - 0.5).abs() < 1e-7);
        assert!((normal_tail(1.959964) - 0.025).abs() < 1e-6);
        assert!((critical_z(0.05) - 1.959964).abs() < 1e-4);
        assert!((critical_z(0.001) - 3.290527).abs() < 1e-4);
    }

    #[test]
    fn chi2_tail_matches_tables() {
        // Critical values from standard chi-square tables.
        assert!((chi2_sf(3.841459, 1.0) - 0.05).abs() < 1e-6);
        assert!((chi2_sf(23.209251, 10.0) - 0.01).abs() < 1e-6);
        assert!((chi2_sf(124.342113, 100.0) - 0.05).abs() < 1e-6);
        assert!((chi2_sf(2.0, 2.0) - (-1.0f64).exp()).abs() < 1e-12);
    }
}
