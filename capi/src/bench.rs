//! Benchmark only: the Rust loop a renderer linking lpe directly would run, timed inside
//! the library, so that `examples/c/step_bench.c` compares its C rows with a Rust row in
//! the same run. Exported but kept out of the header (`capi/cbindgen.toml`); the bench
//! declares it.

use std::hint::black_box;
use std::time::Instant;

use lpe::Class;

use crate::classify::lpe_class;
use crate::set::lpe_set;

/// Steps `path_count` paths (`lens[p]` classes each, concatenated in `classes`) `reps`
/// times with `AovSet::step_class` from `start`, adds each path's final state id to
/// `*checksum`, and returns the nanoseconds the stepping took (conversion excluded).
/// Returns 0 and leaves `*checksum` alone on a NULL pointer or a class out of range.
#[no_mangle]
pub extern "C" fn lpe_bench_rust_loop(
    set: *const lpe_set,
    classes: *const lpe_class,
    lens: *const usize,
    path_count: usize,
    reps: u64,
    checksum: *mut u64,
) -> u64 {
    // SAFETY: NULL or valid pointers from the caller.
    let (Some(set), Some(checksum)) = (unsafe { set.as_ref() }, unsafe { checksum.as_mut() })
    else {
        return 0;
    };
    if path_count > 0 && (classes.is_null() || lens.is_null()) {
        return 0;
    }
    // SAFETY: the caller passes `path_count` lengths (checked non-null).
    let lens = unsafe { std::slice::from_raw_parts(lens, path_count) };
    let mut paths: Vec<Vec<Class>> = Vec::with_capacity(path_count);
    let mut at = 0;
    for &n in lens {
        // SAFETY: the caller passes the sum of `lens` classes (checked non-null).
        let path = unsafe { std::slice::from_raw_parts(classes.add(at), n) };
        let Some(path) = path.iter().map(|c| c.to_class(set)).collect() else {
            return 0;
        };
        paths.push(path);
        at += n;
    }
    let rust = set.set.automaton();
    let mut sum = 0u64;
    let t = Instant::now();
    for _ in 0..reps {
        // The same loop as the Rust row of `cargo bench -p lpe-bench --bench step`.
        for path in black_box(&paths) {
            let mut s = rust.start();
            for &c in path {
                s = rust.step_class(s, c);
            }
            sum = sum.wrapping_add(u64::from(s.to_u32()));
        }
    }
    let ns = t.elapsed().as_nanos() as u64;
    *checksum = checksum.wrapping_add(sum);
    ns.max(1)
}
