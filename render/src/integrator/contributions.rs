//! Contributions: every vertex the scene can produce, classified once for the matcher,
//! and the hand-over of each contribution (its path's AOV mask) to the film.

use lpe::{Dialect, LobeCategory, LobeMap, Vertex, VertexType};

use super::{Integrator, USER_SIGNALS};
use crate::aov::matcher::{AovMask, PathMatcher, RenderMatcher};
use crate::aov::vertex::{SceneClassifier, SceneVertex};
use crate::film::{Contribution, SampleValues, Strategy};
use crate::geometry::Hit;
use crate::material::Material;
use crate::scene::Scene;
use glam::Vec3;

/// The per-path state the integrator carries from vertex to vertex.
pub(super) struct PathState<S> {
    pub(super) matcher: S,
    /// Throughput to reach the last scattering vertex.
    pub(super) beta: Vec3,
    /// `f cos / (p_pick pdf) / q` of the last scattering vertex.
    pub(super) bounce: Vec3,
    /// The last scattering vertex, for MIS: position and BSDF-strategy density
    /// (`None` after the camera or a delta lobe: light sampling could not compete).
    pub(super) prev: Option<(Vec3, f32)>,
    pub(super) holdout: bool,
}

/// What one worker accumulates for the camera sample it traces: the sample's values
/// and the rays cast.
pub(super) struct Tally<K> {
    pub(super) values: SampleValues<K>,
    pub(super) rays: u64,
}

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
    ) -> Self {
        let label = |l: &Option<String>| if labels { l.clone() } else { None };
        let camera = m.classify_scene(&SceneVertex::Camera);
        // User lobes are RenderMan's: OSL has no pseudo paths (docs/language.md §18.12).
        // Their vertices are RenderMan ones, whose class on an OSL set lpe leaves
        // unspecified, so they are not even asked for.
        let user_lobes = m.dialect() == Dialect::RenderMan;
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
                                    scattering: l.scattering(),
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
                let s = m.step(
                    m.step(m.start(), camera),
                    m.classify(&Vertex::scatter(VertexType::R, ev, group.as_deref())),
                );
                m.matches(m.step(s, m.classify(&Vertex::light(None))))
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

impl<M: RenderMatcher> Integrator<'_, M> {
    /// Hands a contribution whose complete path ended in matcher state `state` to the
    /// sample's values.
    pub(super) fn splat(&self, state: M::State, c: &Contribution, acc: &mut Tally<M::State>) {
        acc.values
            .add(&self.weighting, c, state, |s| self.matcher.matches(s));
    }

    /// The path reached an emitter of radiance `le` through vertex class `class`.
    pub(super) fn arrive(
        &self,
        path: &PathState<M::State>,
        class: M::Class,
        le: Vec3,
        strategy: Strategy,
        holdout: bool,
        acc: &mut Tally<M::State>,
    ) {
        let state = if self.plan.matching {
            self.matcher.step(path.matcher, class)
        } else {
            path.matcher
        };
        let c = Contribution {
            beta: path.beta,
            local: path.bounce * le,
            strategy,
            holdout,
        };
        self.splat(state, &c, acc);
    }

    /// User-lobe pseudo paths `C <R Un> L` at a camera hit: material properties, not
    /// light transport (never in beauty).
    pub(super) fn user_lobes(&self, hit: &Hit, mat: &Material, acc: &mut Tally<M::State>) {
        for &(signal, mask) in &self.vertices.user[hit.object as usize] {
            let value = match signal {
                UserSignal::Albedo => mat.albedo(),
                UserSignal::Position => hit.p,
                UserSignal::Normal => hit.n,
            }
            .as_dvec3();
            for i in mask.iter() {
                acc.values.add_signal(&self.weighting, i, value);
            }
        }
    }
}
