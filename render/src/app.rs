//! The pipeline the CLI runs: render with an engine, check the invariants a render can
//! check on its own, the `check` suite and the `bench` measurement.

use lpe::{LobeMap, Parser};

use crate::aovs::AovList;
use crate::check::{self, Invariant};
use crate::integrator::{Integrator, Render, Settings, Technique};
use crate::matcher::{PathMatcher, Reference, ReferenceMatcher};
use crate::scene::Scene;

/// Renders `scene` with `aovs`.
///
/// ENGINE: the one place that picks the matcher: the fast matcher (`lpe::aov::AovSet`),
/// or, for a set it refuses to compile (over its size limits), the memoized reference
/// matcher with a warning on stderr. Both give the same image; only the time differs.
pub fn render(
    scene: &Scene,
    aovs: &AovList,
    lobes: &LobeMap,
    settings: &Settings,
) -> Result<Render, String> {
    render_announcing(scene, aovs, lobes, settings, &mut |_| {})
}

/// [`render`], calling `on_plan` with the effects plan once it is decided, before any
/// sample is traced (the CLI prints it).
pub fn render_announcing(
    scene: &Scene,
    aovs: &AovList,
    lobes: &LobeMap,
    settings: &Settings,
    on_plan: &mut dyn FnMut(&crate::plan::Plan),
) -> Result<Render, String> {
    match lpe::aov::AovSet::compile(&aovs.named()) {
        Ok(set) => render_with(&set, scene, aovs, lobes, settings, on_plan),
        Err(e) => {
            eprintln!(
                "warning: the fast matcher refused this AOV set ({e}); using the reference matcher"
            );
            let matcher = ReferenceMatcher::memoized(Reference::new(&aovs.lpes())?);
            render_with(&matcher, scene, aovs, lobes, settings, on_plan)
        }
    }
}

/// Renders with a given matcher, calling `on_plan` with the effects plan first.
pub fn render_with<M: PathMatcher>(
    matcher: &M,
    scene: &Scene,
    aovs: &AovList,
    lobes: &LobeMap,
    settings: &Settings,
    on_plan: &mut dyn FnMut(&crate::plan::Plan),
) -> Result<Render, String> {
    let integrator = Integrator::new(scene, aovs, matcher, lobes, settings);
    on_plan(&integrator.plan());
    integrator.render()
}

/// Name of the engine [`render`] uses, for reports.
pub const ENGINE: &str = "fast (lpe::aov::AovSet; reference if the set cannot compile)";

/// The furnace's parameters `(albedo a, emission Le)` if `scene` is a furnace: one
/// material, one Lambert lobe, grey albedo and glow.
pub fn furnace_params(scene: &Scene) -> Option<(f64, f64)> {
    if scene.name != "furnace" || scene.materials.len() != 1 {
        return None;
    }
    let m = &scene.materials[0];
    let [lobe] = m.lobes.as_slice() else {
        return None;
    };
    let crate::material::Model::Lambert { albedo } = lobe.model else {
        return None;
    };
    Some((albedo.x as f64, m.glow.x as f64))
}

/// Diffuse bounce counts the furnace AOVs cover.
pub const FURNACE_BOUNCES: u32 = 4;

/// The AOV list for a render: the defaults, plus for the furnace the per-bounce AOVs
/// `furnace_bounceK = C<RD>{K}O`.
pub fn default_aovs(scene: &Scene, parser: &Parser) -> Result<AovList, String> {
    let mut list = AovList::defaults(scene, parser)?;
    if furnace_params(scene).is_some() {
        for k in 0..=FURNACE_BOUNCES {
            list.push(
                &format!("furnace_bounce{k}"),
                &format!("C<RD>{{{k}}}O"),
                parser,
            )?;
        }
    }
    Ok(list)
}

/// Family-wise significance of the statistical tests.
pub const ALPHA: f64 = 1e-3;

/// The invariants one render can check by itself.
pub fn invariants(scene: &Scene, aovs: &AovList, render: &Render) -> Vec<Invariant> {
    let film = &render.film;
    let mut out: Vec<Invariant> = aovs
        .partitions
        .iter()
        .map(|p| check::partition(film, aovs, p))
        .collect();
    out.push(check::finite(film, aovs));
    if let Some((a, le)) = furnace_params(scene) {
        let bounces: Vec<(usize, u32)> = (0..=FURNACE_BOUNCES)
            .filter_map(|k| aovs.index(&format!("furnace_bounce{k}")).map(|i| (i, k)))
            .collect();
        let tests = 1 + bounces.len();
        let each = crate::chi2::sidak(ALPHA, tests);
        let z = check::critical_z(each);
        out.push(check::z_test(
            &format!("furnace beauty = Le/(1-a) = {}", le / (1.0 - a)),
            &check::channel_values(film, 0),
            le / (1.0 - a),
            z,
            ALPHA,
        ));
        for (i, k) in bounces {
            out.push(check::z_test(
                &format!(
                    "furnace C<RD>{{{k}}}O = Le a^{k} = {}",
                    le * a.powi(k as i32)
                ),
                &check::channel_values(film, 1 + i),
                le * a.powi(k as i32),
                z,
                ALPHA,
            ));
        }
    }
    out
}

/// Settings for the small renders of the check suite.
fn small(width: usize, spp: u32, threads: Option<usize>) -> Settings {
    Settings {
        width,
        height: width,
        spp,
        seed: 1,
        threads,
        ..Settings::default()
    }
}

/// `lpe-render check`: every invariant on small renders of the built-in scenes.
pub fn check_suite(
    threads: Option<usize>,
    log: &mut dyn FnMut(&str),
) -> Result<Vec<Invariant>, String> {
    let cfg = lpe::Config::default();
    let parser = Parser::new(cfg.limits.clone(), cfg.macros.clone());
    let load = |n: &str| Scene::load(n, &cfg.lobes).map_err(|e| e.to_string());
    let mut out = Vec::new();

    // 1, 2, 4: partitions, finiteness, furnace closed form.
    for (name, width, spp) in [
        ("cornell", 40, 8),
        ("still-life", 40, 8),
        ("furnace", 32, 64),
    ] {
        let scene = load(name)?;
        let aovs = default_aovs(&scene, &parser)?;
        let r = render(&scene, &aovs, &cfg.lobes, &small(width, spp, threads))?;
        log(&format!(
            "{name}: {width}x{width}, {spp} spp, {:.2}s",
            r.seconds
        ));
        out.extend(invariants(&scene, &aovs, &r).into_iter().map(|mut i| {
            i.name = format!("{name}: {}", i.name);
            i
        }));
    }

    // shadows = unoccluded - occluded, per pixel in expectation.
    {
        let scene = load("still-life")?;
        let mut aovs = AovList::default();
        let u = aovs.push("unocc", "unoccluded;C<RD>L", &parser)?;
        let d = aovs.push("occ", "C<RD>L", &parser)?;
        let s = aovs.push("shadow", "shadows;C<RD>L", &parser)?;
        let r = render(&scene, &aovs, &cfg.lobes, &small(32, 16, threads))?;
        let f = &r.film;
        let x: Vec<f64> = (0..f.height)
            .flat_map(|y| (0..f.width).map(move |x| (x, y)))
            .map(|(x, y)| {
                let v = f.pixel(x, y, 1 + u) - f.pixel(x, y, 1 + d) - f.pixel(x, y, 1 + s);
                v.x + v.y + v.z
            })
            .collect();
        out.push(check::zero_mean_test(
            "still-life: shadows = unoccluded - occluded",
            &x,
            check::critical_z(ALPHA),
            "per-pixel unocc - occ - shadow for C<RD>L has mean zero",
        ));
    }

    // The estimator itself: MIS, BSDF sampling alone and light sampling alone are three
    // unbiased estimators of the same image (where BSDF sampling can reach every light:
    // cornell has no delta lights), so per-pixel differences of independent renders
    // have mean zero. Direct diffuse lighting is compared as well as beauty: it is where
    // a wrong light or BSDF density shows with the least noise around it.
    for (name, a, b) in [
        ("cornell", Technique::Mis, Technique::BsdfOnly),
        ("cornell", Technique::LightOnly, Technique::BsdfOnly),
        ("still-life", Technique::Mis, Technique::LightOnly),
    ] {
        let scene = load(name)?;
        let mut aovs = AovList::default();
        aovs.push("direct", "C<RD>L", &parser)?;
        let settings = |technique, seed| Settings {
            technique,
            seed,
            ..small(48, 32, threads)
        };
        let ra = render(&scene, &aovs, &cfg.lobes, &settings(a, 11))?;
        let rb = render(&scene, &aovs, &cfg.lobes, &settings(b, 12))?;
        for (layer, what) in [(0, "beauty"), (1, "C<RD>L")] {
            let x: Vec<f64> = ra
                .film
                .layer(layer)
                .iter()
                .zip(rb.film.layer(layer))
                .map(|(p, q)| (*p - q).element_sum())
                .collect();
            out.push(check::zero_mean_test(
                &format!("{name}: {what} with {a:?} = with {b:?} in expectation"),
                &x,
                check::critical_z(ALPHA),
                "per-pixel difference of two independent renders has mean zero",
            ));
        }
    }

    // 3: determinism across threads, AOV sets and the effects plan.
    {
        let scene = load("cornell")?;
        let aovs = default_aovs(&scene, &parser)?;
        let one = render(&scene, &aovs, &cfg.lobes, &small(24, 4, Some(1)))?;
        let two = render(&scene, &aovs, &cfg.lobes, &small(24, 4, Some(2)))?;
        out.push(identical(
            "cornell: 1 vs 2 threads, all layers bit-identical",
            &one,
            &two,
            &pairs_all(&aovs),
        ));
        let (a, b) = (
            crate::output::exr_bytes(&one.film, &aovs)?,
            crate::output::exr_bytes(&two.film, &aovs)?,
        );
        out.push(Invariant {
            name: "cornell: 1 vs 2 threads, EXR files byte-identical".into(),
            measured: (a != b) as u8 as f64,
            tolerance: 0.0,
            passed: Some(a == b),
            detail: format!("{} bytes each", a.len()),
        });
    }
    {
        let scene = load("still-life")?;
        let full = default_aovs(&scene, &parser)?;
        let mut few = AovList::default();
        for name in ["indirectDiffuse", "transmissive", "emissive"] {
            few.push(name, &format!("lpe:{name}"), &parser)?;
        }
        few.push("unrelated", "C<TS>'nothing'.*[<L.>O]", &parser)?;
        let a = render(&scene, &full, &cfg.lobes, &small(24, 4, threads))?;
        let b = render(&scene, &few, &cfg.lobes, &small(24, 4, threads))?;
        let mut pairs = vec![(0, 0)];
        for name in ["indirectDiffuse", "transmissive", "emissive"] {
            if let (Some(i), Some(j)) = (full.index(name), few.index(name)) {
                pairs.push((1 + i, 1 + j));
            }
        }
        out.push(identical(
            "still-life: AOVs bit-identical with all defaults vs 3 of them + an unrelated one",
            &a,
            &b,
            &pairs,
        ));
        let generic = Settings {
            all_effects: true,
            ..small(24, 4, threads)
        };
        let c = render(&scene, &full, &cfg.lobes, &generic)?;
        out.push(identical(
            "still-life: all layers bit-identical with the effects plan vs --all-effects",
            &a,
            &c,
            &pairs_all(&full),
        ));
    }

    // 5: the formal partition check: every possible path, decided on the automata.
    let scene = load("cornell")?;
    out.extend(check::formal_partition(&default_aovs(&scene, &parser)?));
    Ok(out)
}

fn pairs_all(aovs: &AovList) -> Vec<(usize, usize)> {
    (0..=aovs.aovs.len()).map(|i| (i, i)).collect()
}

/// Counts layer pairs that differ in any bit.
fn identical(name: &str, a: &Render, b: &Render, pairs: &[(usize, usize)]) -> Invariant {
    let differ: Vec<String> = pairs
        .iter()
        .filter(|(i, j)| !a.film.layer_bits_equal(*i, &b.film, *j))
        .map(|(i, _)| i.to_string())
        .collect();
    Invariant {
        name: name.into(),
        measured: differ.len() as f64,
        tolerance: 0.0,
        passed: Some(differ.is_empty()),
        detail: format!(
            "{} layer pairs compared bit for bit; differing layers: {}",
            pairs.len(),
            if differ.is_empty() {
                "none".into()
            } else {
                differ.join(", ")
            }
        ),
    }
}

/// `lpe-render bench`: cost of LPE tracking, the same scene and samples rendered with
/// beauty only (matcher off) and with 32 AOVs, back to back in each round. The overhead
/// is the median over rounds of the paired time ratio, which resists load that drifts
/// during the run better than comparing separate best times.
pub struct Bench {
    pub beauty_seconds: f64,
    pub aov_seconds: f64,
    /// Median over rounds of `aov time / beauty time`, minus 1.
    pub overhead: f64,
    pub aov_count: usize,
    pub paths: u64,
}

pub fn bench(
    scene: &Scene,
    lobes: &LobeMap,
    parser: &Parser,
    settings: &Settings,
    rounds: usize,
) -> Result<Bench, String> {
    let mut aovs = AovList::defaults(scene, parser)?;
    // Pad with distinct, plausible AOVs up to 32.
    let extra = [
        ("caustics", "lpe:caustics"),
        ("diffuseLegacy", "lpe:diffuse"),
        ("specularLegacy", "lpe:specular"),
        ("emissionLegacy", "lpe:emission"),
        ("twoBounce", "C.{2}[<L.>O]"),
        ("threeBounce", "C.{3}[<L.>O]"),
        ("diffuseOnly", "C<RD>+[<L.>O]"),
        ("specThenDiffuse", "C<RS>.*<RD>.*[<L.>O]"),
    ];
    for (n, s) in extra {
        if aovs.aovs.len() >= 32 {
            break;
        }
        aovs.push(n, s, parser)?;
    }
    let mut k = 0;
    while aovs.aovs.len() < 32 {
        aovs.push(
            &format!("bounces{k}"),
            &format!("C.{{{},}}[<L.>O]", 4 + k),
            parser,
        )?;
        k += 1;
    }
    let none = AovList::default();
    let (mut tb, mut ta) = (f64::INFINITY, f64::INFINITY);
    let mut ratios = Vec::new();
    let mut paths = 0;
    for _ in 0..rounds {
        let b = render(scene, &none, lobes, settings)?;
        let a = render(scene, &aovs, lobes, settings)?;
        tb = tb.min(b.seconds);
        ta = ta.min(a.seconds);
        ratios.push(a.seconds / b.seconds);
        paths = a.paths;
    }
    ratios.sort_by(f64::total_cmp);
    Ok(Bench {
        beauty_seconds: tb,
        aov_seconds: ta,
        overhead: ratios[ratios.len() / 2] - 1.0,
        aov_count: aovs.aovs.len(),
        paths,
    })
}
