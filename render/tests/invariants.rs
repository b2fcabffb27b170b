//! The renderer's invariants, each against an independent computation: partitions vs
//! beauty (accumulated without the matcher), the furnace's closed form, a second render
//! (threads, AOV sets, effects plan), and prefix identities that follow from the
//! definitions in `integrator.rs`.

mod common;

use common::{parser, render, scene};
use lpe::renderman::Config;
use lpe::renderman::RenderMan;
use lpe_render::aov::AovList;
use lpe_render::integrator;
use lpe_render::integrator::Settings;
use lpe_render::scene::Scene;
use lpe_render::verify;

fn small(w: usize, spp: u32) -> Settings {
    common::small(w, spp, 5)
}

#[test]
fn the_check_suite_passes() {
    let list = verify::suite::check_suite::<RenderMan>(Some(2), &mut |_| {}).unwrap();
    let failed: Vec<_> = list.iter().filter(|i| i.failed()).collect();
    assert!(failed.is_empty(), "{failed:#?}");
    // Everything is actually checked but the formal check of the per-lobe set, which is
    // not declared universal (informational); the declared universal partitions must be
    // proven, not merely "not checked".
    let unchecked: Vec<&str> = list
        .iter()
        .filter(|i| i.passed.is_none())
        .map(|i| i.name.as_str())
        .collect();
    assert_eq!(
        unchecked,
        ["formal partition check: per-lobe AOVs + emissive (lpe::analysis)"]
    );
    for universal in ["basic AOVs", "light groups + default group + emission"] {
        let name = format!("formal partition check: {universal} (lpe::analysis)");
        let i = list.iter().find(|i| i.name == name).expect(&name);
        assert_eq!(i.passed, Some(true), "{name}: {}", i.detail);
    }
    assert!(list.len() >= 20);
}

#[test]
fn holdout_paths_move_from_beauty_to_the_holdouts_aov() {
    // Same scene with and without the holdout flag: every contribution the flag removes
    // from beauty must land in `holdouts;C.*[<L.>O]`, so beauty + holdouts == beauty of
    // the unflagged scene (same random numbers, same paths; sums in another order).
    let with = scene("still-life");
    let mut without = with.clone();
    without.objects.iter_mut().for_each(|o| o.holdout = false);
    let mut aovs = AovList::<RenderMan>::new();
    let h = aovs.push("held", "holdouts;C.*[<L.>O]", &parser()).unwrap();
    let a = render(&with, &aovs, &small(32, 4));
    let b = render(&without, &AovList::<RenderMan>::new(), &small(32, 4));
    let mut moved = 0.0;
    for y in 0..32 {
        for x in 0..32 {
            let sum = a.film.pixel(x, y, 0) + a.film.pixel(x, y, 1 + h);
            let want = b.film.pixel(x, y, 0);
            assert!(
                (sum - want).abs().max_element() <= 1e-9 * want.abs().max_element().max(1e-12),
                "({x},{y})"
            );
            moved += a.film.pixel(x, y, 1 + h).x;
        }
    }
    assert!(
        moved > 0.0,
        "the holdout ball is in view, so something must move"
    );
}

#[test]
fn noclamp_aov_equals_the_unclamped_beauty_and_clamping_bites() {
    let mut clamped = scene("cornell");
    clamped.settings.clamp = Some(0.5);
    let unclamped = scene("cornell");
    let mut aovs = AovList::<RenderMan>::new();
    let i = aovs.push("all", "noclamp;C.*[<L.>O]", &parser()).unwrap();
    let a = render(&clamped, &aovs, &small(24, 4));
    let b = render(&unclamped, &AovList::<RenderMan>::new(), &small(24, 4));
    assert!(
        a.film.layer_bits_equal(1 + i, &b.film, 0),
        "noclamp AOV differs from unclamped beauty"
    );
    assert!(
        !a.film.layer_bits_equal(0, &b.film, 0),
        "a clamp of 0.5 must change beauty"
    );
}

#[test]
fn nothruput_is_the_identity_on_direct_paths() {
    // At the first scattering vertex the accumulated throughput is 1, so for direct
    // lighting `nothruput;` changes nothing, bit for bit; for indirect paths it must.
    let s = scene("cornell");
    let p = parser();
    let mut aovs = AovList::<RenderMan>::new();
    let d = aovs.push("d", "C<RD>[<L.>O]", &p).unwrap();
    let dn = aovs.push("dn", "nothruput;C<RD>[<L.>O]", &p).unwrap();
    let i = aovs.push("i", "C<RD>.+[<L.>O]", &p).unwrap();
    let inn = aovs.push("in", "nothruput;C<RD>.+[<L.>O]", &p).unwrap();
    let r = render(&s, &aovs, &small(24, 4));
    assert!(r.film.layer_bits_equal(1 + d, &r.film, 1 + dn));
    assert!(!r.film.layer_bits_equal(1 + i, &r.film, 1 + inn));
}

#[test]
fn user_lobe_pseudo_paths_carry_the_albedo_and_only_when_asked() {
    let s = scene("still-life");
    let p = parser();
    let mut aovs = AovList::<RenderMan>::new();
    let a = aovs.push("albedo", "overwrite;C<RU2>L", &p).unwrap();
    let r = render(&s, &aovs, &small(32, 2));
    assert!(r.plan.user_lobes);
    // The bottom row of the image sees only the floor, whose albedo is (0.55, 0.5, 0.45).
    let v = r.film.pixel(16, 31, 1 + a);
    assert_eq!(v.to_array().map(|x| x as f32), [0.55, 0.5, 0.45]);
    // User lobes are not light transport: beauty is unaffected.
    let plain = render(&s, &AovList::<RenderMan>::new(), &small(32, 2));
    assert!(r.film.layer_bits_equal(0, &plain.film, 0));
    let mut no_user = AovList::<RenderMan>::new();
    no_user.push("d", "lpe:directDiffuse", &p).unwrap();
    assert!(!render(&s, &no_user, &small(8, 1)).plan.user_lobes);
}

#[test]
fn exr_reads_back_with_the_expected_layers_and_values() {
    let s = scene("cornell");
    let aovs = AovList::<RenderMan>::for_render(&s, &parser()).unwrap();
    let r = render(
        &s,
        &aovs,
        &Settings {
            height: 12,
            ..small(16, 2)
        },
    );
    let dir = std::env::temp_dir().join(format!("lpe-render-exr-{}", std::process::id()));
    let mut report = lpe_render::output::Report {
        scene: "cornell".into(),
        width: 16,
        height: 12,
        spp: 2,
        seed: 5,
        threads: 2,
        matcher: integrator::ENGINE.into(),
        dialect: "renderman".into(),
        timing: lpe_render::output::Timing {
            render_seconds: r.seconds,
            total_seconds: r.seconds,
            paths: r.paths,
            rays: r.rays,
            paths_per_second: 0.0,
            rays_per_second: 0.0,
        },
        effects_plan: r.plan.describe(),
        effects: r.plan,
        aovs: Vec::new(),
        invariants: verify::invariants::invariants(&s, &aovs, &r),
        notes: Vec::new(),
        rejected_samples: 0,
        rejected_aov_values: 0,
        files: Vec::new(),
        contact_sheet_order: Vec::new(),
    };
    let files = lpe_render::output::write_all(&dir, &r.film, &aovs, &mut report).unwrap();
    let layers = lpe_render::output::read_exr(&dir.join("cornell.exr")).unwrap();
    let mut names: Vec<&str> = layers.iter().map(|l| l.name.as_str()).collect();
    let mut want: Vec<&str> = std::iter::once("beauty")
        .chain(aovs.aovs.iter().map(|a| a.name.as_str()))
        .collect();
    names.sort();
    want.sort();
    assert_eq!(names, want);
    for l in &layers {
        let (name, px) = (&l.name, &l.pixels);
        assert_eq!((l.width, l.height), (16, 12));
        let layer = if name == "beauty" {
            0
        } else {
            1 + aovs.index(name).unwrap()
        };
        for (p, v) in px.iter().enumerate() {
            let f = r.film.pixel(p % 16, p / 16, layer);
            assert_eq!(*v, [f.x as f32, f.y as f32, f.z as f32], "{name} pixel {p}");
        }
    }
    // Every promised file exists and the JSON report parses.
    for f in &files {
        assert!(f.exists(), "{}", f.display());
    }
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("report.json")).unwrap()).unwrap();
    assert!(json["invariants"].as_array().unwrap().len() >= 4);
    let png = image::open(dir.join("png").join("beauty.png")).unwrap();
    assert_eq!((png.width(), png.height()), (16, 12));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn non_finite_samples_are_rejected_everywhere_but_in_noinfinitecheck_aovs() {
    // A dome of radiance f32::MAX: light samples carry Le / pdf = Le * 4 pi, which
    // overflows f32 to infinity, so those samples are not finite.
    let text = r#"
        [camera]
        position = [0.0, 1.0, 0.0]
        look_at = [0.0, 0.0, 0.0]
        up = [0.0, 0.0, -1.0]
        [materials.grey]
        lobes = [{ name = "Diffuse", model = "lambert", albedo = [0.5, 0.5, 0.5] }]
        [[objects]]
        material = "grey"
        quad = { corner = [-5.0, 0.0, -5.0], u = [0.0, 0.0, 10.0], v = [10.0, 0.0, 0.0] }
        [[lights]]
        kind = "dome"
        radiance = [3.4028235e38, 3.4028235e38, 3.4028235e38]
    "#;
    let s = Scene::from_toml(text, "huge.toml", &Config::default().lobes).unwrap();
    let p = parser();
    let mut aovs = AovList::<RenderMan>::new();
    let checked = aovs.push("checked", "C.*[<L.>O]", &p).unwrap();
    let kept = aovs.push("kept", "noinfinitecheck;C.*[<L.>O]", &p).unwrap();
    let r = render(&s, &aovs, &small(8, 2));
    assert!(r.film.rejected > 0);
    for layer in [0, 1 + checked] {
        assert!(
            r.film.layer(layer).iter().all(|v| v.is_finite()),
            "layer {layer}"
        );
    }
    assert!(r.film.layer(1 + kept).iter().any(|v| !v.is_finite()));
    let inv = verify::invariants::invariants(&s, &aovs, &r);
    let finite = inv
        .iter()
        .find(|i| i.name.starts_with("no NaN/Inf"))
        .unwrap();
    assert_eq!(
        finite.passed,
        Some(false),
        "the kept infinities are reported"
    );
    assert!(finite.detail.contains("kept"), "{}", finite.detail);
}

#[test]
fn label_classes_split_paths_by_lpegroup() {
    // First vertex on the floor, or on anything else: together exactly the paths whose
    // first vertex is diffuse (`<.D>` = R or T with a D event), per pixel.
    let s = scene("still-life");
    let p = parser();
    let mut aovs = AovList::<RenderMan>::new();
    let floor = aovs.push("floor", "C<.D'floor'>.*[<L.>O]", &p).unwrap();
    let other = aovs.push("other", "C<.D[^'floor']>.*[<L.>O]", &p).unwrap();
    let all = aovs.push("all", "C<.D>.*[<L.>O]", &p).unwrap();
    let r = render(&s, &aovs, &small(32, 4));
    let (mut floor_sum, mut other_sum, mut all_sum) = (0.0, 0.0, 0.0);
    for y in 0..32 {
        for x in 0..32 {
            let parts = r.film.pixel(x, y, 1 + floor) + r.film.pixel(x, y, 1 + other);
            let whole = r.film.pixel(x, y, 1 + all);
            let tol = 1e-12 * whole.abs().max_element().max(1e-12);
            assert!((parts - whole).abs().max_element() <= tol, "({x},{y})");
            floor_sum += r.film.pixel(x, y, 1 + floor).x;
            other_sum += r.film.pixel(x, y, 1 + other).x;
            all_sum += r.film.pixel(x, y, 1 + all).x;
        }
    }
    // Both sides non-empty: a matcher that ignored labels (floor = all, other = 0) would
    // still satisfy parts = whole.
    assert!(floor_sum > 0.0, "the floor is in view");
    assert!(other_sum > 0.0, "other diffuse objects are in view");
    assert!(floor_sum < all_sum, "{floor_sum} vs {all_sum}");
}
