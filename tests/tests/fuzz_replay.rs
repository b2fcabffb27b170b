//! Replays every committed fuzz input on stable: `fuzz/corpus/TARGET/*` and
//! `fuzz/regressions/TARGET/*` through the same function the fuzz target calls
//! (`lpe_engines::fuzzing`). A regression file is a crash input saved by a campaign; it
//! must pass once the bug is fixed.

use std::path::PathBuf;

fn replay(kind: &str) -> usize {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../fuzz")
        .join(kind);
    let Ok(targets) = std::fs::read_dir(&root) else {
        return 0;
    };
    let mut n = 0;
    for dir in targets.flatten() {
        if !dir.path().is_dir() {
            continue; // README, .gitkeep
        }
        let name = dir.file_name().to_string_lossy().into_owned();
        let Some(body) = lpe_engines::fuzzing::target(&name) else {
            panic!("{}: no fuzz target called `{name}`", root.display());
        };
        for file in std::fs::read_dir(dir.path()).unwrap().flatten() {
            let data = std::fs::read(file.path()).unwrap();
            let r = std::panic::catch_unwind(|| body(&data));
            assert!(r.is_ok(), "{} fails", file.path().display());
            n += 1;
        }
    }
    n
}

#[test]
fn corpus_files_pass() {
    let n = replay("corpus");
    assert!(n > 0, "no corpus files found under fuzz/corpus");
}

#[test]
fn regression_files_pass() {
    // A missing or misnamed folder would otherwise pass with nothing replayed;
    // fuzz/regressions/differential has a committed file.
    let n = replay("regressions");
    assert!(n > 0, "no regression files found under fuzz/regressions");
}

/// A differential input that only the reference could build passes `replay` without
/// comparing anything, so the corpus must mostly be inputs where engines are compared.
#[test]
fn differential_corpus_files_compare_engines() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../fuzz/corpus");
    for name in ["differential", "aov_set", "osl_differential"] {
        let compared = lpe_engines::fuzzing::compared_target(name).unwrap();
        let (mut n, mut uncompared) = (0usize, 0usize);
        for file in std::fs::read_dir(root.join(name)).unwrap().flatten() {
            let data = std::fs::read(file.path()).unwrap();
            n += 1;
            if !compared(&data) {
                uncompared += 1;
            }
        }
        eprintln!("{name}: {uncompared} of {n} corpus files uncompared");
        assert!(n > 0, "no corpus files for {name}");
        assert_eq!(uncompared, 0, "{name}: {uncompared} of {n} uncompared");
    }
}
