//! The seven basic AOVs partition all light-transport paths: checked exhaustively on the
//! reference matcher, over every path up to length 4 of a small alphabet. (The
//! vector-by-vector conformance cases are in `tests/testdata/`.)

use lpe::renderman::{parse, Event, EventKind, Path, Vertex, VertexType};
use lpe_reference::is_match;

/// A small alphabet: both scattering types with D1, D2, S2, S8, one or no label; both
/// emitters with one or no label. No user lobes (user-lobe pseudo paths are outside the
/// universe).
fn small_alphabet() -> (Vec<Vertex>, Vec<Vertex>) {
    let mut scatter = Vec::new();
    for ty in [VertexType::R, VertexType::T] {
        for (k, l) in [
            (EventKind::D, 1),
            (EventKind::D, 2),
            (EventKind::S, 2),
            (EventKind::S, 8),
        ] {
            for label in [None, Some("floor")] {
                scatter.push(Vertex::scatter(ty, Event::new(k, l).unwrap(), label));
            }
        }
    }
    let ends = vec![
        Vertex::light(None),
        Vertex::light(Some("key")),
        Vertex::emissive(None),
        Vertex::emissive(Some("floor")),
    ];
    (scatter, ends)
}

fn all_paths(max_len: usize) -> Vec<Path> {
    let (scatter, ends) = small_alphabet();
    let mut mids: Vec<Vec<Vertex>> = vec![vec![]];
    let mut out = Vec::new();
    for _ in 0..max_len - 1 {
        for mid in &mids {
            for e in &ends {
                let mut v = vec![Vertex::camera()];
                v.extend(mid.iter().cloned());
                v.push(e.clone());
                out.push(Path::new(v).unwrap());
            }
        }
        mids = mids
            .iter()
            .flat_map(|m| {
                scatter.iter().map(move |s| {
                    let mut m = m.clone();
                    m.push(s.clone());
                    m
                })
            })
            .collect();
    }
    out
}

#[test]
fn basic_aovs_are_disjoint_and_exhaustive_up_to_length_4() {
    let basic: Vec<_> = lpe::renderman::macros::BASIC
        .iter()
        .map(|(n, _)| (n, parse(n).unwrap()))
        .collect();
    let paths = all_paths(4);
    // 4 ends x (1 + 16 + 256) middles.
    assert_eq!(paths.len(), 4 * (1 + 16 + 256));
    for p in &paths {
        let hits: Vec<_> = basic
            .iter()
            .filter(|(_, e)| is_match(e, p))
            .map(|(n, _)| n)
            .collect();
        assert_eq!(hits.len(), 1, "`{p}` matched {hits:?}");
    }
    // And caustics overlaps indirectDiffuse (the RenderMan page says why it is not basic).
    let caustics = parse("caustics").unwrap();
    let ind = parse("indirectDiffuse").unwrap();
    let p: Path = "C RD RS L".parse().unwrap();
    assert!(is_match(&caustics, &p) && is_match(&ind, &p));
}
