//! The canonical printer: printing any (normalized) AST and parsing the text gives the
//! same AST back, and printing is idempotent on source text.

use proptest::prelude::*;

proptest! {
    #![proptest_config(lpe_tests::cases(2000))]

    #[test]
    fn print_then_parse_is_identity(l in lpe_testkit::strategy::lpe()) {
        let text = l.to_string();
        let back = lpe::renderman::parse(&text).map_err(|e| TestCaseError::fail(format!("{text}\n{e}")))?;
        prop_assert_eq!(back, l, "printed as {}", text);
    }

    /// Case and blanks are not significant outside labels, and `lpe:` is optional: a
    /// generated expression written with random case, random blanks between tokens and
    /// an optional `lpe:` parses to the generated AST, and its canonical text is stable.
    /// (Random text, below, almost never parses, so it cannot test this.)
    #[test]
    fn respelled_expressions_parse_to_the_same_ast_and_print_stably(
        l in lpe_testkit::strategy::lpe(),
        flips in prop::collection::vec(any::<bool>(), 64),
        blanks in prop::collection::vec(0u8..8, 64),
        lpe_prefix in any::<bool>(),
    ) {
        let text = respell(&l.to_string(), &flips, &blanks, lpe_prefix);
        let parsed = lpe::renderman::parse(&text).map_err(|e| TestCaseError::fail(format!("{text:?}\n{e}")))?;
        prop_assert_eq!(&parsed, &l, "respelled as {:?}", text);
        let once = parsed.to_string();
        let again = lpe::renderman::parse(&once).expect("canonical text re-parses").to_string();
        prop_assert_eq!(once, again);
    }

    #[test]
    fn parsing_arbitrary_text_never_panics_and_canonical_text_is_stable(
        s in "[CRTLODSU0-9.<>\\[\\]^()|*+?{},' a-z;:_]{0,40}"
    ) {
        if let Ok(l) = lpe::renderman::parse(&s) {
            let once = l.to_string();
            let again = lpe::renderman::parse(&once).expect("canonical text re-parses").to_string();
            prop_assert_eq!(once, again);
        }
    }
}

/// `text` with letters outside labels in random case and random blanks before tokens
/// that cannot run into the previous one (never before a digit, which could be a lobe
/// or a count, nor inside a prefix name), optionally behind `lpe:`.
fn respell(text: &str, flips: &[bool], blanks: &[u8], lpe_prefix: bool) -> String {
    let mut out = String::new();
    if lpe_prefix {
        out.push_str(if flips[0] { "LPE:" } else { "lpe:" });
    }
    let mut in_label = false;
    for (i, c) in text.chars().enumerate() {
        let flip = flips[i % flips.len()];
        let blank = blanks[i % blanks.len()];
        let starts_token = !c.is_ascii_digit() && !c.is_ascii_lowercase() && c != ';';
        if !in_label && starts_token && blank < 3 {
            out.push([' ', '\t', '\n'][usize::from(blank)]);
        }
        if c == '\'' {
            in_label = !in_label;
        }
        if !in_label && flip {
            out.push(if c.is_ascii_uppercase() {
                c.to_ascii_lowercase()
            } else {
                c.to_ascii_uppercase()
            });
        } else {
            out.push(c);
        }
    }
    out
}
