//! Parser tests: each construct against a hand-built AST, and every error case of
//! docs/language.md with its kind and position.

use super::*;
use crate::renderman::ast::{EventPattern, Expr, Repetition};
use crate::renderman::path::EventKind;

fn p(s: &str) -> Expr {
    parse(s).unwrap_or_else(|e| panic!("{s}: {e}")).expr
}

fn ty(t: VertexType) -> Expr {
    Expr::Atom(Atom::Item(Item::Type(t)))
}

fn ev(kind: EventKind, lobe: Option<u8>) -> Expr {
    Expr::Atom(Atom::Item(Item::Event(EventPattern { kind, lobe })))
}

fn dot() -> Expr {
    Expr::Atom(Atom::Item(Item::Any))
}

fn rep(e: Expr, min: u32, max: Option<u32>) -> Expr {
    Expr::Repeat(Box::new(e), Repetition { min, max })
}

use VertexType::{C, L, O, R};

#[test]
fn letters_lobes_and_case() {
    assert_eq!(
        p("CD2s8u12RL"),
        Expr::Concat(vec![
            ty(C),
            ev(EventKind::D, Some(2)),
            ev(EventKind::S, Some(8)),
            ev(EventKind::U, Some(12)),
            ty(R),
            ty(L),
        ])
    );
    assert_eq!(p("cdl"), p("CDL"));
    assert_eq!(p(" C  D\tL "), p("CDL"));
}

#[test]
fn alternation_binds_tighter_than_concatenation() {
    // `CD|(SD)L` is `C (D|(SD)) L`.
    assert_eq!(
        p("CD|(SD)L"),
        Expr::Concat(vec![
            ty(C),
            Expr::Alt(vec![
                ev(EventKind::D, None),
                Expr::Concat(vec![ev(EventKind::S, None), ev(EventKind::D, None)]),
            ]),
            ty(L),
        ])
    );
    // `a|b*` is `a|(b*)`; a chain is one node.
    assert_eq!(
        p("C D|S*|T L"),
        Expr::Concat(vec![
            ty(C),
            Expr::Alt(vec![
                ev(EventKind::D, None),
                rep(ev(EventKind::S, None), 0, None),
                ty(VertexType::T),
            ]),
            ty(L),
        ])
    );
}

#[test]
fn groups_anywhere_including_the_start() {
    assert_eq!(
        p("(C<RD>)[LO]"),
        Expr::Concat(vec![
            Expr::Concat(vec![
                ty(C),
                Expr::Atom(Atom::Item(Item::Triple(Triple {
                    ty: TypePos::One(R),
                    event: EventPos::One(EventPattern {
                        kind: EventKind::D,
                        lobe: None
                    }),
                    label: LabelPos::Any,
                }))),
            ]),
            Expr::Atom(Atom::Class {
                negated: false,
                items: vec![Item::Type(L), Item::Type(O)],
            }),
        ])
    );
    assert_eq!(p("((C))(L)"), Expr::Concat(vec![ty(C), ty(L)]));
}

#[test]
fn quantifiers() {
    let cases = [
        ("C.*L", 0, None),
        ("C.+L", 1, None),
        ("C.?L", 0, Some(1)),
        ("C.{3}L", 3, Some(3)),
        ("C.{2,}L", 2, None),
        ("C.{0,2}L", 0, Some(2)),
        ("C.{ 1 , 4 }L", 1, Some(4)),
        ("C.{0}L", 0, Some(0)),
    ];
    for (s, min, max) in cases {
        assert_eq!(
            p(s),
            Expr::Concat(vec![ty(C), rep(dot(), min, max), ty(L)]),
            "{s}"
        );
    }
}

#[test]
fn triples_in_all_their_forms() {
    let t = |s: &str| match p(&format!("C{s}")) {
        Expr::Concat(v) => match &v[1] {
            Expr::Atom(Atom::Item(Item::Triple(t))) => t.clone(),
            other => panic!("{s}: {other:?}"),
        },
        other => panic!("{s}: {other:?}"),
    };
    assert_eq!(t("<L>"), t("<L.>"));
    assert_eq!(t("<L.>"), t("<L..>"));
    assert_eq!(t("< L . 'key' >").label, LabelPos::One("key".into()));
    assert_eq!(
        t("<[RT][^DS]['a''b']>"),
        Triple {
            ty: TypePos::Class {
                negated: false,
                types: vec![R, VertexType::T]
            },
            event: EventPos::Class {
                negated: true,
                events: vec![
                    EventPattern {
                        kind: EventKind::D,
                        lobe: None
                    },
                    EventPattern {
                        kind: EventKind::S,
                        lobe: None
                    }
                ]
            },
            label: LabelPos::Class {
                negated: false,
                labels: vec!["a".into(), "b".into()]
            },
        }
    );
    assert_eq!(t("<.U3[^'x']>").ty, TypePos::Any);
}

#[test]
fn labels_keep_case_and_spaces() {
    assert_eq!(
        p("C'My Floor'L"),
        Expr::Concat(vec![
            ty(C),
            Expr::Atom(Atom::Item(Item::Label("My Floor".into()))),
            ty(L)
        ])
    );
}

#[test]
fn prefixes_and_lpe_colon() {
    let l = parse("lpe: unoccluded ; Shadows;C.*L").unwrap();
    assert!(l.prefixes.contains(Prefix::Unoccluded));
    assert!(l.prefixes.contains(Prefix::Shadows));
    assert!(!l.prefixes.contains(Prefix::Holdouts));
    assert_eq!(l.expr, p("C.*L"));
    // Every prefix is known.
    for pre in Prefix::ALL {
        let l = parse(&format!("{};CL", pre.name())).unwrap();
        assert!(l.prefixes.contains(pre));
    }
    // Labels may contain `;` without being taken for a prefix.
    assert_eq!(parse("C'a;b'L").unwrap().prefixes, Prefixes::NONE);
}

#[test]
fn macros_expand_with_light_groups() {
    assert_eq!(
        parse("lpe:directDiffuse").unwrap(),
        parse("C<RD>[<L.>O]").unwrap()
    );
    assert_eq!(
        parse("DIRECTDIFFUSE").unwrap(),
        parse("C<RD>[<L.>O]").unwrap()
    );
    assert_eq!(
        parse("indirectSpecular_key_light").unwrap(),
        parse("C<RS>.+[<L.'key_light'>O]").unwrap()
    );
    let sc = parse("shadowcollector").unwrap();
    assert!(sc.prefixes.contains(Prefix::Shadows));
    // The user's prefixes join the macro's.
    let sc = parse("unoccluded;shadowcollector").unwrap();
    assert!(sc.prefixes.contains(Prefix::Shadows) && sc.prefixes.contains(Prefix::Unoccluded));
    // Only `<L.>` gets the group: `O` and labelled lights stay.
    let mut t = MacroTable::builtin();
    t.define("mine", "C.*[<L.><L.'fixed'>O]");
    let parser = Parser::new(Limits::default(), t);
    assert_eq!(
        parser.parse("mine_g").unwrap(),
        parse("C.*[<L.'g'><L.'fixed'>O]").unwrap()
    );
    // An identifier-like body that is a valid expression stays one.
    assert_eq!(parse("CDL").unwrap().expr, p("C D L"));
}

#[test]
fn every_builtin_macro_parses() {
    for (name, source) in MacroTable::builtin().iter() {
        let a = parse(name).unwrap_or_else(|e| panic!("{name}: {e}"));
        let b = parse(source).unwrap();
        assert_eq!(a, b, "{name}");
    }
}

/// `(source, kind, span start, text the message or help must contain)`.
const ERRORS: &[(&str, ErrorKind, usize, &str)] = &[
    ("", ErrorKind::Empty, 0, "empty expression"),
    ("   ", ErrorKind::Empty, 3, "empty expression"),
    ("lpe:", ErrorKind::Empty, 4, "empty expression"),
    ("shadows;", ErrorKind::Empty, 8, "empty expression"),
    ("C[]L", ErrorKind::Empty, 1, "empty class"),
    ("C[^]L", ErrorKind::Empty, 1, "empty class"),
    ("C()L", ErrorKind::Empty, 1, "empty group"),
    ("C<>L", ErrorKind::Empty, 1, "empty triple"),
    ("C.{,2}L", ErrorKind::Quantifier, 2, "write `{0,2}`"),
    ("C.{}L", ErrorKind::Quantifier, 2, "empty repetition"),
    ("C.{3,2}L", ErrorKind::Quantifier, 2, "lower bound is above"),
    ("C.{2L", ErrorKind::Quantifier, 4, "expected a number"),
    ("C.**L", ErrorKind::Quantifier, 3, "one quantifier per atom"),
    ("C.*+L", ErrorKind::Quantifier, 3, "one quantifier per atom"),
    (
        "C.{2}?L",
        ErrorKind::Quantifier,
        5,
        "one quantifier per atom",
    ),
    ("*CL", ErrorKind::Quantifier, 0, "nothing to repeat"),
    ("C(*)L", ErrorKind::Quantifier, 2, "nothing to repeat"),
    (
        "C<R*>L",
        ErrorKind::Quantifier,
        3,
        "quantifier inside `<...>`",
    ),
    (
        "C<RD+>L",
        ErrorKind::Quantifier,
        4,
        "quantifier inside `<...>`",
    ),
    (
        "C<RD'x'{2}>L",
        ErrorKind::Quantifier,
        7,
        "quantifier inside `<...>`",
    ),
    (
        "C[D*]L",
        ErrorKind::Quantifier,
        3,
        "quantifier inside `[...]`",
    ),
    ("C<DR>L", ErrorKind::TriplePosition, 2, "write `<RD>`"),
    ("C<D>L", ErrorKind::TriplePosition, 2, "write `<.D>`"),
    (
        "C<L'key'>",
        ErrorKind::TriplePosition,
        3,
        "write `<L.'key'>`",
    ),
    ("C<R'a'>L", ErrorKind::TriplePosition, 3, "write `<R.'a'>`"),
    ("C<'a'>L", ErrorKind::TriplePosition, 2, "write `<..'a'>`"),
    ("C<RDR>L", ErrorKind::TriplePosition, 4, "type comes first"),
    ("C<R.D>L", ErrorKind::TriplePosition, 4, "label position"),
    ("C<R['a']>L", ErrorKind::TriplePosition, 4, "third position"),
    ("C<[RD]>L", ErrorKind::TriplePosition, 4, "type class"),
    ("C<R.[D]>L", ErrorKind::TriplePosition, 5, "label class"),
    ("C<RD", ErrorKind::Syntax, 1, "unclosed `<`"),
    ("C(DL", ErrorKind::Syntax, 1, "unclosed `(`"),
    ("CD)L", ErrorKind::Syntax, 2, "unmatched `)`"),
    ("C[DL", ErrorKind::Syntax, 4, "expected `]`"),
    ("C[(D)]L", ErrorKind::Syntax, 2, "inside `[...]`"),
    ("C[[D]]L", ErrorKind::Syntax, 2, "inside `[...]`"),
    ("C D| L|", ErrorKind::Syntax, 6, "both sides"),
    ("C||L", ErrorKind::Syntax, 1, "both sides"),
    ("|CL", ErrorKind::Syntax, 0, "both sides"),
    ("C'floorL", ErrorKind::Syntax, 1, "unterminated label"),
    ("C D 2 L", ErrorKind::Syntax, 4, "unexpected number"),
    ("C2L", ErrorKind::Syntax, 1, "unexpected number"),
    ("CX L", ErrorKind::Syntax, 1, "event letters are"),
    ("C.;L", ErrorKind::Syntax, 2, "prefixes go first"),
    ("C;L", ErrorKind::UnknownPrefix, 0, "unknown prefix `C`"),
    ("C\"a\"L", ErrorKind::Syntax, 1, "single quotes"),
    ("CD5L", ErrorKind::Lobe, 1, "D1 to D4"),
    ("CS9L", ErrorKind::Lobe, 1, "S1 to S8"),
    ("CU13L", ErrorKind::Lobe, 1, "U1 to U12"),
    ("CD0L", ErrorKind::Lobe, 1, "D1 to D4"),
    (
        "C<RS99999999999999999999999>L",
        ErrorKind::Lobe,
        3,
        "S1 to S8",
    ),
    (
        "directDifuse",
        ErrorKind::UnknownMacro,
        0,
        "`directDiffuse`",
    ),
    ("lpe:caustic", ErrorKind::UnknownMacro, 4, "`caustics`"),
    ("CDL_key", ErrorKind::UnknownMacro, 0, "nearest macros"),
    ("directDiffuse_", ErrorKind::Syntax, 0, "empty light group"),
    (
        "holdout;C.*L",
        ErrorKind::UnknownPrefix,
        0,
        "did you mean `holdouts`",
    ),
    (
        "lpe:unocluded;C.*L",
        ErrorKind::UnknownPrefix,
        4,
        "`unoccluded`",
    ),
    (";C.*L", ErrorKind::UnknownPrefix, 0, "empty prefix"),
    ("C.{257}L", ErrorKind::Limit, 3, "over the limit of 256"),
    (
        "C.{0,99999999999999999999}L",
        ErrorKind::Limit,
        5,
        "over the limit",
    ),
    (
        "C((.{256}){256}){2}L",
        ErrorKind::Limit,
        1,
        "over the limit of 65536",
    ),
];

#[test]
fn every_error_case_is_an_error_with_its_position() {
    for &(src, kind, start, needle) in ERRORS {
        let e = parse(src).expect_err(src);
        let text = e.to_string();
        assert_eq!(e.kind(), kind, "{src}: {text}");
        assert_eq!(e.span().start, start, "{src}: {text}");
        assert!(
            text.contains(needle),
            "{src}: expected `{needle}` in\n{text}"
        );
        // The caret line is there and points inside the source.
        assert!(
            text.lines().nth(2).is_some_and(|l| l.contains('^')),
            "{text}"
        );
    }
}

#[test]
fn nesting_and_size_limits_are_errors_not_crashes() {
    let deep = format!("C{}D{}L", "(".repeat(100_000), ")".repeat(100_000));
    assert_eq!(parse(&deep).unwrap_err().kind(), ErrorKind::Limit);
    let wide = format!("C{}L", "D".repeat(70_000));
    assert_eq!(parse(&wide).unwrap_err().kind(), ErrorKind::Limit);
    let classes = format!("C{}L", "[".repeat(1000));
    assert_eq!(parse(&classes).unwrap_err().kind(), ErrorKind::Syntax);
    // Limits are configurable.
    let strict = Parser::new(
        Limits {
            max_repeat: 4,
            ..Limits::default()
        },
        MacroTable::builtin(),
    );
    assert_eq!(strict.parse("C.{5}L").unwrap_err().kind(), ErrorKind::Limit);
    assert!(strict.parse("C.{4}L").is_ok());
}

#[test]
fn recursive_user_macros_are_a_limit_error() {
    let mut t = MacroTable::builtin();
    t.define("a", "b");
    t.define("b", "a");
    let parser = Parser::new(Limits::default(), t);
    let e = parser.parse("a").unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Limit, "{e}");
}

#[test]
fn printing_is_canonical_and_reparses() {
    let cases = [
        ("lpe:C<RD>.+[<L.>O]", "C<RD>.+[<L.>O]"),
        ("c d|(s d) l", "CD|(SD)L"),
        ("C(D|S)*L", "C(D|S)*L"),
        ("C((DS))L", "C(DS)L"),
        ("C(D*)+L", "C(D*)+L"),
        ("C.{0,1}L", "C.?L"),
        ("C.{2,2}L", "C.{2}L"),
        ("C.{1,}L", "C.+L"),
        ("C<L>", "C<L.>"),
        ("C<R[DS]['a' 'b c']>L", "C<R[DS]['a''b c']>L"),
        ("shadows;unoccluded;CL", "unoccluded;shadows;CL"),
        ("C(D|(S|T))L", "CD|(S|T)L"),
        ("(CD)L", "(CD)L"),
    ];
    for (src, want) in cases {
        let l = parse(src).unwrap();
        assert_eq!(l.to_string(), want, "{src}");
        assert_eq!(parse(want).unwrap(), l, "{src}");
    }
}

#[test]
fn set_algebra_over_whole_bodies() {
    let l = parse("lpe:shadows;C.*L - (directDiffuse - C<RS>L) & ^C<RD>.*L").unwrap();
    assert!(l.prefixes.contains(Prefix::Shadows));
    let t = l.algebra.as_ref().expect("algebra");
    assert_eq!(l.operands().len(), 4);
    assert_eq!(l.expr, p("C.*L"), "expr holds the first operand");
    // Left-associative: ((A - (B - C)) & ^D).
    assert!(matches!(t, crate::algebra::Algebra::And(a, d)
        if matches!(**a, crate::algebra::Algebra::Minus(..))
        && matches!(**d, crate::algebra::Algebra::Not(_))));
    // The canonical text parses back to the same value.
    assert_eq!(parse(&l.to_string()).unwrap(), l);
    assert_eq!(
        l.to_string(),
        "shadows;C.*L - (C<RD>[<L.>O] - C<RS>L) & ^C<RD>.*L"
    );
}

#[test]
fn set_algebra_errors_point_into_the_whole_text() {
    let cases = [
        ("C.*L - ", ErrorKind::Empty, 6),
        ("C.*L - C<L'k'>", ErrorKind::TriplePosition, 10),
        ("C.*L & directDifuse", ErrorKind::UnknownMacro, 7),
        ("C(.* - D)L", ErrorKind::Syntax, 5),
        ("^", ErrorKind::Empty, 0),
        ("C.*L - C{3L", ErrorKind::Quantifier, 10),
    ];
    for (src, kind, at) in cases {
        let e = parse(src).unwrap_err();
        assert_eq!((e.kind(), e.span().start), (kind, at), "{src}: {e}");
        assert_eq!(e.source_text(), src);
    }
    let deep = format!("{}C.*L - CL{}", "(".repeat(200), ")".repeat(200));
    assert_eq!(parse(&deep).unwrap_err().kind(), ErrorKind::Limit);
    // `-` and `^` where the dialect gives them a meaning are not algebra.
    assert!(parse("C[^D]'a-b'L").unwrap().algebra.is_none());
}
