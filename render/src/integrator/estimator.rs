//! The path estimator: one camera sample traced through the scene, with next-event
//! estimation at each scattering vertex (see the module docs of [`super`]).

use glam::Vec3;

use super::contributions::{PathState, Tally};
use super::settings::Technique;
use super::setup::Integrator;
use crate::aov::matcher::RenderMatcher;
use crate::film::{Contribution, Strategy, ONLY_STRATEGY};
use crate::geometry::{error_bound, Hit, Ray};
use crate::material::Material;
use crate::rng::Rng;
use crate::sampling::{max_component, power_heuristic, Frame};

impl<M: RenderMatcher> Integrator<'_, M> {
    /// Traces one camera sample through pixel `(x, y)`.
    pub(super) fn sample(&self, x: usize, y: usize, rng: &mut Rng, acc: &mut Tally<M::State>) {
        let s = self.settings;
        let scene = self.scene;
        let m = self.matcher;
        let jitter = rng.vec2();
        let mut ray = self.camera.ray(
            (x as f32 + jitter.x) / s.width as f32,
            (y as f32 + jitter.y) / s.height as f32,
        );
        let mut path = PathState {
            matcher: m.step(m.start(), self.vertices.camera),
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
        acc: &mut Tally<M::State>,
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
            let c = Contribution {
                beta: path.beta,
                local: f_cos * ls.li / p_light,
                strategy: Strategy::Nee { w, visible },
                holdout: path.holdout,
            };
            self.splat(state, &c, acc);
        }
    }
}
