//! The RenderMan parser's errors in full: kind, the whole span (start and end, where the
//! conformance suite checks only the start), the message and the help, each worked out
//! by hand from the source text; plus the parser's accessors, the edit distance behind
//! its suggestions, and each limit exactly at its bound (set-algebra operands as macros
//! expand, nesting, positions, repetition counts).

use lpe::algebra::MAX_OPERANDS;
use lpe::renderman::macros::MacroTable;
use lpe::renderman::syntax::edit_distance;
use lpe::renderman::{parse, ErrorKind, Limits, Parser};

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
    // Characters that are no token: the span covers the whole character, and the help
    // fits the character.
    Case {
        src: "C#L",
        kind: ErrorKind::Syntax,
        span: 1..2,
        says: "unexpected character `#`",
        help: None,
    },
    Case {
        src: "CD€L",
        kind: ErrorKind::Syntax,
        span: 2..5,
        says: "unexpected character `€`",
        help: None,
    },
    Case {
        src: "C.;L",
        kind: ErrorKind::Syntax,
        span: 2..3,
        says: "unexpected character `;`",
        help: Some("prefixes go first, each followed by `;`: `shadows;C.*L`"),
    },
    Case {
        src: "C.xL",
        kind: ErrorKind::Syntax,
        span: 2..3,
        says: "unexpected character `x`",
        help: Some("event letters are C R T L O D S U; a macro name must be the whole expression"),
    },
    Case {
        src: "C._L",
        kind: ErrorKind::Syntax,
        span: 2..3,
        says: "unexpected character `_`",
        help: Some("event letters are C R T L O D S U; a macro name must be the whole expression"),
    },
    Case {
        src: "C\"a\"L",
        kind: ErrorKind::Syntax,
        span: 1..2,
        says: "unexpected character `\"`",
        help: Some("labels are quoted with single quotes: `'name'`"),
    },
    // Errors at the end of the body have an empty span there.
    Case {
        src: "C.{2",
        kind: ErrorKind::Quantifier,
        span: 4..4,
        says: "expected a number, `,` or `}` in `{n,m}`, found end of expression",
        help: None,
    },
    Case {
        src: "C[D",
        kind: ErrorKind::Syntax,
        span: 3..3,
        says: "expected `]`, found end of expression",
        help: None,
    },
    Case {
        src: "C(",
        kind: ErrorKind::Syntax,
        span: 2..2,
        says: "expected an event, found end of expression",
        help: None,
    },
    Case {
        src: "C(D",
        kind: ErrorKind::Syntax,
        span: 1..2,
        says: "unclosed `(`",
        help: None,
    },
    Case {
        src: "C)L",
        kind: ErrorKind::Syntax,
        span: 1..2,
        says: "unmatched `)`",
        help: None,
    },
    Case {
        src: ")CL",
        kind: ErrorKind::Syntax,
        span: 0..1,
        says: "unmatched `)`",
        help: None,
    },
    Case {
        src: "|CL",
        kind: ErrorKind::Syntax,
        span: 0..1,
        says: "`|` needs an alternative on both sides",
        help: None,
    },
    Case {
        src: "C[D*]L",
        kind: ErrorKind::Quantifier,
        span: 3..4,
        says: "quantifier inside `[...]`: put it after the `]`",
        help: None,
    },
    // Triples: what stands in the wrong position, and how to write it.
    Case {
        src: "C<R'a'>L",
        kind: ErrorKind::TriplePosition,
        span: 3..6,
        says: "the label belongs in the third position of `<type event label>`",
        help: Some("write `<R.'a'>`"),
    },
    Case {
        src: "C<DR>L",
        kind: ErrorKind::TriplePosition,
        span: 2..3,
        says: "`D` is an event, but the first position of `<type event label>` is the vertex type",
        help: Some("write `<RD>`"),
    },
    Case {
        src: "C<D>L",
        kind: ErrorKind::TriplePosition,
        span: 2..3,
        says: "`D` is an event",
        help: Some("write `<.D>` for any R/T vertex with a D event"),
    },
    Case {
        src: "C<'a'>L",
        kind: ErrorKind::TriplePosition,
        span: 2..5,
        says: "a label in the type position of `<type event label>`",
        help: Some("write `<..'a'>`"),
    },
    Case {
        src: "C<RDR>L",
        kind: ErrorKind::TriplePosition,
        span: 4..5,
        says: "`R` is a vertex type; in `<type event label>` the type comes first",
        help: None,
    },
    Case {
        src: "C<RDD>L",
        kind: ErrorKind::TriplePosition,
        span: 4..5,
        says: "`D` in the label position of `<type event label>`",
        help: None,
    },
    Case {
        src: "C<RD*>L",
        kind: ErrorKind::Quantifier,
        span: 4..5,
        says: "quantifier inside `<...>`: a triple is one vertex",
        help: Some("put the quantifier after the `>`"),
    },
    Case {
        src: "C<['a']>L",
        kind: ErrorKind::TriplePosition,
        span: 3..6,
        says: "label `'a'` in a type class: the type position holds C R T L O",
        help: Some("labels go in the third position: `<R.['a' 'b']>`"),
    },
    Case {
        src: "C<R[R]>L",
        kind: ErrorKind::TriplePosition,
        span: 4..5,
        says: "`R` in an event class: the event position holds D S U",
        help: None,
    },
    Case {
        src: "C<[]>L",
        kind: ErrorKind::Empty,
        span: 2..4,
        says: "empty type class `[]`",
        help: None,
    },
    Case {
        src: "C<[R",
        kind: ErrorKind::Syntax,
        span: 2..3,
        says: "unclosed `[`",
        help: None,
    },
    Case {
        src: "C<R",
        kind: ErrorKind::Syntax,
        span: 1..2,
        says: "unclosed `<`",
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

#[test]
fn limits_hold_exactly_at_their_bound() {
    let with = |limits: Limits| Parser::new(limits, MacroTable::builtin());
    // Nesting: groups and classes count while open, and only while open.
    let depth = |max_depth| {
        with(Limits {
            max_depth,
            ..Limits::default()
        })
    };
    assert!(depth(2).parse("C((D))[D]L").is_ok());
    assert!(depth(1).parse("C(D)(D)(D)[D][D][D]L").is_ok());
    let e = depth(2).parse("C(((D)))L").unwrap_err();
    assert_eq!((e.kind(), e.span()), (ErrorKind::Limit, 3..4), "{e}");
    assert_eq!(e.message(), "nesting deeper than the limit of 2");
    let e = depth(1).parse("C([D])L").unwrap_err();
    assert_eq!((e.kind(), e.span()), (ErrorKind::Limit, 2..3), "{e}");
    // Positions: a repetition is checked as soon as it is read, the whole body at the
    // end.
    let positions = |max_positions| {
        with(Limits {
            max_positions,
            ..Limits::default()
        })
    };
    assert!(positions(4).parse("CD{2}L").is_ok());
    let e = positions(4).parse("CD{3}L").unwrap_err();
    assert_eq!((e.kind(), e.span()), (ErrorKind::Limit, 0..6), "{e}");
    assert_eq!(
        e.message(),
        "expression unrolls to 5 positions, over the limit of 4"
    );
    let e = positions(2).parse("CD{3}L").unwrap_err();
    assert_eq!((e.kind(), e.span()), (ErrorKind::Limit, 1..5), "{e}");
    assert!(positions(3).parse("CDL").is_ok());
    let e = positions(3).parse("CDDL").unwrap_err();
    assert_eq!((e.kind(), e.span()), (ErrorKind::Limit, 0..4), "{e}");
    // Repetition counts.
    let repeat = |max_repeat| {
        with(Limits {
            max_repeat,
            ..Limits::default()
        })
    };
    assert!(repeat(4).parse("C.{4}L").is_ok());
    let e = repeat(4).parse("C.{1,5}L").unwrap_err();
    assert_eq!((e.kind(), e.span()), (ErrorKind::Limit, 5..6), "{e}");
    assert_eq!(e.message(), "repetition count 5 is over the limit of 4");
}
