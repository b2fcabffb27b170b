//! What the bitset NFA reports about itself, on sets small enough to decide by hand: the
//! AOVs that match the empty sequence (reported for the start state and no other), the
//! emptiness warnings of a set whose NFA spans more than one 64-bit word, and the bytes
//! it holds.

use lpe::renderman::Path;
use lpe::{AovSet, Options};

fn set(srcs: &[(&str, &str)], dfa_budget: usize) -> AovSet<lpe::renderman::RenderMan> {
    lpe_tests::compile_with_dfa_budget(srcs, dfa_budget)
}

/// The same set stepped on its DFA and on its NFA (a DFA budget of 0).
fn both(srcs: &[(&str, &str)]) -> [AovSet<lpe::renderman::RenderMan>; 2] {
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
fn positions_always_active_together_are_kept_once() {
    // `C<RD>DL` and `C<RD>DO` begin alike: the start, one C, one <RD>, one D, then an L
    // and an O (each final position ends its own AOV): 6 positions, not 9.
    let alike = [("l", "C<RD>DL"), ("o", "C<RD>DO")];
    // `C<RD>DDL` and `C<RS>DDL`: the D positions read the same atom after different
    // lobes, so they are active after different paths and stay apart (the second pair
    // too, though their predecessors read alike): the start, C, <RD>, <RS>, four Ds,
    // two Ls: 10.
    let apart = [("rd", "C<RD>DDL"), ("rs", "C<RS>DDL")];
    // Two `C<RD>D*L`: the loops merge too, since each loops alike after a merged <RD>:
    // the start, C, <RD>, D, and the two Ls: 6.
    let loops = [("a", "C<RD>D*L"), ("b", "C<RD>D*L")];
    for (srcs, positions) in [(&alike, 6), (&apart, 10), (&loops, 6)] {
        let [dfa, nfa] = both(srcs);
        assert_eq!(nfa.nfa_positions(), positions, "{srcs:?}");
        for p in [
            "C RD1 TD2 L",
            "C RD1 TD2 O",
            "C RS1 TD2 L",
            "C RS1 TD2 RD3 L",
            "C RD1 L",
            "C RD1 TD2 RD3 L",
        ] {
            let want: Vec<usize> = (0..2)
                .filter(|&i| {
                    lpe_reference::is_match(&lpe::renderman::parse(srcs[i].1).unwrap(), &path(p))
                })
                .collect();
            for s in [&dfa, &nfa] {
                assert_eq!(
                    s.match_path(&path(p)).iter().collect::<Vec<_>>(),
                    want,
                    "{srcs:?} {p}"
                );
            }
        }
    }
}

#[test]
fn nfa_memory_is_tables_rows_classes_finals_and_ids() {
    // CDL: positions start, C, D, L (4, one word); classes camera, D scatter, light,
    // anything else (4). The NFA holds its per-byte follow tables (8 chunks * 256
    // entries of one word), one follow row per position (4 words), one accept row per
    // class (4 words), the finals (1 word): 2057 words = 16 456 bytes; and per position
    // its AOV and its atom (2 * 4 u32s = 32 bytes): 16 488. A set without a DFA steps
    // lazily, and its registry starts with two NFA states (dead and start), each a
    // one-word subset in a shared allocation (8 bytes and its two 8-byte counts) that the
    // list and the map key point to (16 bytes each), with a u32 id and a map control
    // byte: 2 * 61 = 122.
    // The DFA of the same set (see dfa_size.rs): 5 states of stride 4 u32s plus a
    // 32-byte mask each = 5 * 16 + 5 * 32 = 240 bytes. Both sets hold the same
    // alphabet tables, so the difference is 16 488 + 122 - 240.
    let [dfa, nfa] = both(&[("cdl", "CDL")]);
    assert_eq!((nfa.nfa_positions(), nfa.class_count()), (4, 4));
    assert_eq!(dfa.dfa_states(), Some(5));
    assert_eq!(nfa.memory_bytes() - dfa.memory_bytes(), 16_488 + 122 - 240);
}

/// Each NFA state the lazy DFA registers costs its subset's words and a fixed 53 bytes
/// (the two 8-byte counts of its shared allocation, the list's and the map key's
/// 16-byte pointers, the id and a map control byte, as above: 61 for one word). On
/// `C(<RD><RD>){150}L`, 303 positions (5 words), stepping registers states at
/// 8 * 5 + 53 = 93 bytes each, and nothing else grows.
#[test]
fn a_registered_state_costs_its_words_and_53_bytes() {
    let [_, set] = both(&[("wide", "C(<RD><RD>){150}L")]);
    assert_eq!(set.nfa_positions(), 303);
    let words = set.nfa_positions().div_ceil(64);
    assert_eq!(words, 5);
    let before = (set.memory_bytes(), set.lazy_states().unwrap());
    let path: Path = format!("C{} L", " RD".repeat(300)).parse().unwrap();
    assert!(set.match_path(&path).contains(0));
    let after = (set.memory_bytes(), set.lazy_states().unwrap());
    assert!(after.1 > before.1 + 300, "{after:?}");
    assert_eq!(after.0 - before.0, (after.1 - before.1) * (8 * words + 53));
}

/// A set's memory counts its vertex classes' tables, label text included: two sets
/// that differ only in the length of one label differ by exactly that length.
#[test]
fn set_memory_counts_the_label_text() {
    let long = "k".repeat(1000);
    let [short_set, _] = both(&[("a", "C<RD'k'>L")]);
    let [long_set, _] = both(&[("a", &format!("C<RD'{long}'>L"))]);
    assert_eq!(
        long_set.automaton().memory_bytes(),
        short_set.automaton().memory_bytes()
    );
    assert_eq!(long_set.memory_bytes() - short_set.memory_bytes(), 999);
}
