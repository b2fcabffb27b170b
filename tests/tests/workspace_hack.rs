//! Every build CI runs selects the same features of every third-party crate, so that no
//! build compiles the dependency graph again for itself. Cargo unifies features only over
//! the packages one command selects: without `lpe-workspace-hack` (written by `cargo
//! hakari`), `cargo run -p lpe-render` and `cargo test --workspace` chose different
//! features of `serde`, `either` and `rustix`, and so rebuilt `openusd`, `image`, `exr`,
//! `lpe-lint` and the renderer a second time, and `cargo build -p lpe-cli` a third.
//!
//! The test asks `cargo tree` (no build) for the features each selection resolves and
//! compares them crate by crate. On the tree before the workspace hack the same
//! comparison found 75 differences (`serde`, `either`, `rustix`, `syn`, `regex-automata`).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::Command;

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("tests/ sits in the workspace")
        .to_path_buf()
}

/// The builds of `.ci/run` and the README, as `cargo` arguments, each with the dependency
/// kinds it compiles (a `cargo run` or `build` compiles no dev-dependencies).
const SELECTIONS: [(&[&str], &str); 5] = [
    (&["-p", "lpe-render"], "normal,build"),
    (&["--workspace"], "normal,build,dev"),
    (
        &["-p", "lpe-render", "--features", "engines"],
        "normal,build,dev",
    ),
    (&["-p", "lpe-cli"], "normal,build"),
    (
        &["-p", "lpe-python", "--features", "extension-module"],
        "normal,build",
    ),
];

/// pyo3's `extension-module` feature belongs to the maturin build alone (the workspace's
/// tests link libpython, which that feature leaves out), so the Python extension's build
/// recompiles pyo3 on purpose.
const BUILT_DIFFERENTLY_ON_PURPOSE: [&str; 3] = ["pyo3", "pyo3-ffi", "pyo3-build-config"];

/// Third-party crate (name and version) -> the feature sets `cargo tree` shows for it
/// (one per build context: a crate built for a build script may differ from the same
/// crate linked into a binary, consistently in every selection).
fn resolved(args: &[&str], edges: &str) -> BTreeMap<String, BTreeSet<String>> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".to_string());
    let out = Command::new(cargo)
        .current_dir(workspace())
        .args([
            "tree", "--locked", "--prefix", "none", "--format", "{p}|{f}",
        ])
        .args(["--target", "x86_64-unknown-linux-gnu", "-e", edges])
        .args(args)
        .output()
        .expect("cargo tree runs");
    assert!(
        out.status.success(),
        "cargo tree {args:?} failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut map: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for line in String::from_utf8_lossy(&out.stdout).lines() {
        let Some((package, features)) = line.split_once('|') else {
            continue;
        };
        // Workspace members print their path: `lpe-cli v0.1.0 (/work/cli)`.
        if package.contains('(') {
            continue;
        }
        let name = package.split(' ').next().unwrap_or_default();
        if BUILT_DIFFERENTLY_ON_PURPOSE.contains(&name) {
            continue;
        }
        let features = features.trim_end_matches(" (*)").to_string();
        map.entry(package.trim().to_string())
            .or_default()
            .insert(features);
    }
    map
}

#[test]
fn every_ci_build_selects_the_same_third_party_features() {
    let resolutions: Vec<(String, BTreeMap<String, BTreeSet<String>>)> = SELECTIONS
        .iter()
        .map(|(args, edges)| (args.join(" "), resolved(args, edges)))
        .collect();
    let mut differences = Vec::new();
    for (i, (a, ra)) in resolutions.iter().enumerate() {
        for (b, rb) in &resolutions[i + 1..] {
            for (package, fa) in ra {
                if let Some(fb) = rb.get(package) {
                    if fa != fb {
                        differences.push(format!(
                            "{package}: `{a}` selects {fa:?}, `{b}` selects {fb:?}"
                        ));
                    }
                }
            }
        }
    }
    assert!(
        differences.is_empty(),
        "CI's builds select different features of third-party crates, so each recompiles \
         them: run `cargo hakari generate && cargo hakari manage-deps` (cargo install \
         cargo-hakari --locked)\n{}",
        differences.join("\n")
    );
}
