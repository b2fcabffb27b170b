//! Lights: quad and sphere area lights (also scene geometry), point, distant and a
//! constant dome. Each may belong to a light group (the label of its `L` vertices).

use glam::{Vec2, Vec3};
use std::f32::consts::PI;

use crate::sampling::{one_minus_cos_from_sin2, uniform_cone, uniform_sphere, Frame};

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightKind {
    /// One-sided parallelogram emitting `radiance` toward `u x v`.
    Quad {
        corner: Vec3,
        u: Vec3,
        v: Vec3,
        radiance: Vec3,
    },
    /// Sphere emitting `radiance` outward.
    Sphere {
        center: Vec3,
        radius: f32,
        radiance: Vec3,
    },
    /// Isotropic point light of `intensity` (W/sr).
    Point { position: Vec3, intensity: Vec3 },
    /// Directional light arriving from `direction` (unit, toward the light) with this
    /// irradiance on a surface facing it.
    Distant { direction: Vec3, irradiance: Vec3 },
    /// Constant radiance from every direction at infinity.
    Dome { radiance: Vec3 },
}

#[derive(Clone, Debug, PartialEq)]
pub struct Light {
    pub kind: LightKind,
    pub group: Option<String>,
}

/// A light sample as seen from a shading point.
#[derive(Clone, Copy, Debug)]
pub struct LightSample {
    /// Unit direction toward the light.
    pub wi: Vec3,
    /// Distance to the sampled point (infinite for distant and dome lights).
    pub dist: f32,
    /// Incident radiance (for delta lights: the delta's weight, e.g. I / d^2).
    pub li: Vec3,
    /// Solid-angle pdf; 1 for delta lights (see `delta`).
    pub pdf: f32,
    /// Point and distant lights: only light sampling can reach them (no MIS).
    pub delta: bool,
    /// Surface normal at the sampled point (area lights), for ray offsetting.
    pub n: Option<Vec3>,
}

impl Light {
    /// Samples a direction toward the light from `p`.
    pub fn sample(&self, p: Vec3, u: Vec2) -> Option<LightSample> {
        match self.kind {
            LightKind::Quad {
                corner,
                u: eu,
                v: ev,
                radiance,
            } => {
                let q = corner + eu * u.x + ev * u.y;
                let n_raw = eu.cross(ev);
                let area = n_raw.length();
                let n = n_raw / area;
                let d = q - p;
                let dist2 = d.length_squared();
                let dist = dist2.sqrt();
                let wi = d / dist;
                let cos_l = -wi.dot(n);
                if !(cos_l > 0.0) {
                    return None; // the back of a one-sided light
                }
                Some(LightSample {
                    wi,
                    dist,
                    li: radiance,
                    pdf: dist2 / (area * cos_l),
                    delta: false,
                    n: Some(n),
                })
            }
            LightKind::Sphere {
                center,
                radius,
                radiance,
            } => {
                let to_c = center - p;
                let dist2_c = to_c.length_squared();
                if dist2_c <= radius * radius {
                    return None; // inside the light: it is all around, BSDF sampling finds it
                }
                // Sample the cone of directions the sphere subtends (pbrt-v4), so the pdf
                // is the exact solid-angle pdf the MIS weights need. `1 - cos_max` comes
                // from `sin^2` without cancellation: a sphere of radius 1e-6 at distance 1
                // has `cos_max = 1` in f32, and the naive pdf would be infinite.
                let sin2_max = radius * radius / dist2_c;
                let omc_max = one_minus_cos_from_sin2(sin2_max);
                let dist_c = dist2_c.sqrt();
                let axis = to_c / dist_c;
                let local = uniform_cone(u, omc_max);
                let wi = Frame::from_normal(axis).to_world(local).normalize();
                // The point on the sphere along `wi`, from the triangle (p, center, point):
                // the near root of |p + t wi - c| = r with t = d cos - sqrt(r^2 - d^2 sin^2),
                // where d^2 sin^2 = d^2 (1 - cos^2) is taken from the sampled `local`
                // (sin^2 = x^2 + y^2), not re-derived from `wi`, so it stays exact for tiny
                // cones instead of intersecting a 1e-6 sphere in f32 from afar.
                let sin2 = local.x * local.x + local.y * local.y;
                let disc = (radius * radius - dist2_c * sin2).max(0.0);
                let dist = (dist_c * local.z - disc.sqrt()).max(0.0);
                let n = (p + wi * dist - center).normalize_or(-axis);
                Some(LightSample {
                    wi,
                    dist,
                    li: radiance,
                    pdf: 1.0 / (2.0 * PI * omc_max),
                    delta: false,
                    n: Some(n),
                })
            }
            LightKind::Point {
                position,
                intensity,
            } => {
                let d = position - p;
                let dist2 = d.length_squared();
                let dist = dist2.sqrt();
                Some(LightSample {
                    wi: d / dist,
                    dist,
                    li: intensity / dist2,
                    pdf: 1.0,
                    delta: true,
                    n: None,
                })
            }
            LightKind::Distant {
                direction,
                irradiance,
            } => Some(LightSample {
                wi: direction,
                dist: f32::INFINITY,
                li: irradiance,
                pdf: 1.0,
                delta: true,
                n: None,
            }),
            LightKind::Dome { radiance } => Some(LightSample {
                wi: uniform_sphere(u),
                dist: f32::INFINITY,
                li: radiance,
                pdf: 1.0 / (4.0 * PI),
                delta: false,
                n: None,
            }),
        }
    }

    /// Solid-angle pdf with which [`Light::sample`] from `p` produces the direction to
    /// the light point `q` (normal `n`) a ray reached; for the dome, `q` is ignored.
    pub fn pdf(&self, p: Vec3, q: Vec3, n: Vec3) -> f32 {
        match self.kind {
            LightKind::Quad { u, v, .. } => {
                let area = u.cross(v).length();
                let d = q - p;
                let dist2 = d.length_squared();
                let cos_l = (-d.normalize().dot(n)).max(0.0);
                if cos_l == 0.0 {
                    0.0
                } else {
                    dist2 / (area * cos_l)
                }
            }
            LightKind::Sphere { center, radius, .. } => {
                let dist2_c = (center - p).length_squared();
                if dist2_c <= radius * radius {
                    return 0.0;
                }
                1.0 / (2.0 * PI * one_minus_cos_from_sin2(radius * radius / dist2_c))
            }
            LightKind::Dome { .. } => 1.0 / (4.0 * PI),
            LightKind::Point { .. } | LightKind::Distant { .. } => 0.0,
        }
    }

    /// Radiance leaving an area light's surface toward direction `-d` (the ray's
    /// direction is `d`) at a point with normal `n`.
    pub fn emitted(&self, d: Vec3, n: Vec3) -> Vec3 {
        match self.kind {
            LightKind::Quad { radiance, .. } if d.dot(n) < 0.0 => radiance,
            LightKind::Sphere { radiance, .. } if d.dot(n) < 0.0 => radiance,
            LightKind::Dome { radiance } => radiance,
            _ => Vec3::ZERO,
        }
    }

    /// The geometry of an area light, to put into the scene's BVH.
    pub fn shape(&self) -> Option<crate::geometry::Shape> {
        match self.kind {
            LightKind::Quad { corner, u, v, .. } => {
                Some(crate::geometry::Shape::Quad { corner, u, v })
            }
            LightKind::Sphere { center, radius, .. } => {
                Some(crate::geometry::Shape::Sphere { center, radius })
            }
            _ => None,
        }
    }
}
