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

use glam::DVec3;
use lpe::{LobeMap, Parser};
use serde::Serialize;
use std::path::Path;

use crate::aovs::AovList;
use crate::camera::Camera;
use crate::film::{Accumulation, Film};
use crate::integrator::{Render, Settings, Technique};
#[cfg(feature = "engines")]
use crate::matcher::CheckEngine;
use crate::matcher::{Reference, WholePathMatcher};
use crate::scene::Scene;

/// The LPE engines `converge` can time. Each renders the same image (same paths, same
/// AOV masks); only the cost differs. A new engine is one arm in [`Engine::render`] and
/// one entry in [`Engine::ALL`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Engine {
    /// The fast matcher's DFA (`lpe::aov::AovSet`), as renders use it (the default).
    FastDfa,
    /// The fast matcher with its DFA budget at 0: the bitset NFA stepped per vertex.
    BitsetNfa,
    /// The regex-automata engine of `lpe-check` (`oracle`: lazy DFA over the encoded
    /// path), run on every emitter reached. Only with the `engines` feature.
    #[cfg(feature = "engines")]
    Oracle,
    /// `reference::is_match`, memoized per distinct vertex sequence.
    ReferenceMemo,
    /// `reference::is_match` on every emitter reached: the verification engine's cost.
    ReferenceDirect,
}

impl Engine {
    #[cfg(feature = "engines")]
    pub const ALL: [Engine; 5] = [
        Engine::FastDfa,
        Engine::BitsetNfa,
        Engine::Oracle,
        Engine::ReferenceMemo,
        Engine::ReferenceDirect,
    ];
    #[cfg(not(feature = "engines"))]
    pub const ALL: [Engine; 4] = [
        Engine::FastDfa,
        Engine::BitsetNfa,
        Engine::ReferenceMemo,
        Engine::ReferenceDirect,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Engine::FastDfa => "fast-dfa",
            Engine::BitsetNfa => "bitset-nfa",
            #[cfg(feature = "engines")]
            Engine::Oracle => "oracle",
            Engine::ReferenceMemo => "reference-memo",
            Engine::ReferenceDirect => "reference-direct",
        }
    }

    pub fn render(
        self,
        scene: &Scene,
        aovs: &AovList,
        lobes: &LobeMap,
        settings: &Settings,
    ) -> Result<Render, String> {
        let lpes = aovs.lpes();
        let fast = |dfa_budget| {
            let opts = lpe::aov::Options {
                dfa_budget,
                ..lpe::aov::Options::default()
            };
            lpe::aov::AovSet::compile_with(&aovs.named(), &opts).map_err(|e| e.to_string())
        };
        use crate::app::render_with;
        let quiet = &mut |_: &crate::plan::Plan| {};
        match self {
            Engine::FastDfa => {
                let set = fast(lpe::aov::Options::default().dfa_budget)?;
                render_with(&set, scene, aovs, lobes, settings, quiet)
            }
            Engine::BitsetNfa => render_with(&fast(0)?, scene, aovs, lobes, settings, quiet),
            #[cfg(feature = "engines")]
            Engine::Oracle => {
                let m = WholePathMatcher::direct(CheckEngine::new(&engines::regex::LAZY, &lpes)?);
                render_with(&m, scene, aovs, lobes, settings, quiet)
            }
            Engine::ReferenceMemo => {
                let m = WholePathMatcher::memoized(Reference::new(&lpes)?);
                render_with(&m, scene, aovs, lobes, settings, quiet)
            }
            Engine::ReferenceDirect => {
                let m = WholePathMatcher::direct(Reference::new(&lpes)?);
                render_with(&m, scene, aovs, lobes, settings, quiet)
            }
        }
    }
}

/// One way of rendering: a row group of the table.
#[derive(Clone, Debug, Serialize)]
pub struct Variant {
    pub name: String,
    pub technique: Technique,
    pub russian_roulette: bool,
    /// Clamp at this multiple of the reference's mean beauty (None: the scene's own).
    pub clamp: Option<f64>,
    pub accumulation: Accumulation,
    pub engine: Engine,
}

impl Variant {
    fn base(name: &str) -> Variant {
        Variant {
            name: name.into(),
            technique: Technique::Mis,
            russian_roulette: true,
            clamp: None,
            accumulation: Accumulation::F64,
            engine: Engine::FastDfa,
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
        for e in Engine::ALL.into_iter().skip(1) {
            v.push(Variant {
                engine: e,
                ..Variant::base(&format!("MIS, {}", e.name()))
            });
        }
        v
    }
}

/// A scene with a reference value for every pixel of beauty and of each AOV.
pub struct Known {
    pub scene: Scene,
    pub aovs: AovList,
    pub width: usize,
    pub height: usize,
    /// `reference[layer][pixel]`, layer 0 beauty, `1 + i` AOV `i`, pixels row-major.
    pub reference: Vec<Vec<DVec3>>,
    /// How the reference was obtained (for the table).
    pub source: String,
}

/// Albedo of the plane in the plane scenes.
pub const PLANE_ALBEDO: f64 = 0.5;

/// The plane scenes: a large diffuse quad at y = 0 seen from above, lit by one light
/// that stays out of frame, so beauty is exactly the direct diffuse term `C<RD>L`.
pub fn plane_scene(name: &str, light: &str) -> String {
    format!(
        r#"name = "{name}"
[camera]
position = [0.0, 4.0, 4.0]
look_at = [0.0, 0.0, 0.0]
fov = 40.0
[materials.floor]
lobes = [{{ name = "Diffuse", model = "lambert", albedo = [{a}, {a}, {a}] }}]
[[objects]]
material = "floor"
quad = {{ corner = [-50.0, 0.0, 50.0], u = [100.0, 0.0, 0.0], v = [0.0, 0.0, -100.0] }}
[[lights]]
{light}
"#,
        a = PLANE_ALBEDO
    )
}

/// Point light: `L = (a / pi) I cos / d^2` (Lambert BRDF times irradiance).
pub const POINT: ([f32; 3], f64) = ([1.5, 2.0, -0.5], 10.0);
/// Sphere light: center, radius, radiance. Fully above the plane's horizon, it gives
/// irradiance `pi Le (R/d)^2 cos`, so `L = a Le (R/d)^2 cos`.
pub const SPHERE: ([f32; 3], f64, f64) = ([3.5, 1.5, -1.0], 0.5, 8.0);

/// Sub-pixel grid for averaging closed forms over a pixel's footprint (the renderer
/// jitters within the pixel, so the pixel's expectation is that average). 16 x 16
/// midpoints: relative quadrature error ~1e-6 here, far below the noise of any step.
const FOOTPRINT: usize = 16;

/// Closed form over each pixel's footprint for a plane scene; `radiance(x)` is the
/// outgoing radiance at plane point `x` (y = 0).
pub fn plane_reference(
    scene: &Scene,
    width: usize,
    height: usize,
    radiance: impl Fn(DVec3) -> f64,
) -> Vec<DVec3> {
    let c = &scene.camera;
    let cam = Camera::new(
        c.position,
        c.look_at,
        c.up,
        c.fov,
        width as f32 / height as f32,
    );
    let mut out = Vec::with_capacity(width * height);
    for y in 0..height {
        for x in 0..width {
            let mut sum = 0.0;
            for j in 0..FOOTPRINT {
                for i in 0..FOOTPRINT {
                    let sx = (x as f64 + (i as f64 + 0.5) / FOOTPRINT as f64) / width as f64;
                    let sy = (y as f64 + (j as f64 + 0.5) / FOOTPRINT as f64) / height as f64;
                    let ray = cam.ray(sx as f32, sy as f32);
                    let (o, d) = (ray.o.as_dvec3(), ray.d.as_dvec3());
                    if d.y < 0.0 {
                        let p = o + d * (-o.y / d.y);
                        if p.x.abs() <= 50.0 && p.z.abs() <= 50.0 {
                            sum += radiance(p);
                        }
                    }
                }
            }
            out.push(DVec3::splat(sum / (FOOTPRINT * FOOTPRINT) as f64));
        }
    }
    out
}

fn load(text: &str, name: &str, lobes: &LobeMap) -> Result<Scene, String> {
    Scene::from_toml(text, name, lobes).map_err(|e| e.to_string())
}

/// `[[lights]]` body of a point light of intensity `i` (grey) at `p`.
pub fn point_light_toml(p: [f32; 3], i: f64, group: Option<&str>) -> String {
    let [x, y, z] = p;
    let group = group.map_or(String::new(), |g| format!("group = \"{g}\"\n"));
    format!(
        "kind = \"point\"\n{group}position = [{x}, {y}, {z}]\nintensity = [{i:e}, {i:e}, {i:e}]"
    )
}

/// Radiance leaving the plane point `x` lit by a point light of intensity `i` at `l`:
/// `(a / pi) I cos / d^2`.
pub fn point_radiance(l: DVec3, i: f64) -> impl Fn(DVec3) -> f64 {
    move |x| {
        let d = l - x;
        let d2 = d.length_squared();
        PLANE_ALBEDO / std::f64::consts::PI * i * (d.y / d2.sqrt()) / d2
    }
}

/// The point light over the plane.
pub fn point_over_plane(width: usize, height: usize, lobes: &LobeMap) -> Result<Known, String> {
    let (p, i) = POINT;
    let text = plane_scene("point-over-plane", &point_light_toml(p, i, None));
    let scene = load(&text, "point-over-plane", lobes)?;
    let l = glam::Vec3::from(p).as_dvec3();
    let reference = plane_reference(&scene, width, height, point_radiance(l, i));
    direct_known(
        scene,
        width,
        height,
        reference,
        "closed form (a/pi) I cos/d^2",
    )
}

/// The sphere light over the plane, radius `radius` and radiance scaled so its power
/// equals that of [`SPHERE`] (the hard-case tests shrink it to 1e-6).
pub fn sphere_over_plane(
    width: usize,
    height: usize,
    radius: f64,
    lobes: &LobeMap,
) -> Result<Known, String> {
    let ([cx, cy, cz], r0, le0) = SPHERE;
    let le = le0 * (r0 / radius).powi(2);
    let text = plane_scene(
        "sphere-over-plane",
        &format!(
            "kind = \"sphere\"\ncenter = [{cx}, {cy}, {cz}]\nradius = {radius:e}\nradiance = [{le:e}, {le:e}, {le:e}]"
        ),
    );
    let scene = load(&text, "sphere-over-plane", lobes)?;
    let c = DVec3::new(cx as f64, cy as f64, cz as f64);
    // The radiance actually stored is f32: use it, so the test measures the estimator.
    let (r, le) = match scene.lights[0].kind {
        crate::light::LightKind::Sphere {
            radius, radiance, ..
        } => (radius as f64, radiance.x as f64),
        _ => unreachable!("the scene text declares a sphere light"),
    };
    let reference = plane_reference(&scene, width, height, |x| {
        let d = c - x;
        let d2 = d.length_squared();
        PLANE_ALBEDO * le * (r * r / d2) * (d.y / d2.sqrt())
    });
    direct_known(
        scene,
        width,
        height,
        reference,
        "closed form a Le (R/d)^2 cos",
    )
}

/// Beauty and `direct = C<RD>L` share the plane scenes' reference.
fn direct_known(
    scene: Scene,
    width: usize,
    height: usize,
    reference: Vec<DVec3>,
    source: &str,
) -> Result<Known, String> {
    let mut aovs = AovList::default();
    aovs.push("direct", "C<RD>L", &Parser::default())?;
    Ok(Known {
        scene,
        aovs,
        width,
        height,
        reference: vec![reference.clone(), reference],
        source: source.into(),
    })
}

/// Bounce AOVs of the furnace in the table.
const FURNACE_BOUNCES: u32 = 3;

/// The furnace: beauty `Le/(1-a)`, `C<RD>{k}O` = `Le a^k`, at every pixel.
pub fn furnace(width: usize, height: usize, lobes: &LobeMap) -> Result<Known, String> {
    let scene = Scene::load("furnace", lobes).map_err(|e| e.to_string())?;
    let (a, le) = crate::app::furnace_params(&scene).ok_or("furnace: unexpected scene")?;
    let mut aovs = AovList::default();
    let mut reference = vec![vec![DVec3::splat(le / (1.0 - a)); width * height]];
    for k in 0..=FURNACE_BOUNCES {
        aovs.push(
            &format!("bounce{k}"),
            &format!("C<RD>{{{k}}}O"),
            &Parser::default(),
        )?;
        reference.push(vec![DVec3::splat(le * a.powi(k as i32)); width * height]);
    }
    Ok(Known {
        scene,
        aovs,
        width,
        height,
        reference,
        source: "closed form Le/(1-a), Le a^k".into(),
    })
}

/// `cornell` with the seven basic AOVs against an MIS render at `ref_spp` with its own
/// seed, cached in `cache_dir` (the file names its size, spp and seed, so a cache never
/// stands in for another reference).
pub fn cornell(
    width: usize,
    height: usize,
    ref_spp: u32,
    cache_dir: &Path,
    lobes: &LobeMap,
) -> Result<Known, String> {
    let scene = Scene::load("cornell", lobes).map_err(|e| e.to_string())?;
    let parser = Parser::default();
    let aovs = AovList::basic(&parser)?;
    const REF_SEED: u64 = 0x5EED_CAFE;
    let file = cache_dir.join(format!(
        "converge_ref_cornell_{width}x{height}_{ref_spp}spp_{REF_SEED:x}.bin"
    ));
    let layers = 1 + aovs.aovs.len();
    let reference = match read_cache(&file, width * height * layers) {
        Some(flat) => flat,
        None => {
            let settings = Settings {
                width,
                height,
                spp: ref_spp,
                seed: REF_SEED,
                ..Settings::default()
            };
            let r = Engine::FastDfa.render(&scene, &aovs, lobes, &settings)?;
            let flat: Vec<DVec3> = (0..layers).flat_map(|l| r.film.layer(l)).collect();
            write_cache(&file, &flat)?;
            flat
        }
    };
    Ok(Known {
        scene,
        aovs,
        width,
        height,
        reference: reference
            .chunks(width * height)
            .map(<[_]>::to_vec)
            .collect(),
        source: format!("MIS render at {ref_spp} spp, cached in {}", file.display()),
    })
}

fn read_cache(file: &Path, n: usize) -> Option<Vec<DVec3>> {
    let bytes = std::fs::read(file).ok()?;
    if bytes.len() != n * 24 {
        return None;
    }
    let f = |i: usize| f64::from_le_bytes(bytes[i * 8..i * 8 + 8].try_into().expect("8 bytes"));
    Some(
        (0..n)
            .map(|i| DVec3::new(f(3 * i), f(3 * i + 1), f(3 * i + 2)))
            .collect(),
    )
}

fn write_cache(file: &Path, data: &[DVec3]) -> Result<(), String> {
    let bytes: Vec<u8> = data
        .iter()
        .flat_map(|v| v.to_array())
        .flat_map(f64::to_le_bytes)
        .collect();
    crate::output::atomic_write(file, &bytes).map_err(|e| format!("{}: {e}", file.display()))
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

/// One measurement: a variant on a scene at one spp, one layer.
#[derive(Clone, Debug, Serialize)]
pub struct Point {
    pub scene: String,
    pub variant: String,
    pub layer: String,
    pub spp: u32,
    pub seconds: f64,
    pub mse: f64,
    pub rel_mse: f64,
    /// Largest relative error of the basic-AOV partition vs beauty (cornell only).
    pub partition_error: Option<f64>,
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
) -> Result<Vec<Point>, String> {
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
            .map(|p| crate::check::partition(&r.film, &known.aovs, p).measured);
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

/// One row of the summary: a (scene, variant, layer) series at its largest spp.
#[derive(Clone, Debug, Serialize)]
pub struct Summary {
    /// The series' measurement at its largest spp.
    #[serde(flatten)]
    pub last: Point,
    /// Slope of ln MSE vs ln spp (None: MSE is 0, the layer is exact).
    pub slope: Option<f64>,
    /// `1 / (MSE x seconds)` at the largest spp.
    pub efficiency: f64,
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

pub fn csv(points: &[Point]) -> String {
    let mut s = String::from("scene,variant,layer,spp,seconds,mse,rel_mse,partition_error\n");
    for p in points {
        s += &format!(
            "{},\"{}\",{},{},{:.6},{:.6e},{:.6e},{}\n",
            p.scene,
            p.variant,
            p.layer,
            p.spp,
            p.seconds,
            p.mse,
            p.rel_mse,
            p.partition_error
                .map_or(String::new(), |e| format!("{e:.3e}"))
        );
    }
    s
}

/// The Markdown table of [`Summary`] rows (`layers`: which layers to include, all if
/// empty).
pub fn markdown(rows: &[Summary], layers: &[&str]) -> String {
    let mut s = String::from(
        "| scene | variant | layer | spp | time s | MSE | relMSE | slope | efficiency 1/(MSE·s) | partition err |\n\
         |---|---|---|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for r in rows
        .iter()
        .filter(|r| layers.is_empty() || layers.contains(&r.last.layer.as_str()))
    {
        let p = &r.last;
        s += &format!(
            "| {} | {} | {} | {} | {:.3} | {:.3e} | {:.3e} | {} | {} | {} |\n",
            p.scene,
            p.variant,
            p.layer,
            p.spp,
            p.seconds,
            p.mse,
            p.rel_mse,
            r.slope.map_or("exact".into(), |x| format!("{x:.2}")),
            if p.mse > 0.0 {
                format!("{:.3e}", r.efficiency)
            } else {
                "∞".into()
            },
            p.partition_error.map_or("".into(), |e| format!("{e:.1e}")),
        );
    }
    s
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
pub fn run(cfg: &Config, out: &Path, log: &mut dyn FnMut(&str)) -> Result<Outcome, String> {
    std::fs::create_dir_all(out).map_err(|e| format!("{}: {e}", out.display()))?;
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
    let (errors, _) = crate::stress::mixed_partition(mixed_spp, &lobes)?;
    log(&format!(
        "{mixed_spp} mixed samples, every film: {:.1}s",
        t0.elapsed().as_secs_f64()
    ));
    let mut accumulation = String::from(
        "| film | samples in the pixel | basic AOVs vs beauty (max rel.) | within 1e-6 |\n\
         |---|---:|---:|---|\n",
    );
    for (a, e) in errors {
        accumulation += &format!(
            "| {} | {mixed_spp} | {e:.2e} | {} |\n",
            a.name(),
            if e <= 1e-6 { "yes" } else { "**no**" }
        );
    }
    let mut files = Vec::new();
    let mut write = |name: &str, text: String| -> Result<(), String> {
        let f = out.join(name);
        crate::output::atomic_write(&f, text.as_bytes())
            .map_err(|e| format!("{}: {e}", f.display()))?;
        files.push(f);
        Ok(())
    };
    write("converge.csv", csv(&points))?;
    let mut md = String::from("# lpe-render converge\n\nReferences:\n");
    for (k, _) in &scenes {
        md += &format!("- `{}`: {}\n", k.scene.name, k.source);
    }
    md += "\n";
    md += &markdown(&summary, &[]);
    md += "\n## Accumulation\n\n";
    md += &accumulation;
    write("converge.md", md)?;
    write(
        "converge.json",
        serde_json::to_string_pretty(&summary).map_err(|e| e.to_string())?,
    )?;
    // Error against time, beauty, one panel per scene.
    let panels: Vec<crate::plot::Panel> = scenes
        .iter()
        .map(|(k, _)| crate::plot::Panel {
            title: format!("{} (beauty)", k.scene.name),
            lines: Variant::all()
                .iter()
                .map(|v| crate::plot::Line {
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
    let plot_text = crate::plot::write(out, "converge", &panels, "render time (s)", "relMSE")?;
    files.push(out.join("converge.png"));
    files.push(out.join("converge.svg"));
    Ok(Outcome {
        summary,
        accumulation,
        files,
        plot_text,
    })
}
