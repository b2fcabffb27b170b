//! Hard cases stay numerically stable. Each test compares against a closed form
//! or an independent computation; statistical ones state their significance.

use glam::{DVec3, Vec3};
use lpe::renderman::RenderMan;
use lpe::renderman::{LobeMap, Parser};
use lpe_render::aov::AovList;
use lpe_render::film::Accumulation;
use lpe_render::geometry::{Bvh, Ray, Shape};
use lpe_render::integrator::{Render, Settings, Technique};
use lpe_render::light::{Light, LightKind};
use lpe_render::material::{fresnel_dielectric, Lobe, Model};
use lpe_render::rng::Rng;
use lpe_render::sampling::power_heuristic;
use lpe_render::scene::Scene;
use lpe_render::verify::known;
use lpe_render::verify::stats::{critical_z, mean_and_se, sidak};
use lpe_render::verify::stress;

/// Family-wise significance of each statistical test below (Sidak over its cases).
const ALPHA: f64 = 0.01;

fn lobes() -> LobeMap {
    LobeMap::default()
}

fn wo(cos: f32) -> Vec3 {
    Vec3::new((1.0 - cos * cos).max(0.0).sqrt(), 0.0, cos)
}

fn render(scene: &Scene, aovs: &AovList<RenderMan>, settings: &Settings) -> Render {
    lpe_render::integrator::render(scene, aovs, &lobes(), settings).unwrap()
}

#[test]
fn ggx_from_alpha_1e_1_to_1e_7_and_at_grazing_is_finite_and_conserves_energy() {
    let map = lobes();
    let alphas = [1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7];
    let coses = [1.0, 0.5, 1e-3, 1e-6];
    let m = alphas.len() * coses.len();
    // One-sided, Sidak-corrected over all (alpha, cos) cases.
    let z = critical_z(2.0 * sidak(ALPHA, m));
    for alpha in alphas {
        // f0 = 1: a white furnace for the lobe; the mean weight is its directional
        // albedo, which single-scattering GGX keeps below 1.
        let lobe = Lobe::white_ggx(alpha, &map);
        for cos in coses {
            let w = wo(cos);
            let mut rng = Rng::for_sample(1, 0, 0);
            let mut weights = Vec::new();
            let mut far = 0;
            for _ in 0..20_000 {
                let Some(s) = lobe.sample(w, rng.vec2()) else {
                    weights.push(0.0);
                    continue;
                };
                assert!(
                    s.weight.is_finite() && s.weight.min_element() >= 0.0,
                    "alpha {alpha} cos {cos}: weight {}",
                    s.weight
                );
                assert!(
                    s.pdf.is_finite() && s.pdf > 0.0,
                    "alpha {alpha} cos {cos}: pdf {}",
                    s.pdf
                );
                let (f, pdf) = lobe.eval(w, s.wi);
                assert!(
                    f.is_finite() && pdf.is_finite(),
                    "alpha {alpha} cos {cos}: eval {f} {pdf}"
                );
                weights.push(s.weight.x as f64);
                let mirror = Vec3::new(-w.x, -w.y, w.z);
                let angle = s.wi.normalize().dot(mirror).clamp(-1.0, 1.0).acos();
                far += (angle > 100.0 * alpha + 1e-3) as usize;
            }
            let (mean, se) = mean_and_se(&weights);
            assert!(
                mean <= 1.0 + z * se + 1e-6,
                "alpha {alpha} cos {cos}: mean weight {mean} > 1 (se {se})"
            );
            if alpha <= 1e-4 && cos >= 0.5 {
                // A near-delta lobe is a mirror: directions within 100 alpha of the
                // mirror direction (plus f32 rounding of unit vectors) except for GGX's
                // long tail, P(tan theta_h > 50 alpha) = 1/2501 (allow 1%); all energy
                // returned (F = 1, G = 1 to within alpha).
                assert!(
                    far <= weights.len() / 100,
                    "alpha {alpha} cos {cos}: {far} samples off the mirror"
                );
                assert!(
                    (mean - 1.0).abs() < 1e-3,
                    "alpha {alpha} cos {cos}: mean {mean}"
                );
            }
        }
    }
}

#[test]
fn diffuse_lobes_return_exactly_their_albedo() {
    // White furnace per lobe: cosine sampling makes every weight exactly the albedo.
    let map = lobes();
    for model in [
        Model::Lambert { albedo: Vec3::ONE },
        Model::DiffuseTransmission { albedo: Vec3::ONE },
    ] {
        let lobe = Lobe::new("Diffuse", model, &map);
        for cos in [1.0, 0.3, 1e-6, -0.7] {
            let mut rng = Rng::for_sample(2, 0, 0);
            for _ in 0..10_000 {
                if let Some(s) = lobe.sample(wo(cos), rng.vec2()) {
                    assert!(
                        (s.weight - Vec3::ONE).abs().max_element() < 1e-5,
                        "{model:?} {cos}: {}",
                        s.weight
                    );
                }
            }
        }
    }
}

#[test]
fn dielectrics_at_ior_1_1_5_and_10_obey_fresnel_snell_and_total_internal_reflection() {
    // Closed forms: normal-incidence reflectance ((n-1)/(n+1))^2.
    for (n, r0) in [
        (1.0f32, 0.0f32),
        (1.5, 0.04),
        (10.0, (9.0f32 / 11.0).powi(2)),
    ] {
        assert!((fresnel_dielectric(1.0, n) - r0).abs() < 1e-6, "ior {n}");
    }
    let map = lobes();
    let coses = [1.0f32, 0.5, 0.1, 1e-3, 1e-6];
    let iors = [1.0f32, 1.5, 10.0];
    // Binomial z-test of the reflected fraction, two-sided, Sidak over all cases.
    let z = critical_z(sidak(ALPHA, coses.len() * iors.len() * 2));
    for ior in iors {
        let glass = Lobe::new(
            "Glass",
            Model::Dielectric {
                ior,
                tint: Vec3::ONE,
            },
            &map,
        );
        for cos in coses {
            for side in [1.0f32, -1.0] {
                let w = wo(cos) * Vec3::new(1.0, 1.0, side);
                let eta = if side > 0.0 { ior } else { 1.0 / ior };
                let sin_i = (1.0 - cos as f64 * cos as f64).sqrt();
                let tir = sin_i / eta as f64 >= 1.0;
                let fr = fresnel_dielectric(cos, eta) as f64;
                if ior == 1.0 {
                    assert_eq!(fr, 0.0, "IOR 1 is not an interface, even at cos {cos}");
                }
                if tir {
                    assert_eq!(fr, 1.0);
                }
                let n = 20_000;
                let mut reflected = 0;
                let mut rng = Rng::for_sample(3, 0, 0);
                for _ in 0..n {
                    let s = glass
                        .sample(w, rng.vec2())
                        .expect("a dielectric always scatters");
                    assert!(s.delta && s.wi.is_finite() && s.weight.is_finite());
                    if s.wi.z * w.z > 0.0 {
                        reflected += 1;
                        assert!((s.wi - Vec3::new(-w.x, -w.y, w.z)).length() < 1e-6);
                        assert_eq!(s.weight, Vec3::ONE);
                    } else {
                        // Snell: sin_t = sin_i / eta, opposite side; radiance / eta^2.
                        let sin_t = (s.wi.x as f64).hypot(s.wi.y as f64);
                        assert!(
                            (sin_t - sin_i / eta as f64).abs() < 1e-5,
                            "ior {ior} cos {cos} side {side}"
                        );
                        assert!(s.wi.x * w.x <= 0.0);
                        assert!((s.weight.x - 1.0 / (eta * eta)).abs() < 1e-5 / (eta * eta));
                        if ior == 1.0 {
                            assert!(
                                (s.wi + w).length() < 1e-6,
                                "IOR 1 passes straight through: {}",
                                s.wi
                            );
                        }
                    }
                }
                let p = reflected as f64 / n as f64;
                let se = (fr * (1.0 - fr) / n as f64).sqrt();
                if se == 0.0 {
                    assert_eq!(p, fr, "ior {ior} cos {cos} side {side}");
                } else {
                    assert!(
                        (p - fr).abs() <= z * se,
                        "ior {ior} cos {cos} side {side}: {p} vs {fr}"
                    );
                }
            }
        }
    }
}

/// Irradiance at `p` (normal `n`) from a sphere light by its own sampler:
/// mean of `Le cos / pdf`.
fn irradiance_by_sampling(light: &Light, p: Vec3, n: Vec3, samples: usize) -> (f64, f64) {
    let mut rng = Rng::for_sample(4, 0, 0);
    let x: Vec<f64> = (0..samples)
        .map(|_| {
            let s = light.sample(p, rng.vec2()).expect("outside the light");
            assert!(s.pdf.is_finite() && s.pdf > 0.0 && s.li.is_finite() && s.dist.is_finite());
            // The sampler's pdf is the one MIS uses when a ray reaches the light.
            let q = p + s.wi * s.dist;
            let pdf2 = light.pdf(p, q, s.n.unwrap());
            assert!((pdf2 / s.pdf - 1.0).abs() < 1e-4, "pdf {} vs {pdf2}", s.pdf);
            (s.li.x * s.wi.dot(n).max(0.0) / s.pdf) as f64
        })
        .collect();
    mean_and_se(&x)
}

#[test]
fn tiny_sphere_lights_keep_their_power_and_stay_finite() {
    // Same power at radius 1 and 1e-6: Le scales with 1/R^2. Irradiance from a sphere
    // fully above the horizon is pi Le (R/d)^2 cos (closed form), the same for both.
    let center = Vec3::new(0.3, 2.0, -0.4);
    let p = Vec3::ZERO;
    let n = Vec3::new(0.2, 1.0, 0.1).normalize();
    let to_c = center - p;
    let cos = (to_c.normalize().dot(n)) as f64;
    let le0 = 3.0f64;
    for radius in [1.0f32, 1e-2, 1e-4, 1e-6] {
        let le = le0 / (radius as f64).powi(2);
        let light = Light {
            kind: LightKind::Sphere {
                center,
                radius,
                radiance: Vec3::splat(le as f32),
            },
            group: None,
        };
        let want = std::f64::consts::PI * le0 / to_c.length_squared() as f64 * cos;
        let (got, se) = irradiance_by_sampling(&light, p, n, 50_000);
        // 5 standard errors (significance < 1e-6) plus f32 rounding of Le and the pdf.
        assert!(
            (got - want).abs() <= 5.0 * se + 1e-4 * want,
            "radius {radius}: {got} vs {want} (se {se})"
        );
    }
}

#[test]
fn tiny_sphere_light_over_a_plane_renders_its_closed_form() {
    // Through the integrator: direct lighting of the plane scene by a sphere light of
    // radius 0.5 and of radius 1e-6 with the same power, against a Le (R/d)^2 cos.
    let (w, h) = (12, 12);
    for radius in [0.5, 1e-6] {
        let known = known::sphere_over_plane(w, h, radius, &lobes()).unwrap();
        for technique in [Technique::Mis, Technique::LightOnly] {
            let settings = Settings {
                width: w,
                height: h,
                spp: 64,
                seed: 9,
                technique,
                ..Settings::default()
            };
            let r = render(&known.scene, &known.aovs, &settings);
            assert_eq!(r.film.rejected + r.film.aov_rejected, 0);
            assert_mean_matches(
                &r.film.layer(1),
                &known.reference[1],
                &format!("radius {radius} {technique:?}"),
            );
        }
    }
}

/// The image mean of `got` matches that of `want` (see [`stress::mean_check`]: 5
/// standard errors of the per-pixel residuals, significance < 1e-6, plus 1e-4 relative).
fn assert_mean_matches(got: &[DVec3], want: &[DVec3], what: &str) {
    let (e, bound) = stress::mean_check(got, want);
    assert!(e <= bound, "{what}: relative error {e:e} > {bound:e}");
}

#[test]
fn intensities_from_1e_minus_6_to_1e12_in_one_scene_each_keep_their_light_group() {
    // Four point lights whose intensities span 18 orders of magnitude, each in its own
    // light group; each group's AOV must match its closed form (a/pi) I cos/d^2.
    let (scene, aovs) = known::intensities_scene(&lobes()).unwrap();
    let (w, h) = (12, 12);
    let settings = Settings {
        width: w,
        height: h,
        spp: 128,
        seed: 3,
        ..Settings::default()
    };
    let r = render(&scene, &aovs, &settings);
    assert_eq!(r.film.rejected + r.film.aov_rejected, 0);
    assert!(r.film.layer(0).iter().all(|v| v.is_finite()));
    for k in 0..known::INTENSITIES.len() {
        let want = known::intensity_reference(&scene, k, w, h);
        assert_mean_matches(&r.film.layer(1 + k), &want, &format!("light {k}"));
    }
}

#[test]
fn mis_weights_stay_finite_and_complementary_for_pdfs_from_0_to_1e30_and_beyond() {
    let pdfs = [
        0.0f32,
        1e-45,
        1e-38,
        1e-30,
        1e-6,
        1.0,
        1e6,
        1e30,
        3e38,
        f32::INFINITY,
    ];
    for a in pdfs {
        for b in pdfs {
            let (wa, wb) = (power_heuristic(a, b), power_heuristic(b, a));
            assert!((0.0..=1.0).contains(&wa), "w({a}, {b}) = {wa}");
            if a > 0.0 || b > 0.0 {
                assert!(
                    (wa + wb - 1.0).abs() < 1e-6,
                    "w({a},{b}) + w({b},{a}) = {}",
                    wa + wb
                );
            }
        }
    }
    // In a render: a near-mirror (alpha 1e-7, pdf peak ~1e13) lit by a 1e-6 sphere light
    // (light pdf ~1e12), a point light and a dome: nothing is rejected as non-finite.
    let scene = Scene::from_toml(known::MIS_EXTREMES, "mis", &lobes()).unwrap();
    let aovs = AovList::<RenderMan>::defaults(&scene, &Parser::default()).unwrap();
    for technique in [Technique::Mis, Technique::BsdfOnly, Technique::LightOnly] {
        let s = Settings {
            width: 16,
            height: 16,
            spp: 16,
            seed: 2,
            technique,
            ..Settings::default()
        };
        let r = render(&scene, &aovs, &s);
        assert_eq!(r.film.rejected + r.film.aov_rejected, 0, "{technique:?}");
        for l in 0..r.film.layers {
            assert!(
                r.film.layer(l).iter().all(|v| v.is_finite()),
                "{technique:?} layer {l}"
            );
        }
    }
}

#[test]
fn spawned_rays_never_hit_their_own_surface_at_scales_1e_minus_6_to_1e6() {
    let mut failures = Vec::new();
    for e in -6..=6 {
        let s = 10f32.powi(e);
        // Each shape sits at coordinates ~s with size ~s (and one at 1e3 s with size s:
        // the offset must follow the coordinates, not the size).
        for at in [1.0f32, 1e3] {
            let c = Vec3::new(1.0, 2.0, -1.5) * s * at;
            let shapes = [
                Shape::Sphere {
                    center: c,
                    radius: s,
                },
                Shape::Quad {
                    corner: c,
                    u: Vec3::new(2.0, 0.1, 0.0) * s,
                    v: Vec3::new(0.0, 0.3, 2.0) * s,
                },
                Shape::Triangle {
                    p0: c,
                    e1: Vec3::new(2.0, 0.0, 0.2) * s,
                    e2: Vec3::new(0.1, 0.4, 2.0) * s,
                },
            ];
            for shape in shapes {
                let bvh = Bvh::new(vec![(shape, 0)]);
                let target = shape.centroid();
                let mut rng = Rng::for_sample((e + 100) as u64, at as u64, 0);
                let mut hits = 0;
                for i in 0..400 {
                    // Rays from a few sizes away, aimed near the centroid.
                    let from =
                        target + lpe_render::sampling::uniform_sphere(rng.vec2()) * (4.0 * s);
                    let aim = target + (Vec3::new(rng.f32(), rng.f32(), rng.f32()) - 0.5) * s;
                    let ray = Ray {
                        o: from,
                        d: (aim - from).normalize(),
                    };
                    let Some(hit) = bvh.intersect(&ray, f32::INFINITY) else {
                        continue;
                    };
                    hits += 1;
                    // Leave to both sides of the surface.
                    let d = lpe_render::sampling::uniform_sphere(rng.vec2());
                    for dir in [d, -d] {
                        let spawned = Ray::spawn(hit.p, hit.n, hit.err, dir);
                        let again = bvh.intersect(&spawned, f32::INFINITY);
                        let entering = dir.dot(hit.n) < 0.0;
                        let ok = match (shape, again) {
                            // Into a sphere: only the far side, at least half the chord
                            // 2 r cos away (the offset lengthens a grazing chord).
                            (Shape::Sphere { radius, .. }, Some(h2)) if entering => {
                                h2.t >= radius * dir.dot(-hit.n)
                            }
                            (Shape::Sphere { .. }, None) => !entering || dir.dot(-hit.n) < 1e-3,
                            (_, None) => true,
                            (_, Some(_)) => false,
                        };
                        if !ok {
                            failures.push(format!("scale {s:e} at {at}: {shape:?} ray {i} dir {dir} hit {hit:?} again {again:?}"));
                        }
                    }
                }
                // Rays that miss test nothing: a broken intersector must not pass here.
                if hits < 100 {
                    failures.push(format!(
                        "scale {s:e} at {at}: {shape:?}: only {hits} of 400 rays hit"
                    ));
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} failures (self-intersections, or too few hits), first: {:#?}",
        failures.len(),
        &failures[..failures.len().min(3)]
    );
}

#[test]
fn ten_million_mixed_samples_per_pixel_partition_beauty_in_f64_and_compensated_f32_not_naive_f32() {
    let spp: u32 = std::env::var("LPE_MIXED_SPP")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(10_000_000);
    let (errors, beauty) = stress::mixed_partition(spp, &lobes()).unwrap();
    assert!(beauty.min_element() > 0.0);
    for &(a, err) in &errors {
        eprintln!("{spp} spp: partition error, {} film: {err:.2e}", a.name());
        match a {
            Accumulation::F64 | Accumulation::F32Compensated => assert!(
                err <= 1e-6,
                "{} film: basic AOVs miss beauty by {err:e} relative",
                a.name()
            ),
            Accumulation::F32 if spp >= 10_000_000 => assert!(
                err > 1e-4,
                "the naive f32 film should visibly fail, error only {err:e}"
            ),
            Accumulation::F32 => {}
        }
    }
    assert_eq!(errors.len(), Accumulation::ALL.len());
}

#[test]
fn degenerate_geometry_and_a_camera_inside_spheres_render_finite() {
    // Zero-area and sliver triangles in a mesh (skipped or harmless), a camera at the
    // exact center of a diffuse sphere and inside a glass sphere.
    let text = r#"
[camera]
position = [0.0, 0.0, 0.0]
look_at = [0.0, 0.0, -1.0]
[materials.wall]
lobes = [{ name = "Diffuse", model = "lambert", albedo = [0.5, 0.5, 0.5] }]
[materials.glass]
lobes = [{ name = "Glass", model = "dielectric", ior = 1.5 }]
[[objects]]
material = "wall"
sphere = { center = [0.0, 0.0, 0.0], radius = 5.0 }
[[objects]]
material = "glass"
sphere = { center = [0.0, 0.0, 0.0], radius = 1.0 }
[[objects]]
material = "wall"
mesh = { vertices = [[0.0, 0.0, -0.5], [0.0, 0.0, -0.5], [0.1, 0.0, -0.5], [0.2, 1e-20, -0.5], [0.3, 0.0, -0.5], [0.0, 0.3, -0.5]], triangles = [[0, 1, 2], [0, 2, 4], [2, 3, 4], [0, 4, 5]] }
[[lights]]
kind = "point"
position = [1.0, 2.0, -2.0]
intensity = [10.0, 10.0, 10.0]
"#;
    let scene = Scene::from_toml(text, "inside", &lobes()).unwrap();
    let aovs = AovList::<RenderMan>::defaults(&scene, &Parser::default()).unwrap();
    let r = render(
        &scene,
        &aovs,
        &Settings {
            width: 16,
            height: 16,
            spp: 16,
            ..Settings::default()
        },
    );
    assert_eq!(r.film.rejected, 0);
    for l in 0..r.film.layers {
        assert!(r.film.layer(l).iter().all(|v| v.is_finite()), "layer {l}");
    }
    assert!(
        r.film.layer(0).iter().any(|v| v.x > 0.0),
        "light reaches the camera through the glass"
    );
}

#[test]
fn nan_and_infinity_in_a_scene_file_are_rejected_with_file_line_and_field() {
    let base = |field: &str| {
        format!(
            "[camera]\nposition = [0.0, 0.0, 5.0]\nlook_at = [0.0, 0.0, 0.0]\n\
             [materials.m]\nlobes = [{{ name = \"Specular\", model = \"ggx\", f0 = [0.5, 0.5, 0.5], roughness = 0.5 }}]\n\
             [[objects]]\nmaterial = \"m\"\n{}\n[[lights]]\nkind = \"point\"\nposition = [0.0, 1.0, 0.0]\nintensity = [1.0, 1.0, 1.0]\n",
            field
        )
    };
    let cases = [
        (base("sphere = { center = [nan, 0.0, 0.0], radius = 1.0 }"), "center"),
        (base("sphere = { center = [0.0, 0.0, 0.0], radius = inf }"), "radius"),
        (base("quad = { corner = [0.0, 0.0, 0.0], u = [1.0, -inf, 0.0], v = [0.0, 1.0, 0.0] }"), "u"),
        (base("mesh = { vertices = [[0.0, 0.0, 0.0], [1.0, nan, 0.0], [0.0, 1.0, 0.0]], triangles = [[0, 1, 2]] }"), "mesh vertex"),
        (base("sphere = { center = [0.0, 0.0, 0.0], radius = 1e39 }"), "radius"),
        (base("sphere = { center = [0.0, 0.0, 0.0], radius = 1.0 }").replace("roughness = 0.5", "roughness = nan"), "roughness"),
        (base("sphere = { center = [0.0, 0.0, 0.0], radius = 1.0 }").replace("intensity = [1.0, 1.0, 1.0]", "intensity = [1.0, inf, 1.0]"), "intensity"),
        (base("sphere = { center = [0.0, 0.0, 0.0], radius = 1.0 }").replace("position = [0.0, 0.0, 5.0]", "position = [0.0, nan, 5.0]"), "camera position"),
    ];
    for (text, field) in &cases {
        let e = Scene::from_toml(text, "bad.toml", &lobes()).expect_err(field);
        let msg = e.to_string();
        assert!(msg.starts_with("bad.toml"), "{msg}");
        assert!(msg.contains(field), "{field}: {msg}");
        assert!(
            msg.contains("finite") || msg.contains("positive") || msg.contains("[0, 1]"),
            "{field}: {msg}"
        );
    }
    // Through the CLI: exit status 2 and the message, nothing rendered.
    let dir = std::env::temp_dir().join(format!("lpe-hard-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("nan.toml");
    std::fs::write(&file, &cases[0].0).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_lpe-render"))
        .args([
            "--scene",
            file.to_str().unwrap(),
            "--out",
            dir.join("out").to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("nan.toml:") && err.contains("finite"), "{err}");
    assert!(
        !dir.join("out").exists(),
        "nothing is written for a rejected scene"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
