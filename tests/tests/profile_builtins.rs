//! The built-in AOV lists of the renderer profiles, checked formally against beauty as
//! docs/profiles.md states it (Arnold is the only shipped profile with built-ins).
//!
//! The universe is the paths Arnold makes by its page's letters: camera, then
//! reflections and transmissions scattering `D` or `S` (its specular is `S`, glossy
//! included), then a light, emissive object or background scattering nothing:
//! `C<[RT][DS]>*<[LOB]x>`. Partition questions are asked on that universe; the members'
//! matches outside it (a light scattering `A`, a path OSL's model allows and no renderer
//! makes) are not the question here.

use lpe::analysis::{partition_within, AnalysisBudget, Decision, Partition};
use lpe::osl::{parse, Osl, Path, Registered};
use lpe_profile::ProfileDialect;

const UNIVERSE: &str = "C<[RT][DS]>*<[LOB]x>";

fn arnold() -> Registered {
    <Osl as ProfileDialect>::with_profile(
        lpe_profile::by_name("arnold").unwrap(),
        Registered::none(),
    )
}

fn split(names: &[&str]) -> Partition<Path> {
    let reg = arnold();
    let aovs: Vec<(String, lpe::osl::Lpe)> = names
        .iter()
        .map(|n| (n.to_string(), parse(n, &reg).unwrap()))
        .collect();
    let universe = parse(UNIVERSE, &reg).unwrap();
    match partition_within(&aovs, &universe, &reg, &AnalysisBudget::default()).unwrap() {
        Decision::Decided(p) => p,
        Decision::Undecided(u) => panic!("{u}"),
    }
}

/// `direct`, `indirect`, `emission`, `background` split Arnold's beauty: a path's first
/// vertex after the camera is an emitter or background (`emission`, `background`) or a
/// `[DSV]` bounce, followed by a light (`direct`) or by anything else (`indirect`).
#[test]
fn arnolds_direct_indirect_emission_background_split_beauty() {
    let p = split(&["direct", "indirect", "emission", "background"]);
    assert!(p.overlaps.is_empty(), "{:?}", p.overlaps);
    assert!(p.gap.is_none(), "{:?}", p.gap);
}

/// The lobe AOVs leave a gap: `specular` is `C<RS[^'coat']>.*`, and a quoted negation
/// needs some label on the vertex (docs/language.md §18.3), so a specular bounce of a
/// closure Arnold does not label lands in none. Worked by hand: `C,~ R,S L,~` is in the
/// universe, and no member matches it (each is checked with the reference matcher).
#[test]
fn arnolds_lobe_aovs_miss_an_unlabelled_specular_bounce() {
    let names = [
        "diffuse",
        "specular",
        "coat",
        "transmission",
        "sss",
        "volume",
        "emission",
        "background",
    ];
    let p = split(&names);
    assert!(p.overlaps.is_empty(), "{:?}", p.overlaps);
    assert_eq!(p.gap.map(|g| g.to_string()).as_deref(), Some("C,~ R,S L,~"));
    let reg = lpe_engines::osl::reference_registration(&arnold());
    let path: Path = "C,~ R,S L,~".parse().unwrap();
    for n in names {
        let tree = lpe_reference::osl::parse(n, &reg).unwrap();
        assert!(!lpe_reference::osl::is_match(&tree, &path), "{n}");
    }
    let universe = lpe_reference::osl::parse(UNIVERSE, &reg).unwrap();
    assert!(lpe_reference::osl::is_match(&universe, &path));
}
