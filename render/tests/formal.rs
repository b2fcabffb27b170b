//! The formal partition check a render reports before tracing: decided by
//! `lpe::analysis` for every path, with a witness the reference matcher confirms.

use lpe::renderman::RenderMan;
use lpe::renderman::{Parser, Path};
use lpe_render::aov::{AovList, Partition};
use lpe_render::verify::invariants::formal_partition;

fn list(aovs: &[(&str, &str)], declare: bool) -> AovList<RenderMan> {
    let parser = Parser::default();
    let mut l = AovList::<RenderMan>::new();
    let members = aovs
        .iter()
        .map(|(n, s)| l.push(n, s, &parser).unwrap())
        .collect();
    if declare {
        l.partitions.push(Partition {
            name: "declared".into(),
            members,
            universal: true,
        });
    }
    l
}

#[test]
fn basic_aovs_pass_and_basic_plus_caustics_fails_with_a_real_witness() {
    let basic: Vec<(&str, &str)> = lpe::renderman::macros::BASIC.to_vec();
    let r = formal_partition(&list(&basic, true));
    assert_eq!(r.len(), 1);
    assert_eq!(r[0].passed, Some(true), "{}", r[0].detail);

    let mut with_caustics = basic.clone();
    with_caustics.push(("caustics", "CDS+[<L.>O]"));
    let r = formal_partition(&list(&with_caustics, true));
    assert_eq!(r[0].passed, Some(false), "{}", r[0].detail);
    // The witness is a path both named AOVs match, by the reference matcher's account.
    let detail = &r[0].detail;
    let witness: Path = detail
        .split('`')
        .nth(1)
        .expect("a quoted witness path")
        .parse()
        .unwrap();
    let matches =
        |src: &str| lpe_reference::is_match(&lpe::renderman::parse(src).unwrap(), &witness);
    assert!(matches("caustics"), "{detail}");
    let other = if detail.contains("indirectDiffuse") {
        "indirectDiffuse"
    } else {
        "subsurface"
    };
    assert!(matches(other), "{detail}");
}

#[test]
fn requested_aovs_without_a_declared_partition_are_reported_not_failed() {
    let r = formal_partition(&list(&[("key", "C.*<L.'key'>"), ("all", "C.*L")], false));
    assert_eq!(r[0].passed, None, "{}", r[0].detail);
    assert!(r[0].detail.contains("overlap"), "{}", r[0].detail);
}
