//! `fuzz/sancov-scope`, the rustc wrapper of fuzz builds: a crate whose source is outside
//! the repository loses the coverage flags and keeps every other flag in order; a crate
//! of the repository, or a call with no crate root, keeps every flag.
#![cfg(unix)]

use std::path::{Path, PathBuf};
use std::process::Command;

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

const COVERAGE: [&str; 3] = [
    "-Cpasses=sancov-module",
    "-Cllvm-args=-sanitizer-coverage-level=4",
    "-Cllvm-args=-sanitizer-coverage-trace-compares",
];

/// The arguments the wrapper hands to "rustc" (here `echo`), run from `cwd`.
fn passed(cwd: &Path, args: &[&str]) -> Vec<String> {
    let out = Command::new("sh")
        .arg(repo().join("fuzz/sancov-scope"))
        .arg("echo")
        .args(args)
        .current_dir(cwd)
        .output()
        .expect("sh runs");
    assert!(out.status.success(), "{out:?}");
    String::from_utf8(out.stdout)
        .unwrap()
        .split_whitespace()
        .map(str::to_string)
        .collect()
}

fn rustc_args(root: &str) -> Vec<String> {
    let mut args = vec!["--crate-name".to_string(), "x".into(), root.into()];
    args.push("-Zsanitizer=address".into());
    args.extend(COVERAGE.map(String::from));
    args.push("-Cllvm-args=-simplifycfg-branch-fold-threshold=0".into());
    args
}

fn strs(v: &[String]) -> Vec<&str> {
    v.iter().map(String::as_str).collect()
}

#[test]
fn a_crate_from_outside_the_repository_loses_only_the_coverage_flags() {
    let root = "/cargo-home/registry/src/index/regex-automata-0.4.18/src/lib.rs";
    let args = rustc_args(root);
    let got = passed(&std::env::temp_dir(), &strs(&args));
    let want: Vec<&str> = strs(&args)
        .into_iter()
        .filter(|a| !COVERAGE.contains(a))
        .collect();
    assert_eq!(got, want);
    assert!(got.contains(&"-Zsanitizer=address".to_string()));
}

#[test]
fn a_crate_of_the_repository_keeps_every_flag() {
    // Cargo names a workspace member's root relative to its directory, a path
    // dependency's absolutely.
    let relative = rustc_args("src/lib.rs");
    assert_eq!(passed(&repo().join("lpe"), &strs(&relative)), relative);
    let absolute = rustc_args(repo().join("engines/src/lib.rs").to_str().unwrap());
    assert_eq!(passed(&std::env::temp_dir(), &strs(&absolute)), absolute);
}

#[test]
fn a_call_without_a_crate_root_passes_through() {
    assert_eq!(passed(&std::env::temp_dir(), &["-vV"]), ["-vV"]);
}
