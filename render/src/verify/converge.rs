//! `lpe-render converge`: what each bit of accuracy costs in time.
//!
//! Scenes with a known answer per pixel and per AOV ([`Known`]): the furnace (closed
//! form), a point light over a diffuse plane and a sphere light over it (closed forms
//! averaged over each pixel's footprint), and `cornell` against a high-spp render cached
//! in the output directory. Each [`Variant`] (estimator technique, Russian roulette,
//! clamp, film accumulation, matcher engine) renders every scene at geometric spp steps
//! with a fixed seed; per AOV we record wall time, MSE and relMSE against the reference,
//! the fitted log-log slope of MSE against spp (-1 for an unbiased estimator, flattening
//! to 0 at a bias floor) and the efficiency `1 / (MSE x time)`.

pub use super::matcher_row::MatcherRow;
pub use super::tables::{Point, Summary};
use super::{tables, VerifyError};
use glam::DVec3;
use lpe::renderman::LobeMap;
use serde::Serialize;
use std::path::Path;

use super::known::{cornell, furnace, point_over_plane, sphere_over_plane, Known, SPHERE};
use crate::film::{Accumulation, Film};
use crate::integrator::{Settings, Technique};
use crate::output::OutputError;

/// One way of rendering: a row group of the table.
#[derive(Clone, Debug, Serialize)]
pub struct Variant {
    pub name: String,
    pub technique: Technique,
    pub russian_roulette: bool,
    /// Clamp at this multiple of the reference's mean beauty (None: the scene's own).
    pub clamp: Option<f64>,
    pub accumulation: Accumulation,
    pub engine: MatcherRow,
}

impl Variant {
    fn base(name: &str) -> Variant {
        Variant {
            name: name.into(),
            technique: Technique::Mis,
            russian_roulette: true,
            clamp: None,
            accumulation: Accumulation::F64,
            engine: MatcherRow::Fast,
        }
    }

    /// The variants compared, each differing from MIS in one respect.
    pub fn all() -> Vec<Variant> {
        let mut v = vec![
            Variant::base("MIS"),
            Variant {
                technique: Technique::BsdfOnly,
                ..Variant::base("BSDF only")
            },
            Variant {
                technique: Technique::LightOnly,
                ..Variant::base("light only")
            },
            Variant {
                russian_roulette: false,
                ..Variant::base("MIS, no RR")
            },
            Variant {
                clamp: Some(1.0),
                ..Variant::base("MIS, clamp 1x mean")
            },
        ];
        for a in Accumulation::ALL.into_iter().skip(1) {
            v.push(Variant {
                accumulation: a,
                ..Variant::base(&format!("MIS, {} film", a.name()))
            });
        }
        for e in MatcherRow::ALL.into_iter().skip(1) {
            v.push(Variant {
                engine: e,
                ..Variant::base(&format!("MIS, {}", e.name()))
            });
        }
        v
    }
}

/// Error of one layer of a film against a reference.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct LayerError {
    /// Mean over pixels and channels of `(x - ref)^2`.
    pub mse: f64,
    /// Mean of `(x - ref)^2 / (ref^2 + 1e-4)` (pbrt's relMSE; the 1e-4 keeps black pixels
    /// from dominating).
    pub rel_mse: f64,
}

pub fn layer_error(film: &Film, layer: usize, reference: &[DVec3]) -> LayerError {
    let (mut mse, mut rel) = (0.0, 0.0);
    for (x, r) in film.layer(layer).iter().zip(reference) {
        let e2 = (*x - *r) * (*x - *r);
        mse += e2.element_sum();
        rel += (e2 / (*r * *r + DVec3::splat(1e-4))).element_sum();
    }
    let n = 3.0 * reference.len() as f64;
    LayerError {
        mse: mse / n,
        rel_mse: rel / n,
    }
}

/// Least-squares slope of `ln y` against `ln x` over points with `y > 0`; `None` with
/// fewer than two such points (an exact layer has MSE 0 at every step).
pub fn loglog_slope(points: &[(f64, f64)]) -> Option<f64> {
    let p: Vec<(f64, f64)> = points
        .iter()
        .filter(|(x, y)| *x > 0.0 && *y > 0.0)
        .map(|(x, y)| (x.ln(), y.ln()))
        .collect();
    if p.len() < 2 {
        return None;
    }
    let n = p.len() as f64;
    let mx = p.iter().map(|q| q.0).sum::<f64>() / n;
    let my = p.iter().map(|q| q.1).sum::<f64>() / n;
    let sxy: f64 = p.iter().map(|q| (q.0 - mx) * (q.1 - my)).sum();
    let sxx: f64 = p.iter().map(|q| (q.0 - mx).powi(2)).sum();
    (sxx > 0.0).then(|| sxy / sxx)
}

/// How much to run.
#[derive(Clone, Debug)]
pub struct Config {
    pub plane_res: usize,
    pub cornell_res: usize,
    /// spp steps are 1, 2, 4, ... up to this.
    pub max_spp: u32,
    pub cornell_max_spp: u32,
    pub cornell_ref_spp: u32,
    pub seed: u64,
    pub threads: Option<usize>,
    /// Samples of the one-pixel accumulation comparison.
    pub mixed_spp: u32,
}

impl Config {
    pub fn default_run() -> Config {
        Config {
            plane_res: 48,
            cornell_res: 32,
            max_spp: 256,
            cornell_max_spp: 128,
            cornell_ref_spp: 4096,
            seed: 7,
            threads: None,
            mixed_spp: 10_000_000,
        }
    }

    /// Seconds, for CI.
    pub fn quick() -> Config {
        Config {
            plane_res: 12,
            cornell_res: 8,
            max_spp: 16,
            cornell_max_spp: 8,
            cornell_ref_spp: 128,
            seed: 7,
            threads: None,
            mixed_spp: 100_000,
        }
    }
}

/// Renders `known` with `variant` at spp 1, 2, 4, ... `max_spp`.
pub fn run_variant(
    known: &Known,
    variant: &Variant,
    max_spp: u32,
    cfg: &Config,
    lobes: &LobeMap,
) -> Result<Vec<Point>, VerifyError> {
    let mut scene = known.scene.clone();
    if let Some(k) = variant.clamp {
        let mean = known.reference[0]
            .iter()
            .map(|v| v.element_sum() / 3.0)
            .sum::<f64>()
            / known.reference[0].len() as f64;
        scene.settings.clamp = Some((k * mean) as f32);
    }
    let mut out = Vec::new();
    let mut spp = 1;
    while spp <= max_spp {
        let settings = Settings {
            width: known.width,
            height: known.height,
            spp,
            seed: cfg.seed,
            threads: cfg.threads,
            technique: variant.technique,
            russian_roulette: variant.russian_roulette,
            accumulation: variant.accumulation,
            ..Settings::default()
        };
        let r = variant
            .engine
            .render(&scene, &known.aovs, lobes, &settings)?;
        let partition_error = known
            .aovs
            .partitions
            .first()
            .map(|p| crate::verify::invariants::partition(&r.film, &known.aovs, p).measured);
        for (layer, reference) in known.reference.iter().enumerate() {
            let e = layer_error(&r.film, layer, reference);
            out.push(Point {
                scene: known.scene.name.clone(),
                variant: variant.name.clone(),
                layer: if layer == 0 {
                    "beauty".into()
                } else {
                    known.aovs.aovs[layer - 1].name.clone()
                },
                spp,
                seconds: r.seconds,
                mse: e.mse,
                rel_mse: e.rel_mse,
                partition_error,
            });
        }
        spp *= 2;
    }
    Ok(out)
}

pub fn summarize(points: &[Point]) -> Vec<Summary> {
    let mut keys: Vec<(String, String, String)> = Vec::new();
    for p in points {
        let k = (p.scene.clone(), p.variant.clone(), p.layer.clone());
        if !keys.contains(&k) {
            keys.push(k);
        }
    }
    keys.into_iter()
        .map(|(scene, variant, layer)| {
            let series: Vec<&Point> = points
                .iter()
                .filter(|p| p.scene == scene && p.variant == variant && p.layer == layer)
                .collect();
            let last = series.last().expect("a key comes from a point");
            let slope = loglog_slope(
                &series
                    .iter()
                    .map(|p| (p.spp as f64, p.mse))
                    .collect::<Vec<_>>(),
            );
            Summary {
                last: (*last).clone(),
                slope,
                efficiency: 1.0 / (last.mse * last.seconds),
            }
        })
        .collect()
}

/// What [`run`] wrote.
pub struct Outcome {
    pub summary: Vec<Summary>,
    /// Markdown table: basic-AOV partition error of every film ([`Accumulation::ALL`]) after
    /// [`Config::mixed_spp`] mixed samples in one pixel.
    pub accumulation: String,
    pub files: Vec<std::path::PathBuf>,
    /// Whether the plots have text (a font was found).
    pub plot_text: bool,
}

/// `lpe-render converge`: every variant on every known scene, then CSV, Markdown and
/// plots in `out`.
pub fn run(cfg: &Config, out: &Path, log: &mut dyn FnMut(&str)) -> Result<Outcome, VerifyError> {
    std::fs::create_dir_all(out).map_err(OutputError::write(out))?;
    let lobes = LobeMap::default();
    let (pr, cr) = (cfg.plane_res, cfg.cornell_res);
    log("references: closed forms, and cornell from the cache or a fresh render");
    let scenes: Vec<(Known, u32)> = vec![
        (furnace(pr, pr, &lobes)?, cfg.max_spp),
        (point_over_plane(pr, pr, &lobes)?, cfg.max_spp),
        (sphere_over_plane(pr, pr, SPHERE.1, &lobes)?, cfg.max_spp),
        (
            cornell(cr, cr, cfg.cornell_ref_spp, out, &lobes)?,
            cfg.cornell_max_spp,
        ),
    ];
    let mut points = Vec::new();
    for (known, max_spp) in &scenes {
        for v in Variant::all() {
            let t0 = std::time::Instant::now();
            points.extend(run_variant(known, &v, *max_spp, cfg, &lobes)?);
            log(&format!(
                "{} / {}: spp 1..{max_spp} in {:.1}s",
                known.scene.name,
                v.name,
                t0.elapsed().as_secs_f64()
            ));
        }
    }
    let summary = summarize(&points);
    // The film's accumulation where it matters: many samples of mixed magnitude in one
    // pixel (the stress set's scene), basic AOVs against beauty for both films.
    let mixed_spp = cfg.mixed_spp;
    let t0 = std::time::Instant::now();
    let (errors, _) = crate::verify::stress::mixed_partition(mixed_spp, &lobes)?;
    log(&format!(
        "{mixed_spp} mixed samples, every film: {:.1}s",
        t0.elapsed().as_secs_f64()
    ));
    let accumulation = tables::accumulation(&errors, mixed_spp);
    let mut files = Vec::new();
    let mut write = |name: &str, text: String| -> Result<(), VerifyError> {
        let f = out.join(name);
        crate::output::write_file(&f, text.as_bytes())?;
        files.push(f);
        Ok(())
    };
    write("converge.csv", tables::csv(&points)?)?;
    let mut md = String::from("# lpe-render converge\n\nReferences:\n");
    for (k, _) in &scenes {
        md += &format!("- `{}`: {}\n", k.scene.name, k.source);
    }
    md += "\n";
    md += &tables::converge(&summary, &[]);
    md += "\n## Accumulation\n\n";
    md += &accumulation;
    write("converge.md", md)?;
    write(
        "converge.json",
        serde_json::to_string_pretty(&summary).map_err(OutputError::from)?,
    )?;
    // Error against time, beauty, one panel per scene.
    let panels: Vec<crate::verify::plot::Panel> = scenes
        .iter()
        .map(|(k, _)| crate::verify::plot::Panel {
            title: format!("{} (beauty)", k.scene.name),
            lines: Variant::all()
                .iter()
                .map(|v| crate::verify::plot::Line {
                    label: v.name.clone(),
                    points: points
                        .iter()
                        .filter(|p| {
                            p.scene == k.scene.name && p.variant == v.name && p.layer == "beauty"
                        })
                        .map(|p| (p.seconds, p.rel_mse))
                        .collect(),
                })
                .collect(),
        })
        .collect();
    let plot_text =
        crate::verify::plot::write(out, "converge", &panels, "render time (s)", "relMSE")?;
    files.push(out.join("converge.png"));
    files.push(out.join("converge.svg"));
    Ok(Outcome {
        summary,
        accumulation,
        files,
        plot_text,
    })
}
