//! CI runs the README's quick start exactly as a newcomer does: the commands of README.md's
//! first `sh` block under "Quick start", in that order, as the first commands `.ci/run`
//! runs, before anything else can write into the fresh clone (a build, a venv, a render
//! into `out/`). A newcomer who renders first and then tests must see what CI saw.
//!
//! Checked against planted faults: swapping the two commands in `.ci/run`, adding
//! `--features lpe-render/engines` to CI's test command, and moving `cargo fmt` or a
//! `python3 -m venv` above them each fail `ci_runs_the_quick_start_first`.

use std::fs;
use std::path::{Path, PathBuf};

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("tests/ sits in the workspace")
        .to_path_buf()
}

/// The commands of the first ```` ```sh ```` block after the `## Quick start` heading,
/// comments and blank lines left out.
fn quick_start(readme: &str) -> Vec<String> {
    let after = readme
        .split_once("## Quick start")
        .expect("README.md has a `## Quick start` section")
        .1;
    let block = after
        .split_once("```sh\n")
        .expect("the quick start has a ```sh block")
        .1
        .split_once("```")
        .expect("the ```sh block is closed")
        .0;
    block
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .map(str::to_string)
        .collect()
}

/// The commands `script` runs, in order: lines that are neither comments, blank, nor
/// shell plumbing that writes nothing (`set`, `cd`, `export`, `echo`).
fn commands(script: &str) -> Vec<String> {
    script
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .filter(|l| {
            let word = l.split_whitespace().next().unwrap_or("");
            !matches!(word, "set" | "cd" | "export" | "echo")
        })
        .map(str::to_string)
        .collect()
}

#[test]
fn ci_runs_the_quick_start_first() {
    let ws = workspace();
    let readme = fs::read_to_string(ws.join("README.md")).expect("README.md");
    let ci = fs::read_to_string(ws.join(".ci/run")).expect(".ci/run");
    let quick = quick_start(&readme);
    assert_eq!(
        quick,
        [
            "cargo run --release -p lpe-render",
            "cargo test --workspace --release"
        ],
        "README.md's quick start changed: update this test and .ci/run together"
    );
    let run = commands(&ci);
    assert!(
        run.len() > quick.len(),
        ".ci/run runs more than the quick start: {run:#?}"
    );
    assert_eq!(
        run[..quick.len()],
        quick[..],
        ".ci/run must start with the README's quick start, exactly and in order"
    );
}

#[test]
fn the_readers_take_what_they_should() {
    let readme = "# x\n## Quick start\n\n```sh\n# render\ncargo a\n\n# test\ncargo b\n```\n```sh\ncargo c\n```\n";
    assert_eq!(quick_start(readme), ["cargo a", "cargo b"]);
    let script = "#!/bin/sh\nset -e\ncd x\nexport A=1\necho \"== a\"\n  # note\ncargo a\npython3 -m venv v\n";
    assert_eq!(commands(script), ["cargo a", "python3 -m venv v"]);
}
