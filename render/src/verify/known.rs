//! Known-answer scenes: scenes whose every pixel has a reference value (closed forms, or
//! a cached high-spp render), shared by `converge`, `stress` and the hard-case tests. The
//! scene bodies are TOML files under `verify/scenes/`; only what varies (a light, a name)
//! is added as text.

use super::VerifyError;
use glam::{DVec3, Vec3};
use lpe::renderman::{LobeMap, Parser};
use std::path::Path;

use super::matcher_row::MatcherRow;
use crate::aov::AovList;
use crate::camera::Camera;
use crate::integrator::Settings;
pub use crate::scene::furnace::{furnace_params, FURNACE_BOUNCES};
use crate::scene::Scene;
use lpe::renderman::RenderMan;

/// A scene with a reference value for every pixel of beauty and of each AOV.
pub struct Known {
    pub scene: Scene,
    pub aovs: AovList<RenderMan>,
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
    format!("name = \"{name}\"\n{PLANE}[[lights]]\n{light}\n")
}

/// The plane scenes' body (no name, no light).
const PLANE: &str = include_str!("scenes/plane.toml");

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

fn load(text: &str, name: &str, lobes: &LobeMap) -> Result<Scene, VerifyError> {
    Ok(Scene::from_toml(text, name, lobes)?)
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
pub fn point_over_plane(
    width: usize,
    height: usize,
    lobes: &LobeMap,
) -> Result<Known, VerifyError> {
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
) -> Result<Known, VerifyError> {
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
) -> Result<Known, VerifyError> {
    let mut aovs = AovList::<RenderMan>::new();
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
const CONVERGE_FURNACE_BOUNCES: u32 = 3;

/// The furnace: beauty `Le/(1-a)`, `C<RD>{k}O` = `Le a^k`, at every pixel.
pub fn furnace(width: usize, height: usize, lobes: &LobeMap) -> Result<Known, VerifyError> {
    let scene = Scene::load("furnace", lobes)?;
    let (a, le) = furnace_params(&scene).ok_or_else(|| VerifyError::NotAFurnace {
        scene: scene.name.clone(),
    })?;
    let mut aovs = AovList::<RenderMan>::new();
    let mut reference = vec![vec![DVec3::splat(le / (1.0 - a)); width * height]];
    for k in 0..=CONVERGE_FURNACE_BOUNCES {
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
) -> Result<Known, VerifyError> {
    let scene = Scene::load("cornell", lobes)?;
    let parser = Parser::default();
    let aovs = AovList::<RenderMan>::basic(&parser)?;
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
            let r = MatcherRow::Fast.render(&scene, &aovs, lobes, &settings)?;
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

fn write_cache(file: &Path, data: &[DVec3]) -> Result<(), VerifyError> {
    let bytes: Vec<u8> = data
        .iter()
        .flat_map(|v| v.to_array())
        .flat_map(f64::to_le_bytes)
        .collect();
    Ok(crate::output::write_file(file, &bytes)?)
}

/// Point lights with intensities 1e-6 .. 1e12 over the plane, one light group each.
pub const INTENSITIES: [(f64, [f32; 3]); 4] = [
    (1e-6, [1.0, 2.0, 0.0]),
    (1.0, [-1.0, 2.0, 0.5]),
    (1e6, [0.0, 3.0, -1.0]),
    (1e12, [0.5, 1.5, 1.0]),
];

/// The plane lit by [`INTENSITIES`], with AOV `gK = C<RD><L.'gK'>` per light.
pub fn intensities_scene(lobes: &LobeMap) -> Result<(Scene, AovList<RenderMan>), VerifyError> {
    let text: Vec<String> = INTENSITIES
        .iter()
        .enumerate()
        .map(|(k, (i, p))| point_light_toml(*p, *i, Some(&format!("g{k}"))))
        .collect();
    let scene = Scene::from_toml(
        &plane_scene("intensities", &text.join("\n[[lights]]\n")),
        "intensities",
        lobes,
    )?;
    let mut aovs = AovList::<RenderMan>::new();
    for k in 0..INTENSITIES.len() {
        aovs.push(
            &format!("g{k}"),
            &format!("C<RD><L.'g{k}'>"),
            &Parser::default(),
        )?;
    }
    Ok((scene, aovs))
}

/// Closed form of light `k` of [`INTENSITIES`]: `(a/pi) I cos / d^2`, with I as stored.
pub fn intensity_reference(scene: &Scene, k: usize, w: usize, h: usize) -> Vec<DVec3> {
    let (i, p) = INTENSITIES[k];
    // The scene stores I as f32: compare against that value.
    plane_reference(
        scene,
        w,
        h,
        point_radiance(Vec3::from(p).as_dvec3(), i as f32 as f64),
    )
}

/// A near-mirror (alpha 1e-7: pdf peak ~1e13) and a 1e-6 sphere light (light pdf
/// ~1e12) with a point light and a dome: MIS between densities from 0 to ~1e13.
pub const MIS_EXTREMES: &str = include_str!("scenes/mis-extremes.toml");

/// Samples spanning many magnitudes that reach every basic AOV: a diffuse + glossy
/// floor, a glowing ball, a glass ball, lights from 1e-3 to 1e3.
pub const MIXED: &str = include_str!("scenes/mixed.toml");

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_plane_file_has_the_albedo_the_closed_forms_use() {
        let scene = Scene::from_toml(
            &plane_scene("p", &point_light_toml(POINT.0, POINT.1, None)),
            "p",
            &LobeMap::default(),
        )
        .unwrap();
        let crate::material::Model::Lambert { albedo } = scene.materials[0].lobes[0].model else {
            panic!("the plane is Lambertian");
        };
        assert_eq!(albedo, Vec3::splat(PLANE_ALBEDO as f32));
        assert_eq!(scene.name, "p");
    }
}
