//! `fuzz/sancov-scope`, the rustc wrapper of fuzz builds: a crate whose source is outside
//! the repository loses the coverage flags and keeps every other flag in order; a crate
//! of the repository keeps every flag but comparison tracing, which it keeps too with
//! `LPE_FUZZ_TRACE_COMPARES=1`; a call with no crate root keeps every flag. And
//! `fuzz/run`, which sets the wrapper up: what it hands to cargo.
#![cfg(unix)]

use std::path::{Path, PathBuf};
use std::process::Command;

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

const TRACE_COMPARES: &str = "-Cllvm-args=-sanitizer-coverage-trace-compares";

const COVERAGE: [&str; 3] = [
    "-Cpasses=sancov-module",
    "-Cllvm-args=-sanitizer-coverage-level=4",
    TRACE_COMPARES,
];

/// The arguments the wrapper hands to "rustc" (here `echo`), run from `cwd`, with
/// comparison tracing asked for or not.
fn passed_with(cwd: &Path, args: &[&str], trace_compares: bool) -> Vec<String> {
    let mut cmd = Command::new("sh");
    cmd.arg(repo().join("fuzz/sancov-scope"))
        .arg("echo")
        .args(args)
        .current_dir(cwd);
    if trace_compares {
        cmd.env("LPE_FUZZ_TRACE_COMPARES", "1");
    } else {
        cmd.env_remove("LPE_FUZZ_TRACE_COMPARES");
    }
    stdout_of(&mut cmd)
        .split_whitespace()
        .map(str::to_string)
        .collect()
}

/// What `cmd` printed, once it has run and succeeded.
fn stdout_of(cmd: &mut Command) -> String {
    let out = cmd.output().expect("sh runs");
    assert!(out.status.success(), "{out:?}");
    String::from_utf8(out.stdout).unwrap()
}

fn passed(cwd: &Path, args: &[&str]) -> Vec<String> {
    passed_with(cwd, args, false)
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
    let want: Vec<&str> = strs(&args)
        .into_iter()
        .filter(|a| !COVERAGE.contains(a))
        .collect();
    for trace_compares in [false, true] {
        let got = passed_with(&std::env::temp_dir(), &strs(&args), trace_compares);
        assert_eq!(got, want, "trace compares asked for: {trace_compares}");
        assert!(got.contains(&"-Zsanitizer=address".to_string()));
    }
}

#[test]
fn a_crate_of_the_repository_keeps_every_flag_but_comparison_tracing_unless_asked() {
    // Cargo names a workspace member's root relative to its directory, a path
    // dependency's absolutely.
    let relative = rustc_args("src/lib.rs");
    let absolute = rustc_args(repo().join("engines/src/lib.rs").to_str().unwrap());
    for (cwd, args) in [
        (repo().join("lpe"), &relative),
        (std::env::temp_dir(), &absolute),
    ] {
        let without: Vec<&str> = strs(args)
            .into_iter()
            .filter(|a| *a != TRACE_COMPARES)
            .collect();
        assert_eq!(without.len() + 1, args.len());
        assert_eq!(passed(&cwd, &strs(args)), without);
        assert_eq!(passed_with(&cwd, &strs(args), true), *args);
    }
}

#[test]
fn a_call_without_a_crate_root_passes_through() {
    assert_eq!(passed(&std::env::temp_dir(), &["-vV"]), ["-vV"]);
}

/// What `fuzz/run` hands to cargo (here a fake `cargo` that prints its environment and
/// arguments), with `ASAN_OPTIONS` set to `asan` or unset.
fn run_env(asan: Option<&str>) -> Vec<String> {
    let bin = std::env::temp_dir().join(format!("lpe-fuzz-run-{}", std::process::id()));
    std::fs::create_dir_all(&bin).unwrap();
    let cargo = bin.join("cargo");
    std::fs::write(
        &cargo,
        "#!/bin/sh\nprintf '%s\\n' \"ASAN_OPTIONS=$ASAN_OPTIONS\" \"RUSTFLAGS=$RUSTFLAGS\" \
         \"RUSTC_WRAPPER=$RUSTC_WRAPPER\" \"$@\"\n",
    )
    .unwrap();
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&cargo, std::fs::Permissions::from_mode(0o755)).unwrap();
    let path = format!(
        "{}:{}",
        bin.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let mut cmd = Command::new("sh");
    cmd.arg(repo().join("fuzz/run"))
        .args(["run", "differential"])
        .env("PATH", path)
        .env_remove("RUSTFLAGS")
        .env_remove("LPE_FUZZ_TRACE_COMPARES");
    match asan {
        Some(a) => cmd.env("ASAN_OPTIONS", a),
        None => cmd.env_remove("ASAN_OPTIONS"),
    };
    let out = stdout_of(&mut cmd);
    std::fs::remove_dir_all(&bin).unwrap();
    out.lines().map(str::to_string).collect()
}

#[test]
fn fuzz_run_trims_asan_diagnostics_and_lets_the_callers_options_win() {
    const TRIMMED: &str = "malloc_context_size=0:detect_stack_use_after_return=0";
    let wrapper = repo().join("fuzz/sancov-scope");
    let rest = [
        "RUSTFLAGS=--cfg=sancov_scope_edges".to_string(),
        format!("RUSTC_WRAPPER={}", wrapper.display()),
        "+nightly".into(),
        "fuzz".into(),
        "run".into(),
        "differential".into(),
    ];
    let got = run_env(None);
    assert_eq!(got[0], format!("ASAN_OPTIONS={TRIMMED}"));
    assert_eq!(got[1..], rest);
    // AddressSanitizer reads its options in order, a later value replacing an earlier.
    let got = run_env(Some("malloc_context_size=30:detect_leaks=0"));
    assert_eq!(
        got[0],
        format!("ASAN_OPTIONS={TRIMMED}:malloc_context_size=30:detect_leaks=0")
    );
    assert_eq!(got[1..], rest);
}
