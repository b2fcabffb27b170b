//! `lpe-render stress`: the hard-case scene set (tiny lights, extreme intensities and
//! pdfs, a 10^7-sample film, degenerate input), rendered, one table row per measured
//! property. The same scenes and checks back `render/tests/hard_cases.rs`.

use super::VerifyError;
use glam::{DVec3, Vec3};
use lpe::renderman::{LobeMap, Parser};

use super::known::{
    intensities_scene, intensity_reference, sphere_over_plane, INTENSITIES, MIS_EXTREMES, MIXED,
};
use super::stats::mean_and_se;
use crate::aov::AovList;
use crate::film::Accumulation;
use crate::integrator::{Render, Settings, Technique};
use crate::material::Lobe;
use crate::rng::Rng;
use crate::scene::Scene;
use lpe::renderman::RenderMan;

/// One measured property.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Row {
    pub case: String,
    pub measure: String,
    pub value: f64,
    pub bound: f64,
    pub passed: bool,
}

fn row(case: &str, measure: &str, value: f64, bound: f64, passed: bool) -> Row {
    Row {
        case: case.into(),
        measure: measure.into(),
        value,
        bound,
        passed,
    }
}

/// Relative error of the image mean of `got` (red channel) against `want`, and the
/// bound it must meet: 5 standard errors of the per-pixel residuals (significance
/// < 1e-6) plus 1e-4 relative (f32 radiance and pdfs).
pub fn mean_check(got: &[DVec3], want: &[DVec3]) -> (f64, f64) {
    let res: Vec<f64> = got.iter().zip(want).map(|(g, w)| g.x - w.x).collect();
    let (m, se) = mean_and_se(&res);
    let scale = want.iter().map(|w| w.x).sum::<f64>() / res.len() as f64;
    ((m / scale).abs(), (5.0 * se + 1e-4 * scale) / scale)
}

/// [`MIXED`] rendered into one pixel with `spp` samples by each film of
/// [`Accumulation::ALL`] (one thread each, same samples); for each, the largest
/// relative error of the basic-AOV partition against beauty, and the f64 film's beauty.
pub fn mixed_partition(
    spp: u32,
    lobes: &LobeMap,
) -> Result<(Vec<(Accumulation, f64)>, DVec3), VerifyError> {
    let scene = Scene::from_toml(MIXED, "mixed", lobes)?;
    let aovs = AovList::<RenderMan>::basic(&Parser::default())?;
    let basic = &aovs.partitions[0];
    let render = |accumulation| {
        let settings = Settings {
            width: 1,
            height: 1,
            spp,
            seed: 17,
            threads: Some(1),
            accumulation,
            ..Settings::default()
        };
        crate::integrator::render(&scene, &aovs, lobes, &settings).map_err(VerifyError::from)
    };
    let renders: Vec<Result<Render, VerifyError>> = std::thread::scope(|t| {
        let handles: Vec<_> = Accumulation::ALL
            .map(|a| t.spawn(move || render(a)))
            .into_iter()
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().unwrap_or_else(|_| Err(VerifyError::Panicked)))
            .collect()
    });
    let mut errors = Vec::new();
    let mut beauty = DVec3::ZERO;
    for (a, r) in Accumulation::ALL.into_iter().zip(renders) {
        let r = r?;
        if r.film.rejected > 0 {
            return Err(VerifyError::Rejected {
                samples: r.film.rejected,
            });
        }
        if a == Accumulation::F64 {
            beauty = r.film.pixel(0, 0, 0);
        }
        errors.push((
            a,
            crate::verify::invariants::partition(&r.film, &aovs, basic).measured,
        ));
    }
    Ok((errors, beauty))
}

/// Mean weight of a GGX lobe with `f0 = 1` (its directional albedo: a white furnace)
/// over `n` samples, its standard error, and how many samples were not finite.
pub fn ggx_furnace(alpha: f32, cos: f32, n: usize) -> (f64, f64, usize) {
    let lobe = Lobe::white_ggx(alpha, &LobeMap::default());
    let wo = Vec3::new((1.0 - cos * cos).max(0.0).sqrt(), 0.0, cos);
    let mut rng = Rng::for_sample(1, 0, 0);
    let mut bad = 0;
    let x: Vec<f64> = (0..n)
        .map(|_| match lobe.sample(wo, rng.vec2()) {
            Some(s) if s.weight.is_finite() && s.pdf.is_finite() => s.weight.x as f64,
            Some(_) => {
                bad += 1;
                0.0
            }
            None => 0.0,
        })
        .collect();
    let (m, se) = mean_and_se(&x);
    (m, se, bad)
}

fn render(scene: &Scene, aovs: &AovList<RenderMan>, s: &Settings) -> Result<Render, VerifyError> {
    Ok(crate::integrator::render(
        scene,
        aovs,
        &LobeMap::default(),
        s,
    )?)
}

/// Runs the set. `quick`: fewer samples (the 10^7-sample film test uses 10^5).
pub fn run(quick: bool) -> Result<Vec<Row>, VerifyError> {
    let lobes = LobeMap::default();
    let mut rows = Vec::new();
    let small = |spp| Settings {
        width: 12,
        height: 12,
        spp,
        seed: 9,
        ..Settings::default()
    };
    let spp = if quick { 16 } else { 64 };

    for radius in [0.5, 1e-6] {
        let k = sphere_over_plane(12, 12, radius, &lobes)?;
        for t in [Technique::Mis, Technique::LightOnly] {
            let r = render(
                &k.scene,
                &k.aovs,
                &Settings {
                    technique: t,
                    ..small(spp)
                },
            )?;
            let (e, b) = mean_check(&r.film.layer(1), &k.reference[1]);
            rows.push(row(
                &format!("sphere light R={radius:e}, same power, {t:?}"),
                "rel. error vs a Le (R/d)^2 cos",
                e,
                b,
                e <= b && r.film.rejected == 0,
            ));
        }
    }

    let (scene, aovs) = intensities_scene(&lobes)?;
    let r = render(&scene, &aovs, &small(2 * spp))?;
    for (k, (i, _)) in INTENSITIES.iter().enumerate() {
        let (e, b) = mean_check(
            &r.film.layer(1 + k),
            &intensity_reference(&scene, k, 12, 12),
        );
        rows.push(row(
            &format!("point light I={i:e} among 1e-6..1e12"),
            "rel. error of its light group",
            e,
            b,
            e <= b && r.film.rejected == 0,
        ));
    }

    let scene = Scene::from_toml(MIS_EXTREMES, "mis-extremes", &lobes)?;
    let aovs = AovList::<RenderMan>::defaults(&scene, &Parser::default())?;
    for t in [Technique::Mis, Technique::BsdfOnly, Technique::LightOnly] {
        let r = render(
            &scene,
            &aovs,
            &Settings {
                technique: t,
                ..small(spp)
            },
        )?;
        let bad = (r.film.rejected + r.film.aov_rejected) as f64;
        rows.push(row(
            &format!("MIS pdfs 0..1e13 (alpha 1e-7, 1e-6 light), {t:?}"),
            "non-finite samples",
            bad,
            0.0,
            bad == 0.0,
        ));
    }

    let mixed_spp = if quick { 100_000 } else { 10_000_000 };
    for (a, e) in mixed_partition(mixed_spp, &lobes)?.0 {
        // The naive f32 film is here to fail visibly; the others must pass.
        let naive = a == Accumulation::F32;
        rows.push(row(
            &format!("{mixed_spp} mixed samples in one pixel, {} film", a.name()),
            if naive {
                "basic AOVs vs beauty, rel. (fails by design)"
            } else {
                "basic AOVs vs beauty, rel."
            },
            e,
            1e-6,
            naive || e <= 1e-6,
        ));
    }

    let n = if quick { 5_000 } else { 50_000 };
    for alpha in [1e-1, 1e-3, 1e-5, 1e-7] {
        for cos in [1.0, 1e-6] {
            let (m, se, bad) = ggx_furnace(alpha, cos, n);
            rows.push(row(
                &format!("GGX alpha {alpha:e}, cos {cos:e}, f0 = 1"),
                "mean weight (albedo) / non-finite",
                m,
                // 5 standard errors, plus f32 rounding of weights that are all ~1.
                1.0 + 5.0 * se + 1e-6,
                m <= 1.0 + 5.0 * se + 1e-6 && bad == 0,
            ));
        }
    }
    Ok(rows)
}
