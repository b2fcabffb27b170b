//! The canonical printer: printing any (normalized) AST and parsing the text gives the
//! same AST back, and printing is idempotent on source text.

use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(
        std::env::var("PROPTEST_CASES").ok().and_then(|s| s.parse().ok()).unwrap_or(2000)
    ))]

    #[test]
    fn print_then_parse_is_identity(l in lpe::strategy::lpe()) {
        let text = l.to_string();
        let back = lpe::parse(&text).map_err(|e| TestCaseError::fail(format!("{text}\n{e}")))?;
        prop_assert_eq!(back, l, "printed as {}", text);
    }

    #[test]
    fn parsing_arbitrary_text_never_panics_and_canonical_text_is_stable(
        s in "[CRTLODSU0-9.<>\\[\\]^()|*+?{},' a-z;:_]{0,40}"
    ) {
        if let Ok(l) = lpe::parse(&s) {
            let once = l.to_string();
            let again = lpe::parse(&once).expect("canonical text re-parses").to_string();
            prop_assert_eq!(once, again);
        }
    }
}
