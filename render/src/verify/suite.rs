//! `lpe-render check`: every invariant on small renders of the built-in scenes.

use lpe::renderman::{Parser, RenderMan};

use super::invariants::{self as check, invariants, ALPHA};
use super::stats::critical_z;
use super::VerifyError;
use crate::aov::{AovList, SceneDialect};
use crate::integrator::{render, Render, Settings, Technique};
use crate::invariant::Invariant;
use crate::scene::Scene;

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

/// `lpe-render check --dialect D`. What depends on the dialect: its default AOVs' sums to
/// beauty (and the furnace's closed form) on the built-in scenes, and the formal
/// partition check over its universe. In the renderer's own dialect
/// ([`SceneDialect::NATIVE`], RenderMan's) the estimator, prefix and determinism checks
/// follow, written in it; another dialect's basic set is instead checked against the
/// RenderMan basic AOVs of the same name, bit for bit: the dialect changes no sample.
pub fn check_suite<D: SceneDialect>(
    threads: Option<usize>,
    log: &mut dyn FnMut(&str),
) -> Result<Vec<Invariant>, VerifyError> {
    let cfg = lpe::renderman::Config::default();
    let parser = Parser::new(cfg.limits.clone(), cfg.macros.clone());
    let registration = D::Registration::default();
    let load = |n: &str| Scene::load(n, &cfg.lobes);
    let mut out = Vec::new();

    // 1, 2, 4: partitions, finiteness, furnace closed form.
    for (name, width, spp) in [
        ("cornell", 40, 8),
        ("still-life", 40, 8),
        ("furnace", 32, 64),
    ] {
        let scene = load(name)?;
        let aovs = AovList::<D>::for_render(&scene, &registration)?;
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
    if !D::NATIVE {
        let scene = load("still-life")?;
        let view = AovList::<D>::basic(&registration)?;
        let native = AovList::<RenderMan>::basic(&parser)?;
        let a = render(&scene, &view, &cfg.lobes, &small(24, 4, threads))?;
        let b = render(&scene, &native, &cfg.lobes, &small(24, 4, threads))?;
        out.push(identical(
            &format!(
                "still-life: {} bit-identical with RenderMan's of the same name",
                D::BASIC_PARTITION
            ),
            &a,
            &b,
            &pairs_all(view.aovs.len()),
        ));
        out.extend(check::formal_partition(&view));
        return Ok(out);
    }

    // shadows = unoccluded - occluded, per pixel in expectation.
    {
        let scene = load("still-life")?;
        let mut aovs = AovList::<RenderMan>::new();
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
            critical_z(ALPHA),
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
        let mut aovs = AovList::<RenderMan>::new();
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
                critical_z(ALPHA),
                "per-pixel difference of two independent renders has mean zero",
            ));
        }
    }

    // 3: determinism across threads, AOV sets and the effects plan.
    {
        let scene = load("cornell")?;
        let aovs = AovList::<RenderMan>::for_render(&scene, &parser)?;
        let one = render(&scene, &aovs, &cfg.lobes, &small(24, 4, Some(1)))?;
        let two = render(&scene, &aovs, &cfg.lobes, &small(24, 4, Some(2)))?;
        out.push(identical(
            "cornell: 1 vs 2 threads, all layers bit-identical",
            &one,
            &two,
            &pairs_all(aovs.aovs.len()),
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
            formal: false,
        });
    }
    {
        let scene = load("still-life")?;
        let full = AovList::<RenderMan>::for_render(&scene, &parser)?;
        let mut few = AovList::<RenderMan>::new();
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
            &pairs_all(full.aovs.len()),
        ));
    }

    // 5: the formal partition check: every possible path, decided on the automata.
    let scene = load("cornell")?;
    out.extend(check::formal_partition(&AovList::<RenderMan>::for_render(
        &scene, &parser,
    )?));
    Ok(out)
}

/// Beauty and each of `aovs` AOVs, paired with the same layer of another film.
fn pairs_all(aovs: usize) -> Vec<(usize, usize)> {
    (0..=aovs).map(|i| (i, i)).collect()
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
        formal: false,
    }
}
