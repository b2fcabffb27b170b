//! What the DFA reports about its own size, on sets small enough to work out by hand:
//! the minimized state count, where the DFA budget cuts over to the NFA (to the byte),
//! the memory one more state costs, and the point where minimization gives up and
//! keeps the DFA unminimized. Every expected number is derived in the comments from the
//! layout documented on the DFA (dead state included, rows of `stride` = class count
//! rounded up to a power of two `u32`s, one 32-byte `AovMask` per state) and from its
//! budget accounting (`stride * 4 + 32 + 2 * words * 8 + 32` bytes per state built).

use lpe::{AovMask, AovSet, Options};

fn set(expr: &str, dfa_budget: usize) -> AovSet<lpe::renderman::RenderMan> {
    lpe_tests::compile_with_dfa_budget(&[("a", expr)], dfa_budget)
}

fn default_set(expr: &str) -> AovSet<lpe::renderman::RenderMan> {
    set(expr, Options::default().dfa_budget)
}

/// `atom{n}` written as repetitions the parser's 256 limit accepts.
fn repeat(atom: &str, n: usize) -> String {
    let mut s = String::new();
    for _ in 0..n / 100 {
        s.push_str(atom);
        s.push_str("{100}");
    }
    for _ in 0..n % 100 {
        s.push_str(atom);
    }
    s
}

/// `.{n}`.
fn dots(n: usize) -> String {
    repeat(".", n)
}

#[test]
fn minimized_state_counts() {
    // dead, before the camera, after C, after D, after L.
    assert_eq!(default_set("CDL").dfa_states(), Some(5));
    // The subset construction keeps "after D" and "after S" apart (two NFA
    // positions); both then need a light, so minimization merges them: 5, not 6.
    assert_eq!(default_set("C(D|S)L").dfa_states(), Some(5));
    // C.{70}L: dead, start, after C, after each of the 70 dots, after L.
    assert_eq!(
        default_set(&format!("C{}L", dots(70))).dfa_states(),
        Some(74)
    );
    // Matches nothing: the start state is the dead state.
    assert_eq!(default_set("C[^.]L").dfa_states(), Some(1));
}

#[test]
fn the_budget_cuts_over_to_the_nfa_to_the_byte() {
    // CDL: 4 classes (camera, D scatter, light, anything else) -> stride 4; 4 NFA
    // positions -> 1 word. A state costs 4*4 + 32 + 2*1*8 + 32 = 96 bytes, and the
    // construction builds 5 states: 480 bytes fit, 479 do not.
    let s = set("CDL", 480);
    assert_eq!(s.class_count(), 4);
    assert!(s.uses_dfa());
    assert_eq!(s.dfa_states(), Some(5));
    let s = set("CDL", 479);
    assert!(!s.uses_dfa());
    assert_eq!(s.dfa_states(), None);

    // C.{70}L: 73 positions -> 2 words; 4 classes -> stride 4. 4*4 + 32 + 2*2*8 + 32 =
    // 112 bytes a state, 74 states: 8288 bytes fit, 8287 do not.
    let e = format!("C{}L", dots(70));
    assert_eq!(set(&e, 8288).class_count(), 4);
    assert!(set(&e, 8288).uses_dfa());
    assert!(!set(&e, 8287).uses_dfa());

    // C[^.]L matches nothing: classes camera, light, other -> stride 4; 1 word; 96
    // bytes a state; the construction builds the dead and the start state only, so two
    // states' worth (192 bytes) is enough and 191 is not.
    let s = set("C[^.]L", 192);
    assert_eq!(s.class_count(), 3);
    assert!(s.uses_dfa());
    assert_eq!(s.dfa_states(), Some(1));
    assert!(!set("C[^.]L", 191).uses_dfa());
}

#[test]
fn one_more_state_costs_one_row_and_one_mask() {
    // Same atoms, so the same alphabet tables; the DFA has one more state (6 vs 5),
    // i.e. one more row of stride 4 `u32`s and one more mask.
    let a = default_set("C.L");
    let b = default_set("C..L");
    assert_eq!((a.dfa_states(), b.dfa_states()), (Some(5), Some(6)));
    assert_eq!(
        b.memory_bytes() - a.memory_bytes(),
        4 * 4 + std::mem::size_of::<AovMask>()
    );
    assert_eq!(std::mem::size_of::<AovMask>(), 32);
}

#[test]
fn minimization_gives_up_past_its_work_cap() {
    // C(D|S).{1900}L: the construction builds dead, start, after C, after D, after S,
    // one state per dot and after L: 1906 states, minimal 1905 (D and S merge). Moore's
    // algorithm needs about one round per dot to tell the chain apart, each round
    // costing states * (classes + 1) = 1906 * 6 units of work, so it would need about
    // 1906 * 6 * 1904 = 21.8 M units: over the 20 M cap, and the DFA is kept
    // unminimized. (Any miscount of the work that stays under the cap, e.g. 1906 * 5 a
    // round, = 18.1 M, would minimize it to 1905.)
    let s = default_set(&format!("C(D|S){}L", dots(1900)));
    assert_eq!(s.class_count(), 5);
    assert_eq!(s.dfa_states(), Some(1906));
    // 1800 dots: 1806 * 6 * 1804 = 19.5 M, under the cap, so it is minimized.
    let s = default_set(&format!("C(D|S){}L", dots(1800)));
    assert_eq!(s.dfa_states(), Some(1805));
}

#[test]
fn minimization_runs_when_its_work_lands_exactly_on_the_cap() {
    // (C a{k} L) | (C b{m} L) | (C c L) | (C d L), with a..d D-scatter vertices told
    // apart by label: 7 classes (camera, light, the four labels, anything else). The
    // alternatives start with different letters after C, so the construction builds
    // dead, start, after C, k a-states, m b-states, after c, after d and four after-L
    // states: k + m + 9. Moore's algorithm starts from "same AOV mask" and each round
    // tells apart the states a word one letter longer separates; the state after C a
    // needs a{k-1}L (k letters) to be told from the dead state, so it takes k rounds
    // that split and one that splits nothing: k + 1 rounds of (k + m + 9) * (7 + 1)
    // work. k = 1249, m = 742: 1250 * 2000 * 8 = 20 000 000, exactly the cap, which is
    // still allowed: minimized, the four after-L states and the four "L next" states
    // (after a{k}, after b{m}, after c, after d) merge: 2000 - 6 = 1994.
    let expr = |k: usize, m: usize| {
        format!(
            "(C{}L)|(C{}L)|(C<.D'c'>L)|(C<.D'd'>L)",
            repeat("<.D'a'>", k),
            repeat("<.D'b'>", m)
        )
    };
    let s = default_set(&expr(1249, 742));
    assert_eq!(s.class_count(), 7);
    assert_eq!(s.dfa_states(), Some(1994));
    // One more b: 1250 * 2001 * 8 = 20 008 000, over the cap: kept unminimized.
    assert_eq!(default_set(&expr(1249, 743)).dfa_states(), Some(2001));
}

/// A set wider than the NFA state (more than 256 positions) attempts the eager DFA only
/// within 2^20 row reads (per state built: classes x active positions x words), then
/// steps lazily; a narrower set has no such bound. `C(<RD><RD>){150}L` is 303 positions
/// (5 words) of 5 classes; beside `C.*<RD>.{11}L` its DFA (4 400 states) is built, beside
/// `.{12}` the reads run out before the DFA does (it fits the byte budget, and fails even
/// with a budget of 2^40). The same `.{12}` in a narrow set of 20 classes builds its
/// 8 225 states, over a million row reads.
#[test]
fn only_sets_wider_than_the_nfa_state_bound_the_dfa_attempt_by_row_reads() {
    let wide = "C(<RD><RD>){150}L";
    let eleven = default_set(&format!("{wide} | C.*<RD>.{{11}}L"));
    assert_eq!(
        (eleven.nfa_positions(), eleven.dfa_states()),
        (318, Some(4400))
    );
    let twelve = set(&format!("{wide} | C.*<RD>.{{12}}L"), 1 << 40);
    assert_eq!(twelve.nfa_positions(), 319);
    assert!(!twelve.uses_dfa());
    let mut narrow = "C.*<RD>.{12}L".to_string();
    for lobe in [
        "TS1", "TS2", "TS3", "TS4", "TS5", "TS6", "TS7", "TD1", "TD2", "TD3",
    ] {
        narrow.push_str(&format!(" | C<{lobe}>L"));
    }
    for lobe in ["RS1", "RS2", "RS3", "RS4", "RS5"] {
        narrow.push_str(&format!(" | C<{lobe}>L"));
    }
    let narrow = default_set(&narrow);
    assert_eq!(
        (narrow.class_count(), narrow.dfa_states()),
        (20, Some(8225))
    );
}
