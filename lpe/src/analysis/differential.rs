//! The NFA route of the analyses against the lazy-DFA route on generated expressions:
//! every comparison and partition report equal, witnesses included (both give the first
//! shortest witness in letter order). The two share the parsed trees, the vertex classes
//! and the letters' order; the NFA route searches runs and position subsets of the
//! Glushkov NFA (`antichain`), the oracle the states of the set's DFA or lazy DFA
//! (`search`), built from that NFA by a subset construction of its own.

use super::*;
use crate::dialect::Dialect;
use crate::osl;
use crate::renderman;
use crate::rng::SplitMix64;

/// A random expression body over `atoms`: a few items, each an atom or an alternation of
/// two, each perhaps quantified.
fn body(rng: &mut SplitMix64, atoms: &[&str]) -> String {
    const QUANTIFIERS: [&str; 7] = ["", "", "*", "+", "?", "{2}", "{1,3}"];
    let mut s = String::new();
    for _ in 0..1 + rng.below(4) {
        let atom = |rng: &mut SplitMix64| atoms[rng.below(atoms.len())].to_string();
        let item = if rng.below(4) == 0 {
            format!("({}|{})", atom(rng), atom(rng))
        } else {
            atom(rng)
        };
        s.push_str(&item);
        s.push_str(QUANTIFIERS[rng.below(QUANTIFIERS.len())]);
    }
    s
}

/// A random whole expression: `C`, a body, an emitter; a fifth of them set algebra of
/// two such.
fn expression(rng: &mut SplitMix64, atoms: &[&str], ends: &[&str]) -> String {
    let one =
        |rng: &mut SplitMix64| format!("C{}{}", body(rng, atoms), ends[rng.below(ends.len())]);
    match rng.below(10) {
        0 => format!("{} - {}", one(rng), one(rng)),
        1 => format!("{} & {}", one(rng), one(rng)),
        _ => one(rng),
    }
}

const RM_ATOMS: [&str; 10] = [
    "D", "S", ".", "<RD>", "<TS>", "<RS>", "'a'", "[DS]", "[^'a']", "<RU>",
];
const RM_ENDS: [&str; 5] = ["L", "O", "[LO]", "<L.'k'>", "[<L.>O]"];
const OSL_ATOMS: [&str; 8] = ["D", "G", "S", ".", "<RD>", "<TG>", "<TS>", "[DG]"];
const OSL_ENDS: [&str; 3] = ["L", "O", "[LO]"];

/// Both routes agree, or one is undecided (then the pair is not counted).
fn same_comparison<D: Dialect>(a: &D::Lpe, b: &D::Lpe) -> bool {
    let budget = AnalysisBudget::steps(200_000);
    let new = compare_within::<D, D::Lpe>(a, b, &budget).unwrap();
    let old = compare_by_lazy_dfa::<D, D::Lpe>(a, b, &budget).unwrap();
    match (new, old) {
        (Decision::Decided(n), Decision::Decided(o)) => {
            assert_eq!(n, o, "{a} vs {b}");
            true
        }
        _ => false,
    }
}

/// The NFA route gives the lazy-DFA route's comparisons, exact witnesses included, on
/// 400 generated RenderMan pairs. Returning the breadth-first witness without the
/// letter-order search when a same-layer node was removed (`Graph::first_in_order`)
/// fails it (a shortest witness, not the first), and so does subsumption the wrong way
/// round (dropping a node whose subset is a *subset* of a kept one's).
#[test]
fn comparisons_agree_with_the_lazy_dfa_search() {
    let mut rng = SplitMix64::new(20261121);
    let mut decided = 0;
    for _ in 0..400 {
        let a = expression(&mut rng, &RM_ATOMS, &RM_ENDS);
        let b = if rng.below(3) == 0 {
            // A near copy: one more item, so the two often differ late.
            format!("{a}|{}", expression(&mut rng, &RM_ATOMS, &RM_ENDS))
        } else {
            expression(&mut rng, &RM_ATOMS, &RM_ENDS)
        };
        let (Ok(a), Ok(b)) = (renderman::parse(&a), renderman::parse(&b)) else {
            continue;
        };
        decided += usize::from(same_comparison::<renderman::RenderMan>(&a, &b));
    }
    assert!(decided > 300, "{decided}");
}

/// As [`comparisons_agree_with_the_lazy_dfa_search`], in the OSL dialect (every sequence
/// of vertices, no path shape).
#[test]
fn comparisons_agree_with_the_lazy_dfa_search_in_the_osl_dialect() {
    let mut rng = SplitMix64::new(7);
    let reg = osl::Registered::none();
    let mut decided = 0;
    for _ in 0..300 {
        // OSL has no `?`.
        let a = expression(&mut rng, &OSL_ATOMS, &OSL_ENDS).replace('?', "{0,1}");
        let b = expression(&mut rng, &OSL_ATOMS, &OSL_ENDS).replace('?', "{0,1}");
        let (Ok(a), Ok(b)) = (osl::parse(&a, &reg), osl::parse(&b, &reg)) else {
            continue;
        };
        decided += usize::from(same_comparison::<osl::Osl>(&a, &b));
    }
    assert!(decided > 200, "{decided}");
}

/// Partitions of three to five generated AOVs of the default universe or a generated
/// one: the NFA route's overlaps, gap and strays are the lazy-DFA route's, in both
/// dialects. Expanding the nodes of one layer one by one instead of in groups of one
/// word (`Graph::shortest`) fails it: two nodes of one word interleave their
/// continuations, and a later letter's witness comes first.
#[test]
fn partitions_agree_with_the_lazy_dfa_search() {
    let mut rng = SplitMix64::new(99);
    let budget = AnalysisBudget::steps(400_000);
    let mut decided = 0;
    for round in 0..120 {
        let n = 3 + rng.below(3);
        if round % 2 == 0 {
            let reg = renderman::Parser::default();
            let aovs: Vec<(String, renderman::Lpe)> = (0..n)
                .filter_map(|i| {
                    let s = expression(&mut rng, &RM_ATOMS, &RM_ENDS);
                    renderman::parse(&s).ok().map(|l| (format!("a{i}"), l))
                })
                .collect();
            let universe = match rng.below(2) {
                0 => default_universe::<renderman::RenderMan>(&reg),
                _ => renderman::parse("C[DS]*[LO]").unwrap(),
            };
            let new = partition_within(&aovs, &universe, &reg, &budget).unwrap();
            let old = partition_by_lazy_dfa(&aovs, &universe, &reg, &budget).unwrap();
            if let (Decision::Decided(n), Decision::Decided(o)) = (new, old) {
                assert_eq!(n, o, "{aovs:?}");
                decided += 1;
            }
        } else {
            let reg = osl::Registered::none();
            let aovs: Vec<(String, osl::Lpe)> = (0..n)
                .filter_map(|i| {
                    let s = expression(&mut rng, &OSL_ATOMS, &OSL_ENDS).replace('?', "{0,1}");
                    osl::parse(&s, &reg).ok().map(|l| (format!("a{i}"), l))
                })
                .collect();
            let universe = match rng.below(2) {
                0 => default_universe::<osl::Osl>(&reg),
                _ => osl::parse("C[DG]*[LO]", &reg).unwrap(),
            };
            let new = partition_within(&aovs, &universe, &reg, &budget).unwrap();
            let old = partition_by_lazy_dfa(&aovs, &universe, &reg, &budget).unwrap();
            if let (Decision::Decided(n), Decision::Decided(o)) = (new, old) {
                assert_eq!(n, o, "{aovs:?}");
                decided += 1;
            }
        }
    }
    assert!(decided > 100, "{decided}");
}

/// The blow-up pair: decided on the NFA within a budget the lazy-DFA route runs out of,
/// with the witness one letter-order search away (`C` then 25 vertices then `O`).
#[test]
fn the_blowup_pair_is_decided_on_the_nfa_and_not_on_the_lazy_dfa() {
    let (a, b) = (
        renderman::parse("C.*D.{20}L").unwrap(),
        renderman::parse("C.*D.{20}[LO]").unwrap(),
    );
    let budget = AnalysisBudget::steps(100_000);
    let Decision::Decided(c) = compare_within(&a, &b, &budget).unwrap() else {
        panic!("undecided on the NFA")
    };
    assert_eq!(c.first_only, None);
    assert_eq!(c.second_only.map(|p| p.len()), Some(23));
    let old = compare_by_lazy_dfa(&a, &b, &budget).unwrap();
    assert_eq!(
        old,
        Decision::Undecided(Undecided {
            limit: Limit::Steps(100_000)
        })
    );
}

/// A pair past a tiny budget is undecided, not an error, through compare, partition and
/// the warnings; the legacy entry points turn it into [`AnalysisError::TooLarge`].
#[test]
fn a_tiny_budget_answers_undecided() {
    let (a, b) = (
        renderman::parse("C.*D.{8}L").unwrap(),
        renderman::parse("C.*D.{8}[LO]").unwrap(),
    );
    let tiny = AnalysisBudget::steps(5);
    let undecided = Decision::Undecided(Undecided {
        limit: Limit::Steps(5),
    });
    assert_eq!(compare_within(&a, &b, &tiny).unwrap(), undecided);
    let reg = renderman::Parser::default();
    let aovs = vec![("a".to_string(), a.clone()), ("b".to_string(), b.clone())];
    let universe = default_universe::<renderman::RenderMan>(&reg);
    assert!(matches!(
        partition_within(&aovs, &universe, &reg, &tiny).unwrap(),
        Decision::Undecided(Undecided {
            limit: Limit::Steps(5)
        })
    ));
    let algebra = vec![(
        "x".to_string(),
        renderman::parse("C.*D.{8}L - C.*D.{8}[LO]").unwrap(),
    )];
    let set = crate::AovSet::compile(&algebra).unwrap();
    let (found, stopped) = warnings_within(&set, &tiny);
    assert!(found.is_empty() && stopped.is_some());
    // With the default budget the same algebra is decided empty.
    let (found, stopped) = warnings_within(&set, &AnalysisBudget::default());
    assert_eq!((found.len(), stopped), (1, None));
}
