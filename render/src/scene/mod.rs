//! Scenes: the in-memory form the integrator reads, and the TOML scene file format
//! (built-in scenes are TOML files compiled into the binary, so they double as
//! documented examples of the format; see `render/scenes/README.md`).

use glam::Vec3;
use lpe::renderman::LobeMap;
use std::fmt;

use crate::geometry::{Bvh, Hit, Ray};
use crate::light::{Light, LightKind};
use crate::material::Material;

mod file;
pub mod furnace;

/// A built-in scene: name and TOML source.
pub const BUILTIN: [(&str, &str); 3] = [
    ("cornell", include_str!("../../scenes/cornell.toml")),
    ("still-life", include_str!("../../scenes/still-life.toml")),
    ("furnace", include_str!("../../scenes/furnace.toml")),
];

/// An object: geometry (in the BVH) with a material or an area light.
#[derive(Clone, Debug)]
pub struct Object {
    pub name: String,
    /// Index into [`Scene::materials`]; `None` for an area light's surface.
    pub material: Option<usize>,
    /// The label of the object's R/T/O vertices.
    pub lpegroup: Option<String>,
    /// Paths touching a holdout object go only to `holdouts;` AOVs.
    pub holdout: bool,
    /// Index into [`Scene::lights`] when the object is an area light.
    pub light: Option<usize>,
}

/// Pinhole camera placement (the aspect ratio comes from the image size).
#[derive(Clone, Copy, Debug)]
pub struct CameraDesc {
    pub position: Vec3,
    pub look_at: Vec3,
    pub up: Vec3,
    pub fov: f32,
}

/// Integrator settings a scene file may set.
#[derive(Clone, Copy, Debug)]
pub struct SceneSettings {
    /// Most scattering vertices on a path.
    pub max_depth: u32,
    /// Russian roulette starts after this many scattering vertices.
    pub rr_depth: u32,
    /// Largest component a single contribution may have (`noclamp;` AOVs bypass it).
    pub clamp: Option<f32>,
}

/// A scene ready to render.
#[derive(Clone, Debug)]
pub struct Scene {
    pub name: String,
    pub camera: CameraDesc,
    pub objects: Vec<Object>,
    pub materials: Vec<Material>,
    pub material_names: Vec<String>,
    pub lights: Vec<Light>,
    pub settings: SceneSettings,
    bvh: Bvh,
}

/// Most distinct labels (object `lpegroup`s and light groups) in one scene.
pub const MAX_LABELS: usize = 1024;

/// Most scattering vertices a path may have: paths are kept in fixed-size buffers by
/// the reference matcher (see `aov::matcher`).
pub const MAX_DEPTH_LIMIT: u32 = 60;

impl Scene {
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        self.bvh.intersect(ray, t_max)
    }

    pub fn occluded(&self, ray: &Ray, t_max: f32) -> bool {
        self.bvh.occluded(ray, t_max)
    }

    /// The dome light, if any (what escaping rays see).
    pub fn dome(&self) -> Option<usize> {
        self.lights
            .iter()
            .position(|l| matches!(l.kind, LightKind::Dome { .. }))
    }

    /// Light groups in order of first appearance.
    pub fn light_groups(&self) -> Vec<String> {
        let mut out: Vec<String> = Vec::new();
        for g in self.lights.iter().filter_map(|l| l.group.clone()) {
            if !out.contains(&g) {
                out.push(g);
            }
        }
        out
    }

    /// Loads a built-in scene by name or a TOML file by path.
    pub fn load(name_or_path: &str, lobes: &LobeMap) -> Result<Scene, SceneError> {
        if let Some((_, src)) = BUILTIN.iter().find(|(n, _)| *n == name_or_path) {
            return Scene::from_toml(src, name_or_path, lobes);
        }
        let text = std::fs::read_to_string(name_or_path).map_err(|e| SceneError {
            file: name_or_path.to_string(),
            line: None,
            problem: if std::path::Path::new(name_or_path).extension().is_none() {
                SceneProblem::NotFound {
                    builtins: BUILTIN.map(|b| b.0).join(", "),
                    error: e.to_string(),
                }
            } else {
                SceneProblem::Unreadable {
                    error: e.to_string(),
                }
            },
        })?;
        let stem = std::path::Path::new(name_or_path)
            .file_stem()
            .map_or("scene".into(), |s| s.to_string_lossy().into_owned());
        Scene::from_toml(&text, name_or_path, lobes).map(|mut s| {
            if s.name.is_empty() {
                s.name = stem;
            }
            s
        })
    }
}

/// A scene file problem: file, line (when known) and what.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub struct SceneError {
    pub file: String,
    pub line: Option<usize>,
    pub problem: SceneProblem,
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            Some(l) => write!(f, "{}:{}: {}", self.file, l, self.problem),
            None => write!(f, "{}: {}", self.file, self.problem),
        }
    }
}

/// What is wrong with a scene file.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SceneProblem {
    #[error("not a built-in scene ({builtins}) and not a readable file: {error}")]
    NotFound { builtins: String, error: String },
    #[error("cannot read: {error}")]
    Unreadable { error: String },
    /// TOML syntax or a field of the wrong type or name (toml's message).
    #[error("{message}")]
    Toml { message: String },
    #[error("{what} must be finite, got {value:?}")]
    NotFinite { what: &'static str, value: [f32; 3] },
    #[error("{what} must not be negative, got {value:?}")]
    Negative { what: &'static str, value: [f32; 3] },
    #[error("{what} must be a positive number, got {value}")]
    NotPositive { what: &'static str, value: f32 },
    #[error("a {kind} needs `{what}`")]
    Missing {
        kind: &'static str,
        what: &'static str,
    },
    #[error("roughness must be in [0, 1], got {value}")]
    Roughness { value: f32 },
    #[error("unknown lobe model `{model}` (lambert, diffuse_transmission, ggx, dielectric)")]
    UnknownLobeModel { model: String },
    #[error("box max must exceed min on every axis")]
    EmptyBox,
    #[error("an object needs exactly one of `sphere`, `quad`, `box`, `mesh`")]
    ShapeCount,
    #[error("{}edges `u` and `v` are parallel (zero area)", if *light { "quad light " } else { "quad " })]
    DegenerateQuad { light: bool },
    #[error("triangle index {index} out of range ({vertices} vertices)")]
    TriangleIndex { index: u32, vertices: usize },
    #[error("distant light direction must not be zero")]
    ZeroDirection,
    #[error("unknown light kind `{kind}` (quad, sphere, point, distant, dome)")]
    UnknownLightKind { kind: String },
    #[error("camera: look_at must differ from position and not lie along up")]
    CameraAxis,
    #[error("render.max_depth must be 1..={max}, got {value}")]
    MaxDepth { value: u32, max: u32 },
    #[error("unknown material `{material}` (defined: {defined})")]
    UnknownMaterial { material: String, defined: String },
    #[error("{labels} distinct lpegroup/group labels; at most {max}")]
    TooManyLabels { labels: usize, max: usize },
    #[error("at most one dome light")]
    SecondDome,
    #[error("material `{name}`: {problem}")]
    InMaterial {
        name: String,
        problem: Box<SceneProblem>,
    },
    #[error("object `{name}`: {problem}")]
    InObject {
        name: String,
        problem: Box<SceneProblem>,
    },
    #[error("light {index}: {problem}")]
    InLight {
        index: usize,
        problem: Box<SceneProblem>,
    },
}

impl SceneProblem {
    fn in_material(self, name: &str) -> SceneProblem {
        SceneProblem::InMaterial {
            name: name.into(),
            problem: Box::new(self),
        }
    }

    fn in_object(self, name: &str) -> SceneProblem {
        SceneProblem::InObject {
            name: name.into(),
            problem: Box::new(self),
        }
    }

    fn in_light(self, index: usize) -> SceneProblem {
        SceneProblem::InLight {
            index,
            problem: Box::new(self),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtin_scenes_load() {
        for (name, _) in BUILTIN {
            let s = Scene::load(name, &LobeMap::default()).unwrap();
            assert!(!s.objects.is_empty(), "{name}");
        }
    }

    #[test]
    fn errors_name_file_and_line() {
        let map = LobeMap::default();
        let text = "[camera]\nposition = [0,0,0]\nlook_at = [0,0,1]\n\n[[objects]]\nmaterial = \"nope\"\nsphere = { center = [0,0,3], radius = 1 }\n";
        let e = Scene::from_toml(text, "s.toml", &map).unwrap_err();
        assert_eq!(e.line, Some(5), "{e}");
        assert!(e.to_string().starts_with("s.toml:5: "), "{e}");
        assert!(
            e.problem.to_string().contains("unknown material `nope`"),
            "{e}"
        );

        let e = Scene::from_toml(
            "[camera]\nposition = [0,0,0]\nlook_at = [0,0,1]\nfoo = 1\n",
            "s.toml",
            &map,
        )
        .unwrap_err();
        assert_eq!(e.line, Some(4), "{e}");
        assert!(e.problem.to_string().contains("foo"), "{e}");

        let e = Scene::from_toml(
            "[camera]\nposition = [0,0,nan]\nlook_at = [0,0,1]\n",
            "s.toml",
            &map,
        )
        .unwrap_err();
        assert!(e.problem.to_string().contains("finite"), "{e}");
    }
}
