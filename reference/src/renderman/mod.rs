//! The RenderMan dialect's reference: an independent front end and the backtracking
//! matcher that runs on its tree.
//!
//! - [`ast`]: the front end's own tree (no type of lpe's parser);
//! - [`parse`]: the parser, written from docs/language.md §3–§10 alone;
//! - [`macros`]: the built-in macros of §6.1 and [`Registration`], user macros and
//!   limits as plain data;
//! - [`print`]: the tree as text lpe's parser reads (the front-end comparison re-parses
//!   it);
//! - [`matcher`]: the executable semantics of §4–§5 on that tree.
//!
//! Only paths are lpe's (`lpe::renderman::Path`): the path parser is not what this front
//! end checks.

pub mod ast;
pub mod macros;
pub mod matcher;
pub mod parse;
pub mod print;

pub use ast::Lpe;
pub use macros::Registration;
pub use matcher::is_match;
pub use parse::parse;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::ErrorKind;

    fn reg_ini(macros: &[(&str, &str)]) -> Registration {
        Registration {
            macros: macros
                .iter()
                .map(|(n, s)| (n.to_string(), s.to_string()))
                .collect(),
            ..Registration::default()
        }
    }

    fn m(expr: &str, path: &str) -> bool {
        let lpe = parse(expr, &Registration::default()).unwrap_or_else(|e| panic!("{expr}: {e}"));
        is_match(&lpe, &path.parse().unwrap())
    }

    fn err(expr: &str) -> (ErrorKind, usize) {
        match parse(expr, &Registration::default()) {
            Ok(l) => panic!("{expr} parsed as {l}"),
            Err(e) => (e.kind, e.pos),
        }
    }

    fn printed(expr: &str) -> String {
        parse(expr, &Registration::default())
            .unwrap_or_else(|e| panic!("{expr}: {e}"))
            .to_string()
    }

    // Expected values are the examples of docs/language.md §3–§10, written by hand.
    #[test]
    fn atoms_match_as_section_4_says() {
        assert!(m("C.L", "C RD2'floor' L"));
        assert!(!m("C.L", "C RU1 L"), "`.` never matches a user lobe");
        assert!(m("CUL", "C RU1 L"));
        assert!(!m("C.*", "C L"), "`.` cannot match the emitter");
        assert!(!m("C'g'L", "C L'g'") && m("C<L.'g'>", "C L'g'"));
        assert!(m("C<[^R].>L", "C TS L") && !m("C<[^R].>L", "C RS L"));
        assert!(m("C<R[^D]>L", "C RS L") && !m("C<R[^D]>L", "C RU2 L"));
        assert!(
            m("C<.D[^'foo']>L", "C RD L"),
            "negated labels take unlabelled vertices"
        );
        assert!(!m("C<.D[^'foo']>L", "C RD'foo' L"));
        assert!(m("C[^R D]L", "C TS L") && !m("C[^R D]L", "C TD L"));
        assert!(!m("C<LD>", "C L"));
        assert!(m("c<rd>l", "C RD L"));
        assert!(m("C [S2 S3 S4] L", "C TS4 L"));
        assert!(m("C'a b'L", "C RD'a b' L") && m("C''L", "C RD'' L") && !m("C''L", "C RD L"));
    }

    #[test]
    fn combining_atoms_as_section_5_says() {
        assert!(m("CD|(SD)L", "C RD L") && m("CD|(SD)L", "C RS RD L"));
        assert!(!m("CD|(SD)L", "C RS L"));
        assert!(m("C.{0}L", "C L"));
        assert!(m("C(.?){3,5}L", "C L"));
        assert!(m("C(RD)+L", "C RS RD RS RD L") && !m("C(RD)+L", "C RS L"));
        assert!(!m("C<RD>", "C RD L"));
    }

    #[test]
    fn set_algebra_prefixes_and_macros() {
        assert!(m("C.*L - C.*DL", "C RS L") && !m("C.*L - C.*DL", "C RS RD L"));
        assert!(m("^C.*[<L.>O]", "C RU1 L") && !m("^C.*[<L.>O]", "C RD L"));
        assert!(
            m("^(C|D)L", "C RS L"),
            "`^(C|D)L` is the complement of `(C|D)L`"
        );
        assert_eq!(printed("lpe:indirectDiffuse_key"), "C<RD>.+[<L.'key'>O]");
        assert_eq!(printed("emission_key"), "CO");
        assert_eq!(printed("directDiffuse_key_fill"), "C<RD>[<L.'key_fill'>O]");
        assert_eq!(
            printed("noclamp;unoccluded;unoccluded;C.L"),
            "unoccluded;noclamp;C.L"
        );
        assert_eq!(
            printed("shadowcollector"),
            "shadows;C[<.D'collector'><.S'collector'>]<L.>"
        );
        let r = reg_ini(&[("myDiffuse", "unoccluded;C<RD>[<L.>O]"), ("emissive", "CL")]);
        assert_eq!(
            parse("mydiffuse_k", &r).unwrap().to_string(),
            "unoccluded;C<RD>[<L.'k'>O]"
        );
        assert_eq!(parse("emissive", &r).unwrap().to_string(), "CL");
    }

    #[test]
    fn errors_have_the_kinds_and_positions_of_section_9() {
        assert_eq!(err(""), (ErrorKind::Empty, 0));
        assert_eq!(err("unoccluded;").0, ErrorKind::Empty);
        assert_eq!(err("()").0, ErrorKind::Empty);
        assert_eq!(err("C<L'key'>"), (ErrorKind::TriplePosition, 3));
        assert_eq!(err("<D>"), (ErrorKind::TriplePosition, 1));
        assert_eq!(err("C.*L & C<L'key'>"), (ErrorKind::TriplePosition, 10));
        assert_eq!(err("C.**L").0, ErrorKind::Quantifier);
        assert_eq!(err("C.{3,2}L").0, ErrorKind::Quantifier);
        assert_eq!(err("CD5L"), (ErrorKind::Lobe, 1));
        assert_eq!(err("C D 2 L").0, ErrorKind::Syntax);
        assert_eq!(err("directDifuse").0, ErrorKind::UnknownMacro);
        assert_eq!(err("unocluded;C.*L"), (ErrorKind::UnknownPrefix, 0));
        assert_eq!(err("C.{257}L").0, ErrorKind::Limit);
        assert_eq!(err("C(.{256}){256}L").0, ErrorKind::Limit);
        assert_eq!(err("C.*L -").0, ErrorKind::Empty);
        assert_eq!(err("directDiffuse_").0, ErrorKind::Syntax);
        let looping = reg_ini(&[("a", "b"), ("b", "a")]);
        assert_eq!(parse("a", &looping).unwrap_err().kind, ErrorKind::Limit);
    }

    #[test]
    fn set_algebra_operators_stand_outside_regions_and_negation_where_an_operand_starts() {
        // `&` and `-` inside `<…>` or `[…]`, nested either way, are no operators: the
        // operand's own parser refuses the character where it stands.
        assert_eq!(err("C<[>&]D>L"), (ErrorKind::Syntax, 3));
        assert_eq!(err("C[<]&>]L"), (ErrorKind::Syntax, 3));
        assert_eq!(err("C[&]L"), (ErrorKind::Syntax, 2));
        // `^` after an operand's first character, spaces or not, is no negation.
        assert_eq!(err("C^L"), (ErrorKind::Syntax, 1));
        assert_eq!(err("C ^L"), (ErrorKind::Syntax, 2));
        // Where an operand starts, spaces between the `^`s and after them are allowed.
        let twice = parse("C.*L & ^ ^C<RD>L", &Registration::default()).unwrap();
        assert_eq!(twice.to_string(), "C.*L & (^(^C<RD>L))");
        assert!(is_match(&twice, &"C RD L".parse().unwrap()));
        assert!(!is_match(&twice, &"C RD RD L".parse().unwrap()));
        // A group holding an operator must be a whole operand.
        assert_eq!(err("(C.*L & C<RD>L) C"), (ErrorKind::Algebra, 6));
        assert_eq!(err("(C.*L - C<RD>L)^C"), (ErrorKind::Algebra, 6));
        // An operator inside a group that is only part of an operand.
        assert_eq!(err("C(D & S)L"), (ErrorKind::Algebra, 4));
        assert_eq!(err("C(D - S)L & C.*L"), (ErrorKind::Algebra, 4));
        // Whole groups, and what follows them.
        for src in [
            "(C.*L - C<RD>L) & C.*DL",
            "( C.*L - C<RD>L )&C.*DL",
            "((C.*L - C<RD>L)) & (C.*DL)",
        ] {
            let l = parse(src, &Registration::default()).unwrap();
            assert!(is_match(&l, &"C RD RD L".parse().unwrap()), "{src}");
            assert!(!is_match(&l, &"C RD L".parse().unwrap()), "{src}");
            assert!(!is_match(&l, &"C RS L".parse().unwrap()), "{src}");
        }
        // A whole group last, with spaces after it or not.
        for src in ["C.*DL & (C.*L - C<RD>L)", "C.*DL & (C.*L - C<RD>L)  "] {
            let l = parse(src, &Registration::default()).unwrap();
            assert!(is_match(&l, &"C RD RD L".parse().unwrap()), "{src}");
            assert!(!is_match(&l, &"C RD L".parse().unwrap()), "{src}");
        }
        // Algebra groups nest 128 deep too.
        let groups = |n: usize| format!("{}C.*L & C<RD>L{}", "(".repeat(n), ")".repeat(n));
        assert!(parse(&groups(128), &Registration::default()).is_ok());
        assert_eq!(err(&groups(129)), (ErrorKind::Limit, 129));
        // Algebra nests 128 deep (the negations of `^…^C.*L` each one level).
        let nots = |n: usize| format!("{}C.*L", "^".repeat(n));
        assert!(parse(&nots(128), &Registration::default()).is_ok());
        assert_eq!(err(&nots(129)), (ErrorKind::Limit, 129));
    }

    #[test]
    fn macro_chains_light_groups_prefixes_and_spaces() {
        // Errors in an operand point past its leading spaces.
        assert_eq!(err("  directDifuse"), (ErrorKind::UnknownMacro, 2));
        assert_eq!(err("C.*L &  directDifuse"), (ErrorKind::UnknownMacro, 8));
        assert_eq!(err("  diffuse_"), (ErrorKind::Syntax, 9));
        assert_eq!(err("C.*L &  diffuse_ "), (ErrorKind::Syntax, 15));
        assert_eq!(err("shadows;  directDifuse"), (ErrorKind::UnknownMacro, 10));
        assert_eq!(err("lpe:  directDifuse"), (ErrorKind::UnknownMacro, 6));
        assert_eq!(err("shadows;  diffuse_"), (ErrorKind::Syntax, 17));
        // Macros nest 16 deep; a failure deep inside points at the outermost name.
        let chain = |n: usize| {
            let mut r = Registration::default();
            for i in 1..n {
                r.macros.insert(format!("m{i}"), format!("m{}", i + 1));
            }
            r.macros.insert(format!("m{n}"), "C.*L".to_string());
            r
        };
        assert!(parse("m1", &chain(16)).is_ok());
        for (src, at) in [("m1", 0), ("  m1", 2)] {
            let e = parse(src, &chain(17)).unwrap_err();
            assert_eq!((e.kind, e.pos), (ErrorKind::Limit, at));
        }
        // A light group is written into exactly the `<L.>` triples.
        let lit = reg_ini(&[("lit", "(C<RD><L.>)|(C<TD><L.'fill'>)")]);
        let keyed = parse("lit_key", &lit).unwrap();
        let m = |p: &str| is_match(&keyed, &p.parse().unwrap());
        assert!(m("C RD L'key'"));
        assert!(m("C RD'x' L'key'"));
        assert!(!m("C RD L'fill'"));
        assert!(!m("C RD L"));
        assert!(m("C TD L'fill'"), "`<L.'fill'>` keeps its label");
        assert!(!m("C TD L'key'"));
        // Spaces between atoms, and around prefixes after `lpe:`.
        assert!(super::tests::m("C <RD> L", "C RD L"));
        for src in [
            "lpe: shadows; unoccluded; C<RD>L",
            " lpe:unoccluded;  shadows;C<RD>L",
        ] {
            let l = parse(src, &Registration::default()).unwrap();
            assert_eq!(l.to_string(), "unoccluded;shadows;C<RD>L", "{src}");
        }
    }

    #[test]
    fn the_position_limit_counts_atoms_after_unrolling() {
        // C, three `.`, L: 5 atom positions.
        let limited = |max_positions| Registration {
            limits: crate::error::Limits {
                max_positions,
                ..Default::default()
            },
            ..Registration::default()
        };
        assert!(parse("C.{3}L", &limited(5)).is_ok());
        let e = parse("C.{3}L", &limited(4)).unwrap_err();
        assert_eq!((e.kind, e.pos), (ErrorKind::Limit, 0));
    }

    #[test]
    fn errors_say_what_is_wrong_where() {
        let said = |src: &str| {
            let e = parse(src, &Registration::default()).unwrap_err();
            (e.kind, e.pos, e.message)
        };
        let syntax = |pos, m: &str| (ErrorKind::Syntax, pos, m.to_string());
        assert_eq!(said("C\"a\"L"), syntax(1, "labels take single quotes"));
        assert_eq!(said("C.*L & C;L"), syntax(8, "prefixes go first"));
        assert_eq!(said("C)L"), syntax(1, "unmatched `)`"));
        assert_eq!(said("C||L"), syntax(2, "`|` needs something on both sides"));
        assert_eq!(said("C5L"), syntax(1, "a stray number"));
        let misplaced = |pos, m: &str| (ErrorKind::TriplePosition, pos, m.to_string());
        assert_eq!(
            said("C<DR.>L"),
            misplaced(2, "an event in the type position")
        );
        assert_eq!(
            said("C<'a'..>L"),
            misplaced(2, "the label belongs in the third position")
        );
        assert_eq!(
            said("C<.'a'.>L"),
            misplaced(3, "the label belongs in the third position")
        );
        assert_eq!(
            said("C<RL.>L"),
            misplaced(3, "a type letter in the event position")
        );
        assert_eq!(
            said("C<..D>L"),
            misplaced(4, "a letter in the label position")
        );
        assert_eq!(
            said("C<...D>L"),
            misplaced(5, "a letter in the label position")
        );
        assert_eq!(
            said("C<....>L"),
            misplaced(5, "a letter in the label position")
        );
    }

    #[test]
    fn the_printer_groups_what_would_otherwise_read_differently() {
        let printed = |s: &str| parse(s, &Registration::default()).unwrap().to_string();
        assert_eq!(printed("C(D(SD))L"), "C(D(SD))L");
        // `|` binds tighter than concatenation: sequences inside an alternation keep
        // their parentheses, atoms and repetitions do not.
        assert_eq!(printed("C(D|SD|D*|[DS])L"), "C((D|S)(D|D*|[DS]))L");
        assert_eq!(printed("C((DS)|D)L"), "C((DS)|D)L");
    }

    #[test]
    fn nesting_is_bounded_without_overflowing_the_stack() {
        let deep = format!("C{}D{}L", "(".repeat(100_000), ")".repeat(100_000));
        // The 129th `(` (byte 129, after `C`) is one level too deep.
        assert_eq!(err(&deep), (ErrorKind::Limit, 129));
        let classes = format!("C{}", "<[".repeat(100_000));
        assert!(parse(&classes, &Registration::default()).is_err());
    }
}
