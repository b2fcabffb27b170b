//! The explorer's views on a renderer-sized AOV list, and the drawing of a ~200-state
//! automaton: `cargo bench -p lpe-bench --bench explore`. Each row is one call of
//! `lpe_explore::answer` from the JSON body to the JSON reply, as `lpe-check serve`
//! answers a request (numbers in docs/benchmarks.md).

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use lpe::renderman::macros::BASIC;
use lpe_bench::workload;
use serde_json::json;

/// The `groups` workload (the basic AOVs split over four light groups, plus label AOVs:
/// 32 AOVs) as the explorer's list text, and `extra` more light groups of the basic
/// AOVs.
fn list(extra: &[&str]) -> String {
    let groups = workload::all()
        .into_iter()
        .find(|w| w.name == "groups")
        .expect("the groups workload");
    let mut lines: Vec<String> = groups
        .aovs
        .iter()
        .map(|(n, e)| format!("{n} = {e}"))
        .collect();
    for g in extra {
        lines.extend(BASIC.iter().map(|(n, _)| format!("{n}_{g} = {n}_{g}")));
    }
    lines.join("\n")
}

fn bench(c: &mut Criterion) {
    let aovs = list(&[]);
    let body = json!({
        "aovs": aovs,
        "path": "C RD2'floor' RS1 TS8 L'key'",
        "left": "directDiffuse_key",
        "right": "C<RD>[<L.'key'>O]",
    })
    .to_string();
    let mut views = c.benchmark_group("explore_32_aovs");
    for view in lpe_explore::VIEWS {
        let reply = lpe_explore::answer(view, body.as_bytes());
        assert_eq!(reply.status, 200, "{view}: {}", reply.json);
        views.bench_function(view, |b| {
            b.iter(|| lpe_explore::answer(black_box(view), black_box(body.as_bytes())))
        });
    }
    views.finish();
    // Two more light groups: 46 AOVs, 193 states, drawn (no crossing reduction past
    // 200 layout nodes).
    let big = json!({ "aovs": list(&["sky", "sun"]) }).to_string();
    let reply = lpe_explore::answer("graph", big.as_bytes());
    let v: serde_json::Value = serde_json::from_str(&reply.json).expect("JSON");
    assert_eq!(v["state_count"], 193, "{}", v["state_count"]);
    assert!(v["svg"].is_string());
    c.bench_function("explore_graph_193_states", |b| {
        b.iter(|| lpe_explore::answer("graph", black_box(big.as_bytes())))
    });
    // The worst shapes the limits let through or refuse: `C.*<RD>.{n}L` remembers the
    // last n+1 scatter vertices, and every back edge crosses many ranks. n = 5: 66
    // states, drawn; n = 6: 130 states, refused by its layout's size after lowering.
    for (n, states, drawn) in [(5, 66, true), (6, 130, false)] {
        let dense = json!({ "aovs": format!("a = C.*<RD>.{{{n}}}L") }).to_string();
        let reply = lpe_explore::answer("graph", dense.as_bytes());
        let v: serde_json::Value = serde_json::from_str(&reply.json).expect("JSON");
        assert_eq!(
            (v["state_count"].as_u64(), v["svg"].is_string()),
            (Some(states), drawn)
        );
        c.bench_function(&format!("explore_graph_dense_{states}_states"), |b| {
            b.iter(|| lpe_explore::answer("graph", black_box(dense.as_bytes())))
        });
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
