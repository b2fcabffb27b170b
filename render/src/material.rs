//! Materials: sums of named lobes (docs/language.md §2.4). Each lobe is one BSDF model; its name
//! goes through the [`lpe::renderman::LobeMap`] to the event its vertices record.
//!
//! A material's BSDF is the sum of its lobes. Paths pick one lobe per vertex with
//! probability `p_i` (proportional to the lobe's albedo estimate) and sample a direction
//! from it: the estimate `f_i cos / (p_i pdf_i)` is unbiased for the sum, and the vertex
//! records exactly the lobe that scattered, which is what LPE routing needs. Energy
//! conservation across lobes is the scene author's job (weights sum to at most 1), as
//! with a layered shader's mix weights.

use glam::{Vec2, Vec3};
use lpe::renderman::{Event, LobeCategory, LobeMap};
use std::f32::consts::{FRAC_1_PI, PI};

use crate::sampling::{cosine_hemisphere, luminance};

/// How a lobe scatters, as OSL's scattering labels tell lobes apart (RenderMan's events
/// do not: its `S` lobes are glossy and delta alike).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scattering {
    /// OSL `D`.
    Diffuse,
    /// OSL `G`: a rough lobe with a density.
    Glossy,
    /// OSL `S`: a Dirac delta (mirror reflection, refraction).
    Delta,
}

/// The BSDF model of a lobe.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Model {
    /// Lambertian reflection with this albedo.
    Lambert { albedo: Vec3 },
    /// Lambertian transmission (a stand-in for subsurface scattering).
    DiffuseTransmission { albedo: Vec3 },
    /// GGX microfacet reflection with Schlick Fresnel from `f0`.
    Ggx { f0: Vec3, alpha: f32 },
    /// Smooth dielectric: Fresnel-weighted mirror reflection and refraction, total
    /// internal reflection; `ior` inside over outside (the side the normal points from).
    Dielectric { ior: f32, tint: Vec3 },
}

/// One named lobe of a material.
#[derive(Clone, Debug, PartialEq)]
pub struct Lobe {
    pub name: String,
    pub model: Model,
    /// The LPE event its vertices record (from the lobe map).
    pub event: Event,
}

impl Lobe {
    pub fn new(name: &str, model: Model, lobes: &LobeMap) -> Lobe {
        let category = match model {
            Model::Lambert { .. } | Model::DiffuseTransmission { .. } => LobeCategory::Diffuse,
            Model::Ggx { .. } | Model::Dielectric { .. } => LobeCategory::Specular,
        };
        Lobe {
            name: name.to_string(),
            model,
            event: lobes.event(category, name),
        }
    }

    /// A GGX lobe named `Specular` with `f0 = 1`: its directional albedo is the white
    /// furnace the stability tests and the chi-square suite measure against.
    pub fn white_ggx(alpha: f32, lobes: &LobeMap) -> Lobe {
        Lobe::new(
            "Specular",
            Model::Ggx {
                f0: Vec3::ONE,
                alpha,
            },
            lobes,
        )
    }

    /// Whether the lobe is a Dirac delta (cannot be evaluated, only sampled).
    pub fn is_delta(&self) -> bool {
        matches!(self.model, Model::Dielectric { .. })
    }

    /// How the lobe scatters, in OSL's terms: `D`, `G` or `S` (delta).
    pub fn scattering(&self) -> Scattering {
        match self.model {
            Model::Lambert { .. } | Model::DiffuseTransmission { .. } => Scattering::Diffuse,
            Model::Ggx { .. } => Scattering::Glossy,
            Model::Dielectric { .. } => Scattering::Delta,
        }
    }

    /// Whether the lobe can scatter to the other side of the surface.
    pub fn transmits(&self) -> bool {
        matches!(
            self.model,
            Model::DiffuseTransmission { .. } | Model::Dielectric { .. }
        )
    }

    /// Rough estimate of the fraction of light it scatters, for lobe selection and for
    /// the `Albedo` user signal.
    pub fn albedo(&self) -> Vec3 {
        match self.model {
            Model::Lambert { albedo } | Model::DiffuseTransmission { albedo } => albedo,
            Model::Ggx { f0, .. } => f0,
            Model::Dielectric { tint, .. } => tint,
        }
    }
}

/// A direction sampled from a lobe.
#[derive(Clone, Copy, Debug)]
pub struct LobeSample {
    pub wi: Vec3,
    /// `f |cos| / pdf`.
    pub weight: Vec3,
    /// Solid-angle pdf of the lobe alone (for delta lobes: 0, unused by MIS).
    pub pdf: f32,
    pub delta: bool,
}

/// Schlick's approximation of Fresnel reflectance.
fn schlick(f0: Vec3, cos: f32) -> Vec3 {
    let m = (1.0 - cos.clamp(0.0, 1.0)).powi(5);
    f0 + (Vec3::ONE - f0) * m
}

/// Unpolarized Fresnel reflectance of a dielectric interface; `eta` = transmitted over
/// incident index, `cos_i >= 0`. Returns 1 under total internal reflection.
///
/// Computed in f64 from `cos_t^2 = (eta^2 - 1 + cos_i^2) / eta^2`, which (unlike
/// `1 - sin_t^2`) keeps grazing angles exact: at `eta = 1` and `cos_i = 1e-6` the f32 form
/// rounds `sin_t^2` to 1 and reports total internal reflection at a non-interface.
pub fn fresnel_dielectric(cos_i: f32, eta: f32) -> f32 {
    let Some(cos_t) = refracted_cos(cos_i, eta) else {
        return 1.0;
    };
    let (ci, ct, e) = (cos_i as f64, cos_t, eta as f64);
    let rs = (ci - e * ct) / (ci + e * ct);
    let rp = (e * ci - ct) / (e * ci + ct);
    let r = 0.5 * (rs * rs + rp * rp);
    // 0/0 only at cos_i = cos_t = 0 (grazing onto a non-interface): nothing reflects.
    if r.is_finite() {
        r as f32
    } else {
        0.0
    }
}

/// `cos` of the refracted direction for incident `cos_i >= 0` and relative index `eta`
/// (transmitted over incident), or `None` under total internal reflection.
fn refracted_cos(cos_i: f32, eta: f32) -> Option<f64> {
    let (ci, e) = (cos_i as f64, eta as f64);
    let cos2_t = (e * e - 1.0 + ci * ci) / (e * e);
    (cos2_t > 0.0).then(|| cos2_t.sqrt())
}

/// `sin^2` of a unit vector's angle to `+z`, from its tangent components: exact near the
/// pole, where `1 - z^2` cancels (alpha 1e-7 lobes live within 1e-7 rad of it).
fn sin2(w: Vec3) -> f32 {
    w.x * w.x + w.y * w.y
}

/// The half vector `normalize(wo + wi)` of two directions and `wo.h`, from the unit
/// directions in f64. In f32, at grazing incidence the reflection's large tangential
/// components (~ -1 and 1) cancel in the sum and take `h`'s tilt with them: at `cos 1e-6`
/// that tilt is `2 (wo.h) h_t`, below f32's 6e-8 resolution of 1 where `wo.h` is small
/// (near `wi = -wo`, and everywhere for small alpha), and `wo.h` itself cancels there
/// (`h.x ~ -cos_o h.z`): pdfs were off by factors up to 1e2 at alpha 0.1 and 4e4 at 1e-7
/// (chi-square p = 0 at cos 1e-6 for every alpha).
fn half_vector(wo: Vec3, wi: Vec3) -> (Vec3, f32) {
    let wo = wo.as_dvec3().normalize();
    let h = (wo + wi.as_dvec3().normalize()).normalize();
    (h.as_vec3(), wo.dot(h) as f32)
}

/// GGX normal distribution for half vector `h` (local frame, unit):
/// `alpha^2 / (pi (sin^2 + alpha^2 cos^2)^2)`. The usual `cos^2 (alpha^2 - 1) + 1` rounds to
/// 0 at the peak once `alpha^2` is below f32 epsilon (alpha < 3e-4), giving D = inf.
fn ggx_d(h: Vec3, alpha: f32) -> f32 {
    let a2 = alpha * alpha;
    let d = sin2(h) + a2 * h.z * h.z;
    a2 / (PI * d * d)
}

/// Smith masking for GGX, `2 / (1 + sqrt(1 + alpha^2 tan^2))`.
fn ggx_g1(w: Vec3, alpha: f32) -> f32 {
    let c2 = w.z * w.z;
    if c2 <= 0.0 {
        return 0.0;
    }
    let t2 = sin2(w) / c2;
    2.0 / (1.0 + (1.0 + alpha * alpha * t2).sqrt())
}

/// Smallest GGX roughness: `roughness = 0` in a scene file still gives a finite lobe. At
/// 1e-7 the peak of D is 3e13 and `alpha^4` = 1e-28 is still a normal f32, so D, the pdf
/// and (computed without them, see [`Lobe::sample`]) the sample weight stay finite.
pub const MIN_ALPHA: f32 = 1e-7;

impl Lobe {
    /// `(f |cos_i|, pdf)` for a non-delta lobe; directions in the local frame of the
    /// geometric normal.
    pub fn eval(&self, wo: Vec3, wi: Vec3) -> (Vec3, f32) {
        let same_side = wo.z * wi.z > 0.0;
        match self.model {
            Model::Lambert { albedo } if same_side => {
                let c = wi.z.abs();
                (albedo * FRAC_1_PI * c, c * FRAC_1_PI)
            }
            Model::DiffuseTransmission { albedo } if !same_side && wi.z != 0.0 => {
                let c = wi.z.abs();
                (albedo * FRAC_1_PI * c, c * FRAC_1_PI)
            }
            Model::Ggx { f0, alpha } if same_side => {
                let alpha = alpha.max(MIN_ALPHA);
                // Work on the upper hemisphere: flip both directions if wo is below.
                let s = wo.z.signum();
                let (wo, wi) = (wo * s, wi * s);
                let (h, wo_h) = half_vector(wo, wi);
                let d = ggx_d(h, alpha);
                let g = ggx_g1(wo, alpha) * ggx_g1(wi, alpha);
                let f = schlick(f0, wi.dot(h));
                let f_cos = f * (d * g / (4.0 * wo.z));
                let pdf = d * h.z / (4.0 * wo_h);
                (f_cos, pdf)
            }
            _ => (Vec3::ZERO, 0.0),
        }
    }

    /// Samples an incident direction for outgoing `wo` (local frame).
    pub fn sample(&self, wo: Vec3, u: Vec2) -> Option<LobeSample> {
        if wo.z == 0.0 {
            return None;
        }
        let s = wo.z.signum();
        match self.model {
            Model::Lambert { .. } | Model::DiffuseTransmission { .. } => {
                let side = if matches!(self.model, Model::Lambert { .. }) {
                    s
                } else {
                    -s
                };
                let mut wi = cosine_hemisphere(u);
                wi.z *= side;
                self.sample_by_eval(wo, wi)
            }
            Model::Ggx { f0, alpha } => {
                let alpha = alpha.max(MIN_ALPHA);
                // Sample h proportional to D(h) cos(theta_h) (Walter et al. 2007) on wo's
                // side: tan^2 = alpha^2 u / (1 - u), with sin and cos from tan^2 directly
                // (1 - cos^2 would cancel to 0 for tiny alpha).
                let tan2 = alpha * alpha * u.x / (1.0 - u.x).max(1e-12);
                let cos = 1.0 / (1.0 + tan2).sqrt();
                let sin = (tan2 / (1.0 + tan2)).sqrt();
                let phi = 2.0 * PI * u.y;
                let h = Vec3::new(sin * phi.cos(), sin * phi.sin(), cos * s);
                let wo_h = wo.dot(h);
                let wi = 2.0 * wo_h * h - wo;
                if !(wo_h > 0.0 && wi.z * wo.z > 0.0) {
                    return None; // reflected below the surface: masked
                }
                let (_, pdf) = self.eval(wo, wi);
                // f cos / pdf with D cancelled analytically: F G (wo.h) / (|wo.z| cos_h).
                // Dividing the two evaluated values instead gives inf/inf at alpha 1e-7.
                let (wo_u, wi_u) = (wo * s, wi * s);
                let g = ggx_g1(wo_u, alpha) * ggx_g1(wi_u, alpha);
                let weight = schlick(f0, wi.dot(h)) * (g * wo_h / (wo_u.z * cos));
                (pdf > 0.0 && weight.is_finite() && weight != Vec3::ZERO).then_some(LobeSample {
                    wi,
                    weight,
                    pdf,
                    delta: false,
                })
            }
            Model::Dielectric { ior, tint } => {
                // Entering when wo is on the normal's side.
                let eta = if s > 0.0 { ior } else { 1.0 / ior };
                let cos_o = wo.z.abs();
                let fr = fresnel_dielectric(cos_o, eta);
                let refracted = refracted_cos(cos_o, eta).filter(|_| u.x >= fr);
                Some(match refracted {
                    None => LobeSample {
                        wi: Vec3::new(-wo.x, -wo.y, wo.z),
                        weight: tint,
                        pdf: 0.0,
                        delta: true,
                    },
                    // Snell: tangential part scales by 1/eta, normal part is cos_t.
                    Some(cos_t) => LobeSample {
                        wi: Vec3::new(-wo.x / eta, -wo.y / eta, -s * cos_t as f32).normalize(),
                        // Radiance is compressed by eta^2 entering a denser medium.
                        weight: tint / (eta * eta),
                        pdf: 0.0,
                        delta: true,
                    },
                })
            }
        }
    }

    fn sample_by_eval(&self, wo: Vec3, wi: Vec3) -> Option<LobeSample> {
        let (f_cos, pdf) = self.eval(wo, wi);
        (pdf > 0.0 && f_cos != Vec3::ZERO).then(|| LobeSample {
            wi,
            weight: f_cos / pdf,
            pdf,
            delta: false,
        })
    }
}

/// A material: named lobes plus glow (emission seen as the `O` event).
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub lobes: Vec<Lobe>,
    pub glow: Vec3,
    /// Lobe selection probabilities (sum to 1 when there are lobes).
    pick: Vec<f32>,
}

impl Material {
    pub fn new(lobes: Vec<Lobe>, glow: Vec3) -> Material {
        let w: Vec<f32> = lobes
            .iter()
            .map(|l| luminance(l.albedo()).max(1e-3))
            .collect();
        let total: f32 = w.iter().sum();
        let pick = w.iter().map(|x| x / total).collect();
        Material { lobes, glow, pick }
    }

    /// Probability that a path picks lobe `i` at a vertex of this material.
    pub fn pick_pdf(&self, i: usize) -> f32 {
        self.pick[i]
    }

    /// Picks a lobe with `u` in `[0, 1)`: `(index, probability)`.
    pub fn pick(&self, u: f32) -> Option<(usize, f32)> {
        let mut acc = 0.0;
        for (i, p) in self.pick.iter().enumerate() {
            acc += p;
            if u < acc {
                return Some((i, *p));
            }
        }
        // Rounding may leave `acc` a hair below 1.
        self.pick.len().checked_sub(1).map(|i| (i, self.pick[i]))
    }

    /// The `Albedo` user signal: the sum of the lobes' albedos.
    pub fn albedo(&self) -> Vec3 {
        self.lobes.iter().map(Lobe::albedo).sum()
    }

    pub fn transmits(&self) -> bool {
        self.lobes.iter().any(Lobe::transmits)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;

    /// White-furnace estimate of a lobe's directional albedo at `wo`, by its own sampler:
    /// the mean of `weight`. Used to check sampling against evaluation below.
    fn albedo_by_sampling(lobe: &Lobe, wo: Vec3, n: usize) -> Vec3 {
        let mut rng = Rng::for_sample(11, 0, 0);
        let mut sum = Vec3::ZERO;
        for _ in 0..n {
            if let Some(s) = lobe.sample(wo, rng.vec2()) {
                sum += s.weight;
            }
        }
        sum / n as f32
    }

    /// The same albedo by uniform-sphere quadrature of `eval` (independent of the lobe's
    /// sampler): mean of `f cos / (1 / 4 pi)`.
    fn albedo_by_eval(lobe: &Lobe, wo: Vec3, n: usize) -> Vec3 {
        let mut rng = Rng::for_sample(12, 0, 0);
        let mut sum = Vec3::ZERO;
        for _ in 0..n {
            let wi = crate::sampling::uniform_sphere(rng.vec2());
            sum += lobe.eval(wo, wi).0 * (4.0 * PI);
        }
        sum / n as f32
    }

    #[test]
    fn lambert_albedo_is_exact_and_sampling_matches_eval() {
        let map = LobeMap::default();
        let wo = Vec3::new(0.3, 0.1, 0.8).normalize();
        for model in [
            Model::Lambert {
                albedo: Vec3::splat(0.5),
            },
            Model::DiffuseTransmission {
                albedo: Vec3::splat(0.5),
            },
        ] {
            let lobe = Lobe::new("Diffuse", model, &map);
            // Cosine sampling makes every weight exactly the albedo.
            let s = albedo_by_sampling(&lobe, wo, 1000);
            assert!((s - Vec3::splat(0.5)).abs().max_element() < 1e-4, "{s}");
            let e = albedo_by_eval(&lobe, wo, 200_000);
            assert!((e - Vec3::splat(0.5)).abs().max_element() < 0.01, "{e}");
        }
    }

    #[test]
    fn ggx_sampling_agrees_with_quadrature() {
        let map = LobeMap::default();
        let lobe = Lobe::new(
            "Specular",
            Model::Ggx {
                f0: Vec3::splat(0.9),
                alpha: 0.3,
            },
            &map,
        );
        let wo = Vec3::new(0.5, 0.0, 0.6).normalize();
        let s = albedo_by_sampling(&lobe, wo, 200_000);
        let e = albedo_by_eval(&lobe, wo, 400_000);
        assert!(s.x <= 1.0 + 1e-3, "energy gain {s}");
        assert!(
            (s - e).abs().max_element() < 0.02,
            "sampled {s} vs quadrature {e}"
        );
    }

    #[test]
    fn ggx_pdf_at_grazing_incidence_is_the_density_of_the_sampled_half_vector() {
        // Regression: eval took the half vector from the f32 sum wo + wi, whose ~1 and ~-1
        // tangential components cancel at grazing incidence, and reported pdfs off by up
        // to 40000x (118x at alpha 0.1). The reference is the density of the half vector
        // the sampler drew, rebuilt from `u` in f64 by the sampler's recipe, so it never
        // looks at `wi`. It differs from the sampler's f32 half vector by ~1e-7 of its
        // tilt, which near `wo.h = 0` (where the pdf goes like `1 / wo.h`) is a few
        // percent: hence the tolerance.
        let map = LobeMap::default();
        for alpha in [0.1f32, 1e-3, 1e-7] {
            let lobe = Lobe::white_ggx(alpha, &map);
            for cos in [1e-6f32, -1e-6] {
                let wo = Vec3::new(1.0, 0.0, cos);
                let o = wo.as_dvec3().normalize();
                let mut rng = Rng::for_sample(5, 0, 0);
                for _ in 0..20_000 {
                    let u = rng.vec2();
                    let Some(s) = lobe.sample(wo, u) else {
                        continue;
                    };
                    let a2 = (alpha as f64).powi(2);
                    let tan2 = a2 * u.x as f64 / (1.0 - u.x as f64);
                    let phi = 2.0 * std::f64::consts::PI * u.y as f64;
                    let h = glam::DVec3::new(
                        tan2.sqrt() * phi.cos(),
                        tan2.sqrt() * phi.sin(),
                        cos.signum() as f64,
                    )
                    .normalize();
                    let (sin2, cos_h) = (h.x * h.x + h.y * h.y, h.z.abs());
                    let d = a2 / (std::f64::consts::PI * (sin2 + a2 * cos_h * cos_h).powi(2));
                    let want = d * cos_h / (4.0 * o.dot(h));
                    let err = s.pdf as f64 / want - 1.0;
                    assert!(
                        err.abs() < 0.25,
                        "alpha {alpha} cos {cos} u {u}: pdf {} want {want}",
                        s.pdf
                    );
                }
            }
        }
    }

    #[test]
    fn dielectric_conserves_energy_and_reflects_totally_beyond_the_critical_angle() {
        assert!((fresnel_dielectric(1.0, 1.5) - 0.04).abs() < 1e-6);
        // From glass to air (eta = 1/1.5) the critical angle is asin(1/1.5) ~ 41.8 deg: 50 deg is beyond.
        let c = 50f32.to_radians().cos();
        assert_eq!(fresnel_dielectric(c, 1.0 / 1.5), 1.0);
        let map = LobeMap::default();
        let glass = Lobe::new(
            "Glass",
            Model::Dielectric {
                ior: 1.5,
                tint: Vec3::ONE,
            },
            &map,
        );
        assert_eq!(glass.event.to_string(), "S8");
        let inside = Vec3::new(c.acos().sin(), 0.0, -c);
        let s = glass.sample(inside, Vec2::new(0.999, 0.5)).unwrap();
        assert!(s.wi.z < 0.0, "TIR keeps the ray inside");
    }
}
