//! Translation between the dialects, in the renderer: the default correspondence is the
//! mapping `lpe-render --dialect osl` renders with, and an AOV set translated exactly
//! renders layers bit-identical to the source set's from the same samples.

mod common;

use common::{render, scene};
use lpe::osl::Osl;
use lpe::renderman::{RenderMan, VertexType};
use lpe::translate::{translate, Correspondence, Translate};
use lpe::Dialect;
use lpe_render::aov::AovList;
use lpe_render::aov::{SceneDialect, SceneVertex};

#[test]
fn the_default_correspondence_is_the_renderers_osl_mapping() {
    // The translation's map and the renderer's two views are written apart; every kind of
    // vertex the shipped scenes produce must agree.
    let corr = Correspondence::default();
    let mut checked = 0;
    for name in ["cornell", "still-life"] {
        let s = scene(name);
        let mut vertices = vec![SceneVertex::Camera];
        for o in &s.objects {
            let group = o.lpegroup.as_deref();
            vertices.push(SceneVertex::Emissive { group });
            for l in o.material.map_or(&[][..], |m| &s.materials[m].lobes[..]) {
                for side in [VertexType::R, VertexType::T] {
                    vertices.push(SceneVertex::Scatter {
                        side,
                        event: l.event,
                        scattering: l.scattering(),
                        group,
                    });
                }
            }
        }
        for l in &s.lights {
            let group = l.group.as_deref();
            vertices.push(SceneVertex::Light { group });
            vertices.push(SceneVertex::Emissive { group });
        }
        for v in &vertices {
            let rm = RenderMan::scene_vertex(v);
            assert_eq!(corr.view(&rm), Some(Osl::scene_vertex(v)), "{name}: {v:?}");
            checked += 1;
        }
    }
    assert!(checked > 40, "{checked} vertices");
}

/// Renders `sources` (in dialect `D`) and their exact translations (in its target) on
/// the still life; every translated layer must equal its source layer bit for bit.
/// Returns how many were exact.
fn renders_the_same<D>(sources: &[(&str, &str)]) -> usize
where
    D: SceneDialect + Translate,
    D::Target: SceneDialect,
{
    let corr = Correspondence::default();
    let (mut a, mut b) = (AovList::<D>::new(), AovList::<D::Target>::new());
    let from = D::Registration::default();
    let to = <D::Target as Dialect>::Registration::default();
    for (name, src) in sources {
        let t = translate::<D>(&D::parse(src, &from).unwrap(), &corr).unwrap();
        if t.exact {
            a.push(name, src, &from).unwrap();
            b.push(name, &t.text.to_string(), &to).unwrap();
        }
    }
    let s = scene("still-life");
    let settings = common::small(32, 8, 7);
    let (ra, rb) = (render(&s, &a, &settings), render(&s, &b, &settings));
    assert!(ra.film.layer_bits_equal(0, &rb.film, 0), "beauty");
    for (i, aov) in a.aovs.iter().enumerate() {
        assert!(
            ra.film.layer_bits_equal(1 + i, &rb.film, 1 + i),
            "{}: `{}` and its translation `{}` render differently",
            aov.name,
            aov.source,
            b.aovs[i].source
        );
    }
    let lit = (0..a.aovs.len())
        .filter(|&i| rb.film.layer(1 + i).iter().any(|v| v.element_sum() > 0.0))
        .count();
    assert!(
        lit * 2 > a.aovs.len(),
        "only {lit} translated layers are lit"
    );
    a.aovs.len()
}

#[test]
fn renderman_aovs_translated_to_osl_render_the_same_layers() {
    let exact = renders_the_same::<RenderMan>(&[
        ("directDiffuse", "directDiffuse"),
        ("indirectDiffuse", "indirectDiffuse"),
        ("subsurface", "subsurface"),
        ("directSpecular", "directSpecular"),
        ("indirectSpecular", "indirectSpecular"),
        ("transmissive", "transmissive"),
        ("emissive", "emissive"),
        ("glass", "C<TS8>.*[<L.>O]"),
        ("caustics", "caustics"),
        ("floorBounce", "C<RD'floor'>.*[<L.>O]"),
        // Not expressible (lobe numbers): skipped, and counted below.
        ("clearcoat", "directSpecularClearcoatLobe"),
    ]);
    assert_eq!(exact, 10);
}

#[test]
fn aovs_of_the_osl_dialect_translated_to_renderman_render_the_same_layers() {
    let mut sources: Vec<(&str, &str)> = lpe::osl::BASIC.to_vec();
    sources.push(("glossyAny", "C.*<.G>.*[LO]"));
    sources.push(("floor", "C<RD'floor'>.*[LO]"));
    let exact = renders_the_same::<Osl>(&sources);
    assert_eq!(exact, 9);
}
