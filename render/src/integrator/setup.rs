//! The integrator as it is built for one render: the scene, the matcher, and every
//! vertex the scene can produce, classified once before rendering ([`Vertices`]). Its
//! parts (the estimator, the contributions it splats, the row loop) are written as
//! methods on it in files of their own.

use lpe::renderman::{LobeCategory, LobeMap, VertexType};
use lpe::translate::{Correspondence, Scattering as OslScattering};

use super::settings::{Settings, USER_SIGNALS};
use crate::aov::matcher::{AovMask, PathMatcher, RenderMatcher};
use crate::aov::plan::Plan;
use crate::aov::{AovList, SceneClassifier, SceneDialect, SceneVertex};
use crate::camera::Camera;
use crate::film::Weighting;
use crate::material::Scattering;
use crate::scene::Scene;

/// The user signals a material emits as pseudo paths, with the lobe-map name of each.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum UserSignal {
    Albedo,
    Position,
    Normal,
}

impl UserSignal {
    const ALL: [UserSignal; 3] = [UserSignal::Albedo, UserSignal::Position, UserSignal::Normal];

    fn name(self) -> &'static str {
        USER_SIGNALS[self as usize]
    }
}

/// The scattering a vertex off a lobe of `event` and `model` scattering shows: the
/// renderer's correspondence's, when one is set, else the model's. A user lobe has no
/// scattering in a correspondence and keeps its model's; a correspondence's `s`
/// (straight) has no lobe model here, and `lpe-render --renderer` refuses a renderer
/// whose correspondence uses it, so it keeps its model's too.
fn shown_scattering(
    event: lpe::renderman::Event,
    model: Scattering,
    shown: Option<&Correspondence>,
) -> Scattering {
    match shown.and_then(|c| c.scattering(event)) {
        Some(OslScattering::Diffuse) => Scattering::Diffuse,
        Some(OslScattering::Glossy) => Scattering::Glossy,
        Some(OslScattering::Singular) => Scattering::Delta,
        Some(OslScattering::Straight) | None => model,
    }
}

/// Every vertex the scene can produce, classified once for the matcher.
pub(super) struct Vertices<C> {
    /// `[object][lobe]` -> classes of the lobe's `R` and `T` vertices.
    pub(super) scatter: Vec<Vec<[C; 2]>>,
    /// Per light: its `L` vertex (reached by a bounce or a light sample).
    pub(super) light: Vec<C>,
    /// Per light: its `O` vertex (its surface seen straight from the camera).
    pub(super) light_seen: Vec<C>,
    /// Per object: its glow `O` vertex.
    pub(super) glow: Vec<C>,
    /// The camera vertex `C`, every path's first.
    pub(super) camera: C,
    /// Per object: the AOVs each user-signal pseudo path `C <R Un> L` matches.
    pub(super) user: Vec<Vec<(UserSignal, AovMask)>>,
}

impl<C: Copy> Vertices<C> {
    pub(super) fn new<M: PathMatcher<Class = C> + SceneClassifier>(
        scene: &Scene,
        m: &M,
        lobes: &LobeMap,
        labels: bool,
        shown: Option<&Correspondence>,
    ) -> Self {
        let label = |l: &Option<String>| if labels { l.clone() } else { None };
        let camera = m.classify_scene(&SceneVertex::Camera);
        // Pseudo paths exist only in a dialect with user lobes: in another their vertices
        // would show as ordinary scattering, so they are not even asked for.
        let user_lobes = M::Dialect::USER_LOBES;
        let mut scatter = Vec::new();
        let mut glow = Vec::new();
        let mut user = Vec::new();
        for o in &scene.objects {
            let group = label(&o.lpegroup);
            let mat = o.material.map(|i| &scene.materials[i]);
            scatter.push(
                mat.map(|m2| {
                    m2.lobes
                        .iter()
                        .map(|l| {
                            [VertexType::R, VertexType::T].map(|side| {
                                m.classify_scene(&SceneVertex::Scatter {
                                    side,
                                    event: l.event,
                                    scattering: shown_scattering(l.event, l.scattering(), shown),
                                    group: group.as_deref(),
                                })
                            })
                        })
                        .collect()
                })
                .unwrap_or_default(),
            );
            glow.push(m.classify_scene(&SceneVertex::Emissive {
                group: group.as_deref(),
            }));
            let pseudo = |sig: UserSignal| {
                let ev = lobes.event(LobeCategory::User, sig.name());
                // Only asked of dialects with user lobes, which show the event.
                let s = m.step(
                    m.step(m.start(), camera),
                    m.classify_scene(&SceneVertex::Scatter {
                        side: VertexType::R,
                        event: ev,
                        scattering: Scattering::Diffuse,
                        group: group.as_deref(),
                    }),
                );
                m.matches(m.step(s, m.classify_scene(&SceneVertex::Light { group: None })))
            };
            user.push(if mat.is_some() && user_lobes {
                UserSignal::ALL.iter().map(|&s| (s, pseudo(s))).collect()
            } else {
                Vec::new()
            });
        }
        let light = scene
            .lights
            .iter()
            .map(|l| {
                m.classify_scene(&SceneVertex::Light {
                    group: label(&l.group).as_deref(),
                })
            })
            .collect();
        let light_seen = scene
            .lights
            .iter()
            .map(|l| {
                m.classify_scene(&SceneVertex::Emissive {
                    group: label(&l.group).as_deref(),
                })
            })
            .collect();
        Vertices {
            scatter,
            light,
            light_seen,
            glow,
            camera,
            user,
        }
    }
}

pub struct Integrator<'a, M: RenderMatcher> {
    pub(super) scene: &'a Scene,
    pub(super) matcher: &'a M,
    /// How contributions weigh into each AOV (handed to the film).
    pub(super) weighting: Weighting,
    /// The dome light escaping rays see (looked up once, not per escaped ray).
    pub(super) dome: Option<usize>,
    pub(super) vertices: Vertices<M::Class>,
    pub(super) plan: Plan,
    pub(super) settings: &'a Settings,
    pub(super) camera: Camera,
}

impl<'a, M: RenderMatcher> Integrator<'a, M> {
    pub fn new(
        scene: &'a Scene,
        aovs: &AovList<M::Dialect>,
        matcher: &'a M,
        lobes: &LobeMap,
        settings: &'a Settings,
    ) -> Self {
        let mut plan = if settings.all_effects {
            Plan::all_effects(aovs)
        } else {
            Plan::derive(scene, aovs, settings.beauty)
        };
        let vertices = Vertices::new(
            scene,
            matcher,
            lobes,
            plan.labels,
            settings.scattering.as_ref(),
        );
        if !settings.all_effects {
            plan.user_lobes = vertices.user.iter().flatten().any(|(_, m)| !m.is_empty());
        }
        let c = &scene.camera;
        let aspect = settings.width as f32 / settings.height as f32;
        Integrator {
            scene,
            matcher,
            weighting: Weighting::new(aovs.flags(), scene.settings.clamp),
            dome: scene.dome(),
            vertices,
            plan,
            settings,
            camera: Camera::new(c.position, c.look_at, c.up, c.fov, aspect),
        }
    }

    pub fn plan(&self) -> Plan {
        self.plan
    }
}
