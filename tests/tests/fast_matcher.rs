//! The fast matcher (`lpe::aov`: DFA and bitset NFA) and `lpe::DirectSet` (the trees
//! evaluated on each path, what the fast engine compiles for a few paths) against the
//! reference matcher. `DirectSet` shares lpe's parser and set-algebra formulas with the
//! `AovSet`, not its atoms' acceptance (asked per vertex, where the `AovSet` tabulates
//! classes: `renderman::alphabet`'s tests hold the two to each other on every vertex)
//! nor its matching; the reference shares none of it.
//!
//! Expected answers always come from `reference`, never from the code under test. Random
//! paths rarely match random expressions, so every case also samples paths *from* the
//! expressions (walking the AST and picking, per atom, a vertex that the reference says
//! the atom accepts) plus one-vertex mutations of them; the match rate is printed and
//! checked.

use std::cell::Cell;
use std::time::{Duration, Instant};

use lpe::analysis::{self, default_universe};
use lpe::aov::{AovSet, Options};
use lpe::renderman::ast::{Expr, Repetition};
use lpe::renderman::macros::BASIC;
use lpe::renderman::path::{Path, Vertex, VertexType};
use lpe::renderman::{parse, Lpe, Parser, RenderMan};
use lpe::rng::SplitMix64 as Rng;
use lpe::DirectSet;
use lpe_testkit::strategy;
use lpe_tests::{expr_set, framed, named, vertex_pool};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

/// A vertex sequence `e` matches according to the reference's atom semantics, or `None`
/// when some chosen atom matches no vertex.
fn sample(e: &Expr, pool: &[Vertex], rng: &mut Rng, out: &mut Vec<Vertex>) -> Option<()> {
    match e {
        Expr::Atom(a) => {
            let ok: Vec<&Vertex> = pool
                .iter()
                .filter(|v| lpe_reference::atom_matches(a, v))
                .collect();
            if ok.is_empty() {
                return None;
            }
            out.push(ok[rng.below(ok.len())].clone());
        }
        Expr::Concat(es) => {
            for e in es {
                sample(e, pool, rng, out)?;
            }
        }
        Expr::Alt(es) => sample(&es[rng.below(es.len())], pool, rng, out)?,
        Expr::Repeat(body, r) => {
            let extra = r.max.map_or(2, |m| (m - r.min).min(2)) as usize;
            let n = r.min as usize + rng.below(extra + 1);
            for _ in 0..n {
                sample(body, pool, rng, out)?;
            }
        }
    }
    Some(())
}

/// Positive samples of each expression that are valid paths, plus one-vertex mutations.
fn sampled_paths(exprs: &[Lpe], pool: &[Vertex], seed: u64, max_len: usize) -> Vec<Path> {
    let mut rng = Rng::new(seed);
    let mut out = Vec::new();
    for l in exprs {
        for _ in 0..6 {
            let mut vs = Vec::new();
            if sample(&l.expr, pool, &mut rng, &mut vs).is_none() || vs.len() > max_len {
                continue;
            }
            if let Ok(p) = Path::new(vs.clone()) {
                out.push(p);
                // Mutate one vertex into another of the same place in the path.
                let i = rng.below(vs.len());
                let same_place: Vec<&Vertex> = pool
                    .iter()
                    .filter(|v| {
                        v.ty() == vs[i].ty()
                            || (v.ty().is_scattering() && vs[i].ty().is_scattering())
                            || (i == vs.len() - 1
                                && matches!(v.ty(), VertexType::L | VertexType::O))
                    })
                    .collect();
                vs[i] = same_place[rng.below(same_place.len())].clone();
                if let Ok(p) = Path::new(vs) {
                    out.push(p);
                }
            }
        }
    }
    out
}

fn nfa_only() -> Options {
    Options {
        dfa_budget: 0,
        ..Options::default()
    }
}

#[derive(Default)]
struct Stats {
    comparisons: Cell<u64>,
    matches: Cell<u64>,
    skipped: Cell<u64>,
}

/// Fast DFA, bitset NFA, direct set and reference agree on every path; incremental stepping from a
/// saved state agrees with matching the spliced path; an AOV flagged empty matches
/// nothing.
fn check_set(exprs: &[Lpe], paths: &[Path], stats: &Stats) -> Result<(), TestCaseError> {
    let aovs = named(exprs);
    let (fast, nfa) = match (
        AovSet::compile(&aovs),
        AovSet::compile_with(&aovs, &nfa_only()),
    ) {
        (Ok(f), Ok(n)) => (f, n),
        // Sets over the documented size limits: counted, never silently passed.
        _ => {
            stats.skipped.set(stats.skipped.get() + 1);
            return Ok(());
        }
    };
    let direct = DirectSet::compile(&aovs).expect("a set the AovSet compiles compiles directly");
    let empty: Vec<usize> = fast.warnings().iter().map(|w| w.aov).collect();
    for p in paths {
        let want: Vec<bool> = exprs
            .iter()
            .map(|e| lpe_reference::is_match(e, p))
            .collect();
        let got_fast = fast.match_path(p);
        let got_nfa = nfa.match_path(p);
        let got_direct = direct.match_path(p);
        for (i, &w) in want.iter().enumerate() {
            stats.comparisons.set(stats.comparisons.get() + 1);
            stats.matches.set(stats.matches.get() + u64::from(w));
            prop_assert_eq!(got_fast.contains(i), w, "fast: `{}` on `{}`", exprs[i], p);
            prop_assert_eq!(got_nfa.contains(i), w, "nfa: `{}` on `{}`", exprs[i], p);
            prop_assert_eq!(
                got_direct.contains(i),
                w,
                "direct: `{}` on `{}`",
                exprs[i],
                p
            );
            prop_assert!(
                !(w && empty.contains(&i)),
                "`{}` warned empty, matches `{}`",
                exprs[i],
                p
            );
        }
    }
    // Splice: the state after a prefix of one path, stepped over the tail of another.
    for (a, b) in paths.iter().zip(paths.iter().skip(1)) {
        let (k, j) = (1 + a.len() / 2 - 1, b.len() / 2);
        let spliced: Vec<Vertex> = a.vertices()[..k]
            .iter()
            .chain(&b.vertices()[j.max(1)..])
            .cloned()
            .collect();
        let Ok(r) = Path::new(spliced) else { continue };
        for set in [&fast, &nfa] {
            let mut s = a.vertices()[..k]
                .iter()
                .fold(set.start(), |s, v| set.step(s, v));
            let saved = s;
            for v in &b.vertices()[j.max(1)..] {
                s = set.step_class(s, set.classify(v));
            }
            let m = set.matches(s);
            for (i, e) in exprs.iter().enumerate() {
                prop_assert_eq!(
                    m.contains(i),
                    lpe_reference::is_match(e, &r),
                    "splice `{}` on `{}`",
                    e,
                    r
                );
            }
            // The saved state is a copy: stepping on did not change it.
            let again = b.vertices()[j.max(1)..]
                .iter()
                .fold(saved, |s, v| set.step(s, v));
            prop_assert_eq!(again, s);
        }
    }
    Ok(())
}

/// Skips (inputs over a size limit) allowed: 10, or 2.5 % of the cases when
/// `PROPTEST_CASES` raises the count, so a long run does not fail on volume alone.
fn skip_allowance(runner: &proptest::test_runner::TestRunner) -> u64 {
    (u64::from(runner.config().cases) / 40).max(10)
}

#[test]
fn fast_and_nfa_agree_with_reference() {
    let pool = vertex_pool();
    let stats = Stats::default();
    let mut runner = lpe_tests::runner(400);
    let allowed = skip_allowance(&runner);
    let strat = (
        expr_set(1..=3),
        prop::collection::vec(strategy::path(8), 4),
        any::<u64>(),
    );
    runner
        .run(&strat, |(exprs, random, seed)| {
            let mut paths = random;
            paths.extend(sampled_paths(&exprs, &pool, seed, 12));
            check_set(&exprs, &paths, &stats)
        })
        .unwrap();
    let (n, m) = (stats.comparisons.get(), stats.matches.get());
    let rate = m as f64 / n as f64;
    eprintln!(
        "fast/nfa vs reference: {n} comparisons, match rate {:.1}%, {} sets skipped",
        100.0 * rate,
        stats.skipped.get()
    );
    assert!(rate > 0.2, "too few positive cases: {rate}");
    assert!(
        stats.skipped.get() < allowed,
        "{} sets skipped",
        stats.skipped.get()
    );
}

/// `max_path_len`: `e{n,m}` with `m >= L` compiles as `e{n,}`, exact on paths of at most
/// `L` vertices.
#[test]
fn long_bounded_repeats_are_exact_within_max_path_len() {
    const L: u32 = 6;
    let pool = vertex_pool();
    let opts = Options {
        max_path_len: Some(L),
        ..Options::default()
    };
    let mut runner = lpe_tests::runner(200);
    let allowed = skip_allowance(&runner);
    let skipped = Cell::new(0u32);
    let strat = (
        strategy::expr(),
        0u32..3,
        (L - 2)..(L + 4),
        prop::collection::vec(strategy::path(L as usize), 4),
        any::<u64>(),
    );
    runner
        .run(&strat, |(body, min, max, random, seed)| {
            let expr = framed(Expr::Repeat(
                Box::new(body),
                Repetition {
                    min,
                    max: Some(max),
                },
            ));
            let l = Lpe::new(Default::default(), expr);
            let Ok(set) = AovSet::compile_with(&[("x".into(), l.clone())], &opts) else {
                // Over the documented size limits: counted, never silently passed.
                skipped.set(skipped.get() + 1);
                return Ok(());
            };
            let mut paths = random;
            paths.extend(sampled_paths(
                std::slice::from_ref(&l),
                &pool,
                seed,
                L as usize,
            ));
            for p in &paths {
                prop_assert_eq!(
                    set.match_path(p).contains(0),
                    lpe_reference::is_match(&l, p),
                    "`{}` on `{}`",
                    l,
                    p
                );
            }
            Ok(())
        })
        .unwrap();
    assert!(
        u64::from(skipped.get()) < allowed,
        "{} expressions skipped",
        skipped.get()
    );
    // The rewrite makes `C.{0,250}L` a few positions instead of 250.
    let l = parse("C.{0,250}L").unwrap();
    let set = AovSet::compile_with(&[("x".into(), l)], &opts).unwrap();
    assert!(set.nfa_positions() < 10, "{}", set.nfa_positions());
}

fn basic() -> Vec<(String, Lpe)> {
    BASIC
        .iter()
        .map(|(n, s)| (n.to_string(), parse(s).unwrap()))
        .collect()
}

#[test]
fn basic_aovs_are_a_clean_partition() {
    let p = analysis::partition(
        &basic(),
        &default_universe::<lpe::renderman::RenderMan>(&lpe::renderman::Parser::default()),
        &lpe::renderman::Parser::default(),
    )
    .unwrap();
    assert!(p.is_clean(), "{p:?}");
}

#[test]
fn caustics_overlap_witnesses_hold_under_the_reference() {
    let mut aovs = basic();
    aovs.push(("caustics".into(), parse("caustics").unwrap()));
    let universe =
        default_universe::<lpe::renderman::RenderMan>(&lpe::renderman::Parser::default());
    let p = analysis::partition(&aovs, &universe, &lpe::renderman::Parser::default()).unwrap();
    assert!(!p.overlaps.is_empty());
    for (i, j, w) in &p.overlaps {
        assert!(lpe_reference::is_match(&universe, w), "{w}");
        assert!(
            lpe_reference::is_match(&aovs[*i].1, w),
            "{} on {w}",
            aovs[*i].0
        );
        assert!(
            lpe_reference::is_match(&aovs[*j].1, w),
            "{} on {w}",
            aovs[*j].0
        );
        assert!(aovs[*j].0 == "caustics", "{}", aovs[*j].0);
    }
}

/// Comparison witnesses, re-checked by the reference; "equivalent" spot-checked on
/// random and sampled paths.
#[test]
fn comparison_witnesses_hold_under_the_reference() {
    let pool = vertex_pool();
    let mut runner = lpe_tests::runner(150);
    let allowed = skip_allowance(&runner);
    // At least 10 differing pairs at the default count, proportionally fewer when
    // PROPTEST_CASES lowers it.
    let want_differing = (runner.config().cases * 10 / 150).max(1);
    // At least two drawn expressions: padding with a clone compared an expression
    // with itself, which is equivalent whatever the comparison does.
    let strat = (
        expr_set(2..=3),
        prop::collection::vec(strategy::path(7), 6),
        any::<u64>(),
    );
    let differing = Cell::new(0);
    let skipped = Cell::new(0u32);
    runner
        .run(&strat, |(exprs, random, seed)| {
            let (a, b) = (&exprs[0], &exprs[1]);
            let Ok(c) = analysis::compare(a, b) else {
                // Over the documented size limits: counted, never silently passed.
                skipped.set(skipped.get() + 1);
                return Ok(());
            };
            if let Some(w) = &c.first_only {
                prop_assert!(
                    lpe_reference::is_match(a, w) && !lpe_reference::is_match(b, w),
                    "{} vs {}: {}",
                    a,
                    b,
                    w
                );
            }
            if let Some(w) = &c.second_only {
                prop_assert!(
                    !lpe_reference::is_match(a, w) && lpe_reference::is_match(b, w),
                    "{} vs {}: {}",
                    a,
                    b,
                    w
                );
            }
            if !c.equivalent() {
                differing.set(differing.get() + 1);
            }
            let mut paths = random;
            paths.extend(sampled_paths(&exprs[..2], &pool, seed, 10));
            for p in &paths {
                let (ma, mb) = (lpe_reference::is_match(a, p), lpe_reference::is_match(b, p));
                if c.first_only.is_none() {
                    prop_assert!(!ma || mb, "{} not in {}: {}", a, b, p);
                }
                if c.second_only.is_none() {
                    prop_assert!(!mb || ma, "{} not in {}: {}", b, a, p);
                }
            }
            Ok(())
        })
        .unwrap();
    assert!(differing.get() > want_differing, "{}", differing.get());
    assert!(
        u64::from(skipped.get()) < allowed,
        "{} pairs skipped",
        skipped.get()
    );
}

/// "The 13th vertex from the end is diffuse" blows up any DFA; the set must still compile
/// in bounded time (over budget, by falling back to the NFA) and answer right.
#[test]
fn blow_up_shapes_compile_in_bounded_time() {
    let pool = vertex_pool();
    for k in [12, 20, 40] {
        let src = format!("C.*D.{{{k}}}[LO]");
        let l = parse(&src).unwrap();
        let t = Instant::now();
        let set = AovSet::compile_with(
            &[("x".into(), l.clone())],
            &Options {
                dfa_budget: 4 << 20,
                ..Options::default()
            },
        )
        .unwrap();
        assert!(
            t.elapsed() < Duration::from_secs(20),
            "{src}: {:?}",
            t.elapsed()
        );
        assert_eq!(set.uses_dfa(), k == 12, "{src}");
        let paths = sampled_paths(std::slice::from_ref(&l), &pool, k as u64, 200);
        assert!(!paths.is_empty());
        for p in &paths {
            assert_eq!(
                set.match_path(p).contains(0),
                lpe_reference::is_match(&l, p),
                "{src} on {p}"
            );
        }
    }
}

#[test]
fn engines_are_registered() {
    for name in ["reference", "fast", "nfa"] {
        assert!(lpe_engines::by_name::<RenderMan>(name).is_some(), "{name}");
    }
    let exprs: Vec<Lpe> = basic().into_iter().map(|(_, l)| l).collect();
    let p: Path = "C RD2 RS L'key'".parse().unwrap();
    let want: Vec<bool> = exprs
        .iter()
        .map(|e| lpe_reference::is_match(e, &p))
        .collect();
    for name in ["fast", "nfa"] {
        let m = lpe_engines::by_name::<RenderMan>(name)
            .unwrap()
            .compile(&exprs, &Parser::default())
            .unwrap();
        assert_eq!(
            lpe_engines::engine::bits(m.which(&p), exprs.len()),
            want,
            "{name}"
        );
    }
}
