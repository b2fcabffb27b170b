//! The TOML scene file format (serde) and its translation into a [`Scene`]. Unknown keys
//! are errors so that typos do not pass silently.

use glam::Vec3;
use lpe::renderman::LobeMap;
use serde::Deserialize;
use std::collections::BTreeMap;

use super::{
    CameraDesc, Object, Scene, SceneError, SceneProblem, SceneSettings, MAX_DEPTH_LIMIT, MAX_LABELS,
};
use crate::geometry::{Bvh, Shape};
use crate::light::{Light, LightKind};
use crate::material::{Lobe, Material, Model};

type Spanned<T> = toml::Spanned<T>;
pub(super) type BuildError = (Option<std::ops::Range<usize>>, SceneProblem);

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SceneFile {
    #[serde(default)]
    name: String,
    camera: CameraFile,
    #[serde(default)]
    render: RenderFile,
    #[serde(default)]
    materials: BTreeMap<String, Spanned<MaterialFile>>,
    #[serde(default)]
    objects: Vec<Spanned<ObjectFile>>,
    #[serde(default)]
    lights: Vec<Spanned<LightFile>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct CameraFile {
    position: [f32; 3],
    look_at: [f32; 3],
    #[serde(default = "default_up")]
    up: [f32; 3],
    #[serde(default = "default_fov")]
    fov: f32,
}

fn default_up() -> [f32; 3] {
    [0.0, 1.0, 0.0]
}

fn default_fov() -> f32 {
    40.0
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RenderFile {
    #[serde(default = "default_max_depth")]
    max_depth: u32,
    #[serde(default = "default_rr_depth")]
    rr_depth: u32,
    #[serde(default)]
    clamp: Option<f32>,
}

impl Default for RenderFile {
    fn default() -> Self {
        RenderFile {
            max_depth: default_max_depth(),
            rr_depth: default_rr_depth(),
            clamp: None,
        }
    }
}

fn default_max_depth() -> u32 {
    8
}

fn default_rr_depth() -> u32 {
    3
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct MaterialFile {
    #[serde(default)]
    lobes: Vec<LobeFile>,
    #[serde(default)]
    glow: Option<[f32; 3]>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LobeFile {
    /// The lobe's name, mapped to an LPE lobe by the lobe map (e.g. `Clearcoat` -> S4).
    name: String,
    /// `lambert`, `diffuse_transmission`, `ggx` or `dielectric`.
    model: String,
    albedo: Option<[f32; 3]>,
    f0: Option<[f32; 3]>,
    roughness: Option<f32>,
    ior: Option<f32>,
    tint: Option<[f32; 3]>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ObjectFile {
    #[serde(default)]
    name: String,
    material: String,
    lpegroup: Option<String>,
    #[serde(default)]
    holdout: bool,
    sphere: Option<SphereFile>,
    quad: Option<QuadFile>,
    #[serde(rename = "box")]
    cuboid: Option<BoxFile>,
    mesh: Option<MeshFile>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SphereFile {
    center: [f32; 3],
    radius: f32,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct QuadFile {
    corner: [f32; 3],
    u: [f32; 3],
    v: [f32; 3],
}

/// An axis-aligned box `min..max` rotated by `rotate_y` degrees about its center,
/// turned into a 12-triangle mesh.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct BoxFile {
    min: [f32; 3],
    max: [f32; 3],
    #[serde(default)]
    rotate_y: f32,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct MeshFile {
    vertices: Vec<[f32; 3]>,
    triangles: Vec<[u32; 3]>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LightFile {
    /// `quad`, `sphere`, `point`, `distant` or `dome`.
    kind: String,
    group: Option<String>,
    /// Area and dome lights.
    radiance: Option<[f32; 3]>,
    /// Point lights.
    intensity: Option<[f32; 3]>,
    /// Distant lights.
    irradiance: Option<[f32; 3]>,
    /// Distant lights: direction toward the light.
    direction: Option<[f32; 3]>,
    /// Point lights.
    position: Option<[f32; 3]>,
    corner: Option<[f32; 3]>,
    u: Option<[f32; 3]>,
    v: Option<[f32; 3]>,
    center: Option<[f32; 3]>,
    radius: Option<f32>,
}

/// A finite vector, or an error naming the field.
fn vec3(v: [f32; 3], what: &'static str) -> Result<Vec3, SceneProblem> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(Vec3::from(v))
    } else {
        Err(SceneProblem::NotFinite { what, value: v })
    }
}

fn color(v: [f32; 3], what: &'static str) -> Result<Vec3, SceneProblem> {
    let c = vec3(v, what)?;
    if c.min_element() < 0.0 {
        return Err(SceneProblem::Negative { what, value: v });
    }
    Ok(c)
}

fn positive(x: f32, what: &'static str) -> Result<f32, SceneProblem> {
    if x.is_finite() && x > 0.0 {
        Ok(x)
    } else {
        Err(SceneProblem::NotPositive { what, value: x })
    }
}

fn need<T>(x: Option<T>, what: &'static str, kind: &'static str) -> Result<T, SceneProblem> {
    x.ok_or(SceneProblem::Missing { kind, what })
}

impl LobeFile {
    fn build(&self, lobes: &LobeMap) -> Result<Lobe, SceneProblem> {
        let model = match self.model.as_str() {
            "lambert" => Model::Lambert {
                albedo: color(need(self.albedo, "albedo", "lambert lobe")?, "albedo")?,
            },
            "diffuse_transmission" => Model::DiffuseTransmission {
                albedo: color(
                    need(self.albedo, "albedo", "diffuse_transmission lobe")?,
                    "albedo",
                )?,
            },
            "ggx" => {
                let r = need(self.roughness, "roughness", "ggx lobe")?;
                if !(r.is_finite() && (0.0..=1.0).contains(&r)) {
                    return Err(SceneProblem::Roughness { value: r });
                }
                Model::Ggx {
                    f0: color(need(self.f0, "f0", "ggx lobe")?, "f0")?,
                    // Perceptual roughness squared, as in most shading systems.
                    alpha: r * r,
                }
            }
            "dielectric" => Model::Dielectric {
                ior: positive(need(self.ior, "ior", "dielectric lobe")?, "ior")?,
                tint: color(self.tint.unwrap_or([1.0; 3]), "tint")?,
            },
            other => {
                return Err(SceneProblem::UnknownLobeModel {
                    model: other.into(),
                })
            }
        };
        Ok(Lobe::new(&self.name, model, lobes))
    }
}

fn box_triangles(b: &BoxFile) -> Result<Vec<Shape>, SceneProblem> {
    let lo = vec3(b.min, "box min")?;
    let hi = vec3(b.max, "box max")?;
    if !(hi.cmpgt(lo).all()) {
        return Err(SceneProblem::EmptyBox);
    }
    let c = (lo + hi) * 0.5;
    let rot = glam::Quat::from_rotation_y(b.rotate_y.to_radians());
    let corner = |i: u32| {
        let p = Vec3::new(
            if i & 1 == 0 { lo.x } else { hi.x },
            if i & 2 == 0 { lo.y } else { hi.y },
            if i & 4 == 0 { lo.z } else { hi.z },
        );
        c + rot * (p - c)
    };
    // Faces as corner-index quads, counter-clockwise seen from outside.
    const FACES: [[u32; 4]; 6] = [
        [0, 2, 3, 1], // -z
        [4, 5, 7, 6], // +z
        [0, 1, 5, 4], // -y
        [2, 6, 7, 3], // +y
        [0, 4, 6, 2], // -x
        [1, 3, 7, 5], // +x
    ];
    let mut out = Vec::new();
    for f in FACES {
        let [a, b, c2, d] = f.map(corner);
        out.push(Shape::Triangle {
            p0: a,
            e1: b - a,
            e2: c2 - a,
        });
        out.push(Shape::Triangle {
            p0: a,
            e1: c2 - a,
            e2: d - a,
        });
    }
    Ok(out)
}

impl ObjectFile {
    fn shapes(&self) -> Result<Vec<Shape>, SceneProblem> {
        let given = [
            self.sphere.is_some(),
            self.quad.is_some(),
            self.cuboid.is_some(),
            self.mesh.is_some(),
        ];
        if given.iter().filter(|g| **g).count() != 1 {
            return Err(SceneProblem::ShapeCount);
        }
        if let Some(s) = &self.sphere {
            return Ok(vec![Shape::Sphere {
                center: vec3(s.center, "center")?,
                radius: positive(s.radius, "radius")?,
            }]);
        }
        if let Some(q) = &self.quad {
            let (u, v) = (vec3(q.u, "u")?, vec3(q.v, "v")?);
            if u.cross(v).length_squared() == 0.0 {
                return Err(SceneProblem::DegenerateQuad { light: false });
            }
            return Ok(vec![Shape::Quad {
                corner: vec3(q.corner, "corner")?,
                u,
                v,
            }]);
        }
        if let Some(b) = &self.cuboid {
            return box_triangles(b);
        }
        let m = self.mesh.as_ref().expect("one shape is set");
        let verts: Vec<Vec3> = m
            .vertices
            .iter()
            .map(|v| vec3(*v, "mesh vertex"))
            .collect::<Result<_, _>>()?;
        let mut out = Vec::new();
        for t in &m.triangles {
            let p = |i: u32| {
                verts
                    .get(i as usize)
                    .copied()
                    .ok_or(SceneProblem::TriangleIndex {
                        index: i,
                        vertices: verts.len(),
                    })
            };
            let (a, b, c) = (p(t[0])?, p(t[1])?, p(t[2])?);
            // Zero-area triangles can never be hit; skipping them keeps normals finite.
            if (b - a).cross(c - a).length_squared() > 0.0 {
                out.push(Shape::Triangle {
                    p0: a,
                    e1: b - a,
                    e2: c - a,
                });
            }
        }
        Ok(out)
    }
}

impl LightFile {
    fn build(&self) -> Result<LightKind, SceneProblem> {
        let k = self.kind.as_str();
        Ok(match k {
            "quad" => {
                let (u, v) = (
                    vec3(need(self.u, "u", "quad light")?, "u")?,
                    vec3(need(self.v, "v", "quad light")?, "v")?,
                );
                if u.cross(v).length_squared() == 0.0 {
                    return Err(SceneProblem::DegenerateQuad { light: true });
                }
                LightKind::Quad {
                    corner: vec3(need(self.corner, "corner", "quad light")?, "corner")?,
                    u,
                    v,
                    radiance: color(need(self.radiance, "radiance", "quad light")?, "radiance")?,
                }
            }
            "sphere" => LightKind::Sphere {
                center: vec3(need(self.center, "center", "sphere light")?, "center")?,
                radius: positive(need(self.radius, "radius", "sphere light")?, "radius")?,
                radiance: color(need(self.radiance, "radiance", "sphere light")?, "radiance")?,
            },
            "point" => LightKind::Point {
                position: vec3(need(self.position, "position", "point light")?, "position")?,
                intensity: color(
                    need(self.intensity, "intensity", "point light")?,
                    "intensity",
                )?,
            },
            "distant" => {
                let d = vec3(
                    need(self.direction, "direction", "distant light")?,
                    "direction",
                )?;
                if d.length_squared() == 0.0 {
                    return Err(SceneProblem::ZeroDirection);
                }
                LightKind::Distant {
                    direction: d.normalize(),
                    irradiance: color(
                        need(self.irradiance, "irradiance", "distant light")?,
                        "irradiance",
                    )?,
                }
            }
            "dome" => LightKind::Dome {
                radiance: color(need(self.radiance, "radiance", "dome light")?, "radiance")?,
            },
            other => return Err(SceneProblem::UnknownLightKind { kind: other.into() }),
        })
    }
}

impl Scene {
    /// Parses a TOML scene; `file` names it in errors.
    pub fn from_toml(text: &str, file: &str, lobes: &LobeMap) -> Result<Scene, SceneError> {
        let err = |span: Option<std::ops::Range<usize>>, problem: SceneProblem| SceneError {
            file: file.to_string(),
            line: span.map(|s| 1 + text[..s.start.min(text.len())].matches('\n').count()),
            problem,
        };
        let desc: SceneFile = toml::from_str(text).map_err(|e| {
            err(
                e.span(),
                SceneProblem::Toml {
                    message: e.message().to_string(),
                },
            )
        })?;
        desc.build(lobes)
            .map_err(|(span, problem)| err(span, problem))
    }
}

impl SceneFile {
    pub(super) fn build(self, lobe_map: &LobeMap) -> Result<Scene, BuildError> {
        let c = &self.camera;
        let at = |m: SceneProblem| (None, m);
        let camera = CameraDesc {
            position: vec3(c.position, "camera position").map_err(at)?,
            look_at: vec3(c.look_at, "camera look_at").map_err(at)?,
            up: vec3(c.up, "camera up").map_err(at)?,
            fov: positive(c.fov, "camera fov").map_err(at)?,
        };
        if (camera.look_at - camera.position)
            .cross(camera.up)
            .length_squared()
            == 0.0
        {
            return Err((None, SceneProblem::CameraAxis));
        }
        let r = &self.render;
        if r.max_depth == 0 || r.max_depth > MAX_DEPTH_LIMIT {
            return Err((
                None,
                SceneProblem::MaxDepth {
                    value: r.max_depth,
                    max: MAX_DEPTH_LIMIT,
                },
            ));
        }
        if let Some(cl) = r.clamp {
            positive(cl, "render.clamp").map_err(at)?;
        }
        let settings = SceneSettings {
            max_depth: r.max_depth,
            rr_depth: r.rr_depth,
            clamp: r.clamp,
        };

        let mut materials = Vec::new();
        let mut material_names = Vec::new();
        for (name, m) in &self.materials {
            let span = Some(m.span());
            let m = m.get_ref();
            let lobes = m
                .lobes
                .iter()
                .map(|l| l.build(lobe_map))
                .collect::<Result<Vec<_>, _>>()
                .map_err(|e| (span.clone(), e.in_material(name)))?;
            let glow = color(m.glow.unwrap_or([0.0; 3]), "glow")
                .map_err(|e| (span.clone(), e.in_material(name)))?;
            materials.push(Material::new(lobes, glow));
            material_names.push(name.clone());
        }

        let mut objects = Vec::new();
        let mut prims = Vec::new();
        for (i, o) in self.objects.iter().enumerate() {
            let span = Some(o.span());
            let o = o.get_ref();
            let name = if o.name.is_empty() {
                format!("object{i}")
            } else {
                o.name.clone()
            };
            let material = material_names
                .iter()
                .position(|n| *n == o.material)
                .ok_or_else(|| {
                    (
                        span.clone(),
                        SceneProblem::UnknownMaterial {
                            material: o.material.clone(),
                            defined: material_names.join(", "),
                        }
                        .in_object(&name),
                    )
                })?;
            let shapes = o.shapes().map_err(|e| (span.clone(), e.in_object(&name)))?;
            let id = objects.len() as u32;
            prims.extend(shapes.into_iter().map(|s| (s, id)));
            objects.push(Object {
                name,
                material: Some(material),
                lpegroup: o.lpegroup.clone(),
                holdout: o.holdout,
                light: None,
            });
        }

        let mut lights = Vec::new();
        for l in &self.lights {
            let span = Some(l.span());
            let lf = l.get_ref();
            let kind = lf
                .build()
                .map_err(|e| (span.clone(), e.in_light(lights.len())))?;
            let light = Light {
                kind,
                group: lf.group.clone(),
            };
            if let Some(shape) = light.shape() {
                let id = objects.len() as u32;
                prims.push((shape, id));
                objects.push(Object {
                    name: format!("light{}", lights.len()),
                    material: None,
                    lpegroup: None,
                    holdout: false,
                    light: Some(lights.len()),
                });
            }
            lights.push(light);
        }
        // Labels become distinct matcher vertices (label x event x R/T); bounding them
        // keeps every scene within the matcher's class space (see `aov::matcher`).
        let mut labels: Vec<&str> = objects
            .iter()
            .filter_map(|o| o.lpegroup.as_deref())
            .chain(lights.iter().filter_map(|l| l.group.as_deref()))
            .collect();
        labels.sort_unstable();
        labels.dedup();
        if labels.len() > MAX_LABELS {
            return Err((
                None,
                SceneProblem::TooManyLabels {
                    labels: labels.len(),
                    max: MAX_LABELS,
                },
            ));
        }
        if lights
            .iter()
            .filter(|l| matches!(l.kind, LightKind::Dome { .. }))
            .count()
            > 1
        {
            return Err((None, SceneProblem::SecondDome));
        }
        Ok(Scene {
            name: self.name,
            camera,
            objects,
            materials,
            material_names,
            lights,
            settings,
            bvh: Bvh::new(prims),
        })
    }
}
