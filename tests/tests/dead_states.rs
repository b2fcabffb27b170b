//! What a compiled set says about its own states: `is_dead(s)` promises that no
//! continuation of the path can match any AOV, and a renderer stops tracking the path on
//! it. A state flagged dead too early silently drops contributions; a DFA state that is
//! dead but not flagged only costs time, yet the DFA is minimized, so it has exactly one
//! dead state and should say so.
//!
//! Sets with set algebra get their own run: a complement `^A` matches after every operand
//! died, so there the state with no active position is not dead.
//!
//! Checked on every stepping mode: the DFA (default options), the bitset NFA
//! (`dfa_budget: 0`, `lazy_cache: 0`) on small sets, the bitset NFA on sets of more than
//! 64 positions, whose state spans several 64-bit words, and the lazy DFA on both with a
//! cache so small that it clears all the time.
//!
//! Two independent checks per set:
//! - exact: every state reachable from the start (over one vertex per class, in any
//!   order) is explored, the states that can reach a non-empty `matches` are found by a
//!   backward search, and `is_dead` must agree with that (soundness on every mode,
//!   completeness on the DFA);
//! - against the reference matcher: once a path prefix is dead, neither the path nor any
//!   splice of that prefix with the tail of another path matches any AOV.

use std::cell::Cell;

use lpe::renderman::{parse, Event, EventKind, Lpe, Path, Prefixes, Vertex, VertexType};
use lpe::{AovSet, Class, NfaState, Options, PathMatcher, State};
use lpe_testkit::strategy;
use lpe_tests::{expr_set, framed, named, vertex_pool};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

/// One class per distinct answer of `classify` over the pool. A set may have classes no
/// constructible vertex falls in (a labelled camera, which `Vertex` cannot build), so
/// this can be fewer than `class_count()`.
fn letters<M: PathMatcher<Vertex = Vertex, Class = Class> + ?Sized>(
    set: &M,
    pool: &[Vertex],
) -> Vec<Class> {
    let mut out: Vec<Class> = pool.iter().map(|v| set.classify(v)).collect();
    out.sort();
    out.dedup();
    out
}

#[derive(Default)]
struct Stats {
    explored: Cell<u32>,
    complete_checked: Cell<u32>,
    dead_seen: Cell<u32>,
    live_seen: Cell<u32>,
    wide: Cell<u32>,
    dead_prefixes: Cell<u32>,
}

fn bump(c: &Cell<u32>) {
    c.set(c.get() + 1);
}

/// Exact soundness (and completeness when `complete`) of `is_dead` over every reachable
/// state, when there are at most `cap` of them. Through [`PathMatcher`], the interface
/// renderers step.
fn check_exact(
    set: &AovSet<lpe::renderman::RenderMan>,
    pool: &[Vertex],
    complete: bool,
    cap: usize,
    what: &str,
    stats: &Stats,
) -> Result<(), TestCaseError> {
    let class_count = set.class_count();
    let set: &dyn PathMatcher<Vertex = Vertex, Class = Class, State = State> = set;
    let letters = letters(set, pool);
    let Some((states, live)) = lpe_tests::reachable_and_live(set, &letters, cap) else {
        return Ok(());
    };
    bump(&stats.explored);
    // Completeness needs every class: a state may live only through a class that no
    // constructible vertex reaches.
    let every_class = letters.len() == class_count;
    if complete && every_class {
        bump(&stats.complete_checked);
    }
    for (s, &l) in states.iter().zip(&live) {
        let dead = set.is_dead(*s);
        if dead {
            bump(&stats.dead_seen);
            prop_assert!(
                !l,
                "{}: a state flagged dead reaches a match ({} reachable states)",
                what,
                states.len()
            );
            prop_assert!(set.matches(*s).is_empty(), "{}: a dead state matches", what);
        } else {
            bump(&stats.live_seen);
            if complete && every_class {
                prop_assert!(
                    l,
                    "{}: a DFA state not flagged dead reaches no match ({} states)",
                    what,
                    states.len()
                );
            }
        }
    }
    Ok(())
}

/// Once a prefix is dead, the reference matches no AOV on any path that extends it:
/// the path itself and the prefix spliced with the tails of the other paths.
fn check_paths<M: PathMatcher<Vertex = Vertex> + ?Sized>(
    set: &M,
    exprs: &[Lpe],
    paths: &[Path],
    what: &str,
    stats: &Stats,
) -> Result<(), TestCaseError> {
    for p in paths {
        let vs = p.vertices();
        let mut s = set.start();
        for k in 0..vs.len() {
            s = set.step(s, set.classify(&vs[k]));
            if !set.is_dead(s) {
                continue;
            }
            bump(&stats.dead_prefixes);
            let prefix = &vs[..=k];
            let mut extensions = vec![p.clone()];
            for q in paths {
                let tail = &q.vertices()[1..];
                for cut in 0..tail.len() {
                    let v: Vec<Vertex> = prefix.iter().chain(&tail[cut..]).cloned().collect();
                    if let Ok(e) = Path::new(v) {
                        extensions.push(e);
                    }
                }
            }
            for e in &extensions {
                for (i, x) in exprs.iter().enumerate() {
                    prop_assert!(
                        !lpe_reference::is_match(x, e),
                        "{}: dead after `{}` but AOV {} `{}` matches `{}`",
                        what,
                        Path::new(prefix.to_vec()).map_or("(prefix)".into(), |p| p.to_string()),
                        i,
                        x,
                        e
                    );
                }
            }
            break;
        }
    }
    Ok(())
}

/// An AOV of 66 positions that dies on the vertex after the camera unless that vertex
/// is a `U12` lobe: placed first, it fills word 0 of an NFA state (and a little of word
/// 1), so the drawn AOVs live in the higher words once it is dead. A chain, since
/// positions always active together are merged (64 alternatives `<RU12>` would be one).
fn padding() -> Lpe {
    padding_words(1)
}

/// [`padding`] over `words` whole words of an NFA state: `64 * words + 2` positions.
fn padding_words(words: usize) -> Lpe {
    parse(&format!("C<RU12>{{{}}}L", 64 * words)).unwrap()
}

/// Every step runs the bitset NFA (no lazy cache).
fn nfa_only() -> Options {
    Options {
        dfa_budget: 0,
        lazy_cache: 0,
        ..Options::default()
    }
}

/// The lazy DFA with a two-row cache: cleared on nearly every new transition, so states
/// in flight keep crossing clears.
fn lazy_two_rows() -> Options {
    Options {
        dfa_budget: 0,
        lazy_cache: 1,
        ..Options::default()
    }
}

/// Every stepping mode on one drawn set: the DFA, the NFA and the lazy DFA, and the
/// NFA and lazy DFA behind a padding AOV that makes their states wide.
fn check_modes(
    exprs: &[Lpe],
    paths: &[Path],
    stats: &Stats,
    skipped: &Cell<u32>,
) -> Result<(), TestCaseError> {
    let mut wide_exprs = vec![padding()];
    wide_exprs.extend(exprs.iter().cloned());
    let modes = [
        ("dfa", exprs, Options::default()),
        ("nfa", exprs, nfa_only()),
        ("wide nfa", &wide_exprs[..], nfa_only()),
        ("lazy", exprs, lazy_two_rows()),
        ("wide lazy", &wide_exprs[..], lazy_two_rows()),
    ];
    for (what, exprs, opts) in modes {
        let Ok(set) = AovSet::compile_with(&named(exprs), &opts) else {
            // Over the documented size limits: counted below.
            bump(skipped);
            continue;
        };
        let is_dfa = what == "dfa";
        prop_assert_eq!(set.uses_dfa(), is_dfa, "{}", what);
        if what.starts_with("wide") {
            prop_assert!(set.nfa_positions() > 64, "{}", set.nfa_positions());
            bump(&stats.wide);
        }
        check_exact(&set, &vertex_pool(), is_dfa, 20_000, what, stats)?;
        check_paths(&set, exprs, paths, what, stats)?;
    }
    Ok(())
}

#[test]
fn dead_states_are_sound_and_dfa_dead_states_complete() {
    let stats = Stats::default();
    let mut runner = lpe_tests::runner(160);
    let cases = runner.config().cases;
    let strat = (expr_set(1..=3), prop::collection::vec(strategy::path(7), 6));
    let skipped = Cell::new(0u32);
    runner
        .run(&strat, |(exprs, paths)| {
            check_modes(&exprs, &paths, &stats, &skipped)
        })
        .unwrap();
    report(&stats, &skipped, cases);
}

/// Sets where every AOV is set algebra over framed operands, half of them with a
/// complement: once no operand can match, `^A` still does, so "no active position" is
/// not dead there, and `A & B` is dead once `B` is, with `A` still alive.
#[test]
fn dead_states_of_set_algebra_are_sound_and_dfa_dead_states_complete() {
    let stats = Stats::default();
    let mut runner = lpe_tests::runner(120);
    let cases = runner.config().cases;
    let one = strategy::algebra().prop_map(|t| {
        let mut l = Lpe::from_algebra(Prefixes::NONE, t);
        l.operands_mut(&mut |e| *e = framed(e.clone()));
        l
    });
    let strat = (
        prop::collection::vec(one, 1..=3),
        prop::collection::vec(strategy::path(7), 6),
    );
    let skipped = Cell::new(0u32);
    let complement_sets = Cell::new(0u32);
    runner
        .run(&strat, |(exprs, paths)| {
            if exprs.iter().any(|l| l.to_string().contains('^')) {
                bump(&complement_sets);
            }
            check_modes(&exprs, &paths, &stats, &skipped)
        })
        .unwrap();
    report(&stats, &skipped, cases);
    assert!(
        complement_sets.get() * 4 >= cases,
        "{}",
        complement_sets.get()
    );
}

/// Prints the statistics and checks that the exact checks ran on most sets rather than
/// being skipped over the caps.
fn report(stats: &Stats, skipped: &Cell<u32>, cases: u32) {
    let get = |c: &Cell<u32>| c.get();
    eprintln!(
        "dead states: {} sets explored, {} DFA sets checked for completeness, {} dead and {} \
         live states, {} wide NFA sets, {} dead path prefixes, {} compiles skipped",
        get(&stats.explored),
        get(&stats.complete_checked),
        get(&stats.dead_seen),
        get(&stats.live_seen),
        get(&stats.wide),
        get(&stats.dead_prefixes),
        skipped.get()
    );
    assert!(
        get(&stats.explored) * 10 >= cases * 3 * 8,
        "{}",
        get(&stats.explored)
    );
    assert!(
        get(&stats.complete_checked) * 2 >= cases,
        "{}",
        get(&stats.complete_checked)
    );
    assert!(get(&stats.wide) * 10 >= cases * 9, "{}", get(&stats.wide));
    assert!(
        get(&stats.dead_prefixes) >= cases,
        "{}",
        get(&stats.dead_prefixes)
    );
    assert!(get(&stats.dead_seen) > 0 && get(&stats.live_seen) > 0);
    assert!(skipped.get() * 20 <= cases, "{}", skipped.get());
}

/// A hand-built wide NFA: after `C RD1` only positions past bit 64 are active, the set
/// is alive (`C RD1 L'key'` matches), and a wrong light group kills it. The DFA of the
/// same set walks alike.
#[test]
fn a_wide_nfa_state_with_an_empty_first_word_is_alive() {
    let exprs = [padding(), parse("C.*<L.'key'>").unwrap()];
    let nfa = AovSet::compile_with(&named(&exprs), &nfa_only()).unwrap();
    assert!(!nfa.uses_dfa());
    assert!(nfa.nfa_positions() > 64, "{}", nfa.nfa_positions());
    let dfa = AovSet::compile(&named(&exprs)).unwrap();
    assert!(dfa.uses_dfa());
    let rd1 = Vertex::scatter(VertexType::R, Event::new(EventKind::D, 1).unwrap(), None);
    for set in [&nfa, &dfa] {
        let c = set.step(set.start(), &Vertex::camera());
        assert!(!set.is_dead(c));
        let s = set.step(c, &rd1);
        assert!(!set.is_dead(s), "the second AOV is alive after `C RD1`");
        let key = set.step(s, &Vertex::light(Some("key")));
        assert_eq!(set.matches(key).iter().collect::<Vec<_>>(), [1]);
        let fill = set.step(s, &Vertex::light(Some("fill")));
        assert!(set.matches(fill).is_empty());
        assert!(set.is_dead(fill), "an emitter ends every AOV of the set");
        let unlabelled = set.step(c, &Vertex::light(None));
        assert!(set.matches(unlabelled).is_empty() && set.is_dead(unlabelled));
    }
}

/// The plain bitset NFA matcher ([`AovSet::nfa`], stepped on its wide [`NfaState`] with
/// no registry or cache), and the lazy DFA over it, on sets whose drawn AOVs sit behind a
/// padding of one, two or three whole state words: once the padding dies, the live
/// positions are in word 1, 2 or 3 alone. Every reachable state is explored: a state the
/// matcher calls dead never reaches a match and matches nothing, and, on a set without
/// set algebra (where no complement matches from the empty state), it is called dead
/// exactly when no position is active. Against the reference: no extension of a dead prefix matches.
#[test]
fn the_wide_nfa_matchers_dead_states_are_sound_in_every_word() {
    let pool = vertex_pool();
    for words in 1..=3 {
        let stats = Stats::default();
        let later_words_only = Cell::new(0u32);
        let skipped = Cell::new(0u32);
        let mut runner = lpe_tests::runner(40);
        let cases = runner.config().cases;
        let strat = (expr_set(1..=2), prop::collection::vec(strategy::path(7), 6));
        runner
            .run(&strat, |(exprs, paths)| {
                let mut padded = vec![padding_words(words)];
                padded.extend(exprs.iter().cloned());
                let Ok(set) = AovSet::compile_with(&named(&padded), &nfa_only()) else {
                    bump(&skipped);
                    return Ok(());
                };
                prop_assert!(set.nfa_positions() > 64 * words, "{}", set.nfa_positions());
                let nfa = set.nfa().expect("a set without a DFA has its NFA");
                let letters = letters(&nfa, &pool);
                let Some((states, live)) = lpe_tests::reachable_and_live(&nfa, &letters, 20_000)
                else {
                    return Ok(());
                };
                bump(&stats.explored);
                let plain = padded.iter().all(|l| l.algebra.is_none());
                for (s, &l) in states.iter().zip(&live) {
                    let active: Vec<usize> = s.active().collect();
                    if plain {
                        prop_assert_eq!(nfa.is_dead(*s), active.is_empty(), "{:?}", active);
                    }
                    if nfa.is_dead(*s) {
                        bump(&stats.dead_seen);
                        prop_assert!(!l, "words {}: a state called dead reaches a match", words);
                        prop_assert!(nfa.matches(*s).is_empty());
                    } else {
                        bump(&stats.live_seen);
                        if active.iter().all(|&p| p >= 64 * words) {
                            bump(&later_words_only);
                        }
                    }
                }
                check_paths(&nfa, &padded, &paths, "wide nfa", &stats)?;
                let lazy = AovSet::compile_with(&named(&padded), &lazy_two_rows());
                let lazy = lazy.expect("the same set compiles lazily");
                check_exact(&lazy, &pool, false, 20_000, "wide lazy", &stats)?;
                check_paths(&lazy, &padded, &paths, "wide lazy", &stats)
            })
            .unwrap();
        eprintln!(
            "{words} padding word(s): {} matchers explored, {} dead and {} live NFA states, {} of \
             them live in later words alone, {} dead prefixes, {} compiles skipped",
            stats.explored.get(),
            stats.dead_seen.get(),
            stats.live_seen.get(),
            later_words_only.get(),
            stats.dead_prefixes.get(),
            skipped.get()
        );
        // Most sets ran, and states living in the later words alone were checked.
        assert!(
            stats.explored.get() * 2 >= cases,
            "{}",
            stats.explored.get()
        );
        assert!(
            later_words_only.get() >= cases,
            "{}",
            later_words_only.get()
        );
        assert!(stats.dead_seen.get() > 0 && stats.dead_prefixes.get() > 0);
    }
}

/// [`NfaState::active`] lists a hand-built wide state's positions: after `C RD1` behind a
/// one-word padding, only the second AOV's positions (past 64) are active.
/// `CDL`'s positions are the start (0), `C` (1), `D` (2) and `L` (3): each step leaves
/// exactly the next one active.
#[test]
fn an_nfa_state_lists_its_active_positions_by_number() {
    let exprs = [parse("CDL").unwrap()];
    let set = AovSet::compile_with(&named(&exprs), &nfa_only()).unwrap();
    let nfa = set.nfa().unwrap();
    let rd1 = Vertex::scatter(VertexType::R, Event::new(EventKind::D, 1).unwrap(), None);
    let mut s: NfaState = nfa.start();
    let mut seen = vec![s.active().collect::<Vec<_>>()];
    for v in [Vertex::camera(), rd1, Vertex::light(None)] {
        s = nfa.step(s, nfa.classify(&v));
        seen.push(s.active().collect());
    }
    assert_eq!(seen, [vec![0], vec![1], vec![2], vec![3]]);
}

#[test]
fn a_wide_nfa_state_lists_its_active_positions() {
    let exprs = [padding(), parse("C.*<L.'key'>").unwrap()];
    let set = AovSet::compile_with(&named(&exprs), &nfa_only()).unwrap();
    let nfa = set.nfa().unwrap();
    let start: NfaState = nfa.start();
    assert_eq!(start.active().collect::<Vec<_>>(), [0]);
    let rd1 = Vertex::scatter(VertexType::R, Event::new(EventKind::D, 1).unwrap(), None);
    let c = nfa.step(start, nfa.classify(&Vertex::camera()));
    let s = nfa.step(c, nfa.classify(&rd1));
    let active: Vec<usize> = s.active().collect();
    assert!(
        !active.is_empty() && active.iter().all(|&p| p >= 64),
        "{active:?}"
    );
    assert!(!nfa.is_dead(s));
    let fill = nfa.step(s, nfa.classify(&Vertex::light(Some("fill"))));
    assert_eq!(fill.active().count(), 0);
    assert!(nfa.is_dead(fill));
}
