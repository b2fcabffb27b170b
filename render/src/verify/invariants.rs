//! Invariants on rendered films, each compared against an independent computation:
//! partitions against beauty (accumulated without the matcher), the furnace against its
//! closed form, determinism against a second render.

use glam::DVec3;
use serde::Serialize;

use super::stats::{critical_z, mean_and_se, sidak};
use crate::aov::{AovList, Partition};
use crate::film::Film;
use crate::integrator::Render;
use crate::scene::furnace::{furnace_params, FURNACE_BOUNCES};
use crate::scene::Scene;
use lpe::DialectName;

/// One checked property and its measured error.
#[derive(Clone, Debug, Serialize)]
pub struct Invariant {
    pub name: String,
    /// The measured error (its meaning is in `detail`).
    pub measured: f64,
    pub tolerance: f64,
    /// `None`: not checked, or informational (e.g. a formal check of a set that need
    /// not partition every path).
    pub passed: Option<bool>,
    pub detail: String,
    /// Decided on the automata for every possible path (no measurement: `measured` and
    /// `tolerance` mean nothing; `detail` says what was decided, with a witness path).
    pub formal: bool,
}

impl Invariant {
    fn new(
        name: impl Into<String>,
        measured: f64,
        tolerance: f64,
        detail: impl Into<String>,
    ) -> Self {
        Invariant {
            name: name.into(),
            measured,
            tolerance,
            passed: Some(measured <= tolerance),
            detail: detail.into(),
            formal: false,
        }
    }

    /// The measurement as printed (`-` for a formal check).
    pub fn measured_text(&self) -> String {
        if self.formal {
            "-".into()
        } else {
            format!("{:.3e}", self.measured)
        }
    }

    /// The tolerance as printed (`-` for a formal check).
    pub fn tolerance_text(&self) -> String {
        if self.formal {
            "-".into()
        } else {
            format!("{:.3e}", self.tolerance)
        }
    }

    /// One console line: the outcome and name, then what was measured against what,
    /// or for a formal check what was decided and its witness.
    pub fn line(&self) -> String {
        let tag = match self.passed {
            Some(true) => "pass",
            Some(false) => "FAIL",
            None => "skip",
        };
        if self.formal {
            format!("[{tag}] {} — {}", self.name, self.detail)
        } else {
            format!(
                "[{tag}] {} — measured {:.3e} (tolerance {:.3e})",
                self.name, self.measured, self.tolerance
            )
        }
    }

    pub fn failed(&self) -> bool {
        self.passed == Some(false)
    }
}

/// Relative tolerance of "sums to beauty" (the bound; f64 films reach ~1e-15).
pub const PARTITION_TOLERANCE: f64 = 1e-5;

/// Largest per-pixel, per-channel relative error of `sum(members) - beauty`, relative
/// to `max(|beauty|, 1e-12)` (a pixel with zero beauty must have zero sum).
pub fn partition(film: &Film, aovs: &AovList, p: &Partition) -> Invariant {
    let mut worst = 0.0f64;
    let mut at = (0, 0);
    for y in 0..film.height {
        for x in 0..film.width {
            let b = film.pixel(x, y, 0);
            let s: DVec3 = p.members.iter().map(|&i| film.pixel(x, y, 1 + i)).sum();
            let err = ((s - b).abs() / b.abs().max(DVec3::splat(1e-12))).max_element();
            // NaN must fail, so compare with `!(err <= worst)`.
            if !(err <= worst) {
                worst = err;
                at = (x, y);
            }
        }
    }
    let names: Vec<&str> = p
        .members
        .iter()
        .map(|&i| aovs.aovs[i].name.as_str())
        .collect();
    Invariant::new(
        format!("{} sum to beauty", p.name),
        worst,
        PARTITION_TOLERANCE,
        format!(
            "max relative error over pixels and channels (worst at pixel {:?}); members: {}",
            at,
            names.join(" + ")
        ),
    )
}

/// No NaN or infinity in any output layer.
pub fn finite(film: &Film, aovs: &AovList) -> Invariant {
    let mut bad = Vec::new();
    for layer in 0..film.layers {
        let n = film.layer(layer).iter().filter(|v| !v.is_finite()).count();
        if n > 0 {
            let name = if layer == 0 {
                "beauty"
            } else {
                &aovs.aovs[layer - 1].name
            };
            bad.push(format!("{name}: {n} pixels"));
        }
    }
    Invariant::new(
        "no NaN/Inf in any layer",
        bad.len() as f64,
        0.0,
        format!(
            "non-finite layers: {}; samples rejected as non-finite: {} (of {}), AOV-only values dropped: {}",
            if bad.is_empty() { "none".to_string() } else { bad.join(", ") },
            film.rejected,
            film.width as u64 * film.height as u64 * film.spp as u64,
            film.aov_rejected
        ),
    )
}

/// The formal partition check (`lpe::analysis::partition`, or `partition_osl` for an
/// OSL list): decides from the automata, before any sample is traced, whether each
/// declared partition (or, with none declared, the whole AOV set) partitions beauty's
/// universe, with a shortest witness path if not. This is a statement about every
/// possible path, not about this scene.
///
/// The universe is `C.*[<L.>O]` for RenderMan and `lpe::osl::UNIVERSE`,
/// `C<[RT][DGS]>*[LO]`, for OSL: every OSL path the renderer produces is in it (camera
/// `C,~`; events `R`/`T` scattering `D`, `G` or `S`; an `L` or `O` emitter; custom
/// labels never built-in ones), so a partition of it partitions the renderer's paths.
pub fn formal_partition(aovs: &AovList) -> Vec<Invariant> {
    // Requested AOVs with no declared partition need not partition beauty: say whether
    // they do, but only a declared (universal) partition that fails is a failure.
    let sets: Vec<(String, Vec<usize>, bool)> = if aovs.partitions.is_empty() {
        let all = (0..aovs.aovs.len()).collect();
        vec![("all requested AOVs".to_string(), all, false)]
    } else {
        aovs.partitions
            .iter()
            .map(|p| (p.name.clone(), p.members.clone(), p.universal))
            .collect()
    };
    let parser = lpe::renderman::Parser::default();
    let universe = lpe::analysis::default_universe::<lpe::renderman::RenderMan>(&parser);
    let registered = lpe::osl::Registered::none();
    let osl_universe = lpe::analysis::default_universe::<lpe::osl::Osl>(&registered);
    sets.into_iter()
        .map(|(name, members, universal)| {
            let names: Vec<&str> = members
                .iter()
                .map(|&i| aovs.aovs[i].name.as_str())
                .collect();
            let checked = match aovs.dialect {
                DialectName::RenderMan => lpe::analysis::partition(
                    &pick(aovs.named::<lpe::renderman::RenderMan>(), &members),
                    &universe,
                    &parser,
                )
                .map(|r| (universe.to_string(), failures(&r, &names))),
                DialectName::Osl => lpe::analysis::partition(
                    &pick(aovs.named::<lpe::osl::Osl>(), &members),
                    &osl_universe,
                    &registered,
                )
                .map(|r| {
                    let u = lpe::osl::UNIVERSE.to_string();
                    (u, failures(&r, &names))
                }),
            };
            let (passed, detail) = match checked {
                Ok((u, why)) if why.is_empty() => (
                    Some(true),
                    format!("every path of {u} matches exactly one AOV"),
                ),
                Ok((_, why)) if universal => (Some(false), why.join("; ")),
                Ok((_, why)) => {
                    // Expected: e.g. the per-lobe set covers only the lobes this scene
                    // uses (the render-time sum checks that); report, do not fail.
                    let why = why.join("; ");
                    (None, format!("not a partition of every path ({why})"))
                }
                Err(e) => (None, format!("not checked: {e}")),
            };
            Invariant {
                name: format!("formal partition check: {name} (lpe::analysis)"),
                measured: f64::NAN,
                tolerance: 0.0,
                passed,
                detail,
                formal: true,
            }
        })
        .collect()
}

/// The members of a partition out of a list's `(name, expression)` pairs (a list is in
/// one dialect, so its `named*` pairs are indexed like its AOVs).
fn pick<T: Clone>(all: Vec<T>, members: &[usize]) -> Vec<T> {
    members.iter().map(|&i| all[i].clone()).collect()
}

/// What keeps a partition check from being clean, with witnesses (empty: clean).
fn failures<P: std::fmt::Display>(r: &lpe::analysis::Partition<P>, names: &[&str]) -> Vec<String> {
    let mut why = Vec::new();
    if let Some(g) = &r.gap {
        why.push(format!("gap: `{g}` matches none"));
    }
    if let Some((i, j, p)) = r.overlaps.first() {
        why.push(format!(
            "overlap: `{p}` matches both {} and {}",
            names[*i], names[*j]
        ));
    }
    if let Some((i, p)) = r.outside.first() {
        why.push(format!(
            "{} also matches `{p}`, outside the universe",
            names[*i]
        ));
    }
    why
}

/// z-test of a layer's pixel means against a constant expectation. In the furnace every
/// pixel estimates the same value with i.i.d. samples, so pixel means are i.i.d.: their
/// mean has standard error `s / sqrt(n)` with `s` their sample standard deviation.
/// A layer with zero spread must equal the expectation to 1e-9 relative (it is then
/// computed exactly, as `C O` is).
pub fn z_test(name: &str, values: &[f64], expected: f64, z_crit: f64, alpha: f64) -> Invariant {
    let (mean, se) = mean_and_se(values);
    if se == 0.0 {
        let rel = (mean - expected).abs() / expected.abs().max(1e-300);
        return Invariant::new(
            name,
            rel,
            1e-9,
            format!(
                "deterministic layer: mean {mean:.9} vs closed form {expected:.9} (relative error)"
            ),
        );
    }
    let z = (mean - expected) / se;
    Invariant::new(
        name,
        z.abs(),
        z_crit,
        format!(
            "mean {mean:.6} vs closed form {expected:.6}, standard error {se:.2e}: |z| vs critical {z_crit:.3} (two-sided, family-wise alpha {alpha}, Sidak-corrected)"
        ),
    )
}

/// Mean of the red channel of each pixel of `layer` (the furnace is grey).
pub fn channel_values(film: &Film, layer: usize) -> Vec<f64> {
    film.layer(layer).iter().map(|v| v.x).collect()
}

/// Self-normalized z-test that per-pixel values `x_p` have expectation zero each
/// (not identically distributed): `z = sum x_p / sqrt(sum x_p^2)`; under the null
/// `sum x_p^2` is an unbiased estimate of the variance of `sum x_p`.
pub fn zero_mean_test(name: &str, values: &[f64], z_crit: f64, detail: &str) -> Invariant {
    let s: f64 = values.iter().sum();
    let q: f64 = values.iter().map(|v| v * v).sum();
    if q == 0.0 {
        // Every difference exactly 0: the layers compared are identical, in practice both
        // empty (an effect not simulated), which "mean zero" would wave through.
        return Invariant::new(
            name,
            f64::INFINITY,
            z_crit,
            format!("{detail}: degenerate, every value is 0 (nothing was compared)"),
        );
    }
    Invariant::new(
        name,
        (s / q.sqrt()).abs(),
        z_crit,
        format!("{detail}: |z| = |sum| / sqrt(sum of squares) vs critical {z_crit:.3}"),
    )
}

/// Family-wise significance of the statistical tests.
pub const ALPHA: f64 = 1e-3;

/// The invariants one render can check by itself.
pub fn invariants(scene: &Scene, aovs: &AovList, render: &Render) -> Vec<Invariant> {
    let film = &render.film;
    let mut out: Vec<Invariant> = aovs
        .partitions
        .iter()
        .map(|p| partition(film, aovs, p))
        .collect();
    out.push(finite(film, aovs));
    if let Some((a, le)) = furnace_params(scene) {
        let bounces: Vec<(usize, u32)> = (0..=FURNACE_BOUNCES)
            .filter_map(|k| aovs.index(&format!("furnace_bounce{k}")).map(|i| (i, k)))
            .collect();
        let tests = 1 + bounces.len();
        let each = sidak(ALPHA, tests);
        let z = critical_z(each);
        out.push(z_test(
            &format!("furnace beauty = Le/(1-a) = {}", le / (1.0 - a)),
            &channel_values(film, 0),
            le / (1.0 - a),
            z,
            ALPHA,
        ));
        for (i, k) in bounces {
            out.push(z_test(
                &format!(
                    "furnace C<RD>{{{k}}}O = Le a^{k} = {}",
                    le * a.powi(k as i32)
                ),
                &channel_values(film, 1 + i),
                le * a.powi(k as i32),
                z,
                ALPHA,
            ));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zero_mean_test_fails_on_a_shift_and_on_nothing_to_compare() {
        let z = critical_z(0.01);
        let noise: Vec<f64> = (0..1000)
            .map(|i| if i % 2 == 0 { 1.0 } else { -1.0 })
            .collect();
        assert!(!zero_mean_test("noise", &noise, z, "").failed());
        let shifted: Vec<f64> = noise.iter().map(|v| v + 0.5).collect();
        assert!(zero_mean_test("shifted", &shifted, z, "").failed());
        assert!(zero_mean_test("zeros", &[0.0; 100], z, "").failed());
    }
}
