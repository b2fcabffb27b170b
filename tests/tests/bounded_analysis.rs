//! Analyses with a budget: the pair whose DFAs blow up (`C.*D.{k}L` against
//! `C.*D.{k}[LO]`, `2^k` states each) decided on the NFA route with its witness
//! re-checked by the reference matcher, and a question past a tiny budget answered
//! undecided, not an error.

use lpe::analysis::{self, AnalysisBudget, Decision, Limit, Undecided};
use lpe::renderman::parse;

/// At k = 24 the lazy-DFA search needed more than 2 000 000 states; the NFA route
/// decides it within the default budget: `A` is included in `B`, and `B`'s witness is
/// `C`, a diffuse bounce, 24 more vertices, an emissive object: k + 3 vertices, matched
/// by `B` and not by `A` according to the reference matcher. Swapping the two
/// directions' formulas, or a subsumption that drops a needed node, fails it.
#[test]
fn the_blowup_pair_is_decided_at_k_24_with_a_rechecked_witness() {
    let k = 24;
    let a = parse(&format!("C.*D.{{{k}}}L")).unwrap();
    let b = parse(&format!("C.*D.{{{k}}}[LO]")).unwrap();
    let decision = analysis::compare_within(&a, &b, &AnalysisBudget::default()).unwrap();
    let Decision::Decided(c) = decision else {
        panic!("undecided: {decision:?}")
    };
    assert_eq!(c.first_only, None);
    let w = c.second_only.expect("B matches more");
    assert_eq!(w.len(), k + 3, "{w}");
    assert!(lpe_reference::is_match(&b, &w), "{w}");
    assert!(!lpe_reference::is_match(&a, &w), "{w}");
}

/// A pair past a budget of 10 steps: undecided with the limit named, from
/// `compare_within` and `partition_within`; the budget-free entry points give the error
/// they always gave past their limit. Charging nothing for a search node (a meter that
/// never runs out) fails it.
#[test]
fn a_tiny_budget_answers_undecided_through_the_api() {
    let a = parse("C.*D.{12}L").unwrap();
    let b = parse("(C.*D.{12}L)|(C.*S.{12}L)").unwrap();
    let tiny = AnalysisBudget::steps(10);
    let undecided = Undecided {
        limit: Limit::Steps(10),
    };
    assert_eq!(
        analysis::compare_within(&a, &b, &tiny).unwrap(),
        Decision::Undecided(undecided)
    );
    let reg = lpe::renderman::Parser::default();
    let universe = analysis::default_universe::<lpe::renderman::RenderMan>(&reg);
    let aovs = vec![("a".to_string(), a), ("b".to_string(), b)];
    let p = analysis::partition_within(&aovs, &universe, &reg, &tiny).unwrap();
    assert_eq!(p, Decision::Undecided(undecided));
    assert_eq!(
        undecided.to_string(),
        "undecided within the budget of 10 search steps"
    );
}
