//! Unidirectional path tracing with next-event estimation and MIS, routing every
//! contribution into the AOVs whose expressions match its path.
//!
//! # Estimator
//! A path `C x1 ... xk` carries throughput `beta = prod f cos / (p_lobe pdf)` (with
//! Russian roulette's `1/q`). At each scattering vertex two strategies reach an emitter:
//! - light sampling (NEE): pick a light (probability `1/n`), sample a point; for **each
//!   non-delta lobe** `j` of the material this is a separate path `... x_k(j) L` with
//!   contribution `beta * f_j cos Le / p_light`, weighted by the power heuristic against
//!   the BSDF strategy's density for that lobe, `p_pick(j) pdf_j`;
//! - BSDF sampling: pick lobe `i`, sample a direction; if the ray hits an emitter the path
//!   `... x_k(i) E` gets `beta * (f_i cos / (p_pick(i) pdf_i)) Le`, MIS-weighted by the
//!   light-sampling density when NEE could have sampled that emitter.
//!
//! Each lobe term is thus estimated by two strategies whose weights sum to one, and each
//! contribution is attributed to exactly the lobe that scattered, so every path the
//! matcher sees is a real light path with its own value.
//!
//! # Prefixes (how an AOV weighs a contribution; DESIGN.md §3)
//! Every contribution is an `Arrival`: the matcher state of its complete path, the
//! throughput `beta` up to its last scattering vertex, the `local` estimate at that vertex
//! (`f cos Le / pdf`, no MIS, no visibility) and its `Strategy`. An AOV's value is
//! `thru * local * weight` where
//! - `thru = beta`, or 1 with `nothruput;` (no accumulated throughput: only the last
//!   vertex's lighting);
//! - `weight` is the MIS weight times visibility; with `unoccluded;` light samples count
//!   with weight 1 whether or not they are blocked and BSDF hits NEE could have produced
//!   count 0 (light sampling alone estimates those connections, without shadowing); with
//!   `shadows;` the same unshadowed light samples count only when blocked, which is
//!   `unoccluded - occluded` in expectation;
//! - the scene's clamp (max component of one contribution) applies unless `noclamp;`;
//! - holdout paths (a vertex on a holdout object) go only to `holdouts;` AOVs, the others
//!   only to AOVs without it; beauty excludes holdout paths;
//! - a sample whose light transport is not finite is dropped from beauty and every AOV
//!   and counted, except for `noinfinitecheck;` AOVs, which keep it; `overwrite;` AOVs
//!   keep the last value written instead of the mean (user lobes); values only an AOV
//!   receives (other weights, `nothruput;`) that are not finite are dropped for that AOV
//!   alone and counted apart, so whether a sample is rejected never depends on which
//!   AOVs were requested.
//!
//! Beauty is `beta * local * weight` of every non-holdout transport contribution, added
//! independently of the matcher: that is what makes "AOVs sum to beauty" a real check.

use glam::{DVec3, Vec3};
use indicatif::{ProgressBar, ProgressStyle};
use lpe::{LobeCategory, LobeMap, Vertex, VertexType};
use rayon::prelude::*;
use std::time::Instant;

use crate::aov::matcher::{AovMask, PathMatcher};
use crate::aov::plan::Plan;
use crate::aov::{AovFlags, AovList};
use crate::camera::Camera;
use crate::film::{Accumulation, Film};
use crate::geometry::{error_bound, Hit, Ray};
use crate::material::Material;
use crate::rng::Rng;

mod dispatch;
use crate::sampling::{max_component, power_heuristic, Frame};
use crate::scene::Scene;
pub use dispatch::{render, render_announcing, render_with, ENGINE};

/// Which strategies estimate direct lighting (issue 6 compares them).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub enum Technique {
    /// Light sampling and BSDF sampling, power heuristic.
    Mis,
    /// BSDF sampling only: emitters count only when a path hits them (`unoccluded;` and
    /// `shadows;` AOVs then see what the rays see: there are no light samples to unshadow).
    BsdfOnly,
    /// Light sampling only: BSDF hits on lights NEE can sample count zero.
    LightOnly,
}

/// How to render.
#[derive(Clone, Debug)]
pub struct Settings {
    pub width: usize,
    pub height: usize,
    pub spp: u32,
    pub seed: u64,
    /// Worker threads (`None`: rayon's default, one per core).
    pub threads: Option<usize>,
    pub technique: Technique,
    pub russian_roulette: bool,
    /// How the film sums samples.
    pub accumulation: Accumulation,
    /// Force the generic path (`--all-effects`).
    pub all_effects: bool,
    /// Whether beauty is wanted (if not, paths dead for every AOV stop early).
    pub beauty: bool,
    pub progress: bool,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            width: 64,
            height: 64,
            spp: 4,
            seed: 0,
            threads: None,
            technique: Technique::Mis,
            russian_roulette: true,
            accumulation: Accumulation::F64,
            all_effects: false,
            beauty: true,
            progress: false,
        }
    }
}

/// What a render produced.
#[derive(Clone, Debug)]
pub struct Render {
    pub film: Film,
    pub plan: Plan,
    pub seconds: f64,
    /// Camera samples traced.
    pub paths: u64,
    /// Rays cast (camera, bounce and shadow rays).
    pub rays: u64,
}

/// Lobe-map names of the user signals, in [`UserSignal::ALL`] order (the CLI checks
/// them for lobe collisions).
pub const USER_SIGNALS: [&str; 3] = ["Albedo", "Position", "Normal"];

/// The user signals a material emits as pseudo paths, with the lobe-map name of each.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum UserSignal {
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
struct Vertices<C> {
    /// `[object][lobe]` -> classes of the lobe's `R` and `T` vertices.
    scatter: Vec<Vec<[C; 2]>>,
    /// Per light: its `L` vertex (reached by a bounce or a light sample).
    light: Vec<C>,
    /// Per light: its `O` vertex (its surface seen straight from the camera).
    light_seen: Vec<C>,
    /// Per object: its glow `O` vertex.
    glow: Vec<C>,
    /// Per object: the AOVs each user-signal pseudo path `C <R Un> L` matches.
    user: Vec<Vec<(UserSignal, AovMask)>>,
}

impl<C: Copy> Vertices<C> {
    fn new<M: PathMatcher<Class = C>>(scene: &Scene, m: &M, lobes: &LobeMap, labels: bool) -> Self {
        let label = |l: &Option<String>| if labels { l.clone() } else { None };
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
                            [VertexType::R, VertexType::T]
                                .map(|t| m.classify(&Vertex::scatter(t, l.event, group.as_deref())))
                        })
                        .collect()
                })
                .unwrap_or_default(),
            );
            glow.push(m.classify(&Vertex::emissive(group.as_deref())));
            let pseudo = |sig: UserSignal| {
                let ev = lobes.event(LobeCategory::User, sig.name());
                let s = m.step(
                    m.start(),
                    m.classify(&Vertex::scatter(VertexType::R, ev, group.as_deref())),
                );
                m.matches(m.step(s, m.classify(&Vertex::light(None))))
            };
            user.push(if mat.is_some() {
                UserSignal::ALL.iter().map(|&s| (s, pseudo(s))).collect()
            } else {
                Vec::new()
            });
        }
        let light = scene
            .lights
            .iter()
            .map(|l| m.classify(&Vertex::light(label(&l.group).as_deref())))
            .collect();
        let light_seen = scene
            .lights
            .iter()
            .map(|l| m.classify(&Vertex::emissive(label(&l.group).as_deref())))
            .collect();
        Vertices {
            scatter,
            light,
            light_seen,
            glow,
            user,
        }
    }
}

/// How a contribution was found (see the module docs for how AOVs weigh it).
#[derive(Clone, Copy, Debug)]
enum Strategy {
    /// The path itself reached the emitter; `w` is its MIS weight and `nee_could` says
    /// whether light sampling also estimates this connection.
    Hit { w: f32, nee_could: bool },
    /// A light sample with MIS weight `w` and its visibility.
    Nee { w: f32, visible: bool },
}

impl Strategy {
    /// The weight of this contribution in an AOV with these prefixes (beauty: none).
    fn weight(self, f: &AovFlags) -> f32 {
        let unshadowed = f.unoccluded || f.shadows;
        match self {
            Strategy::Hit {
                nee_could: true, ..
            } if unshadowed => 0.0,
            Strategy::Hit { .. } if f.shadows => 0.0,
            Strategy::Hit { w, .. } => w,
            Strategy::Nee { visible, .. } if f.shadows => (!visible) as u8 as f32,
            Strategy::Nee { .. } if f.unoccluded => 1.0,
            Strategy::Nee { w, visible } => w * visible as u8 as f32,
        }
    }
}

/// A hit on an emitter that no other strategy estimates: full weight.
const ONLY_STRATEGY: Strategy = Strategy::Hit {
    w: 1.0,
    nee_could: false,
};

/// One contribution reaching an emitter.
struct Arrival<S> {
    /// Matcher state after the emitter vertex.
    state: S,
    /// Throughput up to the last scattering vertex.
    beta: Vec3,
    /// Estimate at the last scattering vertex (or the emitted radiance, for `C E`).
    local: Vec3,
    strategy: Strategy,
    holdout: bool,
}

/// The values of one camera sample, before they join the pixel.
struct SampleAcc {
    beauty: DVec3,
    aov: Vec<DVec3>,
    touched: AovMask,
    /// All light-transport contributions were finite.
    finite: bool,
    aov_rejected: u64,
    rays: u64,
}

/// The per-path state the integrator carries from vertex to vertex.
struct PathState<S> {
    matcher: S,
    /// Throughput to reach the last scattering vertex.
    beta: Vec3,
    /// `f cos / (p_pick pdf) / q` of the last scattering vertex.
    bounce: Vec3,
    /// The last scattering vertex, for MIS: position and BSDF-strategy density
    /// (`None` after the camera or a delta lobe: light sampling could not compete).
    prev: Option<(Vec3, f32)>,
    holdout: bool,
}

pub struct Integrator<'a, M: PathMatcher> {
    scene: &'a Scene,
    matcher: &'a M,
    flags: Vec<AovFlags>,
    /// AOVs with no prefix that changes a contribution's value: they receive beauty's.
    like_beauty: AovMask,
    /// The dome light escaping rays see (looked up once, not per escaped ray).
    dome: Option<usize>,
    vertices: Vertices<M::Class>,
    plan: Plan,
    settings: &'a Settings,
    camera: Camera,
}

impl<'a, M: PathMatcher> Integrator<'a, M> {
    pub fn new(
        scene: &'a Scene,
        aovs: &AovList,
        matcher: &'a M,
        lobes: &LobeMap,
        settings: &'a Settings,
    ) -> Self {
        let mut plan = if settings.all_effects {
            Plan::all_effects(aovs)
        } else {
            Plan::derive(scene, aovs, settings.beauty)
        };
        let vertices = Vertices::new(scene, matcher, lobes, plan.labels);
        if !settings.all_effects {
            plan.user_lobes = vertices.user.iter().flatten().any(|(_, m)| !m.is_empty());
        }
        let c = &scene.camera;
        let aspect = settings.width as f32 / settings.height as f32;
        Integrator {
            scene,
            matcher,
            flags: aovs.aovs.iter().map(|a| a.flags).collect(),
            like_beauty: (aovs.aovs.iter().enumerate())
                .filter(|(_, a)| a.flags.values_like_beauty())
                .map(|(i, _)| i)
                .collect(),
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

    /// Renders the whole image; rows in parallel, each pixel's samples in order.
    pub fn render(&self) -> Result<Render, String> {
        let s = self.settings;
        let (w, h) = (s.width, s.height);
        let n = self.flags.len();
        let mut film = Film::new(
            w,
            h,
            s.spp,
            self.flags.iter().map(|f| f.overwrite).collect(),
            s.accumulation,
        );
        let mut builder = rayon::ThreadPoolBuilder::new();
        if let Some(t) = s.threads {
            builder = builder.num_threads(t);
        }
        let pool = builder.build().map_err(|e| format!("thread pool: {e}"))?;
        let bar = if s.progress {
            ProgressBar::new(h as u64).with_style(
                ProgressStyle::with_template(
                    "{spinner} rendering [{bar:40}] {pos}/{len} rows {elapsed} (eta {eta})",
                )
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
            )
        } else {
            ProgressBar::hidden()
        };
        let start = Instant::now();
        let stride = film.stride();
        let (rejected, aov_rejected, rays) = pool.install(|| {
            film.data
                .par_chunks_mut(w * stride)
                .enumerate()
                .map(|(y, row)| {
                    let mut acc = SampleAcc {
                        beauty: DVec3::ZERO,
                        aov: vec![DVec3::ZERO; n],
                        touched: AovMask::EMPTY,
                        finite: true,
                        aov_rejected: 0,
                        rays: 0,
                    };
                    let mut rejected = 0;
                    for (x, pixel) in row.chunks_mut(stride).enumerate() {
                        for sample in 0..s.spp {
                            let index = (y * w + x) as u64;
                            let mut rng = Rng::for_sample(s.seed, index, sample as u64);
                            self.sample(x, y, &mut rng, &mut acc);
                            rejected += self.commit(&mut acc, pixel) as u64;
                        }
                    }
                    bar.inc(1);
                    (rejected, acc.aov_rejected, acc.rays)
                })
                .reduce(|| (0, 0, 0), |a, b| (a.0 + b.0, a.1 + b.1, a.2 + b.2))
        });
        bar.finish_and_clear();
        film.rejected = rejected;
        film.aov_rejected = aov_rejected;
        Ok(Render {
            film,
            plan: self.plan,
            seconds: start.elapsed().as_secs_f64(),
            paths: (w * h) as u64 * s.spp as u64,
            rays,
        })
    }

    /// Adds a finished sample to its pixel and clears the accumulator; returns whether
    /// the sample was rejected as non-finite.
    fn commit(&self, acc: &mut SampleAcc, pixel: &mut [DVec3]) -> bool {
        let rejected = !(acc.finite && acc.beauty.is_finite());
        let layers = 1 + self.flags.len();
        let add =
            |pixel: &mut [DVec3], layer, x| self.settings.accumulation.add(pixel, layers, layer, x);
        if !rejected {
            add(pixel, 0, acc.beauty);
        }
        for i in acc.touched.iter() {
            let f = &self.flags[i];
            if !rejected || f.noinfinitecheck {
                if f.overwrite {
                    pixel[1 + i] = acc.aov[i];
                } else {
                    add(pixel, 1 + i, acc.aov[i]);
                }
            }
            acc.aov[i] = DVec3::ZERO;
        }
        acc.touched = AovMask::EMPTY;
        acc.beauty = DVec3::ZERO;
        acc.finite = true;
        rejected
    }

    /// Adds one contribution to beauty and to the AOVs its path matches.
    fn splat(&self, a: &Arrival<M::State>, acc: &mut SampleAcc) {
        let clamp = self.scene.settings.clamp;
        let clamped = |v: Vec3, f: &AovFlags| match clamp {
            Some(c) if !f.noclamp && max_component(v) > c => v * (c / max_component(v)),
            _ => v,
        };
        let full = a.beta * a.local;
        let none = AovFlags::default();
        let wb = a.strategy.weight(&none);
        let beauty = clamped(full * wb, &none);
        let beauty_d = beauty.as_dvec3();
        let counts_in_beauty = wb > 0.0 && !a.holdout;
        if wb > 0.0 {
            acc.finite &= beauty.is_finite();
        }
        if counts_in_beauty {
            acc.beauty += beauty_d;
        }
        if !self.plan.matching {
            return;
        }
        for i in self.matcher.matches(a.state).iter() {
            if self.like_beauty.contains(i) {
                if counts_in_beauty {
                    acc.aov[i] += beauty_d;
                    acc.touched.insert(i);
                }
                continue;
            }
            let f = &self.flags[i];
            if f.holdouts != a.holdout {
                continue;
            }
            let w = a.strategy.weight(f);
            if !(w > 0.0) {
                continue;
            }
            let v = clamped(if f.nothruput { a.local } else { full } * w, f);
            // Values beauty also received were judged with the sample; AOV-only values
            // (other weights or no throughput) are dropped alone if not finite.
            let aov_only = w != wb || f.nothruput;
            if aov_only && !v.is_finite() && !f.noinfinitecheck {
                acc.aov_rejected += 1;
                continue;
            }
            acc.aov[i] += v.as_dvec3();
            acc.touched.insert(i);
        }
    }

    /// Traces one camera sample through pixel `(x, y)`.
    fn sample(&self, x: usize, y: usize, rng: &mut Rng, acc: &mut SampleAcc) {
        let s = self.settings;
        let scene = self.scene;
        let m = self.matcher;
        let jitter = rng.vec2();
        let mut ray = self.camera.ray(
            (x as f32 + jitter.x) / s.width as f32,
            (y as f32 + jitter.y) / s.height as f32,
        );
        let mut path = PathState {
            matcher: m.start(),
            beta: Vec3::ONE,
            bounce: Vec3::ONE,
            prev: None,
            holdout: false,
        };
        let n_lights = scene.lights.len();
        let light_pick_pdf = 1.0 / n_lights.max(1) as f32;
        let use_nee = s.technique != Technique::BsdfOnly && n_lights > 0;
        // Light `l` reached by the path at point `q` (normal `n`): seen straight from the
        // camera it is an `O` vertex; reached by a bounce it is `L`, MIS-weighted against
        // light sampling unless that bounce was a delta lobe (then only this strategy
        // could have found it).
        let light_hit = |l: usize, depth: u32, prev: Option<(Vec3, f32)>, q: Vec3, n: Vec3| {
            if depth == 0 {
                return (self.vertices.light_seen[l], ONLY_STRATEGY);
            }
            let strategy = match prev {
                Some((p, bsdf_pdf)) if use_nee => Strategy::Hit {
                    w: match s.technique {
                        Technique::Mis => {
                            power_heuristic(bsdf_pdf, scene.lights[l].pdf(p, q, n) * light_pick_pdf)
                        }
                        _ => 0.0,
                    },
                    nee_could: true,
                },
                _ => ONLY_STRATEGY,
            };
            (self.vertices.light[l], strategy)
        };

        for depth in 0..=scene.settings.max_depth {
            acc.rays += 1;
            let Some(hit) = scene.intersect(&ray, f32::INFINITY) else {
                if let Some(d) = self.dome {
                    let le = scene.lights[d].emitted(ray.d, Vec3::ZERO);
                    let (class, strategy) = light_hit(d, depth, path.prev, Vec3::ZERO, Vec3::ZERO);
                    self.arrive(&path, class, le, strategy, path.holdout, acc);
                }
                return;
            };
            let object = &scene.objects[hit.object as usize];
            if self.plan.holdouts {
                path.holdout |= object.holdout;
            }

            // Emission where the path arrived: an area light's surface or glow.
            if let Some(l) = object.light {
                let le = scene.lights[l].emitted(ray.d, hit.n);
                if le != Vec3::ZERO {
                    let (class, strategy) = light_hit(l, depth, path.prev, hit.p, hit.n);
                    self.arrive(&path, class, le, strategy, path.holdout, acc);
                }
                return; // lights do not scatter
            }
            let Some(mat) = object.material.map(|i| &scene.materials[i]) else {
                return;
            };
            if mat.glow != Vec3::ZERO {
                // Glow is not sampled by next-event estimation: paths find it alone.
                let class = self.vertices.glow[hit.object as usize];
                self.arrive(&path, class, mat.glow, ONLY_STRATEGY, path.holdout, acc);
            }
            if depth == scene.settings.max_depth || mat.lobes.is_empty() {
                return;
            }
            path.beta *= path.bounce;

            if depth == 0 && self.plan.user_lobes {
                self.user_lobes(&hit, mat, acc);
            }

            let frame = Frame::from_normal(hit.n);
            let wo = frame.to_local(-ray.d);
            if use_nee && mat.lobes.iter().any(|l| !l.is_delta()) {
                self.next_event(&path, &hit, mat, &frame, wo, rng, light_pick_pdf, acc);
            }

            // Continue the path by sampling one lobe.
            let Some((j, p_pick)) = mat.pick(rng.f32()) else {
                return;
            };
            let lobe = &mat.lobes[j];
            let u = rng.vec2();
            let Some(ls) = lobe.sample(wo, u) else {
                return;
            };
            let wi = frame.to_world(ls.wi);
            let side = (ls.wi.z * wo.z <= 0.0) as usize; // 0: R, 1: T
            path.matcher = m.step(
                path.matcher,
                self.vertices.scatter[hit.object as usize][j][side],
            );
            if self.plan.stop_dead && m.is_dead(path.matcher) {
                return;
            }
            path.bounce = ls.weight / p_pick;
            path.prev = (!ls.delta).then_some((hit.p, p_pick * ls.pdf));
            if s.russian_roulette && depth + 1 >= scene.settings.rr_depth {
                let q = max_component(path.beta * path.bounce).min(1.0);
                if !(rng.f32() < q) {
                    return;
                }
                path.bounce /= q;
            }
            ray = Ray::spawn(hit.p, hit.n, hit.err, wi);
        }
    }

    /// The path reached an emitter of radiance `le` through vertex class `class`.
    fn arrive(
        &self,
        path: &PathState<M::State>,
        class: M::Class,
        le: Vec3,
        strategy: Strategy,
        holdout: bool,
        acc: &mut SampleAcc,
    ) {
        let state = if self.plan.matching {
            self.matcher.step(path.matcher, class)
        } else {
            path.matcher
        };
        let a = Arrival {
            state,
            beta: path.beta,
            local: path.bounce * le,
            strategy,
            holdout,
        };
        self.splat(&a, acc);
    }

    /// Light sampling at a scattering vertex: one light sample, evaluated for every
    /// non-delta lobe (each lobe makes its own path).
    #[allow(clippy::too_many_arguments)]
    fn next_event(
        &self,
        path: &PathState<M::State>,
        hit: &Hit,
        mat: &Material,
        frame: &Frame,
        wo: Vec3,
        rng: &mut Rng,
        light_pick_pdf: f32,
        acc: &mut SampleAcc,
    ) {
        let scene = self.scene;
        let n_lights = scene.lights.len();
        let li = ((rng.f32() * n_lights as f32) as usize).min(n_lights - 1);
        let u = rng.vec2();
        let light = &scene.lights[li];
        let Some(ls) = light.sample(hit.p, u) else {
            return;
        };
        if !(ls.pdf > 0.0) || ls.li == Vec3::ZERO {
            return;
        }
        let wi = frame.to_local(ls.wi);
        if !self.plan.transmission && wi.z * wo.z <= 0.0 {
            return; // behind the surface, and no lobe transmits
        }
        acc.rays += 1;
        let mut shadow = Ray::spawn(hit.p, hit.n, hit.err, ls.wi);
        let t_max = if ls.dist.is_finite() {
            // Aim from the offset origin at the sampled point itself: along `wi` from the
            // offset origin the ray meets a curved light up to the offset earlier than
            // `dist`, and the light would shadow itself. Stop short of the point by more
            // than its error (relative, so it holds at every scene scale).
            let q = hit.p + ls.wi * ls.dist;
            let to = q - shadow.o;
            let len = to.length();
            shadow.d = to / len;
            (len * (1.0 - 1e-4) - 4.0 * error_bound(q.abs().max_element())).max(0.0)
        } else {
            f32::INFINITY
        };
        let visible = !scene.occluded(&shadow, t_max);
        if !visible && !self.plan.unshadowed {
            return;
        }
        let p_light = ls.pdf * light_pick_pdf;
        for (j, lobe) in mat.lobes.iter().enumerate() {
            if lobe.is_delta() {
                continue;
            }
            let (f_cos, pdf) = lobe.eval(wo, wi);
            if f_cos == Vec3::ZERO {
                continue;
            }
            let w = if ls.delta {
                1.0
            } else {
                match self.settings.technique {
                    Technique::Mis => power_heuristic(p_light, mat.pick_pdf(j) * pdf),
                    _ => 1.0,
                }
            };
            let side = (wi.z * wo.z <= 0.0) as usize;
            let state = if self.plan.matching {
                let s = self.matcher.step(
                    path.matcher,
                    self.vertices.scatter[hit.object as usize][j][side],
                );
                self.matcher.step(s, self.vertices.light[li])
            } else {
                path.matcher
            };
            let a = Arrival {
                state,
                beta: path.beta,
                local: f_cos * ls.li / p_light,
                strategy: Strategy::Nee { w, visible },
                holdout: path.holdout,
            };
            self.splat(&a, acc);
        }
    }

    /// User-lobe pseudo paths `C <R Un> L` at a camera hit: material properties, not
    /// light transport (never in beauty).
    fn user_lobes(&self, hit: &Hit, mat: &Material, acc: &mut SampleAcc) {
        for &(signal, mask) in &self.vertices.user[hit.object as usize] {
            let value = match signal {
                UserSignal::Albedo => mat.albedo(),
                UserSignal::Position => hit.p,
                UserSignal::Normal => hit.n,
            }
            .as_dvec3();
            for i in mask.iter() {
                if self.flags[i].overwrite {
                    acc.aov[i] = value;
                } else {
                    acc.aov[i] += value;
                }
                acc.touched.insert(i);
            }
        }
    }
}
