//! A step through the C ABI against a step from Rust, same set, same classes, same run:
//! `cargo bench -p lpe-bench --bench step`. The C-ABI row calls `lpe_step` through a
//! function pointer hidden from the optimizer, as a C caller's call would be. The
//! header's inline step (`lpe_view_step`) is C, so its row is in `examples/c/step_bench.c`,
//! beside a Rust row run in the same process.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use lpe::renderman::{Lpe, Path};
use lpe::AovSet;
use lpe_capi::classify::lpe_classify_text;
use lpe_capi::set::{lpe_set_compile, lpe_set_free, LPE_DIALECT_RENDERMAN};
use lpe_capi::step::{lpe_matches, lpe_start, lpe_step, lpe_step_n};
use lpe_capi::{lpe_class, lpe_set, lpe_state, lpe_status};

/// Paths a renderer steps: bounces of every kind, with labels, ending at emitters.
const PATHS: [&str; 4] = [
    "C RD2'floor' RS1 TS8 TS8 RD1 L'key'",
    "C RS1 RD1'wall' RD1 RD1 RD1 O'glow'",
    "C TS8 TS8 RD2'floor' RS1 RD1 L'fill'",
    "C RD1 RD1 RD1 RD1 RS1 RS1 L",
];

fn bench(c: &mut Criterion) {
    let aovs: Vec<(String, Lpe)> = lpe::renderman::macros::BASIC
        .iter()
        .map(|(n, e)| (n.to_string(), lpe::renderman::parse(e).unwrap()))
        .collect();
    let rust = AovSet::compile(&aovs).unwrap();
    let names: Vec<std::ffi::CString> = aovs
        .iter()
        .map(|(n, _)| std::ffi::CString::new(n.as_str()).unwrap())
        .collect();
    let exprs: Vec<std::ffi::CString> = lpe::renderman::macros::BASIC
        .iter()
        .map(|(_, e)| std::ffi::CString::new(*e).unwrap())
        .collect();
    let np: Vec<_> = names.iter().map(|c| c.as_ptr()).collect();
    let ep: Vec<_> = exprs.iter().map(|c| c.as_ptr()).collect();
    let mut set: *mut lpe_set = std::ptr::null_mut();
    let st = lpe_set_compile(
        np.as_ptr(),
        ep.as_ptr(),
        np.len(),
        LPE_DIALECT_RENDERMAN,
        std::ptr::null(),
        std::ptr::null(),
        &mut set,
        std::ptr::null_mut(),
    );
    assert_eq!(st, lpe_status::LPE_OK);

    let paths: Vec<Path> = PATHS.iter().map(|p| p.parse().unwrap()).collect();
    let rust_classes: Vec<Vec<lpe::Class>> = paths
        .iter()
        .map(|p| p.vertices().iter().map(|v| rust.classify(v)).collect())
        .collect();
    let c_classes: Vec<Vec<lpe_class>> = paths
        .iter()
        .map(|p| {
            p.vertices()
                .iter()
                .map(|v| {
                    let t = std::ffi::CString::new(v.to_string()).unwrap();
                    let mut c = lpe_class { id: 0 };
                    assert_eq!(
                        lpe_classify_text(set, t.as_ptr(), &mut c),
                        lpe_status::LPE_OK
                    );
                    c
                })
                .collect()
        })
        .collect();
    let steps: u64 = rust_classes.iter().map(|p| p.len() as u64).sum();

    let mut g = c.benchmark_group("step");
    g.throughput(Throughput::Elements(steps));
    g.bench_function("rust AovSet::step_class", |b| {
        b.iter(|| {
            let mut hits = 0;
            for path in black_box(&rust_classes) {
                let mut s = rust.start();
                for &c in path {
                    s = rust.step_class(s, c);
                }
                hits += rust.matches(s).count();
            }
            hits
        })
    });
    let step: extern "C" fn(*const lpe_set, *mut lpe_state, lpe_class) -> lpe_status =
        black_box(lpe_step);
    let step_n: extern "C" fn(
        *const lpe_set,
        *mut lpe_state,
        *const lpe_class,
        usize,
    ) -> lpe_status = black_box(lpe_step_n);
    g.bench_function("C ABI lpe_step", |b| {
        b.iter(|| {
            let mut hits = 0;
            for path in black_box(&c_classes) {
                let mut s = lpe_state { opaque: 0 };
                lpe_start(set, &mut s);
                for &c in path {
                    step(set, &mut s, c);
                }
                let mut count = 0;
                lpe_matches(set, &s, std::ptr::null_mut(), 0, &mut count);
                hits += count;
            }
            hits
        })
    });
    g.bench_function("C ABI lpe_step_n (one call per path)", |b| {
        b.iter(|| {
            let mut hits = 0;
            for path in black_box(&c_classes) {
                let mut s = lpe_state { opaque: 0 };
                lpe_start(set, &mut s);
                step_n(set, &mut s, path.as_ptr(), path.len());
                let mut count = 0;
                lpe_matches(set, &s, std::ptr::null_mut(), 0, &mut count);
                hits += count;
            }
            hits
        })
    });
    g.finish();
    lpe_set_free(set);
}

criterion_group!(benches, bench);
criterion_main!(benches);
