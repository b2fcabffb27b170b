//! The RenderMan parser's errors in full: kind, the whole span (start and end, where the
//! conformance suite checks only the start), the message and the help, each worked out
//! by hand from the source text; plus the parser's accessors, the edit distance behind
//! its suggestions, and the operand limit as macros expand.

use lpe::algebra::MAX_OPERANDS;
use lpe::macros::MacroTable;
use lpe::syntax::edit_distance;
use lpe::{parse, ErrorKind, Limits, Parser};

/// One expected error: the source, its kind, its span, text the message must contain,
/// and the exact help (`None`: no help).
struct Case {
    src: &'static str,
    kind: ErrorKind,
    span: std::ops::Range<usize>,
    says: &'static str,
    help: Option<&'static str>,
}

const CASES: &[Case] = &[
    // The prefix and its `;`, spaces before the `;` included.
    Case {
        src: "holdout ;C.*L",
        kind: ErrorKind::UnknownPrefix,
        span: 0..9,
        says: "unknown prefix `holdout`",
        help: Some(
            "did you mean `holdouts`? prefixes are unoccluded, noclamp, nothruput, \
             shadows, holdouts, overwrite, noinfinitecheck",
        ),
    },
    // Every punctuation token named in a message, one case each.
    Case {
        src: "C<[R.]D>L",
        kind: ErrorKind::TriplePosition,
        span: 4..5,
        says: "`.` in a type class: the type position holds C R T L O",
        help: None,
    },
    Case {
        src: "C[[D]]L",
        kind: ErrorKind::Syntax,
        span: 2..3,
        says: "`[` inside `[...]`: a class holds events, labels, triples and `.`",
        help: None,
    },
    Case {
        src: "C[(D)]L",
        kind: ErrorKind::Syntax,
        span: 2..3,
        says: "`(` inside `[...]`",
        help: None,
    },
    Case {
        src: "C[D^]L",
        kind: ErrorKind::Syntax,
        span: 3..4,
        says: "unexpected `^`",
        help: None,
    },
    Case {
        src: "C]L",
        kind: ErrorKind::Syntax,
        span: 1..2,
        says: "unexpected `]`",
        help: None,
    },
    // From the `<` to the token that should have been `>`.
    Case {
        src: "C<RD'a'<>L",
        kind: ErrorKind::Syntax,
        span: 1..8,
        says: "expected `>` to close the triple, found `<`",
        help: None,
    },
    Case {
        src: "C>L",
        kind: ErrorKind::Syntax,
        span: 1..2,
        says: "unexpected `>`",
        help: None,
    },
    Case {
        src: "C[)]L",
        kind: ErrorKind::Syntax,
        span: 2..3,
        says: "unexpected `)`",
        help: None,
    },
    Case {
        src: "C[|]L",
        kind: ErrorKind::Syntax,
        span: 2..3,
        says: "unexpected `|`",
        help: None,
    },
    Case {
        src: "*CL",
        kind: ErrorKind::Quantifier,
        span: 0..1,
        says: "quantifier `*` has nothing to repeat",
        help: None,
    },
    Case {
        src: "+CL",
        kind: ErrorKind::Quantifier,
        span: 0..1,
        says: "quantifier `+` has nothing to repeat",
        help: None,
    },
    Case {
        src: "?CL",
        kind: ErrorKind::Quantifier,
        span: 0..1,
        says: "quantifier `?` has nothing to repeat",
        help: None,
    },
    Case {
        src: "{2}CL",
        kind: ErrorKind::Quantifier,
        span: 0..1,
        says: "quantifier `{` has nothing to repeat",
        help: None,
    },
    Case {
        src: "C}L",
        kind: ErrorKind::Syntax,
        span: 1..2,
        says: "unexpected `}`",
        help: None,
    },
    Case {
        src: "C,L",
        kind: ErrorKind::Syntax,
        span: 1..2,
        says: "unexpected `,`",
        help: None,
    },
];

#[test]
fn every_error_has_its_kind_span_message_and_help() {
    for c in CASES {
        let e = parse(c.src).expect_err(c.src);
        let shown = format!("{}: {e}", c.src);
        assert_eq!(e.kind(), c.kind, "{shown}");
        assert_eq!(e.span(), c.span, "{shown}");
        assert!(e.message().contains(c.says), "{shown}");
        assert_eq!(e.help(), c.help, "{shown}");
        assert_eq!(e.source_text(), c.src);
    }
}

#[test]
fn a_parser_reports_the_limits_and_macros_it_was_given() {
    let limits = Limits {
        max_repeat: 3,
        max_positions: 10,
        max_depth: 2,
        max_macro_depth: 1,
    };
    let mut macros = MacroTable::empty();
    macros.define("key", "C<RD><L.'key'>");
    let p = Parser::new(limits.clone(), macros);
    assert_eq!(p.limits(), &limits);
    assert_eq!(p.macros().names().collect::<Vec<_>>(), ["key"]);
    assert_eq!(p.macros().get("key"), Some("C<RD><L.'key'>"));
}

#[test]
fn edit_distances_worked_out_by_hand() {
    for (a, b, d) in [
        ("", "", 0),
        ("", "abc", 3),
        ("abc", "", 3),
        ("a", "b", 1),
        ("ab", "ba", 2),
        ("abc", "abcd", 1),
        ("abcd", "abc", 1),
        ("xabc", "abc", 1),
        ("flaw", "lawn", 2),
        ("kitten", "sitting", 3),
        ("intention", "execution", 5),
        ("holdout", "HOLDOUTS", 1),
    ] {
        assert_eq!(edit_distance(a, b), d, "{a} / {b}");
        assert_eq!(edit_distance(b, a), d, "{b} / {a}");
    }
}

#[test]
fn macros_count_every_operand_they_bring_against_the_limit() {
    // `two` brings 2 operands: half the limit's worth of it is exactly the limit, one
    // more operand is over it.
    let mut macros = MacroTable::empty();
    macros.define("two", "C<RD>L - C<RS>L");
    let p = Parser::new(Limits::default(), macros);
    let at_limit = vec!["two"; MAX_OPERANDS / 2].join(" - ");
    assert_eq!(p.parse(&at_limit).unwrap().operands().len(), MAX_OPERANDS);
    let over = format!("{at_limit} - C.L");
    let e = p.parse(&over).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Limit, "{e}");
    // The operand that passes the limit.
    assert_eq!(e.span(), over.len() - 3..over.len(), "{e}");
    assert!(
        e.message()
            .contains("more than 256 set-algebra operands once macros are expanded"),
        "{e}"
    );
}

#[test]
fn an_identifier_that_is_no_expression_is_an_unknown_macro() {
    // `_` can start a macro name but no expression: the whole body is reported as an
    // unknown macro, with the nearest names (`key` at distance 4, `keyLight` at 8).
    let mut macros = MacroTable::empty();
    macros.define("keyLight", "C<RD><L.'keyLight'>");
    macros.define("key", "C<RD><L.'key'>");
    let p = Parser::new(Limits::default(), macros);
    let e = p.parse("_foo").unwrap_err();
    assert_eq!(e.kind(), ErrorKind::UnknownMacro, "{e}");
    assert_eq!(e.span(), 0..4, "{e}");
    assert_eq!(
        e.message(),
        "unknown macro `_foo` (and not a valid expression)"
    );
    assert_eq!(e.help(), Some("nearest macros: `key`, `keyLight`"));
}
