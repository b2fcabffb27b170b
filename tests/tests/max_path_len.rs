//! The `max_path_len` rewrite at its boundary. `Options::max_path_len = Some(L)` compiles
//! `e{n,m}` with `m >= L` as `e{n,}`, and the set is documented exact on paths of at most
//! `L` vertices, unspecified on longer ones. So, compared with the same set compiled
//! without the option:
//! - on EVERY path of length `L - 1` and `L` (and shorter) over a small alphabet, the
//!   answers are the same, on the DFA and on the bitset NFA;
//! - on paths of length `L + 1` they may differ, and only the way the rewrite allows: the
//!   rewritten repetition accepts more iterations, so the rewritten set matches a
//!   superset, and a difference needs a repetition whose bound is at least `L`.

use std::cell::Cell;

use lpe::renderman::ast::{Expr, Repetition};
use lpe::renderman::{parse, Event, EventKind, Lpe, Path, Vertex, VertexType};
use lpe::Options;
use lpe::{AovSet, CompileError};
use lpe_testkit::strategy;
use lpe_tests::named;
use proptest::prelude::*;

/// The vertices paths are enumerated over: five middle vertices (transport and user
/// lobes, one labelled) and three emitters.
fn alphabet() -> (Vec<Vertex>, Vec<Vertex>) {
    let ev = |k, n| Event::new(k, n).unwrap();
    let middle = vec![
        Vertex::scatter(VertexType::R, ev(EventKind::D, 1), None),
        Vertex::scatter(VertexType::R, ev(EventKind::S, 2), Some("floor")),
        Vertex::scatter(VertexType::T, ev(EventKind::D, 1), None),
        Vertex::scatter(VertexType::T, ev(EventKind::S, 1), None),
        Vertex::scatter(VertexType::R, ev(EventKind::U, 1), None),
    ];
    let ends = vec![
        Vertex::light(None),
        Vertex::light(Some("key")),
        Vertex::emissive(Some("fill")),
    ];
    (middle, ends)
}

/// Every path of exactly `len` vertices over the alphabet.
fn paths_of_len(len: usize) -> Vec<Path> {
    let (middle, ends) = alphabet();
    let mut mids: Vec<Vec<Vertex>> = vec![Vec::new()];
    for _ in 0..len.saturating_sub(2) {
        mids = mids
            .into_iter()
            .flat_map(|m| {
                middle.iter().map(move |v| {
                    let mut m = m.clone();
                    m.push(v.clone());
                    m
                })
            })
            .collect();
    }
    let mut out = Vec::new();
    for m in &mids {
        for e in &ends {
            let mut v = vec![Vertex::camera()];
            v.extend(m.iter().cloned());
            v.push(e.clone());
            out.push(Path::new(v).unwrap());
        }
    }
    out
}

fn bounded(l: u32, dfa: bool) -> Options {
    Options {
        max_path_len: Some(l),
        dfa_budget: if dfa {
            Options::default().dfa_budget
        } else {
            0
        },
        ..Options::default()
    }
}

/// Whether some repetition in `e` has a finite bound of at least `l` (the only thing
/// the rewrite touches).
fn has_rewritable(e: &Expr, l: u32) -> bool {
    match e {
        Expr::Atom(_) => false,
        Expr::Concat(es) | Expr::Alt(es) => es.iter().any(|e| has_rewritable(e, l)),
        Expr::Repeat(b, r) => r.max.is_some_and(|m| m >= l && m >= r.min) || has_rewritable(b, l),
    }
}

/// Why [`compare_at_boundary`] failed: a set over the documented size limits (skipped by
/// the random test, counted), or a wrong answer.
#[derive(Debug)]
enum Failure {
    Compile(CompileError),
    Wrong(String),
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Failure::Compile(e) => write!(f, "does not compile: {e}"),
            Failure::Wrong(e) => f.write_str(e),
        }
    }
}

impl From<CompileError> for Failure {
    fn from(e: CompileError) -> Self {
        Failure::Compile(e)
    }
}

impl From<String> for Failure {
    fn from(e: String) -> Self {
        Failure::Wrong(e)
    }
}

/// Compares the sets with and without `max_path_len = l` on every path of length
/// `2..=l + 1`. Returns how many (path, AOV) answers differ at `l + 1`.
fn compare_at_boundary(exprs: &[Lpe], l: u32) -> Result<usize, Failure> {
    let aovs = named(exprs);
    let exact = AovSet::compile(&aovs)?;
    let mut differing = 0;
    for dfa in [true, false] {
        let rewritten = AovSet::compile_with(&aovs, &bounded(l, dfa))?;
        if rewritten.uses_dfa() != dfa {
            return Err(format!("not the stepping mode asked for (dfa: {dfa})").into());
        }
        for len in 2..=(l as usize + 1) {
            for p in paths_of_len(len) {
                let (want, got) = (exact.match_path(&p), rewritten.match_path(&p));
                for (i, x) in exprs.iter().enumerate() {
                    let (w, g) = (want.contains(i), got.contains(i));
                    if len <= l as usize {
                        if w != g {
                            return Err(Failure::Wrong(format!(
                                "max_path_len {l} ({}): `{x}` on `{p}` ({len} vertices): \
                                 exact {w}, rewritten {g}",
                                if dfa { "dfa" } else { "nfa" }
                            )));
                        }
                    } else if w != g {
                        if w && !g {
                            return Err(Failure::Wrong(format!(
                                "max_path_len {l}: `{x}` on `{p}`: the rewritten set lost a match"
                            )));
                        }
                        if !has_rewritable(&x.expr, l) {
                            return Err(Failure::Wrong(format!(
                                "max_path_len {l}: `{x}` has no repetition bounded at {l} or \
                                 more, yet differs on `{p}`"
                            )));
                        }
                        if dfa {
                            differing += 1;
                        }
                    }
                }
            }
        }
    }
    Ok(differing)
}

/// Expressions whose bounds sit at `l - 1`, `l` and `l + 1`, in every kind of
/// repetition the rewrite meets; `(source, differs at l + 1)`, decided by hand.
fn boundary_cases(l: u32) -> Vec<(String, bool)> {
    let m = |d: i32| (l as i32 + d) as u32;
    vec![
        // Every vertex of a path is an iteration: `l + 1` vertices are `l + 1`
        // iterations, one more than a bound of `l` allows.
        (format!("[C.<L.>O]{{1,{}}}", m(-1)), false),
        (format!("[C.<L.>O]{{1,{}}}", m(0)), true),
        (format!("[C.<L.>O]{{1,{}}}", m(1)), false),
        (format!("[C<RU>.<L.>O]{{2,{}}}", m(0)), true),
        // The middle of the path only: at most `len - 2` iterations.
        (format!("C.{{0,{}}}[<L.>O]", m(-2)), false),
        (format!("C.{{0,{}}}[<L.>O]", m(-1)), false),
        (format!("C.{{1,{}}}[<L.>O]", m(0)), false),
        // Bodies of one or two vertices, bodies that may be empty, nested repetitions.
        (format!("C(<RD><RS>?){{1,{}}}[<L.>O]", m(-2)), false),
        (format!("C(<RD><RS>?){{1,{}}}[<L.>O]", m(0)), false),
        (format!("C(<.D>?){{3,{}}}.*[<L.>O]", m(0)), false),
        (
            format!("C((<.D>|<.S>){{1,2}}){{1,{}}}[<L.>O]", m(-1)),
            false,
        ),
        (format!("(C|.|<L.>){{2,{}}}", m(0)), true),
        // `{n}` exactly, at and around the bound.
        (format!("C.{{{}}}<L.'key'>", m(-2)), false),
        (format!("[C.<L.>O]{{{}}}", m(0)), true),
        (format!("[C.<L.>O]{{{}}}", m(-1)), false),
    ]
}

#[test]
fn rewrite_is_exact_up_to_the_bound_and_differs_only_as_documented_past_it() {
    for l in 3..=6u32 {
        for (src, differs) in boundary_cases(l) {
            let lpe = parse(&src).unwrap_or_else(|e| panic!("{src}: {e}"));
            let n = compare_at_boundary(std::slice::from_ref(&lpe), l)
                .unwrap_or_else(|e| panic!("{src}: {e}"));
            assert_eq!(
                n > 0,
                differs,
                "`{src}` at max_path_len {l}: {n} differences at {}",
                l + 1
            );
            // The exact set is the reference's answer too (spot check on length `l`).
            let exact = AovSet::compile(&named(std::slice::from_ref(&lpe))).unwrap();
            for p in paths_of_len(l as usize).iter().step_by(7) {
                assert_eq!(
                    exact.match_path(p).contains(0),
                    lpe_reference::is_match(&lpe, p),
                    "`{src}` on `{p}`"
                );
            }
        }
    }
}

/// The rewrite fires exactly when the bound reaches `max_path_len` (`m >= L`), which the
/// position count shows: fewer positions at `L = m`, the same as exact at `L = m + 1`.
#[test]
fn rewrite_fires_at_the_documented_bound() {
    for m in [3u32, 5, 9] {
        let l = parse(&format!("C.{{0,{m}}}[<L.>O]")).unwrap();
        let aovs = [("x".to_string(), l)];
        let exact = AovSet::compile(&aovs).unwrap().nfa_positions();
        let at = |len: u32| {
            AovSet::compile_with(&aovs, &bounded(len, true))
                .unwrap()
                .nfa_positions()
        };
        assert!(at(m) < exact, "m = {m}: {} vs {exact}", at(m));
        assert!(at(m - 1) < exact, "m = {m}");
        assert_eq!(at(m + 1), exact, "m = {m}");
    }
}

/// Random sets with a bounded repetition whose bound lands near `L`: exact on every
/// enumerated path of length up to `L`; at `L + 1` only rewritten-side extra matches,
/// only from sets that have a repetition bounded at `L` or more.
#[test]
fn random_sets_agree_up_to_the_bound() {
    let mut runner = lpe_tests::runner(64);
    let cases = runner.config().cases;
    let skipped = Cell::new(0u32);
    let strat = (
        prop::collection::vec(strategy::aov_expr(), 1..=2),
        strategy::expr(),
        0u32..3,
        3u32..=5,
        -1i32..=1,
        any::<bool>(),
    );
    runner
        .run(&strat, |(mut exprs, body, min, l, d, whole)| {
            let max = (l as i32 + d) as u32;
            let r = Repetition {
                min: min.min(max),
                max: Some(max),
            };
            let (camera, emitter) = (parse("C").unwrap().expr, parse("[<L.>O]").unwrap().expr);
            exprs.push(if whole {
                // Iterations that may take every vertex of the path, the camera and the
                // emitter included: the only way `L + 1` vertices exceed a bound of `L`.
                Expr::Repeat(Box::new(Expr::Alt(vec![camera, body, emitter])), r)
            } else {
                Expr::Concat(vec![camera, Expr::Repeat(Box::new(body), r), emitter])
            });
            let lpes: Vec<Lpe> = exprs
                .into_iter()
                .map(|expr| Lpe::new(Default::default(), expr))
                .collect();
            match compare_at_boundary(&lpes, l) {
                Ok(_) => Ok(()),
                Err(Failure::Compile(CompileError::NfaOverBudget { .. })) => {
                    skipped.set(skipped.get() + 1);
                    Ok(())
                }
                Err(e) => Err(TestCaseError::fail(e.to_string())),
            }
        })
        .unwrap();
    assert!(
        skipped.get() * 10 <= cases,
        "{} sets skipped",
        skipped.get()
    );
}
