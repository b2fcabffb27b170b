//! Invariants on rendered films, each compared against an independent computation:
//! partitions against beauty (accumulated without the matcher), the furnace against its
//! closed form, determinism against a second render.

use glam::DVec3;

use super::stats::{critical_z, mean_and_se, sidak};
use lpe::Dialect;

use crate::aov::{AovList, Partition, SceneDialect};
use crate::film::Film;
use crate::integrator::Render;
use crate::invariant::Invariant;
use crate::scene::furnace::{furnace_params, FURNACE_BOUNCES};
use crate::scene::Scene;

/// Relative tolerance of "sums to beauty" (the bound; f64 films reach ~1e-15).
pub const PARTITION_TOLERANCE: f64 = 1e-5;

/// Largest per-pixel, per-channel relative error of `sum(members) - beauty`, relative
/// to `max(|beauty|, 1e-12)` (a pixel with zero beauty must have zero sum).
pub fn partition<D: Dialect>(film: &Film, aovs: &AovList<D>, p: &Partition) -> Invariant {
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
pub fn finite<D: Dialect>(film: &Film, aovs: &AovList<D>) -> Invariant {
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

/// The formal partition check (`lpe::analysis::partition`): decides from the automata,
/// before any sample is traced, whether each declared partition (or, with none declared,
/// the whole AOV set) partitions beauty's universe, with a shortest witness path if not.
/// This is a statement about every possible path, not about this scene.
///
/// The universe is the dialect's default one (`Dialect::DEFAULT_UNIVERSE`, nothing
/// registered): `C.*[<L.>O]` for RenderMan and `C<[RT][DGS]>*[LO]` for OSL, where every
/// OSL path the renderer produces lies (camera `C,~`; events `R`/`T` scattering `D`, `G`
/// or `S`; an `L` or `O` emitter; custom labels never built-in ones), so a partition of
/// it partitions the renderer's paths.
pub fn formal_partition<D: SceneDialect>(aovs: &AovList<D>) -> Vec<Invariant> {
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
    let registration = &aovs.registration;
    let universe = lpe::analysis::default_universe::<D>(registration);
    let named = aovs.named();
    sets.into_iter()
        .map(|(name, members, universal)| {
            let names: Vec<&str> = members
                .iter()
                .map(|&i| aovs.aovs[i].name.as_str())
                .collect();
            let picked: Vec<_> = members.iter().map(|&i| named[i].clone()).collect();
            let checked = lpe::analysis::partition(&picked, &universe, registration)
                .map(|r| failures(&r, &names));
            let (passed, detail) = match checked {
                Ok(why) if why.is_empty() => (
                    Some(true),
                    format!(
                        "every path of {} matches exactly one AOV",
                        D::DEFAULT_UNIVERSE
                    ),
                ),
                Ok(why) if universal => (Some(false), why.join("; ")),
                Ok(why) => {
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
pub fn invariants<D: Dialect>(scene: &Scene, aovs: &AovList<D>, render: &Render) -> Vec<Invariant> {
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
