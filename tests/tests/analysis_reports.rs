//! Every field of the analysis reports, on cases built so that each one is non-empty,
//! with the answers decided by hand: which AOVs overlap, which match outside the
//! universe, whether there is a gap, how long the shortest witnesses are. Witnesses are
//! re-checked with the reference matcher, so any shortest witness is accepted.

use lpe::analysis::{self, default_universe};
use lpe::renderman::{parse, Lpe, Path};
use lpe::AovSet;

fn aovs(srcs: &[(&str, &str)]) -> Vec<(String, Lpe)> {
    srcs.iter()
        .map(|(n, s)| {
            (
                n.to_string(),
                parse(s).unwrap_or_else(|e| panic!("{s}: {e}")),
            )
        })
        .collect()
}

fn m(l: &Lpe, p: &Path) -> bool {
    lpe_reference::is_match(l, p)
}

#[test]
fn partition_report_fills_every_field() {
    let set = aovs(&[
        // 0 and 1 overlap on `C RD L`.
        ("directDiffuse", "C<RD>[<L.>O]"),
        ("diffuseToLight", "C<RD>L"),
        // Inside the universe, overlapping nothing.
        ("specularToEmissive", "C<RS>.*O"),
        // Outside: `.` in the universe is a D or S lobe, so a user lobe leaves it.
        ("userLobe", "C<RU>L"),
        // Partly inside (`C TD L`), partly outside (`C TD TU L`, the shortest).
        ("mixed", "C<TD>(.|<TU>)*[<L.>O]"),
    ]);
    let universe =
        default_universe::<lpe::renderman::RenderMan>(&lpe::renderman::Parser::default());
    let p = analysis::partition(&set, &universe, &lpe::renderman::Parser::default()).unwrap();
    assert!(!p.is_clean());

    // Overlaps: exactly the pair (0, 1), with a shortest witness of 3 vertices.
    let pairs: Vec<(usize, usize)> = p.overlaps.iter().map(|o| (o.0, o.1)).collect();
    assert_eq!(pairs, [(0, 1)], "{p:?}");
    let (i, j, w) = &p.overlaps[0];
    assert_eq!(w.len(), 3, "{w}");
    assert!(
        m(&universe, w) && m(&set[*i].1, w) && m(&set[*j].1, w),
        "{w}"
    );

    // Gap: `C L` or `C O` (no AOV goes from the camera straight to an emitter).
    let gap = p.gap.as_ref().expect("a gap");
    assert_eq!(gap.len(), 2, "{gap}");
    assert!(m(&universe, gap), "{gap}");
    for (name, l) in &set {
        assert!(!m(l, gap), "{name} matches the gap {gap}");
    }

    // Outside: AOVs 3 and 4, in index order, with shortest witnesses of 3 and 4 vertices.
    let outside: Vec<(usize, usize)> = p.outside.iter().map(|(i, w)| (*i, w.len())).collect();
    assert_eq!(outside, [(3, 3), (4, 4)], "{p:?}");
    for (i, w) in &p.outside {
        assert!(!m(&universe, w), "{w} is in the universe");
        assert!(m(&set[*i].1, w), "{} does not match {w}", set[*i].0);
    }
}

#[test]
fn partition_report_of_a_partition_is_empty() {
    let set = aovs(&lpe::renderman::macros::BASIC);
    let p = analysis::partition(
        &set,
        &default_universe::<lpe::renderman::RenderMan>(&lpe::renderman::Parser::default()),
        &lpe::renderman::Parser::default(),
    )
    .unwrap();
    assert!(p.overlaps.is_empty() && p.gap.is_none() && p.outside.is_empty());
    assert!(p.is_clean());
    // A narrower universe: every AOV but `directDiffuse` now matches outside it.
    let narrow = parse("C<RD>[<L.>O]").unwrap();
    let p = analysis::partition(&set, &narrow, &lpe::renderman::Parser::default()).unwrap();
    assert!(p.overlaps.is_empty() && p.gap.is_none(), "{p:?}");
    let outside: Vec<usize> = p.outside.iter().map(|o| o.0).collect();
    assert_eq!(outside, [1, 2, 3, 4, 5, 6]);
    assert!(!p.is_clean());
}

#[test]
fn any_one_field_alone_makes_a_partition_unclean() {
    let basic = aovs(&lpe::renderman::macros::BASIC);
    let universe =
        default_universe::<lpe::renderman::RenderMan>(&lpe::renderman::Parser::default());
    // Overlaps only: caustics lie inside indirectDiffuse and subsurface.
    let mut set = basic.clone();
    set.extend(aovs(&[("caustics", "CDS+[<L.>O]")]));
    let p = analysis::partition(&set, &universe, &lpe::renderman::Parser::default()).unwrap();
    assert!(!p.overlaps.is_empty() && p.gap.is_none() && p.outside.is_empty());
    assert!(!p.is_clean(), "{p:?}");
    // A gap only: the paths of the AOV left out.
    let p =
        analysis::partition(&basic[1..], &universe, &lpe::renderman::Parser::default()).unwrap();
    assert!(p.overlaps.is_empty() && p.gap.is_some() && p.outside.is_empty());
    assert!(!p.is_clean(), "{p:?}");
    // Outside only: the narrow universe of `partition_report_of_a_partition_is_empty`.
    let p = analysis::partition(
        &basic,
        &parse("C<RD>[<L.>O]").unwrap(),
        &lpe::renderman::Parser::default(),
    )
    .unwrap();
    assert!(p.overlaps.is_empty() && p.gap.is_none() && !p.outside.is_empty());
    assert!(!p.is_clean(), "{p:?}");
}

#[test]
fn comparison_reports_both_sides() {
    let lpe = |s: &str| parse(s).unwrap();
    // Neither includes the other: each side has a shortest witness of 4 vertices.
    let (a, b) = (lpe("C<RD>.*L"), lpe("C.*<RD>L"));
    let c = analysis::compare(&a, &b).unwrap();
    assert!(!c.equivalent());
    let first = c.first_only.as_ref().expect("first_only");
    let second = c.second_only.as_ref().expect("second_only");
    assert_eq!((first.len(), second.len()), (4, 4), "{first} / {second}");
    assert!(m(&a, first) && !m(&b, first), "{first}");
    assert!(!m(&a, second) && m(&b, second), "{second}");

    // Strict inclusion, both ways round: only the larger side has a witness.
    let (small, large) = (lpe("C<RD>L"), lpe("C.L"));
    let c = analysis::compare(&small, &large).unwrap();
    assert!(!c.equivalent());
    assert_eq!(c.first_only, None);
    let w = c.second_only.expect("second_only");
    assert_eq!(w.len(), 3, "{w}");
    assert!(!m(&small, &w) && m(&large, &w), "{w}");
    let c = analysis::compare(&large, &small).unwrap();
    assert!(!c.equivalent());
    assert_eq!(c.second_only, None);
    let w = c.first_only.expect("first_only");
    assert!(m(&large, &w) && !m(&small, &w), "{w}");

    // Equivalent, written differently.
    let c = analysis::compare(&lpe("C(<RD>|<RS>)L"), &lpe("C[<RD><RS>]L")).unwrap();
    assert!(c.equivalent());
    assert_eq!((c.first_only, c.second_only), (None, None));
}

#[test]
fn emptiness_warnings_name_the_aov() {
    let set = aovs(&[
        ("fine", "C.*L"),
        ("cameraOnly", "C.*"),
        ("alsoFine", "C<RD>O"),
        ("lightInTheMiddle", "CL<RD>L"),
    ]);
    let s = AovSet::compile(&set).unwrap();
    let w: Vec<(usize, &str)> = s
        .warnings()
        .iter()
        .map(|w| (w.aov, w.name.as_str()))
        .collect();
    assert_eq!(w, [(1, "cameraOnly"), (3, "lightInTheMiddle")]);
    for w in s.warnings() {
        assert!(!w.message.is_empty());
        assert!(w.to_string().contains(&w.name), "{w}");
    }
}

#[test]
fn a_one_sided_witness_stays_the_shortest_while_the_search_goes_on() {
    // Only one side has witnesses, so the search runs over every state: the first
    // (shortest) witness, `C . . L`, must be the one kept.
    let lpe = |s: &str| parse(s).unwrap();
    let (one, more) = (lpe("C.L"), lpe("C.+L"));
    let c = analysis::compare(&more, &one).unwrap();
    let w = c.first_only.expect("first_only");
    assert_eq!((w.len(), c.second_only), (4, None), "{w}");
    let c = analysis::compare(&one, &more).unwrap();
    let w = c.second_only.expect("second_only");
    assert_eq!((c.first_only, w.len()), (None, 4), "{w}");
}

#[test]
fn the_shortest_one_sided_witness_is_kept_over_a_later_one_from_another_state() {
    // The search reports each distinct end state once, so a later witness can only
    // replace the first if two end states match the same side: here `C RS L` and
    // `C RS RS L`, distinct because only the second may go on with `<RD>` after its
    // light. `C RD L` matches both sides; neither side has more, so the search runs to
    // its end and meets the longer witness after the shorter one.
    let lpe = |s: &str| parse(s).unwrap();
    let (common, wider) = (lpe("C<RD>L"), lpe("(C<RD>L)|(C<RS>L)|(C<RS><RS>L<RD>*)"));
    let c = analysis::compare(&common, &wider).unwrap();
    let w = c.second_only.expect("second_only");
    assert_eq!((c.first_only, w.len()), (None, 3), "{w}");
    assert!(!m(&common, &w) && m(&wider, &w), "{w}");
    let c = analysis::compare(&wider, &common).unwrap();
    let w = c.first_only.expect("first_only");
    assert_eq!((w.len(), c.second_only), (3, None), "{w}");
    assert!(m(&wider, &w) && !m(&common, &w), "{w}");
}

#[test]
fn analyses_get_a_dfa_budget_above_the_renderers() {
    // `C.*D.{16}[LO]` remembers which of its last 17 bounces were diffuse: a DFA of
    // 2^17 = 131 072 states and more. Next to a 267-bounce chain the set has 290 NFA
    // positions (five words), so each state costs at least 16 + 32 + 2 * 5 * 8 + 32 =
    // 160 bytes: over 20 MiB, past the 16 MiB a renderer's set gets by default, so the
    // renderer's set steps its lazy DFA; an analysis set compiles too.
    let (a, b) = (
        parse("C.*D.{16}[LO]").unwrap(),
        parse("C<RD'x'>{250}<RS>{17}L").unwrap(),
    );
    let renderer = AovSet::compile(&[("a".into(), a.clone()), ("b".into(), b.clone())]);
    assert!(!renderer.unwrap().uses_dfa());
    let c = analysis::compare(&a, &b).unwrap();
    let first = c.first_only.expect("first_only");
    let second = c.second_only.expect("second_only");
    // `C D .{16} L`, and the chain (its 17th bounce from the end is not diffuse).
    assert_eq!((first.len(), second.len()), (19, 269), "{first} / {second}");
    assert!(m(&a, &first) && !m(&b, &first), "{first}");
    assert!(!m(&a, &second) && m(&b, &second), "{second}");
}

#[test]
fn analysis_errors_say_what_went_wrong() {
    // A set over the NFA budget: the compile error, with its message.
    let big = parse("C(.{256}){200}L").unwrap();
    let err = analysis::compare(&big, &parse("CL").unwrap()).unwrap_err();
    let analysis::AnalysisError::Compile(compile) = &err else {
        panic!("{err:?}")
    };
    assert!(matches!(compile, lpe::CompileError::NfaOverBudget { .. }));
    assert_eq!(err.to_string(), compile.to_string());
    assert!(err.to_string().contains("NFA budget"), "{err}");
    // The search limit names its number.
    let err = analysis::AnalysisError::TooLarge(analysis::MAX_SEARCH_STATES);
    assert_eq!(
        err.to_string(),
        "the search visited more than 2000000 automaton states without finishing"
    );
}
