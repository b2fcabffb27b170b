//! The reference matcher against DESIGN.md §3, row by row, with expectations written by
//! hand from the document (never taken from the matcher's own output).

use lpe::{parse, Event, EventKind, Path, Vertex, VertexType};
use reference::is_match;

fn m(expr: &str, path: &str) -> bool {
    let lpe = parse(expr).unwrap_or_else(|e| panic!("{expr}: {e}"));
    let p: Path = path.parse().unwrap_or_else(|e| panic!("{path}: {e}"));
    is_match(&lpe, &p)
}

/// Asserts `expr` matches every path in `yes` and none in `no`.
fn check(expr: &str, yes: &[&str], no: &[&str]) {
    for p in yes {
        assert!(m(expr, p), "`{expr}` should match `{p}`");
    }
    for p in no {
        assert!(!m(expr, p), "`{expr}` should not match `{p}`");
    }
}

#[test]
fn type_letters_c_l_o_match_any_label() {
    check("CL", &["C L", "C L'key'"], &["C O", "C RD L"]);
    check("CO", &["C O", "C O'glow'"], &["C L"]);
}

#[test]
fn r_and_t_need_a_d_or_s_event() {
    check(
        "CRL",
        &["C RD L", "C RS3 L", "C RD'x' L"],
        &["C TD L", "C RU2 L"],
    );
    check("CTL", &["C TS8 L", "C TD3 L"], &["C RS L", "C TU1 L"]);
}

#[test]
fn event_letters_match_r_or_t_with_that_kind_or_lobe() {
    check(
        "CDL",
        &["C RD L", "C TD4 L", "C RD2'f' L"],
        &["C RS L", "C RU L"],
    );
    check("CD2L", &["C RD2 L", "C TD2 L"], &["C RD1 L", "C RD3 L"]);
    check("CS4L", &["C RS4 L"], &["C RS L", "C RS5 L"]);
    check("CSL", &["C RS8 L", "C TS1 L"], &["C RD L"]);
}

#[test]
fn user_lobes_match_only_explicitly() {
    check("CUL", &["C RU L", "C RU12 L", "C TU3 L"], &["C RD L"]);
    check("CU3L", &["C RU3 L"], &["C RU2 L"]);
    // No wildcard or negated class matches a user lobe.
    check("C.L", &["C RD L"], &["C RU2 L"]);
    check("C.*L", &["C L", "C RD TS L"], &["C RU2 L", "C RD RU1 L"]);
    check("C[^D]L", &["C RS L"], &["C RU2 L", "C RD L"]);
    check("CRL", &[], &["C RU2 L"]);
    check("C<R.>L", &[], &["C RU2 L"]);
    check("C<RU2>L", &["C RU2 L"], &["C TU2 L", "C RU3 L"]);
    check("C<.U>L", &["C RU5 L", "C TU1 L"], &["C RD L"]);
    check("C['x']L", &["C RD'x' L"], &["C RU1'x' L"]);
}

#[test]
fn dot_is_r_or_t_with_d_or_s() {
    // DESIGN: `C.L` = `C<..>L` = `C<[RT][DS]>L`.
    let paths = [
        "C RD L",
        "C TS L",
        "C RS8'a' L",
        "C RU1 L",
        "C L",
        "C RD RD L",
    ];
    for p in paths {
        let a = m("C.L", p);
        assert_eq!(a, m("C<..>L", p), "{p}");
        assert_eq!(a, m("C<[RT][DS]>L", p), "{p}");
    }
    check(
        "C.L",
        &["C RD L", "C TS L"],
        &["C L", "C RU1 L", "C RD RD L"],
    );
}

#[test]
fn labels_match_r_or_t_with_that_label() {
    check(
        "C'floor'L",
        &["C RD'floor' L", "C TS2'floor' L"],
        &["C RD L", "C RD'Floor' L", "C RU2'floor' L"],
    );
    // A bare label never matches an emitter.
    check("C'key'", &[], &["C L'key'", "C O'key'"]);
}

#[test]
fn triples_match_all_three_positions() {
    check(
        "C<RD'floor'>L",
        &["C RD'floor' L", "C RD3'floor' L"],
        &["C TD'floor' L", "C RS'floor' L", "C RD L"],
    );
    check(
        "C.*<L.'key'>",
        &["C L'key'", "C RD L'key'"],
        &["C L", "C L'fill'", "C O'key'"],
    );
    check("C<L>", &["C L", "C L'x'"], &["C O"]);
    check("C<.D>L", &["C RD L", "C TD2 L"], &["C RS L"]);
    check("C<[RT][DS]>L", &["C RD L", "C TS L"], &["C RU L"]);
    check(
        "C<R[D2 S3]>L",
        &["C RD2 L", "C RS3 L"],
        &["C RD1 L", "C TD2 L"],
    );
    // The event position's `.` is "no event" for C/L/O.
    check("C<L.>", &["C L"], &[]);
    check("C<[LO].>", &["C L", "C O'g'"], &[]);
    // An explicit event never matches a light.
    check("C<LD>", &[], &["C L"]);
}

#[test]
fn classes_and_negated_classes() {
    // DESIGN: `C[S2 S3 S4]L` matches CS2L, CS3L, CS4L (whitespace ignored).
    check(
        "C[S2 S3 S4]L",
        &["C RS2 L", "C TS3 L", "C RS4 L"],
        &["C RS1 L", "C RS5 L"],
    );
    check("C[<L.>O]", &["C L", "C O"], &["C RD L"]);
    // `[^D2D3]` is `.` minus D2 and D3: other diffuse lobes and all specular ones.
    check(
        "C[^D2D3]L",
        &["C RD1 L", "C RD4 L", "C RS2 L"],
        &["C RD2 L", "C TD3 L", "C RU1 L"],
    );
    // A negated class never matches C, L or O: it is `.` minus the items.
    check("C[^D]*L", &["C L", "C RS TS L"], &["C RD L"]);
    check("C[^'x']L", &["C RD L", "C RD'y' L"], &["C RD'x' L"]);
}

#[test]
fn negated_label_classes_match_unlabelled_vertices() {
    // Unlike OSL: no label is "not foo".
    check(
        "C<R.[^'foo']>L",
        &["C RD L", "C RD'bar' L"],
        &["C RD'foo' L"],
    );
    check(
        "C.*<L.[^'key' 'fill']>",
        &["C L", "C L'rim'"],
        &["C L'key'", "C L'fill'"],
    );
    check(
        "C<R.['a' 'b']>L",
        &["C RD'a' L", "C RS'b' L"],
        &["C RD L", "C RD'c' L"],
    );
}

#[test]
fn negated_type_and_event_positions_follow_the_negation_rule() {
    // Type position: `.` is [RT], so `[^R]` is T.
    check("C<[^R].>L", &["C TD L"], &["C RD L"]);
    check("C.*<[^R].>", &[], &["C L", "C O"]);
    // Event position: `.` is D or S for R/T, so `[^D]` is S (never U).
    check("C<R[^D]>L", &["C RS L"], &["C RD L", "C RU L"]);
    check("C<R[^D1]>L", &["C RD2 L", "C RS1 L"], &["C RD1 L"]);
}

#[test]
fn each_letter_outside_a_triple_is_its_own_vertex() {
    // DESIGN: `C<RD>L` is three vertices, `CRDL` four.
    check("C<RD>L", &["C RD L"], &["C RD RD L"]);
    check("CRDL", &["C RS RD L", "C RD TD L"], &["C RD L"]);
    check(
        "C(RD)+L",
        &["C RS RD L", "C RD RD RD RD L"],
        &["C RD L", "C RD RD RD L"],
    );
}

#[test]
fn alternation_binds_only_its_neighbours() {
    // DESIGN: `CD|(SD)L` = `C(D|(SD))L` matches CDL or CSDL.
    check(
        "CD|(SD)L",
        &["C RD L", "C RS RD L"],
        &["C RD RD L", "C RS L"],
    );
    // `a b|c d` is `a (b|c) d`.
    check("CD|SL", &["C RD L", "C RS L"], &["C RD RS L"]);
    // `a|b*` is `a|(b*)`.
    check(
        "CD|S*L",
        &["C RD L", "C L", "C RS RS L"],
        &["C RD RD L", "C RD RS L"],
    );
    // A group widens it.
    check("(CDL)|(CSO)", &["C RD L", "C RS O"], &["C RD O", "C RS L"]);
}

#[test]
fn groups_may_start_the_expression() {
    check("(C<RD>)[LO]", &["C RD L", "C RD O"], &["C RS L"]);
}

#[test]
fn quantifiers_and_bounds() {
    check("C.*L", &["C L", "C RD TS RD L"], &["C O"]);
    check("C.+L", &["C RD L", "C RD RD L"], &["C L"]);
    check("C.?L", &["C L", "C RD L"], &["C RD RD L"]);
    check("CT{2}L", &["C TS TD L"], &["C TS L", "C TS TS TS L"]);
    check(
        "C.{2,}L",
        &["C RD RD L", "C RD RD RD RD L"],
        &["C L", "C RD L"],
    );
    check(
        "C.{0,2}L",
        &["C L", "C RD L", "C RD RD L"],
        &["C RD RD RD L"],
    );
    check(
        "C.{1,3}L",
        &["C RD L", "C RD RD RD L"],
        &["C L", "C RD RD RD RD L"],
    );
    check("C.{2,2}L", &["C RD RS L"], &["C RD L"]);
    // `{0}` and `{0,0}` match the empty sequence.
    check("CD{0}L", &["C L"], &["C RD L"]);
    check("CD{0,0}L", &["C L"], &["C RD L"]);
    // The RenderMan page's examples.
    check("C.*[LO]", &["C L", "C O", "C RD RS L"], &[]);
    check("C.+[LO]", &["C RD O"], &["C L"]);
    check("C.?[LO]", &["C L", "C TD O"], &["C RD RD L"]);
}

#[test]
fn nullable_bodies_and_large_counts_terminate() {
    check("C(.?)*L", &["C L", "C RD RS TD L"], &["C RU L"]);
    check("C(D?){256}L", &["C L", "C RD RD RD L"], &["C RS L"]);
    check(
        "C(.?){256}L",
        &["C RD RS TD RD RS TD RD RS TD RD L"],
        &["C RU1 L"],
    );
    check(
        "C((.?){16}){16}L",
        &["C RD RS TD RD RS TD RD RS TD RD L"],
        &["C RU L"],
    );
    check("C(D*|S*)*L", &["C RD RS RD L"], &["C RD RU L"]);
    // At the positions limit, nested and nullable: must answer at once, both ways.
    let long = format!("C {}L", "RD ".repeat(40));
    let long_miss = format!("C {}RU L", "RD ".repeat(40));
    check("C((.?){255}){256}L", &[&long], &[&long_miss]);
    check("C((D?){200}(S?){50}){256}L", &[&long], &[&long_miss]);
    // A nullable body's lower bound can be met with empty iterations.
    check(
        "C(D?){5}L",
        &["C L", "C RD RD L"],
        &["C RD RD RD RD RD RD L"],
    );
}

#[test]
fn anchored_at_both_ends() {
    check("CD", &[], &["C RD L"]);
    check("DL", &[], &["C RD L"]);
    check("C.*", &[], &["C RD L", "C L"]);
    check(".*L", &[], &["C RD L"]);
}

#[test]
fn prefixes_do_not_change_matching() {
    let paths = ["C RD L", "C RS RD O", "C L'key'"];
    for p in paths {
        assert_eq!(m("C.*[LO]", p), m("unoccluded;shadows;C.*[LO]", p), "{p}");
    }
}

#[test]
fn the_documented_macros_match_what_they_say() {
    check(
        "directDiffuse",
        &["C RD L", "C RD2 O"],
        &["C TD L", "C RD RD L"],
    );
    check("indirectDiffuse", &["C RD RS L"], &["C RD L"]);
    check("subsurface", &["C TD L", "C TD RS RD O"], &["C RD L"]);
    check(
        "caustics",
        &["C RD RS L", "C TD RS TS O"],
        &["C RD RD L", "C RS L"],
    );
    check(
        "shadowcollector",
        &["C RD'collector' L", "C TS'collector' L"],
        &["C RD L", "C RD'collector' O"],
    );
    check(
        "directDiffuse_key",
        &["C RD L'key'", "C RD O"],
        &["C RD L", "C RD L'fill'"],
    );
    check(
        "transmissiveGlassLobe",
        &["C TS8 RD L"],
        &["C RS8 L", "C TS7 L"],
    );
}

// ---- the seven basic AOVs partition all light-transport paths ----------------------

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
    let basic: Vec<_> = lpe::macros::BASIC
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
