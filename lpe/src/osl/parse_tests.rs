//! The parser, rule by rule and error by error; expected trees written by hand from the
//! OSL facts (docs/language.md, OSL chapter).

use super::ast::{Expr, Lpe, SymbolPattern as P, VertexPattern, WarningKind};
use super::error::ErrorKind as K;
use super::symbol::{Registered, Symbol};
use super::{parse, parse_source, parse_with};
use crate::automata::ir::Repetition;
use crate::limits::Limits;

fn none() -> Registered {
    Registered::none()
}

fn uy() -> Registered {
    "events=U;scatters=Y".parse().unwrap()
}

fn lbl(s: &str) -> Symbol {
    Symbol::label(s)
}

fn one(s: &str) -> P {
    P::One(lbl(s))
}

/// A vertex pattern with the eater of `reg`.
fn v(reg: &Registered, slots: Vec<P>) -> Expr {
    Expr::Vertex(VertexPattern {
        symbols: slots,
        eater: Some(reg.basic_labels()),
    })
}

fn exact(slots: Vec<P>) -> Expr {
    Expr::Vertex(VertexPattern {
        symbols: slots,
        eater: None,
    })
}

fn ev(c: &str) -> Expr {
    v(&none(), vec![one(c), P::Any])
}

fn sc(c: &str) -> Expr {
    v(&none(), vec![P::Any, one(c)])
}

fn any() -> Expr {
    v(&none(), vec![P::Any, P::Any])
}

fn rep(e: Expr, min: u32, max: Option<u32>) -> Expr {
    Expr::Repeat(Box::new(e), Repetition { min, max })
}

fn p(src: &str) -> Expr {
    parse(src, &none())
        .unwrap_or_else(|e| panic!("{src}: {e}"))
        .expr
}

fn err(src: &str) -> (K, usize) {
    let e = parse(src, &none()).expect_err(src);
    (e.kind, e.pos)
}

#[test]
fn shorthand_expands_to_whole_vertices() {
    assert_eq!(p("C"), ev("C"));
    assert_eq!(p("D"), sc("D"));
    for c in ["L", "B", "V", "T", "R", "O"] {
        assert_eq!(p(c), ev(c), "{c}");
    }
    for c in ["G", "S", "s"] {
        assert_eq!(p(c), sc(c), "{c}");
    }
    assert_eq!(p("."), any());
    assert_eq!(p("'foo'"), v(&none(), vec![P::Any, P::Any, one("foo")]));
    assert_eq!(p("CDL"), Expr::Concat(vec![ev("C"), sc("D"), ev("L")]));
}

#[test]
fn registered_labels_join_the_eater_and_the_shorthand() {
    let r = uy();
    let e = parse("UY", &r).unwrap().expr;
    assert_eq!(
        e,
        Expr::Concat(vec![
            v(&r, vec![one("U"), P::Any]),
            v(&r, vec![P::Any, one("Y")])
        ])
    );
    // Unregistered, `U` is unknown.
    assert_eq!(err("U"), (K::UnrecognizedBasicLabel("U".into()), 0));
    // A quoted label is a custom label even when registered as an event.
    assert_eq!(
        parse("'U'", &r).unwrap().expr,
        v(&r, vec![P::Any, P::Any, one("U")])
    );
}

#[test]
fn groups_fill_slots_in_order() {
    assert_eq!(p("<RD>"), v(&none(), vec![one("R"), one("D")]));
    assert_eq!(p("<R>"), v(&none(), vec![one("R"), P::Any]));
    assert_eq!(p("<>"), v(&none(), vec![P::Any, P::Any]));
    // No slot check: `<DR>` is event D, scattering R.
    assert_eq!(p("<DR>"), v(&none(), vec![one("D"), one("R")]));
    // Every unquoted character is one symbol; `x` is NONE; `|` and space are labels.
    assert_eq!(
        p("<Cx1 |>"),
        v(
            &none(),
            vec![one("C"), P::One(Symbol::None), one("1"), one(" "), one("|")]
        )
    );
    assert_eq!(
        p("<L.'|lightA|lightA-LIGHT'>"),
        v(&none(), vec![one("L"), P::Any, one("|lightA|lightA-LIGHT")])
    );
    assert_eq!(
        p("<R[GS][^'a'D]>"),
        v(
            &none(),
            vec![
                one("R"),
                P::Set(vec![lbl("G"), lbl("S")]),
                P::NotIn(vec![lbl("a"), lbl("D")])
            ]
        )
    );
    assert_eq!(p("<[]D>"), v(&none(), vec![P::Set(vec![]), one("D")]));
}

/// A `[…]` inside `<…>` reads its items as OSL's or-list does (each one slot item: `x`
/// NONE, `.` any symbol, `( … )` a sequence, `[ … ]` nested, `*` a label at an item's
/// start and an error after one). Trees worked from OSL's `parseOrlist`/`parseSymbol`
/// and confirmed on OSL's matcher built from its sources. Planted faults caught: the
/// old reading back (every character of the set a label) fails the first assertion;
/// dropping the repetition check after an item fails the `<[R*]D>` one.
#[test]
fn sets_inside_a_group_read_their_items_as_slots() {
    let none_sym = P::Set(vec![Symbol::None]);
    assert_eq!(p("<[x].>"), v(&none(), vec![none_sym.clone(), P::Any]));
    assert_eq!(p("<.[x]>"), v(&none(), vec![P::Any, none_sym.clone()]));
    assert_eq!(p("<..[x]>"), v(&none(), vec![P::Any, P::Any, none_sym]));
    assert_eq!(p("<[.].>"), v(&none(), vec![P::Any, P::Any]));
    assert_eq!(p("<..[.R]>"), v(&none(), vec![P::Any, P::Any, P::Any]));
    assert_eq!(
        p("<[xR'x'].>"),
        v(
            &none(),
            vec![P::Set(vec![Symbol::None, lbl("R"), lbl("x")]), P::Any]
        )
    );
    // A nested list joins in; a blacklist less the listed labels.
    assert_eq!(
        p("<[[RT]]D>"),
        v(&none(), vec![P::Set(vec![lbl("R"), lbl("T")]), one("D")])
    );
    assert_eq!(
        p("<[[^RT]R]D>"),
        v(&none(), vec![P::NotIn(vec![lbl("T")]), one("D")])
    );
    // `( … )` in a list is a sequence of symbols: one vertex pattern per way.
    assert_eq!(
        p("<[(RD)S]>"),
        Expr::Alt(vec![
            v(&none(), vec![P::Set(vec![lbl("S")]), P::Any]),
            v(&none(), vec![one("R"), one("D"), P::Any]),
        ])
    );
    // `*`, `+`, `{` starting an item are labels; after one they are a repetition.
    assert_eq!(p("<*D>"), v(&none(), vec![one("*"), one("D")]));
    assert_eq!(p("<+>"), v(&none(), vec![one("+"), P::Any]));
    assert_eq!(
        p("<[*]D>"),
        v(&none(), vec![P::Set(vec![lbl("*")]), one("D")])
    );
    assert_eq!(
        p("<(R|{)D>"),
        Expr::Alt(vec![
            v(&none(), vec![one("R"), one("D")]),
            v(&none(), vec![one("{"), one("D")]),
        ])
    );
    for (src, kind, pos) in [
        ("<[R*]D>", K::RepetitionInGroup, 3),
        ("<[(R)+]D>", K::RepetitionInGroup, 5),
        ("<[*]+>", K::RepetitionInGroup, 4),
        ("<R[x]{2}>", K::RepetitionInGroup, 5),
        ("<[<R>]D>", K::NestedGroup, 2),
        ("<[x", K::UnclosedOrList, 3),
        ("<[^x]D>", K::UnrecognizedLabel, 3),
    ] {
        let e = parse(src, &none()).expect_err(src);
        assert_eq!((&e.kind, e.pos), (&kind, pos), "{src}");
    }
    // Printing quotes what a list would read otherwise, and reads back.
    for src in ["<['x''.''*'(RD)].>", "<[x.]>", "<[[^RT]G]D>"] {
        let e = p(src);
        assert_eq!(p(&e.to_string()), e, "{src} printed {e}");
    }
}

#[test]
fn parentheses_inside_a_group_put_a_sequence_in_one_slot() {
    // `<(RD)>`: R, D in the event item, then the missing scattering slot.
    assert_eq!(p("<(RD)>"), v(&none(), vec![one("R"), one("D"), P::Any]));
    // A group is a sub-expression: `|` alternates, one vertex pattern each way.
    assert_eq!(
        p("<(R|T)D>"),
        Expr::Alt(vec![
            v(&none(), vec![one("R"), one("D")]),
            v(&none(), vec![one("T"), one("D")])
        ])
    );
    // `|` takes one item on each side there too, as OSL's sequence parser reads it
    // (confirmed on OSL's matcher: `<(RD|T)S>` matches `R,T,S`, not `T,S`). Planted
    // fault caught: `|` alternating whole sequences (the earlier reading) fails this.
    assert_eq!(
        p("<(RD|T)S>"),
        Expr::Alt(vec![
            v(&none(), vec![one("R"), one("D"), one("S")]),
            v(&none(), vec![one("R"), one("T"), one("S")])
        ])
    );
    assert_eq!(
        p("<(R(D|G)S|T)>"),
        Expr::Alt(vec![
            v(&none(), vec![one("R"), one("D"), one("S"), P::Any]),
            v(&none(), vec![one("R"), one("D"), one("T"), P::Any]),
            v(&none(), vec![one("R"), one("G"), one("S"), P::Any]),
            v(&none(), vec![one("R"), one("G"), one("T"), P::Any]),
        ])
    );
    assert_eq!(
        p("<((R|T)D)>"),
        Expr::Alt(vec![
            v(&none(), vec![one("R"), one("D"), P::Any]),
            v(&none(), vec![one("T"), one("D"), P::Any])
        ])
    );
    // Empty alternatives are errors, as in OSL; so is a product past the bound.
    assert_eq!(err("<(|R)D>"), (K::EmptyAlternative, 2));
    assert_eq!(err("<(R|)D>"), (K::EmptyAlternative, 4));
    assert_eq!(err("<(R||T)D>"), (K::EmptyAlternative, 4));
    let wide = "<(1|2|3|4)(1|2|3|4)(1|2|3|4)(1|2|3|4)(1|2)>";
    assert_eq!(wide.matches('(').count(), 5);
    assert_eq!(err(wide), (K::TooManyAlternatives { max: 256 }, 0));
    // Inside a `( … )`, at the item that takes the count past the bound.
    let inner = "<R((1|2|3|4)(1|2|3|4)(1|2|3|4)(1|2|3|4)(1|2))>";
    let at = inner.rfind("(1|2)").unwrap();
    assert_eq!(err(inner), (K::TooManyAlternatives { max: 256 }, at));
    assert!(parse("<(1|2|3|4)(1|2|3|4)(1|2|3|4)(1|2|3|4)>", &none()).is_ok());
}

#[test]
fn the_eater_goes_with_fewer_than_five_custom_items() {
    assert_eq!(
        p("<RD1234>"),
        v(
            &none(),
            vec![one("R"), one("D"), one("1"), one("2"), one("3"), one("4")]
        )
    );
    assert_eq!(
        p("<RD12345>"),
        exact(vec![
            one("R"),
            one("D"),
            one("1"),
            one("2"),
            one("3"),
            one("4"),
            one("5")
        ])
    );
    // A parenthesized item counts once.
    match p("<RD(12)(34)56'a'>") {
        Expr::Vertex(vp) => assert!(vp.eater.is_none()),
        e => panic!("{e:?}"),
    }
    match p("<RD(12)(34)5>") {
        Expr::Vertex(vp) => {
            assert!(vp.eater.is_some());
            assert_eq!(vp.symbols.len(), 7);
        }
        e => panic!("{e:?}"),
    }
}

#[test]
fn negation_takes_the_slot_of_its_last_label() {
    assert_eq!(
        p("[^D]"),
        v(&none(), vec![P::Any, P::NotIn(vec![lbl("D")])])
    );
    assert_eq!(
        p("[^LO]"),
        v(&none(), vec![P::NotIn(vec![lbl("L"), lbl("O")]), P::Any])
    );
    assert_eq!(
        p("[^'foo']"),
        v(&none(), vec![P::Any, P::Any, P::NotIn(vec![lbl("foo")])])
    );
    // Mixed kinds: accepted with a warning; R lands on the scattering slot.
    let l = parse("C[^RD]", &none()).unwrap();
    assert_eq!(
        l.expr,
        Expr::Concat(vec![
            ev("C"),
            v(&none(), vec![P::Any, P::NotIn(vec![lbl("R"), lbl("D")])])
        ])
    );
    assert_eq!(l.warnings.len(), 1);
    assert_eq!(l.warnings[0].kind, WarningKind::MixedNegation);
    assert_eq!(l.warnings[0].pos, 1);
    assert!(l.warnings[0]
        .to_string()
        .contains("mixing labels of different type"));
    assert!(parse("[^RT]", &none()).unwrap().warnings.is_empty());
}

#[test]
fn or_lists_alternate_whole_items() {
    assert_eq!(p("[RD]"), Expr::Alt(vec![ev("R"), sc("D")]));
    assert_eq!(p("[(RD)]"), Expr::Concat(vec![ev("R"), sc("D")]));
    assert_eq!(p("[C*]"), rep(ev("C"), 0, None));
    assert_eq!(p("[]"), Expr::Nothing);
    // Nested alternations flatten: one tree per language.
    assert_eq!(p("[[CL]R]"), Expr::Alt(vec![ev("C"), ev("L"), ev("R")]));
    assert_eq!(p("C|(L|R)"), Expr::Alt(vec![ev("C"), ev("L"), ev("R")]));
    assert_eq!(p("(C|L)|R"), Expr::Alt(vec![ev("C"), ev("L"), ev("R")]));
    assert_eq!(
        p("C[]L"),
        Expr::Concat(vec![ev("C"), Expr::Nothing, ev("L")])
    );
}

#[test]
fn alternation_binds_tighter_than_concatenation() {
    assert_eq!(
        p("CD|GL"),
        Expr::Concat(vec![ev("C"), Expr::Alt(vec![sc("D"), sc("G")]), ev("L")])
    );
    assert_eq!(
        p("CD*|GL"),
        Expr::Concat(vec![
            ev("C"),
            Expr::Alt(vec![rep(sc("D"), 0, None), sc("G")]),
            ev("L")
        ])
    );
    assert_eq!(
        p("CD|G|SL"),
        Expr::Concat(vec![
            ev("C"),
            Expr::Alt(vec![sc("D"), sc("G"), sc("S")]),
            ev("L")
        ])
    );
    assert_eq!(
        p("C(DL)|(GL)"),
        Expr::Concat(vec![
            ev("C"),
            Expr::Alt(vec![
                Expr::Concat(vec![sc("D"), ev("L")]),
                Expr::Concat(vec![sc("G"), ev("L")])
            ])
        ])
    );
}

#[test]
fn repetitions() {
    assert_eq!(p("D*"), rep(sc("D"), 0, None));
    assert_eq!(p("D+"), rep(sc("D"), 1, None));
    assert_eq!(p("D{2}"), rep(sc("D"), 2, Some(2)));
    assert_eq!(p("D{2,}"), rep(sc("D"), 2, None));
    assert_eq!(p("D{2,3}"), rep(sc("D"), 2, Some(3)));
    assert_eq!(p("D{0,1}"), rep(sc("D"), 0, Some(1)));
    // `{m,n}` with m > n is `{m}`, with a warning at the `{`.
    let l = parse("CD{3,1}", &none()).unwrap();
    assert_eq!(
        l.expr,
        Expr::Concat(vec![ev("C"), rep(sc("D"), 3, Some(3))])
    );
    assert_eq!(
        l.warnings[0].kind,
        WarningKind::ReversedRange { min: 3, max: 1 }
    );
    assert_eq!(l.warnings[0].pos, 2);
    // Behind the `lpe:` mark, the warning points into the whole source.
    let l = parse_source("lpe:CD{3,1}", &none()).unwrap();
    assert_eq!(l.warnings[0].pos, 6);
    // An equal pair is no reversed range: no warning.
    assert_eq!(p("D{2,2}"), rep(sc("D"), 2, Some(2)));
    assert!(parse("CD{2,2}", &none()).unwrap().warnings.is_empty());
    // One postfix per item: a second is read as a label.
    assert_eq!(err("C**"), (K::UnrecognizedBasicLabel("*".into()), 2));
    // No `?`.
    assert_eq!(err("CD?L"), (K::UnrecognizedBasicLabel("?".into()), 2));
}

#[test]
fn leading_zero_repeats_drop_out_and_others_are_errors() {
    assert_eq!(p("C{0}L"), ev("L"));
    assert_eq!(p("C{0,0}D{0}L"), ev("L"));
    assert_eq!(p("(C{0})L"), ev("L"));
    assert_eq!(
        p("C(D{0}G)L"),
        Expr::Concat(vec![ev("C"), sc("G"), ev("L")])
    );
    assert_eq!(err("CD{0}L"), (K::ZeroRepeat, 1));
    assert_eq!(err("CD{0}"), (K::ZeroRepeat, 1));
    assert_eq!(err("C{0}"), (K::ZeroRepeat, 0));
    assert_eq!(err("C{0}|DL"), (K::ZeroRepeat, 0));
    assert_eq!(err("CD|G{0}L"), (K::ZeroRepeat, 3));
    assert_eq!(err("(C{0})*L"), (K::ZeroRepeat, 6));
    assert_eq!(err("C[D{0}]L"), (K::ZeroRepeat, 2));
    // `{0,}` is `*`, `{0,1}` optional: not empty.
    assert_eq!(
        p("CD{0,}"),
        Expr::Concat(vec![ev("C"), rep(sc("D"), 0, None)])
    );
}

#[test]
fn a_leading_parenthesis_parses_the_whole_text() {
    // OSL stops at the first group's `)` and would read `CD`.
    assert_eq!(
        p("(CD)L"),
        Expr::Concat(vec![Expr::Concat(vec![ev("C"), sc("D")]), ev("L")])
    );
    assert_eq!(
        p("(CD){2}"),
        rep(Expr::Concat(vec![ev("C"), sc("D")]), 2, Some(2))
    );
    assert_eq!(
        err("(C)?!garbage"),
        (K::UnrecognizedBasicLabel("?".into()), 3)
    );
}

#[test]
fn error_messages() {
    let cases: &[(&str, K, usize, &str)] = &[
        (
            "E",
            K::UnrecognizedBasicLabel("E".into()),
            0,
            "Unrecognized basic label: E",
        ),
        (
            "C L",
            K::UnrecognizedBasicLabel(" ".into()),
            1,
            "Unrecognized basic label:  ",
        ),
        (
            "Cx",
            K::UnrecognizedBasicLabel(String::new()),
            1,
            "Unrecognized basic label: ",
        ),
        (
            "C|",
            K::UnrecognizedBasicLabel(String::new()),
            2,
            "Unrecognized basic label: ",
        ),
        (
            "C>",
            K::UnrecognizedBasicLabel(">".into()),
            1,
            "Unrecognized basic label: >",
        ),
        (
            "C]",
            K::UnrecognizedBasicLabel("]".into()),
            1,
            "Unrecognized basic label: ]",
        ),
        (
            "C)",
            K::UnrecognizedBasicLabel(")".into()),
            1,
            "Unrecognized basic label: )",
        ),
        (
            "C'ab",
            K::UnrecognizedBasicLabel(String::new()),
            4,
            "Unrecognized basic label: ",
        ),
        ("[^Q]", K::UnrecognizedLabel, 2, "Unrecognized basic label"),
        (
            "<R[^Q]>",
            K::UnrecognizedLabel,
            4,
            "Unrecognized basic label",
        ),
        (
            "<R[^x]>",
            K::UnrecognizedLabel,
            4,
            "Unrecognized basic label",
        ),
        (
            "<[^.]D>",
            K::UnrecognizedLabel,
            3,
            "Unrecognized basic label",
        ),
        (
            "|C",
            K::NoLeftExpression,
            0,
            "No left expression to or with |",
        ),
        (
            "C(|D)",
            K::NoLeftExpression,
            2,
            "No left expression to or with |",
        ),
        (
            "C(D",
            K::UnclosedParen,
            3,
            "Reached end of line looking for )",
        ),
        (
            "(C",
            K::UnclosedParen,
            2,
            "Reached end of line looking for )",
        ),
        (
            "C<(*|",
            K::UnclosedParen,
            5,
            "Reached end of line looking for )",
        ),
        (
            "C<RD",
            K::UnclosedGroup,
            4,
            "Reached end of line looking for > to end a group",
        ),
        (
            "C[RD",
            K::UnclosedOrList,
            4,
            "Reached end of line looking for ] to end an or list",
        ),
        (
            "C[^RD",
            K::UnclosedNegativeOrList,
            5,
            "Reached end of line looking for ] to end an negative or list'",
        ),
        ("C[^]", K::EmptyNegation, 3, "Empty or list [^] not allowed"),
        (
            "<R.'ab>",
            K::UnclosedLiteral,
            7,
            "Reached end of line looking for ' to end a literal",
        ),
        ("CD{", K::BadRange, 3, "Bad {} range definition"),
        ("CD{,2}", K::BadRange, 3, "Bad {} range definition"),
        ("CD{2", K::BadRange, 4, "Bad {} range definition"),
        ("CD{2,a}", K::BadRange, 5, "Bad {} range definition"),
        ("CD{ 2}", K::BadRange, 3, "Bad {} range definition"),
        (
            "C<R<D>>",
            K::NestedGroup,
            3,
            "No groups allowed inside of groups",
        ),
        (
            "C<RD*>",
            K::RepetitionInGroup,
            4,
            "Repetitions not allowed inside '<...>'",
        ),
        (
            "C<R+>",
            K::RepetitionInGroup,
            3,
            "Repetitions not allowed inside '<...>'",
        ),
        (
            "C<R{2}>",
            K::RepetitionInGroup,
            3,
            "Repetitions not allowed inside '<...>'",
        ),
    ];
    for (src, kind, pos, msg) in cases {
        let e = parse(src, &none()).expect_err(src);
        assert_eq!((&e.kind, e.pos), (kind, *pos), "{src}");
        assert_eq!(e.message(), *msg, "{src}");
        assert_eq!(e.to_string(), format!("{msg} at char {pos}"), "{src}");
    }
}

#[test]
fn where_osl_crashes_we_give_an_error() {
    assert_eq!(err(""), (K::Empty, 0));
    assert_eq!(err("()"), (K::EmptyGroup, 0));
    assert_eq!(err("C()L"), (K::EmptyGroup, 1));
    assert_eq!(err("<()D>"), (K::EmptyGroup, 1));
    assert_eq!(err("C'__stop__'"), (K::StopLabel, 1));
    assert_eq!(err("<R.'__stop__'>"), (K::StopLabel, 3));
    assert_eq!(err("C[^'__stop__']"), (K::StopLabel, 3));
}

#[test]
fn limits_bound_depth_counts_and_positions() {
    let deep = format!("{}C{}", "(".repeat(200), ")".repeat(200));
    assert_eq!(err(&deep), (K::TooDeep { max: 128 }, 128));
    let deep = format!("{}C{}", "[".repeat(200), "]".repeat(200));
    assert!(matches!(err(&deep).0, K::TooDeep { .. }));
    // Depth is nesting, not number: 200 sibling groups of every kind parse.
    for unit in ["(C)", "[C]", "<(R)D>", "<R(D|G)>", "[^R]"] {
        let src = unit.repeat(200);
        assert!(
            parse_with(&src, &none(), &Limits::default()).is_ok(),
            "{unit}"
        );
    }
    assert_eq!(err("CD{257}"), (K::RepeatTooLarge { max: 256 }, 3));
    assert_eq!(
        err("CD{1,99999999999}"),
        (K::RepeatTooLarge { max: 256 }, 5)
    );
    let limits = Limits {
        max_positions: 10,
        ..Limits::default()
    };
    let e = parse_with("C(D{5}){2}L", &none(), &limits).unwrap_err();
    assert_eq!(
        e.kind,
        K::TooManyPositions {
            positions: 12,
            max: 10
        }
    );
    // Exactly at the limit is accepted: 1 + 4 * 2 + 1 positions.
    assert!(parse_with("C(D{4}){2}L", &none(), &limits).is_ok());
    // Sibling groups inside one slot's alternatives do not add up to depth either.
    let siblings = format!("<({})D>", vec!["(R)"; 200].join("|"));
    assert!(parse_with(&siblings, &none(), &Limits::default()).is_ok());
    // A source with the `lpe:` mark reports positions in the whole source.
    assert_eq!(parse_source("lpe:C<RD", &none()).unwrap_err().pos, 8);
    assert_eq!(parse("C<RD", &none()).unwrap_err().pos, 4);
    // Every prefix of a tricky expression gives an answer, never a panic.
    let src = "C(R('a'+|G[^S]{2}[^OC]){2,}|(L|T*[sBO]{2,})+)<R.'é'>[^'x']";
    for (i, _) in src.char_indices() {
        let _ = parse(&src[..i], &none());
        let _ = parse(&src[i..], &uy());
    }
}

#[test]
fn printing_parses_back_to_the_same_tree() {
    for src in [
        "C<RD>[LO]",
        "C<RD>.+[LO]",
        "CD*|G(L|O)",
        "C(R('a'+|G[^S]{2}[^OC]){2,}|(L|T*[sBO]{2,})+)",
        "C<RD12345>[]L",
        "<Cx>'|a b|'[^'foo'D]",
        "C<(RD)>(DL){1,3}",
        "C.*L - (C.*DL & ^CGL)",
        "^(CL|O) - [LO]",
    ] {
        let a = parse(src, &none()).unwrap();
        let text = a.to_string();
        let b = parse(&text, &none()).unwrap_or_else(|e| panic!("{src} -> {text}: {e}"));
        assert_eq!((a.expr, a.algebra), (b.expr, b.algebra), "{src} -> {text}");
    }
}

#[test]
fn set_algebra_over_whole_expressions() {
    use crate::algebra::Algebra;
    let l = parse("C.*L - C.*DL & ^CL", &none()).unwrap();
    let leaf = |s: &str| Algebra::Leaf(p(s));
    assert_eq!(
        l.algebra,
        Some(Algebra::and(
            Algebra::minus(leaf("C.*L"), leaf("C.*DL")),
            Algebra::complement(leaf("CL"))
        ))
    );
    assert_eq!(l.expr, p("C.*L"));
    assert_eq!(l.operands().len(), 3);
    // Evaluated over the operands' answers, in operand order: in C.*L, not in C.*DL,
    // not in CL (a path such as `C R,D R,G L`).
    let answers = |a: [bool; 3]| {
        let mut it = a.into_iter();
        move |_: &Expr| it.next().unwrap()
    };
    assert!(l.eval(&mut answers([true, false, false])));
    assert!(!l.eval(&mut answers([true, true, false])));
    assert!(!l.eval(&mut answers([true, false, true])));
    // The same formula over operand numbers, one per expression.
    let f = Lpe::formulas([&l, &parse("CL", &none()).unwrap()]);
    assert_eq!(f.len(), 2);
    assert!(f[0].eval(&mut |&i| i == 0));
    assert!(!f[0].eval(&mut |&i| i <= 1));
    assert_eq!(f[1], Algebra::Leaf(3));
    // A count with equal bounds prints as one number.
    assert_eq!(
        parse("CD{3,3}L", &none()).unwrap().to_string(),
        "<C.><.D>{3}<L.>"
    );
    // A one-character label prints bare unless it means something inside `<>`.
    assert_eq!(
        parse("<R.'x'><R.'.'><R.'k'>", &none()).unwrap().to_string(),
        "<R.'x'><R.'.'><R.k>"
    );
    // An alternation operand prints in parentheses, the rest as the dialect prints.
    assert_eq!(
        parse("CL - [LO]", &none()).unwrap().to_string(),
        "<C.><L.> - (<L.>|<O.>)"
    );
    // Where OSL gives `-`, `^`, `&` a meaning they are not algebra: a label in `<>` or
    // quotes, a negation; and a plain expression has no tree.
    for src in ["C<R-D>L", "C'a-b'L", "C[^'x']L", "C<R&>L", "<R[^D]>"] {
        assert_eq!(parse(src, &none()).unwrap().algebra, None, "{src}");
    }
    assert_eq!(
        p("C<R-D>L"),
        Expr::Concat(vec![
            ev("C"),
            v(&none(), vec![one("R"), one("-"), one("D")]),
            ev("L")
        ])
    );
    // Outside them OSL knows no such character, so an old error became algebra.
    assert!(parse("C-L", &none()).unwrap().algebra.is_some());
    assert_eq!(err("C^L"), (K::UnrecognizedBasicLabel("^".into()), 1));
}

#[test]
fn set_algebra_errors_point_into_the_whole_text() {
    use crate::algebra::AlgebraError as A;
    assert_eq!(
        err("C.*L -"),
        (K::Algebra(A::MissingOperand { at: 6..6 }), 6)
    );
    assert_eq!(err("^"), (K::Algebra(A::MissingOperand { at: 0..1 }), 0));
    assert_eq!(
        err("C(.*L - .*DL)"),
        (K::Algebra(A::InsideOperand { at: 6..7 }), 6)
    );
    assert_eq!(err("(CL - DL"), (K::Algebra(A::Unbalanced { at: 0..1 }), 0));
    // An operand's own error, at its byte in the whole text.
    assert_eq!(err("C.*L - C<RD"), (K::UnclosedGroup, 11));
    assert_eq!(err("CL - C D"), (K::UnrecognizedBasicLabel(" ".into()), 6));
    assert_eq!(err("CL & C{0}"), (K::ZeroRepeat, 5));
    let e = parse("CL - C.*<RD", &none()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "Reached end of line looking for > to end a group at char 11"
    );
    let e = parse("CL -", &none()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "Set algebra operand missing (`&`, `-` take an expression on each side, `^` one \
         after it: `A - B`, `^A`) at char 4"
    );
    // Warnings of every operand, at their bytes in the whole text.
    let l = parse("CL - C[^RD]L & CD{3,1}L", &none()).unwrap();
    let at: Vec<usize> = l.warnings.iter().map(|w| w.pos).collect();
    assert_eq!(at, [6, 17]);
    // Positions count over every operand together.
    let limits = Limits {
        max_positions: 10,
        ..Limits::default()
    };
    let e = parse_with("CD{4}L - CD{4}L", &none(), &limits).unwrap_err();
    assert_eq!(
        e.kind,
        K::TooManyPositions {
            positions: 12,
            max: 10
        }
    );
    assert!(parse_with("CD{4}L - CDL", &none(), &limits).is_ok());
}
