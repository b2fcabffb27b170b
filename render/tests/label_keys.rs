//! The renderer's classification of scene vertices (`SceneClassifier::classify_scene`,
//! called once per kind of scene vertex at setup) keeps light groups one byte apart
//! apart, in both dialects: the labels are `lpe_testkit::labels` (every position and
//! length to past a label key's width, UTF-8 included). A set of `C<L.'group'>` per
//! group routes a light of each group to its own AOV alone, and a light of a group the
//! set does not name to none.

use lpe::osl::Osl;
use lpe::renderman::RenderMan;
use lpe::{AovSet, PathMatcher};
use lpe_render::aov::{SceneClassifier, SceneDialect, SceneVertex};
use lpe_testkit::labels::{groups, LABELS_CHECKED};

fn check<D: SceneDialect>() {
    let mut checked = 0;
    for group in groups() {
        let aovs: Vec<(String, D::Lpe)> = group
            .named
            .iter()
            .enumerate()
            .map(|(i, l)| {
                let src = format!("C<L.'{l}'>");
                let lpe = D::parse(&src, &D::Registration::default()).unwrap();
                (format!("a{i}"), lpe)
            })
            .collect();
        let set: AovSet<D> =
            AovSet::compile_under(&aovs, &D::Registration::default(), &Default::default()).unwrap();
        let camera = PathMatcher::step(&set, set.start(), set.classify_scene(&SceneVertex::Camera));
        let land = |group: &str| -> Vec<usize> {
            let c = set.classify_scene(&SceneVertex::Light { group: Some(group) });
            set.matches(PathMatcher::step(&set, camera, c))
                .iter()
                .collect()
        };
        for (i, label) in group.named.iter().enumerate() {
            assert_eq!(land(label), [i], "{}: `{label}`", D::NAME);
            checked += 1;
        }
        for label in &group.unnamed {
            assert!(land(label).is_empty(), "{}: `{label}`", D::NAME);
            checked += 1;
        }
    }
    assert_eq!(checked, LABELS_CHECKED);
}

#[test]
fn light_groups_one_byte_apart_stay_apart_in_the_renderman_dialect() {
    check::<RenderMan>();
}

#[test]
fn light_groups_one_byte_apart_stay_apart_in_the_osl_dialect() {
    check::<Osl>();
}
