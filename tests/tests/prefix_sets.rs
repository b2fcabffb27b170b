//! The prefix set of an expression: a macro's prefixes JOIN the ones the user writes
//! before its name (a prefix on both sides stays set, it does not cancel out), and
//! `is_empty` tells an expression with prefixes from one without (the differential
//! shrinker drops prefixes only when there are some). Answers decided by hand.

use lpe::renderman::{parse, Config, Prefix, Prefixes};

#[test]
fn user_prefixes_join_the_macros_prefixes() {
    // `shadowcollector` is `shadows;...`: writing `shadows;` again keeps it set.
    let l = parse("shadows;shadowcollector").unwrap();
    assert_eq!(l.prefixes.iter().collect::<Vec<_>>(), [Prefix::Shadows]);
    let l = parse("unoccluded;shadows;shadowcollector").unwrap();
    assert!(l.prefixes.contains(Prefix::Shadows));
    assert!(l.prefixes.contains(Prefix::Unoccluded));
    assert_eq!(l.prefixes.iter().count(), 2);
    // A user macro with two prefixes, one of them repeated by the user.
    let config = Config::from_ini("/prman/lpe/macro/held holdouts;noclamp;C<RD>[<L.>O]\n").unwrap();
    let l = config.parser().parse("noclamp;nothruput;held_key").unwrap();
    let mut got: Vec<Prefix> = l.prefixes.iter().collect();
    got.sort_by_key(|p| p.name());
    let mut want = vec![Prefix::Holdouts, Prefix::Noclamp, Prefix::Nothruput];
    want.sort_by_key(|p| p.name());
    assert_eq!(got, want);
    assert_eq!(
        l,
        parse("holdouts;noclamp;nothruput;C<RD>[<L.'key'>O]").unwrap()
    );
}

#[test]
fn is_empty_tells_prefixed_expressions_apart() {
    assert!(Prefixes::NONE.is_empty());
    assert!(parse("C.*L").unwrap().prefixes.is_empty());
    assert!(parse("directDiffuse").unwrap().prefixes.is_empty());
    for p in Prefix::ALL {
        let l = parse(&format!("{};C.*L", p.name())).unwrap();
        assert!(!l.prefixes.is_empty(), "{}", p.name());
    }
    assert!(!parse("shadowcollector").unwrap().prefixes.is_empty());
}

#[test]
fn prefix_sets_collect_from_an_iterator() {
    let set: Prefixes = [Prefix::Shadows, Prefix::Noclamp, Prefix::Shadows]
        .into_iter()
        .collect();
    assert!(set.contains(Prefix::Shadows) && set.contains(Prefix::Noclamp));
    assert_eq!(set.iter().count(), 2);
    assert_eq!(set, parse("noclamp;shadows;C.*L").unwrap().prefixes);
    let none: Prefixes = std::iter::empty().collect();
    assert_eq!(none, Prefixes::NONE);
}
