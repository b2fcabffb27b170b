//! Prefix routing on rendered scenes, deterministically: each test compares layers of
//! renders that share their random numbers (same seed, same threads), so the identities
//! the prefixes promise (the integrator's "Prefixes" docs, docs/language.md §7) hold bit
//! for bit or to rounding, not merely in expectation.
//!
//! The scene gives every prefix something to get wrong: a glass ball (delta lobes: a
//! light seen through it is found by BSDF sampling alone), a glossy ball (BSDF hits on
//! lights that light sampling also estimates), a holdout ball with a diffuse and a glossy
//! lobe, shadows on the floor, a quad, a sphere and a dome light.

use glam::DVec3;
use lpe::renderman::RenderMan;
use lpe::renderman::{Config, Parser};
use lpe_render::aov::AovList;
use lpe_render::integrator::{self, Render, Settings, Technique};
use lpe_render::scene::Scene;

const SCENE: &str = r#"
[camera]
position = [0.0, 1.4, 4.0]
look_at = [0.0, 0.4, 0.0]
fov = 40.0

[render]
max_depth = 4
rr_depth = 3

[materials.floor]
lobes = [{ name = "Diffuse", model = "lambert", albedo = [0.5, 0.5, 0.5] }]

[materials.gloss]
lobes = [{ name = "Specular", model = "ggx", f0 = [0.8, 0.8, 0.8], roughness = 0.3 }]

[materials.glass]
lobes = [{ name = "Glass", model = "dielectric", ior = 1.5 }]

[materials.plastic]
lobes = [
  { name = "Diffuse", model = "lambert", albedo = [0.4, 0.3, 0.2] },
  { name = "Specular", model = "ggx", f0 = [0.3, 0.3, 0.3], roughness = 0.2 },
]

[[objects]]
material = "floor"
lpegroup = "floor"
quad = { corner = [-6.0, 0.0, -6.0], u = [0.0, 0.0, 12.0], v = [12.0, 0.0, 0.0] }

[[objects]]
material = "gloss"
lpegroup = "gloss"
sphere = { center = [-1.0, 0.45, 0.0], radius = 0.45 }

[[objects]]
material = "glass"
lpegroup = "glass"
sphere = { center = [0.0, 0.45, 0.7], radius = 0.45 }

[[objects]]
material = "plastic"
lpegroup = "held"
holdout = true
sphere = { center = [1.0, 0.45, 0.0], radius = 0.45 }

[[lights]]
kind = "quad"
corner = [-0.6, 2.5, -0.6]
u = [1.2, 0.0, 0.0]
v = [0.0, 0.0, 1.2]
radiance = [8.0, 8.0, 8.0]

[[lights]]
kind = "sphere"
center = [2.0, 1.6, 1.2]
radius = 0.3
radiance = [6.0, 5.0, 4.0]

[[lights]]
kind = "dome"
radiance = [0.3, 0.35, 0.4]
"#;

const W: usize = 24;

fn parser() -> Parser {
    let c = Config::default();
    Parser::new(c.limits.clone(), c.macros.clone())
}

fn scene() -> Scene {
    Scene::from_toml(SCENE, "prefix_routing.toml", &Config::default().lobes).unwrap()
}

fn aovs(sources: &[String]) -> AovList<RenderMan> {
    let p = parser();
    let mut list = AovList::<RenderMan>::new();
    for (i, s) in sources.iter().enumerate() {
        list.push(&format!("a{i}"), s, &p).unwrap();
    }
    list
}

fn render(s: &Scene, sources: &[String], technique: Technique) -> Render {
    let settings = Settings {
        width: W,
        height: W,
        spp: 4,
        seed: 11,
        threads: Some(2),
        technique,
        ..Settings::default()
    };
    integrator::render(s, &aovs(sources), &Config::default().lobes, &settings).unwrap()
}

fn strings(xs: &[&str]) -> Vec<String> {
    xs.iter().map(|s| s.to_string()).collect()
}

/// AOV `i`'s layer.
fn layer(r: &Render, i: usize) -> Vec<DVec3> {
    r.film.layer(1 + i)
}

fn total(v: &[DVec3]) -> f64 {
    v.iter().map(|p| p.element_sum()).sum()
}

#[track_caller]
fn assert_close(a: &[DVec3], b: &[DVec3], what: &str) {
    for (p, (x, y)) in a.iter().zip(b).enumerate() {
        let scale = x.abs().max(y.abs()).max_element().max(1e-12);
        assert!(
            (*x - *y).abs().max_element() <= 1e-9 * scale,
            "{what}: pixel {p}: {x} vs {y}"
        );
    }
}

#[test]
fn unoccluded_and_shadows_ignore_mis_weights_and_bsdf_hits_nee_could_make() {
    // `unoccluded;` and `shadows;` take light samples with weight 1 and no BSDF hit that
    // light sampling could have produced, so they do not depend on the MIS weights: a
    // render with MIS and one with light sampling alone (same random numbers) give them
    // bit for bit the same layers. The plain AOV does depend on the weights.
    let s = scene();
    let src = strings(&[
        "unoccluded;C.*L",
        "shadows;C.*L",
        "nothruput;unoccluded;C.*L",
        "unoccluded;C.*'gloss'L",
        "C.*L",
    ]);
    let mis = render(&s, &src, Technique::Mis);
    let light = render(&s, &src, Technique::LightOnly);
    for (i, s) in src.iter().enumerate().take(4) {
        assert!(total(&layer(&mis, i)) > 0.0, "{s}: empty");
        assert!(
            mis.film.layer_bits_equal(1 + i, &light.film, 1 + i),
            "{s}: MIS and light-only renders differ"
        );
    }
    assert!(!mis.film.layer_bits_equal(5, &light.film, 5));
}

#[test]
fn with_light_sampling_alone_unoccluded_is_visible_plus_shadows() {
    // Light-only: every light sample has weight 1, so each one lands in the plain AOV
    // (unblocked) or in `shadows;` (blocked), and `unoccluded;` gets both; hits only BSDF
    // sampling finds (through the glass) are in the plain AOV and `unoccluded;` alike.
    let s = scene();
    let src = strings(&["C.*L", "shadows;C.*L", "unoccluded;C.*L"]);
    let r = render(&s, &src, Technique::LightOnly);
    let (plain, shadows, unoccluded) = (layer(&r, 0), layer(&r, 1), layer(&r, 2));
    let sum: Vec<DVec3> = plain.iter().zip(&shadows).map(|(a, b)| *a + *b).collect();
    assert_close(&sum, &unoccluded, "plain + shadows vs unoccluded");
    assert!(total(&shadows) > 0.0, "the balls shadow the floor");
    assert!(total(&shadows) < total(&unoccluded));
}

#[test]
fn without_light_samples_unshadowed_aovs_see_what_the_rays_see() {
    // BSDF sampling alone: every hit is the only strategy, so `unoccluded;` is the plain
    // AOV bit for bit and `shadows;` receives nothing.
    let s = scene();
    let src = strings(&["C.*L", "unoccluded;C.*L", "shadows;C.*L"]);
    let r = render(&s, &src, Technique::BsdfOnly);
    assert!(total(&layer(&r, 0)) > 0.0);
    assert!(r.film.layer_bits_equal(1, &r.film, 2));
    assert!(layer(&r, 2).iter().all(|p| *p == DVec3::ZERO));
}

#[test]
fn lights_seen_through_a_delta_lobe_count_fully_in_unoccluded_and_not_in_shadows() {
    // The glass has only delta lobes: light sampling never connects from it, so every
    // path whose last scattering vertex is the glass is a BSDF hit no other strategy
    // finds. `unoccluded;` must take it whole (it is not shadowable), `shadows;` never.
    let s = scene();
    let src = strings(&[
        "C.*<.S'glass'>L",
        "unoccluded;C.*<.S'glass'>L",
        "shadows;C.*<.S'glass'>L",
        "nothruput;C<.S'glass'>L",
    ]);
    let r = render(&s, &src, Technique::Mis);
    assert!(
        total(&layer(&r, 0)) > 0.0,
        "the dome is seen through the glass"
    );
    assert!(r.film.layer_bits_equal(1, &r.film, 2));
    assert!(layer(&r, 2).iter().all(|p| *p == DVec3::ZERO));
    // At the first scattering vertex the throughput is 1: `nothruput;` is the identity
    // there, MIS weight (1) and all.
    let direct = aovs(&strings(&["C<.S'glass'>L"]));
    let d = integrator::render(
        &s,
        &direct,
        &Config::default().lobes,
        &Settings {
            width: W,
            height: W,
            spp: 4,
            seed: 11,
            threads: Some(2),
            ..Settings::default()
        },
    )
    .unwrap();
    assert!(total(&layer(&r, 3)) > 0.0);
    assert!(r.film.layer_bits_equal(4, &d.film, 1));
}

#[test]
fn holdout_paths_reach_only_holdouts_aovs_under_every_prefix() {
    // The same scene with and without the holdout flag (same random numbers): under
    // every prefix, paths through the holdout ball leave the AOVs without `holdouts;`
    // (light samples from it and BSDF hits on lights after it alike) and the `holdouts;`
    // AOV receives exactly what the unflagged scene's AOV gets for them.
    let with = scene();
    let mut without = with.clone();
    without.objects.iter_mut().for_each(|o| o.holdout = false);
    let prefixes = ["", "unoccluded;", "shadows;", "nothruput;", "noclamp;"];
    let mut src = Vec::new();
    for p in prefixes {
        src.push(format!("{p}C.*'held'.*L"));
        src.push(format!("holdouts;{p}C.*'held'.*L"));
        src.push(format!("{p}C.*L"));
        src.push(format!("holdouts;{p}C.*L"));
    }
    let a = render(&with, &src, Technique::Mis);
    let b = render(&without, &src, Technique::Mis);
    let mut moved = 0.0;
    for (k, p) in prefixes.iter().enumerate() {
        let i = 4 * k;
        assert!(
            layer(&a, i).iter().all(|v| *v == DVec3::ZERO),
            "{}: received holdout paths",
            src[i]
        );
        assert!(
            a.film.layer_bits_equal(1 + i + 1, &b.film, 1 + i),
            "{}: not what the unflagged scene's {:?} gets",
            src[i + 1],
            src[i]
        );
        let sum: Vec<DVec3> = (layer(&a, i + 2).iter().zip(layer(&a, i + 3)))
            .map(|(x, y)| *x + y)
            .collect();
        assert_close(&sum, &layer(&b, i + 2), &format!("{p}: split by holdout"));
        moved += total(&layer(&a, i + 1));
        if *p != "shadows;" {
            assert!(total(&layer(&a, i + 1)) > 0.0, "{}: empty", src[i + 1]);
        }
    }
    assert!(moved > 0.0);
    // Nothing of the unflagged scene reaches a `holdouts;` AOV.
    for i in (0..src.len()).filter(|i| src[*i].starts_with("holdouts;")) {
        assert!(layer(&b, i).iter().all(|v| *v == DVec3::ZERO), "{}", src[i]);
    }
}

#[test]
fn noclamp_aovs_are_unclamped_under_every_prefix() {
    // A clamp low enough to bite: each `noclamp;` AOV equals the same AOV without
    // `noclamp;` rendered without a clamp, bit for bit, while the clamped AOVs differ.
    let unclamped = scene();
    let mut clamped = scene();
    clamped.settings.clamp = Some(0.05);
    let prefixes = ["", "unoccluded;", "shadows;", "nothruput;"];
    let plain: Vec<String> = prefixes.iter().map(|p| format!("{p}C.*L")).collect();
    let noclamp: Vec<String> = prefixes
        .iter()
        .map(|p| format!("noclamp;{p}C.*L"))
        .collect();
    let src: Vec<String> = plain.iter().chain(&noclamp).cloned().collect();
    let a = render(&clamped, &src, Technique::Mis);
    let b = render(&unclamped, &src, Technique::Mis);
    for i in 0..prefixes.len() {
        let j = prefixes.len() + i;
        assert!(
            a.film.layer_bits_equal(1 + j, &b.film, 1 + i),
            "{}: clamped",
            src[j]
        );
        assert!(
            !a.film.layer_bits_equal(1 + i, &b.film, 1 + i),
            "{}: the clamp must bite",
            src[i]
        );
    }
}

#[test]
fn nothruput_drops_the_throughput_and_keeps_the_mis_weight() {
    // At the first scattering vertex the throughput is 1, so `nothruput;` changes
    // nothing bit for bit, MIS weight included: on the glossy ball light samples and
    // BSDF hits on lights both carry weights below 1. After a bounce it must differ.
    let s = scene();
    let src = strings(&[
        "C<.S'gloss'>L",
        "nothruput;C<.S'gloss'>L",
        "C.+<.S'gloss'>L",
        "nothruput;C.+<.S'gloss'>L",
    ]);
    let r = render(&s, &src, Technique::Mis);
    assert!(total(&layer(&r, 0)) > 0.0);
    assert!(r.film.layer_bits_equal(1, &r.film, 2));
    assert!(total(&layer(&r, 2)) > 0.0);
    assert!(!r.film.layer_bits_equal(3, &r.film, 4));
}
