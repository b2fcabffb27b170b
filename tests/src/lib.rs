//! Cross-crate property tests and the data-driven conformance suite live in `tests/`;
//! this library holds what the test files share, the suite's in-process runner
//! ([`conformance`]; the loader is `lpe_testkit::suite`), and the workspace's file-level
//! import graph that the layering test checks ([`imports`]) and its collapse onto
//! folders, where no import may run back up ([`folders`]); the files git tracks, which
//! are the workspace apart from what builds write into it ([`tracked`]).

pub mod conformance;
pub mod folders;
pub mod imports;
pub mod tracked;

use lpe::renderman::ast::{Atom, Expr, Item, Triple, TypePos};
use lpe::renderman::{Event, Lpe, Vertex, VertexType};
use lpe_testkit::strategy::{self, LABELS};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};

/// `PROPTEST_CASES` if set, else `default`. An explicit case count in a config would
/// otherwise override the variable, and it is documented to raise every suite. The
/// rejections a run may make grow with its cases: `osl_matching` rejects about one
/// draw in twenty (no text of it parses), so proptest's fixed 1 024 aborted it from
/// about 20 000 cases on.
pub fn cases(default: u32) -> Config {
    let n = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default);
    let config = Config::with_cases(n);
    Config {
        max_global_rejects: config.max_global_rejects.max(n),
        ..config
    }
}

/// A runner for properties driven by hand (to gather statistics across cases), with
/// [`cases`]`(default_cases)`. No failure persistence: a persisted seed would replay
/// into a strategy these tests build inline and may change.
pub fn runner(default_cases: u32) -> TestRunner {
    TestRunner::new(Config {
        failure_persistence: None,
        ..cases(default_cases)
    })
}

/// `C e [<L.>O]`: random bodies inside the path frame, so that samples are paths.
pub fn framed(e: Expr) -> Expr {
    let emitter = Atom::Class {
        negated: false,
        items: vec![
            Item::Triple(Triple {
                ty: TypePos::One(VertexType::L),
                event: lpe::renderman::ast::EventPos::Any,
                label: lpe::renderman::ast::LabelPos::Any,
            }),
            Item::Type(VertexType::O),
        ],
    };
    Expr::Concat(vec![
        Expr::Atom(Atom::Item(Item::Type(VertexType::C))),
        e,
        Expr::Atom(emitter),
    ])
}

/// Sets of generated expressions, about half of them framed as paths ([`framed`]).
pub fn expr_set(sizes: std::ops::RangeInclusive<usize>) -> impl Strategy<Value = Vec<Lpe>> {
    let one = (strategy::lpe(), any::<bool>()).prop_map(|(mut l, frame)| {
        if frame {
            l.operands_mut(&mut |e| *e = framed(e.clone()));
        }
        l
    });
    prop::collection::vec(one, sizes)
}

/// The expressions as an AOV list named `e0`, `e1`, ... in order.
pub fn named(exprs: &[Lpe]) -> Vec<(String, Lpe)> {
    exprs
        .iter()
        .enumerate()
        .map(|(i, e)| (format!("e{i}"), e.clone()))
        .collect()
}

/// Every constructible kind of vertex: the camera, and lights, emissive objects and R/T
/// vertices of every event, each with no label, each pool label, and an unmentioned one.
pub fn vertex_pool() -> Vec<Vertex> {
    let labels: Vec<Option<&str>> = std::iter::once(None)
        .chain(LABELS.iter().map(|l| Some(*l)))
        .chain(std::iter::once(Some("zz")))
        .collect();
    let mut pool = vec![Vertex::camera()];
    for l in &labels {
        pool.push(Vertex::light(*l));
        pool.push(Vertex::emissive(*l));
        for ty in [VertexType::R, VertexType::T] {
            for e in Event::all() {
                pool.push(Vertex::scatter(ty, e, *l));
            }
        }
    }
    pool
}

/// RenderMan `(name, expression)` pairs compiled with the default options but a DFA
/// budget of `dfa_budget` bytes (0: no DFA).
pub fn compile_with_dfa_budget(
    srcs: &[(&str, &str)],
    dfa_budget: usize,
) -> lpe::AovSet<lpe::renderman::RenderMan> {
    let aovs: Vec<_> = srcs
        .iter()
        .map(|(n, s)| (n.to_string(), lpe::renderman::parse(s).unwrap()))
        .collect();
    let opts = lpe::Options {
        dfa_budget,
        ..lpe::Options::default()
    };
    lpe::AovSet::compile_with(&aovs, &opts).unwrap()
}

/// The states reachable from the start over `letters` and, for each, whether it can
/// still reach a state whose `matches` is not empty. `None` past `cap` states.
pub fn reachable_and_live<M>(
    set: &M,
    letters: &[lpe::Class],
    cap: usize,
) -> Option<(Vec<M::State>, Vec<bool>)>
where
    M: lpe::PathMatcher<Class = lpe::Class> + ?Sized,
    M::State: Eq + std::hash::Hash,
{
    use std::collections::{HashMap, VecDeque};
    let mut index: HashMap<M::State, usize> = HashMap::new();
    let mut states = vec![set.start()];
    index.insert(set.start(), 0);
    let mut preds: Vec<Vec<usize>> = vec![Vec::new()];
    let mut head = 0;
    while head < states.len() {
        let s = states[head];
        for &c in letters {
            let t = set.step(s, c);
            let j = match index.get(&t) {
                Some(&j) => j,
                None => {
                    if states.len() == cap {
                        return None;
                    }
                    states.push(t);
                    preds.push(Vec::new());
                    index.insert(t, states.len() - 1);
                    states.len() - 1
                }
            };
            preds[j].push(head);
        }
        head += 1;
    }
    let mut live: Vec<bool> = states.iter().map(|&s| !set.matches(s).is_empty()).collect();
    let mut queue: VecDeque<usize> = (0..states.len()).filter(|&i| live[i]).collect();
    while let Some(j) = queue.pop_front() {
        for &i in &preds[j] {
            if !live[i] {
                live[i] = true;
                queue.push_back(i);
            }
        }
    }
    Some((states, live))
}

/// The verdicts of the conformance suite's `testdata/<file>`, one per (expression, path);
/// panics with the loader's error.
pub fn suite_rows(file: &str) -> Vec<lpe_testkit::suite::Row> {
    let loaded = lpe_testkit::suite::load_file(file).unwrap_or_else(|e| panic!("{e}"));
    lpe_testkit::suite::rows(&loaded)
}

/// The path of a suite row, in the dialect of `P`; panics naming the file and the path.
pub fn row_path<P: std::str::FromStr>(r: &lpe_testkit::suite::Row) -> P
where
    P::Err: std::fmt::Display,
{
    r.path
        .parse()
        .unwrap_or_else(|e| panic!("{}: `{}`: {e}", r.file, r.path))
}
