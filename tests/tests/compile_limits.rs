//! The compile limits at their exact boundaries: a set at a limit compiles and answers,
//! one past it is the documented error with its numbers. Every number is worked out by
//! hand from the documented limits (`MAX_AOVS` AOVs, `64 * NFA_STATE_WORDS` positions
//! for a set stepped on its NFA, `positions * words * 8` bytes of follow rows within
//! `nfa_budget`).

use lpe::renderman::{parse, Event, EventKind, Lpe, Path, Vertex, VertexType};
use lpe::{AovSet, CompileError, Options, MAX_AOVS};

fn named(srcs: &[String]) -> Vec<(String, Lpe)> {
    srcs.iter()
        .enumerate()
        .map(|(i, s)| (format!("a{i}"), parse(s).unwrap()))
        .collect()
}

fn nfa_only() -> Options {
    Options {
        dfa_budget: 0,
        ..Options::default()
    }
}

#[test]
fn max_aovs_compile_and_one_more_does_not() {
    // AOV i matches a diffuse bounce off label `li`, so the last one is told apart.
    let srcs: Vec<String> = (0..MAX_AOVS).map(|i| format!("C<RD'l{i}'>L")).collect();
    let aovs = named(&srcs);
    let set = AovSet::compile(&aovs).unwrap();
    // Every AOV kept, in order, with its name and expression.
    assert_eq!((set.len(), set.is_empty()), (MAX_AOVS, false));
    assert_eq!(set.names()[MAX_AOVS - 1], format!("a{}", MAX_AOVS - 1));
    assert_eq!(
        set.lpes(),
        aovs.iter().map(|(_, l)| l.clone()).collect::<Vec<_>>()
    );
    let bounce = |label: &str| {
        let d = Event::new(EventKind::D, 1).unwrap();
        Path::new(vec![
            Vertex::camera(),
            Vertex::scatter(VertexType::R, d, Some(label)),
            Vertex::light(None),
        ])
        .unwrap()
    };
    let last = format!("l{}", MAX_AOVS - 1);
    assert_eq!(
        set.match_path(&bounce(&last)).iter().collect::<Vec<_>>(),
        [MAX_AOVS - 1]
    );
    let mut more = srcs;
    more.push("CL".to_string());
    assert_eq!(
        AovSet::compile(&named(&more)).unwrap_err(),
        CompileError::TooManyAovs(MAX_AOVS + 1)
    );
}

#[test]
fn a_set_of_no_aovs_compiles_and_matches_nothing() {
    let set = AovSet::compile(&[] as &[(String, lpe::renderman::Lpe)]).unwrap();
    assert_eq!((set.len(), set.is_empty()), (0, true));
    assert!(set.match_path(&"C RD1 L".parse().unwrap()).is_empty());
}

#[test]
fn sets_at_and_past_the_positions_an_nfa_state_holds_step_lazily() {
    // C.{253}L: the start, C, 253 dots and L = 256 positions, four 64-bit words: what a
    // stepping state holds, so with no DFA budget the set steps its NFA.
    let set = AovSet::compile_with(&named(&["C.{253}L".to_string()]), &nfa_only()).unwrap();
    assert!(!set.uses_dfa());
    assert_eq!(set.nfa_positions(), 256);
    for (n, want) in [(253, true), (252, false), (254, false)] {
        let p: Path = format!("C{} L", " RD".repeat(n)).parse().unwrap();
        assert_eq!(set.match_path(&p).contains(0), want, "{n}");
    }
    assert!(set.nfa().is_some(), "an NfaState holds 256 positions");
    // One more dot: 257 positions, five words. The lazy DFA steps states of any width;
    // the plain NFA matcher, whose state is four words, is not offered.
    let wider = AovSet::compile_with(&named(&["C.{254}L".to_string()]), &nfa_only()).unwrap();
    assert!(!wider.uses_dfa() && wider.nfa().is_none());
    assert_eq!(wider.nfa_positions(), 257);
    for (n, want) in [(254, true), (253, false), (255, false)] {
        let p: Path = format!("C{} L", " RD".repeat(n)).parse().unwrap();
        assert_eq!(wider.match_path(&p).contains(0), want, "{n}");
    }
}

#[test]
fn the_nfa_budget_holds_the_follow_rows_to_the_byte() {
    // CDL: 4 positions (the start included), one word each: 4 * 1 * 8 = 32 bytes of
    // follow rows. A budget of 32 bytes compiles (too small for step tables, so the NFA
    // only builds the DFA), 31 does not.
    let cdl = named(&["CDL".to_string()]);
    let budget = |nfa_budget| Options {
        nfa_budget,
        ..Options::default()
    };
    let set = AovSet::compile_with(&cdl, &budget(32)).unwrap();
    assert!(set.uses_dfa());
    assert!(set.match_path(&"C RD1 L".parse().unwrap()).contains(0));
    assert_eq!(
        AovSet::compile_with(&cdl, &budget(31)).unwrap_err(),
        CompileError::NfaOverBudget {
            positions: 4,
            bytes: Some(32),
            budget: 31
        }
    );
}

/// The same budget counts OSL positions after unrolling: `C<RD>{3}L` is 1 + 3 + 1
/// vertex positions and the start, 6 one-word rows: 48 bytes.
#[test]
fn the_nfa_budget_counts_unrolled_positions_in_the_osl_dialect() {
    let reg = lpe::osl::Registered::none();
    let aovs = vec![("a".to_string(), lpe::osl::parse("C<RD>{3}L", &reg).unwrap())];
    let budget = |nfa_budget| Options {
        nfa_budget,
        ..Options::default()
    };
    let set = AovSet::compile_under(&aovs, &reg, &budget(48)).unwrap();
    assert!(set
        .match_path(&"C,_ R,D R,D R,D L,_".parse().unwrap())
        .contains(0));
    assert_eq!(
        AovSet::compile_under(&aovs, &reg, &budget(47)).unwrap_err(),
        CompileError::NfaOverBudget {
            positions: 6,
            bytes: Some(48),
            budget: 47
        }
    );
}

/// A set of 1 437 NFA positions (a fuzzer's find: too wide for an `NfaState`, with a DFA
/// far over the budget) compiles in the fast engine with default options and steps its
/// lazy DFA. Its camera carries a label, which no path's does, so it matches nothing
/// and says so; the same set with a plain camera answers as the reference on paths
/// through each of its branches and at the bounds of its counts.
#[test]
fn a_set_of_thousands_of_positions_compiles_and_steps_lazily() {
    let body = "((('fill'[^<T[^D2US]'fill'>R])U1)|(.[O<..'a b'>])*|\
                U6((<.[^DD]'floor'><[^R].>){1,238}){1,3})'floor'";
    let found = parse(&format!("nothruput;overwrite;[C'key']{body}")).unwrap();
    let set = AovSet::compile(&[("found".to_string(), found)]).unwrap();
    assert!(!set.uses_dfa() && set.nfa().is_none());
    assert_eq!(set.nfa_positions(), 1437);
    assert_eq!(set.warnings().len(), 1, "{:?}", set.warnings());
    assert!(set.match_path(&"C RD L".parse().unwrap()).is_empty());

    // With a light after the last `'floor'` scatter (a bare label names an object), and
    // `|` binding tighter than concatenation: `C (A | B* | U6) (G{1,238}){1,3} 'floor' L`.
    let lpe = parse(&format!("C{body}L")).unwrap();
    let set = AovSet::compile(&[("wide".to_string(), lpe.clone())]).unwrap();
    assert!(!set.uses_dfa() && set.nfa().is_none());
    assert!(set.nfa_positions() > 1000, "{}", set.nfa_positions());
    let mut paths = vec!["C RD L".to_string(), "C RD1'floor' L".to_string()];
    // A first vertex of each alternative, then k copies of the group, then `'floor'`.
    for first in ["RU6", "RS1'a b'", "RD1'fill' TD1 RU1"] {
        for k in [0, 1, 2, 237, 238, 239, 476, 714, 715] {
            let group = " RS1'floor' TD1".repeat(k);
            paths.push(format!("C {first}{group} RD1'floor' L"));
        }
    }
    let mut matched = 0;
    for p in &paths {
        let path: Path = p.parse().unwrap_or_else(|e| panic!("{p}: {e}"));
        let want = lpe_reference::is_match(&lpe, &path);
        assert_eq!(set.match_path(&path).contains(0), want, "{p}");
        matched += usize::from(want);
    }
    // Both answers occur: matches within the counted bounds, none past them.
    assert!(
        matched >= 8 && matched < paths.len(),
        "{matched} of {}",
        paths.len()
    );
}
