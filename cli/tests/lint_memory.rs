//! `lpe-check lint` on a `.usda` stage of many prims and tens of MB of geometry stays
//! within a memory bound: the one test of this file, so that the test process, whose
//! resident size the child's peak includes, stays small.

use std::io::Write;
use std::process::Command;

/// The largest resident size of the children this process waited for, in KiB
/// (`getrusage(RUSAGE_CHILDREN)`'s `ru_maxrss`, Linux).
#[cfg(target_os = "linux")]
fn children_peak_kib() -> i64 {
    // `struct rusage` on Linux: two `struct timeval`s, then 14 longs, `ru_maxrss` first.
    #[repr(C)]
    struct Rusage {
        times: [i64; 4],
        maxrss: i64,
        rest: [i64; 13],
    }
    extern "C" {
        fn getrusage(who: i32, usage: *mut Rusage) -> i32;
    }
    const RUSAGE_CHILDREN: i32 = -1;
    let mut usage = Rusage {
        times: [0; 4],
        maxrss: 0,
        rest: [0; 13],
    };
    // SAFETY: `usage` is a valid, writable `struct rusage` for the call's duration.
    let rc = unsafe { getrusage(RUSAGE_CHILDREN, &mut usage) };
    assert_eq!(rc, 0, "getrusage");
    usage.maxrss
}

/// A generated stage of 10^4 meshes, each with an object group and 100 points (27 MB
/// of text), lints with a peak resident size under 32 MiB (7.4 MiB measured): the flat
/// reader holds a piece of text, the open prims and one hash per child name, not the
/// prims nor the geometry. The peak is the largest of this process's children (the only
/// one is the lint), which on Linux also counts this process's own resident size when it
/// spawned the child: hence a file of its own, whose one test keeps this process small.
/// Planted fault, seen failing: `read` never taking the flat path (every stage composed
/// through the USD library: a peak of 68 MiB).
#[cfg(target_os = "linux")]
#[test]
fn lint_memory_is_bounded_by_the_prims_not_the_file() {
    const MESHES: usize = 10_000;
    const BOUND_KIB: i64 = 32 << 10;
    let dir = std::env::temp_dir().join(format!("lpe-usd-memory-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("stage.usda");
    {
        let mut f = std::io::BufWriter::new(std::fs::File::create(&path).unwrap());
        let points: Vec<String> = (0..100)
            .map(|i| format!("({}, {}, {})", i as f32 * 0.001, -i as f32 * 0.002, i % 97))
            .collect();
        let points = points.join(", ");
        writeln!(f, "#usda 1.0\ndef Xform \"World\"\n{{").unwrap();
        for m in 0..MESHES {
            writeln!(
                f,
                "    def Mesh \"m{m}\"\n    {{\n        point3f[] points = [{points}]\n        \
                 string primvars:karma:object:lpetag = \"g{}\"\n    }}",
                m % 7
            )
            .unwrap();
        }
        writeln!(
            f,
            "    def RectLight \"key\"\n    {{\n        string inputs:karma:light:lpetag = \"key\"\n    }}\n}}\n\
             def Scope \"Render\"\n{{\n    def RenderVar \"d\"\n    {{\n        uniform token sourceType = \"lpe\"\n        \
             uniform string sourceName = \"C<RD>[<L.'key'><O.'g3'>]\"\n    }}\n}}"
        )
        .unwrap();
    }
    let size = std::fs::metadata(&path).unwrap().len();
    assert!(size > 20 << 20, "{size} bytes");
    let out = Command::new(env!("CARGO_BIN_EXE_lpe-check"))
        .args(["lint", "--format", "json"])
        .arg(&path)
        .output()
        .unwrap();
    let peak = children_peak_kib();
    eprintln!("lint of a {size}-byte stage: peak {peak} KiB");
    std::fs::remove_dir_all(&dir).unwrap();
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["aovs"].as_array().unwrap().len(), 1, "{v}");
    assert_eq!(v["findings"], serde_json::json!([]), "{v}");
    assert!(
        peak < BOUND_KIB,
        "lint of a {size}-byte stage peaked at {peak} KiB (bound {BOUND_KIB} KiB)"
    );
}
