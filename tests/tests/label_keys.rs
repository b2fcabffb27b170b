//! Labels that differ in one byte only, at every position, stay apart: in classification
//! (RenderMan's label table keys a label by its length and its first and last bytes, so
//! a key fault shows only on labels alike there), in the DFA and the lazy DFA, and on
//! RenderMan's interned path (`label_id` + `classify_interned`); in both dialects.
//!
//! The labels are `lpe_testkit::labels`: for every length from 0 to 40 bytes (past the
//! 16 bytes a key holds whole), a base label and, per byte position, the base with that
//! one byte changed; the base one byte shorter and one byte longer; and UTF-8 labels of
//! up to 13 three-byte characters whose variants change one character's last byte. The
//! C ABI (`capi/tests/abi.rs`) and the renderer's classification (`render/tests/label_keys.rs`)
//! run the same labels. One set per base holds an AOV
//! `C<L.'label'>` per label; a light carrying each label must land in its own AOV alone,
//! and a light carrying a label the set does not name (one byte off the base elsewhere)
//! in none.

use lpe::osl::{self, Osl};
use lpe::renderman::{self, RenderMan, VertexType};
use lpe::{AovSet, Dialect, DialectLpe, Options};
use lpe_testkit::labels::{groups, LABELS_CHECKED};

/// The two stepping modes: the DFA, and the lazy DFA over the bitset NFA.
fn modes() -> [(&'static str, Options); 2] {
    [
        ("dfa", Options::default()),
        (
            "lazy",
            Options {
                dfa_budget: 0,
                ..Options::default()
            },
        ),
    ]
}

/// Checks every group in dialect `D`: the set of the group's AOVs, under each mode, puts
/// a light carrying each label in that label's AOV alone and a light carrying an unnamed
/// label in none. `light` builds the dialect's light vertex; `also` checks one more
/// classification of a label (RenderMan's interned path) against `classify`.
fn check_groups<D, L>(
    light: impl Fn(&str) -> D::Vertex,
    also: impl Fn(&AovSet<D>, &str) -> Option<lpe::Class>,
) where
    D: Dialect<Lpe = L>,
    L: DialectLpe<Dialect = D>,
{
    let mut checked = 0;
    for group in groups() {
        let aovs: Vec<(String, L)> = group
            .named
            .iter()
            .enumerate()
            .map(|(i, label)| {
                let src = format!("C<L.'{label}'>");
                let lpe = D::parse(&src, &D::Registration::default())
                    .unwrap_or_else(|e| panic!("{}: {src}: {e}", D::NAME));
                (format!("a{i}"), lpe)
            })
            .collect();
        for (mode, opts) in modes() {
            let set = AovSet::compile_under(&aovs, &D::Registration::default(), &opts).unwrap();
            let camera = set.step(set.start(), &light_camera::<D>());
            let land = |label: &str| {
                let v = light(label);
                let c = set.classify(&v);
                if let Some(interned) = also(&set, label) {
                    assert_eq!(interned, c, "{} {mode}: `{label}` interned", D::NAME);
                }
                set.matches(set.step_class(camera, c))
                    .iter()
                    .collect::<Vec<_>>()
            };
            for (i, label) in group.named.iter().enumerate() {
                assert_eq!(land(label), [i], "{} {mode}: `{label}`", D::NAME);
                checked += 1;
            }
            for label in &group.unnamed {
                assert!(land(label).is_empty(), "{} {mode}: `{label}`", D::NAME);
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 2 * LABELS_CHECKED, "{}", D::NAME);
}

/// The camera vertex of dialect `D`: the first vertex of its shortest camera-to-light
/// path text.
fn light_camera<D: Dialect>() -> D::Vertex {
    let text = if D::NAME == RenderMan::NAME {
        "C L"
    } else {
        "C,_ L,_"
    };
    let path: D::Path = text.parse().unwrap();
    D::vertices(&path)[0].clone()
}

#[test]
fn labels_one_byte_apart_stay_apart_in_the_renderman_dialect() {
    check_groups::<RenderMan, renderman::Lpe>(
        |label| renderman::Vertex::light(Some(label)),
        |set, label| {
            let id = set.label_id(Some(label));
            Some(set.classify_interned(VertexType::L, None, id))
        },
    );
}

#[test]
fn labels_one_byte_apart_stay_apart_in_the_osl_dialect() {
    check_groups::<Osl, osl::Lpe>(|label| osl::Vertex::labels(&["L", "_", label]), |_, _| None);
}
