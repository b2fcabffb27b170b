//! `--dialect osl`: the OSL basic set is a partition of beauty on the built-in scenes
//! (summed and proven), the OSL vertex mapping routes each path where the RenderMan AOV
//! of the same meaning does (bit-identical layers from the same samples), and bad OSL
//! input is an error with its position.

mod common;

use common::{parser, render, run, scene};
use lpe::osl::{Osl, Registered};
use lpe::renderman::RenderMan;
use lpe_render::aov::AovList;
use lpe_render::integrator::Settings;
use lpe_render::verify::{self, invariants};

fn small(w: usize, spp: u32) -> Settings {
    common::small(w, spp, 7)
}

#[test]
fn the_osl_basic_set_sums_to_beauty_and_is_proven_a_partition() {
    for name in ["cornell", "still-life"] {
        let s = scene(name);
        let aovs = AovList::<Osl>::for_render(&s, &Registered::none()).unwrap();
        let sources: Vec<&str> = aovs.aovs.iter().map(|a| a.source.as_str()).collect();
        assert_eq!(
            sources,
            [
                "C<RD>[LO]",
                "C<RD>.+[LO]",
                "C<TD>.*[LO]",
                "C<R[GS]>[LO]",
                "C<R[GS]>.+[LO]",
                "C<T[GS]>.*[LO]",
                "C[LO]"
            ]
        );
        let r = render(&s, &aovs, &small(24, 4));
        assert!(
            !r.plan.user_lobes,
            "{name}: OSL has no user-lobe pseudo paths"
        );
        let sum = invariants::partition(&r.film, &aovs, &aovs.partitions[0]);
        assert_eq!(sum.passed, Some(true), "{name}: {}", sum.detail);
        // Not a vacuous sum: every basic AOV the scene can feed is non-zero.
        let lit = |i: usize| r.film.layer(1 + i).iter().any(|v| v.element_sum() > 0.0);
        let fed: &[usize] = if name == "cornell" {
            &[0, 1, 3, 4, 6] // no transmission in the Cornell box
        } else {
            &[0, 1, 2, 3, 4, 5, 6]
        };
        for &i in fed {
            assert!(lit(i), "{name}: {} is black", aovs.aovs[i].name);
        }
        let formal = invariants::formal_partition(&aovs);
        assert_eq!(formal.len(), 1);
        assert_eq!(formal[0].passed, Some(true), "{}", formal[0].detail);
        assert!(formal[0].detail.contains("C<[RT][DGS]>*[LO]"));
    }
}

#[test]
fn the_formal_check_finds_an_osl_gap_with_its_witness() {
    // Without `transmissive` the OSL basic set misses paths whose first bounce is a
    // glossy or delta transmission: a shortest one is the witness.
    let mut aovs = AovList::<Osl>::new();
    for (n, src) in lpe::osl::BASIC.iter().filter(|(n, _)| *n != "transmissive") {
        aovs.push(n, src, &Registered::none()).unwrap();
    }
    let formal = invariants::formal_partition(&aovs);
    assert_eq!(formal[0].passed, None, "undeclared: informational");
    assert!(
        formal[0].detail.contains("gap: `C,~ T,G L,~`")
            || formal[0].detail.contains("gap: `C,~ T,S L,~`"),
        "{}",
        formal[0].detail
    );
}

#[test]
fn the_osl_check_suite_passes_with_everything_checked() {
    let list = verify::suite::check_suite::<Osl>(Some(2), &mut |_| {}).unwrap();
    let failed: Vec<_> = list.iter().filter(|i| i.passed != Some(true)).collect();
    assert!(failed.is_empty(), "{failed:#?}");
    for name in [
        "still-life: OSL basic AOVs sum to beauty",
        "still-life: OSL basic AOVs bit-identical with RenderMan's of the same name",
        "formal partition check: OSL basic AOVs (lpe::analysis)",
        "furnace: furnace C<RD>{2}O = Le a^2 = 0.25",
    ] {
        assert!(list.iter().any(|i| i.name == name), "missing: {name}");
    }
}

/// `(name, RenderMan, OSL)`: AOVs meaning the same on `still-life`, whose lobes are
/// Lambert D2 (`Diffuse`), diffuse transmission D3 (`Subsurface`), GGX S2 (`Specular`),
/// S3 (`RoughSpecular`) and S4 (`Clearcoat`), and the dielectric S8 (`Glass`); the
/// RenderMan side tells glossy from delta by those lobe numbers.
const SAME_MEANING: [(&str, &str, &str); 10] = [
    ("diffuse", "C<RD>[<L.>O]", "C<RD>[LO]"),
    ("glossy", "C(<RS2>|<RS3>|<RS4>).*[<L.>O]", "C<RG>.*[LO]"),
    ("mirror", "C<RS8>.*[<L.>O]", "C<RS>.*[LO]"),
    ("refraction", "C<TS8>.*[<L.>O]", "C<TS>.*[LO]"),
    ("subsurface", "C<TD>.*[<L.>O]", "C<TD>.*[LO]"),
    (
        "caustic",
        "C<RD>(<RS8>|<TS8>)+[<L.>O]",
        "C<RD>[<RS><TS>]+[LO]",
    ),
    ("floor", "C<RD'floor'>.*[<L.>O]", "C<RD'floor'>.*[LO]"),
    ("key", "C.*<L.'key'>", "C.*<L.'key'>"),
    ("ember_seen", "C<O.'ember'>", "C<O.'ember'>"),
    // The camera and the emitters scatter NONE (`x` inside `<...>`).
    ("none_slots", "C<RD>[<L.>O]", "<Cx><RD>[<Lx><Ox>]"),
];

#[test]
fn aovs_in_the_osl_dialect_give_the_images_of_the_renderman_aovs_that_mean_the_same() {
    let s = scene("still-life");
    let mut renderman = AovList::<RenderMan>::new();
    let mut osl = AovList::<Osl>::new();
    for (name, rm, o) in SAME_MEANING {
        renderman.push(name, rm, &parser()).unwrap();
        osl.push(name, o, &Registered::none()).unwrap();
    }
    let a = render(&s, &renderman, &small(32, 8));
    let b = render(&s, &osl, &small(32, 8));
    assert!(a.film.layer_bits_equal(0, &b.film, 0), "beauty");
    for (i, (name, _, _)) in SAME_MEANING.iter().enumerate() {
        // Each pair is lit, so a vertex mapped to the wrong scattering, event or label
        // would leave one side black or differently lit.
        let sum: f64 = b.film.layer(1 + i).iter().map(|v| v.element_sum()).sum();
        assert!(sum > 0.0, "{name} is black");
        assert!(
            a.film.layer_bits_equal(1 + i, &b.film, 1 + i),
            "{name}: the OSL layer differs from the RenderMan one"
        );
    }
}

#[test]
fn glossy_and_delta_split_what_renderman_calls_specular() {
    // RenderMan's `S` is OSL's `G` or `S`: the two OSL AOVs sum to the RenderMan one
    // (to rounding: the sums are formed in another order), and both are lit.
    let s = scene("still-life");
    let mut renderman = AovList::<RenderMan>::new();
    renderman
        .push("specular", "C<RS>.*[<L.>O]", &parser())
        .unwrap();
    let mut osl = AovList::<Osl>::new();
    osl.push("glossy", "C<RG>.*[LO]", &Registered::none())
        .unwrap();
    osl.push("delta", "C<RS>.*[LO]", &Registered::none())
        .unwrap();
    let a = render(&s, &renderman, &small(24, 4));
    let b = render(&s, &osl, &small(24, 4));
    let (spec, glossy, delta) = (a.film.layer(1), b.film.layer(1), b.film.layer(2));
    for (what, layer) in [("glossy", &glossy), ("delta", &delta)] {
        assert!(
            layer.iter().any(|v| v.element_sum() > 0.0),
            "{what} is black"
        );
    }
    for p in 0..spec.len() {
        let err = (glossy[p] + delta[p] - spec[p]).abs().max_element();
        assert!(
            err <= 1e-9 * spec[p].abs().max_element().max(1.0),
            "pixel {p}"
        );
    }
}

/// A renderer's correspondence decides the scattering a vertex shows: in Karma every
/// specular lobe is `G` (docs/profiles.md), in Arnold every one is `S`. So Karma's
/// `C<RG>.*[LO]` and Arnold's `C<RS>.*[LO]` are RenderMan's specular AOV bit for bit,
/// from the same samples, and the other letter is black. Planted fault, checked by
/// hand: showing the lobe's model instead of the correspondence (the plain-OSL mapping,
/// glass `S` and GGX `G`) fails it on Karma.
#[test]
fn a_renderers_correspondence_decides_the_scattering_its_vertices_show() {
    let s = scene("still-life");
    let mut renderman = AovList::<RenderMan>::new();
    renderman
        .push("specular", "C<RS>.*[<L.>O]", &parser())
        .unwrap();
    let a = render(&s, &renderman, &small(24, 4));
    for (renderer, all, none) in [
        ("karma", "C<RG>.*[LO]", "C<RS>.*[LO]"),
        ("arnold", "C<RS>.*[LO]", "C<RG>.*[LO]"),
    ] {
        let profile = lpe_profile::by_name(renderer).unwrap();
        let settings = Settings {
            scattering: Some(profile.correspondence()),
            ..small(24, 4)
        };
        let mut osl = AovList::<Osl>::new();
        osl.push("all", all, &Registered::none()).unwrap();
        osl.push("none", none, &Registered::none()).unwrap();
        let b = render(&s, &osl, &settings);
        assert!(
            a.film.layer_bits_equal(1, &b.film, 1),
            "{renderer}: `{all}` is not RenderMan's specular"
        );
        assert!(
            b.film.layer(2).iter().all(|v| v.element_sum() == 0.0),
            "{renderer}: `{none}` is lit"
        );
    }
}

/// `lpe-render --renderer karma` renders the OSL basic set read with Karma's letters,
/// and every invariant holds; an unknown renderer, or one that contradicts `--dialect`,
/// is bad input. Planted fault, checked by hand: the formal check reading its universe
/// under the default registration instead of the AOVs' fails it (with Karma's `A`
/// registered, `C,~ L,~,A` is a universe path the basic set misses).
#[test]
fn the_cli_renders_as_a_renderer_with_every_invariant_holding() {
    let dir = std::env::temp_dir().join(format!("lpe-render-renderer-{}", std::process::id()));
    let out = dir.join("out");
    for renderer in ["karma", "arnold"] {
        let (code, err) = run(&[
            "--renderer",
            renderer,
            "--scene",
            "still-life",
            "--res",
            "8x8",
            "--spp",
            "2",
            "--out",
            out.to_str().unwrap(),
            "--aov",
            "albedo_free=C<RD>.+[LO]",
        ]);
        assert_eq!(code, 0, "{err}");
        assert!(err.contains("(osl dialect, as "), "{err}");
        assert!(!err.contains("[FAIL]"), "{err}");
        assert!(err.contains("[pass] no NaN/Inf in any layer"), "{err}");
    }
    let (code, err) = run(&[
        "--renderer",
        "karma",
        "--scene",
        "still-life",
        "--res",
        "8x8",
        "--spp",
        "2",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("[pass] OSL basic AOVs sum to beauty"), "{err}");
    assert!(
        err.contains("[pass] formal partition check: OSL basic AOVs"),
        "{err}"
    );
    let (code, err) = run(&["--renderer", "karm"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("did you mean `karma`?"), "{err}");
    let (code, err) = run(&["--renderer", "karma", "--dialect", "renderman"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("contradicts --renderer karma"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_osl_input_is_an_error_with_its_position() {
    let dir = std::env::temp_dir().join(format!("lpe-render-osl-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let display = dir.join("display.rib");
    std::fs::write(
        &display,
        "DisplayChannel \"color ok\" \"string source\" [\"color lpe:C<RD>[LO]\"]\n\
         DisplayChannel \"color bad\" \"string source\" [\"color lpe:C<RD2>L\"]\n",
    )
    .unwrap();
    let ini = dir.join("rendermn.ini");
    std::fs::write(&ini, "/prman/lpe/specular4 Clearcoat\n").unwrap();
    let scene_s = dir.join("builtin_group.toml");
    std::fs::write(
        &scene_s,
        "[camera]\nposition = [0,0,0]\nlook_at = [0,0,-1]\n\n\
         [materials.m]\nlobes = [{ name = \"Diffuse\", model = \"lambert\", albedo = [0.5,0.5,0.5] }]\n\n\
         [[objects]]\nmaterial = \"m\"\nsphere = { center = [0,0,-3], radius = 1 }\n\n\
         [[lights]]\nkind = \"point\"\ngroup = \"S\"\nposition = [0,2,0]\nintensity = [1,1,1]\n",
    )
    .unwrap();
    let out = dir.join("out");
    let out_s = out.to_str().unwrap();
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["--aov", "x=CE"],
            "AOV `x` (OSL dialect): Unrecognized basic label: E at char 1",
        ),
        (
            vec!["--aov", "x=C<RD2>L"],
            "unquoted `2` at char 4 inside <...> is a RenderMan lobe number",
        ),
        (
            vec!["--aov", "x=C<RU>L"],
            "unquoted `U` at char 3 inside <...> is a RenderMan user lobe",
        ),
        (
            vec!["--aov", "x=shadows;C<RD>L"],
            "`shadows;` at char 0 is a RenderMan prefix",
        ),
        (
            vec!["--aov", "x=lpe:indirectDiffuse"],
            "`indirectDiffuse` is a RenderMan macro: the OSL dialect has none (in OSL: `C<RD>.+[LO]`)",
        ),
        (
            vec!["--display", display.to_str().unwrap()],
            "display.rib:2:52: AOV `bad` (OSL dialect): unquoted `2` at char 8",
        ),
        (
            vec!["--ini", ini.to_str().unwrap()],
            "--ini holds RenderMan macros and lobe mappings",
        ),
        (
            vec!["--scene", scene_s.to_str().unwrap()],
            "light 0 group `S` is a built-in OSL label",
        ),
    ];
    for (mut args, want) in cases {
        args.extend([
            "--dialect",
            "osl",
            "--res",
            "4x4",
            "--spp",
            "1",
            "--out",
            out_s,
        ]);
        let (code, err) = run(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(want), "{args:?}: expected `{want}` in:\n{err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
    let (code, err) = run(&["--dialect", "OSL"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("renderman"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn the_cli_renders_the_osl_basic_set_by_default() {
    let dir = std::env::temp_dir().join(format!("lpe-render-osl-cli-{}", std::process::id()));
    let out = dir.join("out");
    let (code, err) = run(&[
        "--dialect",
        "osl",
        "--scene",
        "still-life",
        "--res",
        "8x8",
        "--spp",
        "2",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("7 AOVs (osl dialect)"), "{err}");
    assert!(err.contains("[pass] OSL basic AOVs sum to beauty"), "{err}");
    assert!(
        err.contains("[pass] formal partition check: OSL basic AOVs"),
        "{err}"
    );
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(report.contains("AOVs in the osl dialect"), "{report}");
    assert!(report.contains("`C<R[GS]>.+[LO]`"), "{report}");
    let json = std::fs::read_to_string(out.join("report.json")).unwrap();
    assert!(json.contains("\"dialect\": \"osl\""), "{json}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn usd_render_vars_are_read_in_osl_and_errors_name_the_prim() {
    // Karma is OSL-based: Solaris's RenderVars are OSL expressions.
    let fixture = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../tests/testdata/usd/solaris_karma.usda");
    let dir = std::env::temp_dir().join(format!("lpe-render-osl-usd-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("out");
    let args = |stage: &str| {
        vec![
            "--dialect".to_string(),
            "osl".into(),
            "--usd".into(),
            stage.to_string(),
            "--res=6x6".into(),
            "--spp=1".into(),
            format!("--out={}", out.display()),
        ]
    };
    let a = args(fixture.to_str().unwrap());
    let (code, err) = run(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("3 AOVs (osl dialect)"), "{err}");

    let text = std::fs::read_to_string(&fixture).unwrap();
    let bad_text = text.replace("C<RD>.*<L.'fil'>", "C<RD>.*<L.'fil'>E");
    assert_ne!(bad_text, text);
    let bad = dir.join("bad.usda");
    std::fs::write(&bad, bad_text).unwrap();
    let a = args(bad.to_str().unwrap());
    let (code, err) = run(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains(
            "bad.usda:</Render/Products/Vars/diffuse_fill>.sourceName: AOV `diffuse_fill` \
             (OSL dialect): Unrecognized basic label: E at char 16"
        ),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).ok();
}
