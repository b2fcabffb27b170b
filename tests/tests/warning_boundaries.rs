//! Warnings that must not fire: for every warning kind of both dialects, the smallest
//! input that warns beside the closest valid inputs, which must not. A warning tested
//! only where it appears survives a fault that makes it fire everywhere (or at the wrong
//! bound); these pairs fail on either.
//!
//! The kinds: the emptiness warnings of a compiled set (`AovSet::warnings`, and
//! `analysis::warnings` for set algebra), one per reason an AOV can match no path, in
//! both dialects; and OSL's parse warnings (a reversed range `{m,n}`, a negation mixing
//! slots), which OSL prints while it accepts the expression.

use lpe::algebra::SetExpr;
use lpe::analysis;
use lpe::osl::{self, Osl, Registered, WarningKind};
use lpe::renderman::{self, RenderMan};
use lpe::{AovSet, Dialect, DialectLpe};

/// The warnings of a set of one AOV `src` in dialect `D`, as `analysis::warnings` gives
/// them (the plain AOVs' compile-time warnings and set algebra's).
fn emptiness<D, L>(src: &str) -> Vec<String>
where
    D: Dialect<Lpe = L>,
    L: DialectLpe<Dialect = D> + SetExpr,
{
    let lpe = D::parse(src, &D::Registration::default())
        .unwrap_or_else(|e| panic!("{}: `{src}`: {e}", D::NAME));
    let set = AovSet::compile(&[("a".to_string(), lpe)]).unwrap();
    let all = analysis::warnings(&set);
    // The plain AOVs' warnings are the compile-time ones.
    let plain: Vec<_> = set.warnings().to_vec();
    if set.lpes()[0].algebra().is_some() {
        assert!(
            plain.is_empty(),
            "{src}: set algebra warns through analysis"
        );
    } else {
        assert_eq!(all, plain, "{src}");
    }
    all.iter().map(|w| w.message.clone()).collect()
}

/// `(warns, reason, must not warn)`: the first warns with a message containing the
/// reason; none of the last does.
type Pair<'a> = (&'a str, &'a str, &'a [&'a str]);

const NO_VERTEX: &str = "matches no sequence of vertices at all";
const NOT_FROM_CAMERA: &str = "starts with a vertex other than the camera";
const NO_EMITTER: &str = "never reaches an emitter";
const MIDDLE: &str = "in the middle";
const ALGEBRA: &str = "its set algebra leaves no path";

const RENDERMAN: &[Pair] = &[
    // An atom no vertex matches, and the same atom where it may be skipped.
    (
        "C[^CRTLO]L",
        NO_VERTEX,
        &["C[^CRTLO]*L", "C[^CTLO]L", "C[^CRTL]*L"],
    ),
    ("RL", NOT_FROM_CAMERA, &["CL", "C?RL", "CR*L"]),
    ("CR", NO_EMITTER, &["CRL", "CL", "CR[LO]"]),
    ("CLL", MIDDLE, &["CL", "CL+", "C.L", "CR*L"]),
    ("COL", MIDDLE, &["COL?", "CO"]),
    // Set algebra: an intersection that no path is in, and its closest non-empty ones.
    (
        "CL & CRL",
        ALGEBRA,
        &["C.*L & CRL", "CR*L & CRL", "C(L|RL)"],
    ),
    // Counted repetition at its bounds: zero, equal, one apart.
    (
        "C<RD>{2}L & C<RD>{3}L",
        ALGEBRA,
        &[
            "C<RD>{2,3}L & C<RD>{3}L",
            "C<RD>{0}L",
            "C<RD>{0,0}L",
            "C<RD>{2,2}L",
        ],
    ),
];

/// OSL's path model is any sequence of vertices (`PathShape::Any`): only an expression
/// that matches no sequence at all warns, and OSL has no atom that no vertex matches
/// without registration (a negated list of every basic event still admits the events a
/// renderer may register), so that reason is met through set algebra; what warns in
/// RenderMan for the shape of its paths must not warn here.
const OSL: &[Pair] = &[
    (
        "CL & CRL",
        ALGEBRA,
        &["C.*L & CRL", "RL", "CR", "CLL", "C[^CRTLO]L"],
    ),
    (
        "CD{2}L & CD{3}L",
        ALGEBRA,
        &["CD{2,3}L & CD{3}L", "CD{2,2}L"],
    ),
];

fn check_pairs<D, L>(pairs: &[Pair])
where
    D: Dialect<Lpe = L>,
    L: DialectLpe<Dialect = D> + SetExpr,
{
    for &(warns, reason, quiet) in pairs {
        let got = emptiness::<D, L>(warns);
        assert!(
            got.len() == 1 && got[0].contains(reason),
            "{}: `{warns}` should warn `{reason}`, warned {got:?}",
            D::NAME
        );
        for q in quiet {
            let got = emptiness::<D, L>(q);
            assert!(
                got.is_empty(),
                "{}: `{q}` must not warn, warned {got:?}",
                D::NAME
            );
        }
    }
}

#[test]
fn each_emptiness_reason_warns_at_its_boundary_and_not_past_it_in_the_renderman_dialect() {
    check_pairs::<RenderMan, renderman::Lpe>(RENDERMAN);
}

#[test]
fn each_emptiness_reason_warns_at_its_boundary_and_not_past_it_in_the_osl_dialect() {
    check_pairs::<Osl, osl::Lpe>(OSL);
}

/// OSL's parse warnings, by kind and position.
fn parse_warnings(src: &str) -> Vec<(WarningKind, usize)> {
    osl::parse(src, &Registered::none())
        .unwrap_or_else(|e| panic!("`{src}`: {e}"))
        .warnings
        .into_iter()
        .map(|w| (w.kind, w.pos))
        .collect()
}

#[test]
fn a_reversed_range_warns_and_equal_or_increasing_bounds_do_not_in_the_osl_dialect() {
    // One below equal warns; equal, one apart, zero and open bounds do not.
    assert_eq!(
        parse_warnings("CD{3,2}L"),
        [(WarningKind::ReversedRange { min: 3, max: 2 }, 2)]
    );
    assert_eq!(
        parse_warnings("CD{1,0}L"),
        [(WarningKind::ReversedRange { min: 1, max: 0 }, 2)]
    );
    for quiet in [
        "CD{2,2}L", "CD{2,3}L", "CD{0,1}L", "CD{3}L", "CD{3,}L", "CD{0,}L", "D{0}CL", "D{0,0}CL",
    ] {
        assert_eq!(parse_warnings(quiet), [], "`{quiet}` must not warn");
    }
}

#[test]
fn a_negation_mixing_slots_warns_and_one_slot_does_not_in_the_osl_dialect() {
    // An event and a scattering label in one negation warn at the `[`.
    assert_eq!(parse_warnings("C[^RD]L"), [(WarningKind::MixedNegation, 1)]);
    assert_eq!(parse_warnings("C[^DR]L"), [(WarningKind::MixedNegation, 1)]);
    // One slot, a single label, or a plain (not negated) list mixing slots: no warning.
    for quiet in ["C[^RT]L", "C[^DG]L", "C[^R]L", "C[^D]L", "C[RD]L", "C[RT]L"] {
        assert_eq!(parse_warnings(quiet), [], "`{quiet}` must not warn");
    }
}
