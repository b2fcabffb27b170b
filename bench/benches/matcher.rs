//! `cargo bench -p lpe-bench --bench matcher`: the fast matcher against regex-automata,
//! per vertex and at compile time, with criterion's statistics. The workloads, path
//! sampler, baseline and RenderMan loops are [`lpe_bench`]'s, shared with
//! `lpe-check bench` (which prints the benchmark table).
//!
//! Throughput is in vertices: criterion's `elem/s` is `1e9 / (ns per vertex)`.

use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use lpe::{AovSet, Options};
use lpe_bench::renderman::{encode, flatten, run_dense, run_lazy, run_vertices};
use lpe_bench::{baseline, classify, run_classes, sample, shapes, workload};

/// Small enough for quick runs, large enough to leave the caches' comfort zone no more
/// than a renderer's tile does.
const VERTICES: usize = 200_000;

fn matching(c: &mut Criterion) {
    let paths = sample::paths(VERTICES, 1);
    let vertices: usize = paths.iter().map(|p| p.len()).sum();
    let flat = flatten(&paths);
    for w in workload::all() {
        let mut g = c.benchmark_group(format!("match/{}", w.name));
        g.throughput(Throughput::Elements(vertices as u64));
        let fast = AovSet::compile(&w.aovs).expect("workloads compile");
        let classes = classify(&fast, &paths);
        g.bench_function("fast, on vertices", |b| {
            b.iter(|| run_vertices(&fast, &flat))
        });
        g.bench_function("fast, on classes", |b| {
            b.iter(|| run_classes(fast.automaton(), &classes))
        });
        let nfa_opts = Options {
            dfa_budget: 0,
            ..Options::default()
        };
        g.bench_function("renderer-shaped caller", |b| {
            b.iter(|| shapes::run_renderer(&fast, &classes))
        });
        if let Some(n) = fast.dfa_states() {
            let bare = shapes::BareTable::new(n, fast.class_count(), 1);
            g.bench_function("bare dependent-load chain", |b| {
                b.iter(|| shapes::run_bare(&bare, &classes))
            });
        }
        if let Ok(nfa) = AovSet::compile_with(&w.aovs, &nfa_opts) {
            let classes = classify(&nfa, &paths);
            let mut cache = nfa.cache();
            g.bench_function("lazy DFA, own cache", |b| {
                b.iter(|| shapes::run_cached(&nfa, &mut cache, &classes))
            });
            if let Some(wide) = nfa.nfa() {
                g.bench_function("bitset NFA, on classes", |b| {
                    b.iter(|| shapes::run_renderer(&wide, &classes))
                });
            }
        }
        let enc = baseline::Encoding::new(&w.aovs).expect("workload labels fit a byte");
        let bytes = encode(&enc, &paths);
        let ra_nfa = baseline::nfa(&enc, &w.aovs).expect("the baseline NFA builds");
        if let Ok(dfa) = baseline::dense(&ra_nfa) {
            let start = baseline::dense_start(&dfa).expect("anchored start state");
            g.bench_function("regex-automata dense DFA", |b| {
                b.iter(|| run_dense(&dfa, start, &bytes))
            });
        }
        if let Ok(dfa) = baseline::lazy(ra_nfa) {
            let mut cache = dfa.create_cache();
            g.bench_function("regex-automata lazy DFA", |b| {
                b.iter(|| run_lazy(&dfa, &mut cache, &bytes))
            });
        }
        g.finish();
    }
}

fn compiling(c: &mut Criterion) {
    let mut g = c.benchmark_group("compile");
    for w in workload::all()
        .into_iter()
        .filter(|w| ["basic", "per-lobe", "groups"].contains(&w.name))
    {
        g.bench_function(format!("fast/{}", w.name), |b| {
            b.iter(|| AovSet::compile(&w.aovs).expect("workloads compile"))
        });
        let enc = baseline::Encoding::new(&w.aovs).expect("workload labels fit a byte");
        g.bench_function(format!("regex-automata dense/{}", w.name), |b| {
            b.iter(|| baseline::nfa(&enc, &w.aovs).and_then(|n| baseline::dense(&n)))
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(20)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    targets = matching, compiling
}
criterion_main!(benches);
