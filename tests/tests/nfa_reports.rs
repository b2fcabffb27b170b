//! What the bitset NFA reports about itself, on sets small enough to decide by hand: the
//! AOVs that match the empty sequence (reported for the start state and no other), the
//! emptiness warnings of a set whose NFA spans more than one 64-bit word, and the bytes
//! it holds.

use lpe::{AovSet, Options, Path};

fn set(srcs: &[(&str, &str)], dfa_budget: usize) -> AovSet {
    lpe_tests::compile_with_dfa_budget(srcs, dfa_budget)
}

/// The same set stepped on its DFA and on its NFA (a DFA budget of 0).
fn both(srcs: &[(&str, &str)]) -> [AovSet; 2] {
    let dfa = set(srcs, Options::default().dfa_budget);
    let nfa = set(srcs, 0);
    assert!(dfa.uses_dfa() && !nfa.uses_dfa());
    [dfa, nfa]
}

fn path(s: &str) -> Path {
    s.parse().unwrap()
}

#[test]
fn the_empty_sequence_matches_only_in_the_start_state() {
    // `D*` matches the empty sequence (and no path: paths start at the camera); `CDL`
    // is there so that the set has states other than the start and the dead state.
    for s in both(&[("empty", "D*"), ("cdl", "CDL")]) {
        assert_eq!(s.matches(s.start()).iter().collect::<Vec<_>>(), [0]);
        let after_c = s.step(s.start(), &path("C L").vertices()[0]);
        assert!(s.matches(after_c).is_empty());
        assert_eq!(
            s.match_path(&path("C RD1 L")).iter().collect::<Vec<_>>(),
            [1]
        );
        // A dead path reports nothing either.
        assert!(s.match_path(&path("C RS1 L")).is_empty());
    }
}

#[test]
fn emptiness_is_decided_on_sets_wider_than_one_word() {
    // 70 dots: 73 positions in the first AOV alone, so follow rows take two words and
    // the search must read the row of every position, not of the first ones.
    let dots = ".{70}";
    let long = format!("C{dots}L");
    let stuck = format!("C{dots}D");
    for s in both(&[("long", &long), ("stuck", &stuck)]) {
        let w: Vec<_> = s
            .warnings()
            .iter()
            .map(|w| (w.aov, w.name.as_str()))
            .collect();
        assert_eq!(w, [(1, "stuck")]);
        assert!(s.warnings()[0].message.contains("never reaches an emitter"));
    }
}

#[test]
fn nfa_memory_is_tables_rows_classes_finals_and_ids() {
    // CDL: positions start, C, D, L (4, one word); classes camera, D scatter, light,
    // anything else (4). The NFA holds its per-byte follow tables (8 chunks * 256
    // entries of one word), one follow row per position (4 words), one accept row per
    // class (4 words), the finals (1 word): 2057 words = 16 456 bytes; and per position
    // its AOV and its atom (2 * 4 u32s = 32 bytes): 16 488. A set without a DFA steps
    // lazily, and its registry starts with two NFA states (dead and start), each held
    // twice as a 32-byte subset, with a u32 id and a map control byte: 2 * 69 = 138.
    // The DFA of the same set (see dfa_size.rs): 5 states of stride 4 u32s plus a
    // 32-byte mask each = 5 * 16 + 5 * 32 = 240 bytes. Both sets hold the same
    // alphabet tables, so the difference is 16 488 + 138 - 240.
    let [dfa, nfa] = both(&[("cdl", "CDL")]);
    assert_eq!((nfa.nfa_positions(), nfa.class_count()), (4, 4));
    assert_eq!(dfa.dfa_states(), Some(5));
    assert_eq!(nfa.memory_bytes() - dfa.memory_bytes(), 16_488 + 138 - 240);
}
