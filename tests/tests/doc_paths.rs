//! Every file or folder of the workspace that the user-facing docs name in backquotes
//! (`README.md`, `docs/*.md`, each folder's `README.md`) exists: a file that moved leaves
//! no stale path in the docs (the mutation-testing commands of docs/testing.md, for
//! instance, are run as written).
//!
//! A path counts when its first segment is a folder of the workspace: a top-level folder
//! that holds files git tracks (`git ls-files`), not whatever the checkout's directory
//! listing holds. A folder that builds and runs write (`out/` from `lpe-render`, whose
//! `out/converge` docs/accuracy.md names, `target/`) is untracked, so a path under it is
//! an output the docs describe, not a workspace path to check, whether or not a run has
//! made it. Left out as well: paths with a placeholder segment in capitals
//! (`fuzz/corpus/TARGET/`), globs, and what a build writes inside tracked folders
//! (`fuzz/target/`, a `build/` folder).

use std::collections::BTreeSet;
use std::fs;

use lpe_tests::imports::workspace;
use lpe_tests::tracked::{top_folders, tracked_files};

/// The markdown files users read, from the tracked list: the top `README.md`, each
/// top-level folder's, `docs/*.md` and `tests/testdata/README.md`.
fn docs(tracked: &[String]) -> Vec<&str> {
    tracked
        .iter()
        .map(String::as_str)
        .filter(|p| {
            let segs: Vec<&str> = p.split('/').collect();
            match segs[..] {
                ["README.md"] | [_, "README.md"] => true,
                ["docs", name] => name.ends_with(".md"),
                _ => *p == "tests/testdata/README.md",
            }
        })
        .collect()
}

/// The backquoted spans of `text` that look like workspace paths.
fn paths_in(text: &str, top: &BTreeSet<String>) -> Vec<String> {
    let mut out = Vec::new();
    for (i, span) in text.split('`').enumerate() {
        // Odd pieces are inside backquotes.
        if i % 2 == 0 || !span.contains('/') {
            continue;
        }
        let ok = |c: char| c.is_ascii_alphanumeric() || "_.-/".contains(c);
        if !span.chars().all(ok) {
            continue;
        }
        let segs: Vec<&str> = span.trim_end_matches('/').split('/').collect();
        let placeholder = segs
            .iter()
            .any(|s| s.len() > 1 && s.chars().all(|c| c.is_ascii_uppercase() || c == '_'));
        let built = segs.iter().any(|s| *s == "target" || *s == "build");
        if top.contains(segs[0]) && !placeholder && !built {
            out.push(span.to_string());
        }
    }
    out
}

#[test]
fn docs_name_only_paths_that_exist() {
    let ws = workspace();
    let tracked = tracked_files();
    let top = top_folders(&tracked);
    let docs = docs(&tracked);
    // Sanity: the doc list holds what it claims to.
    for doc in ["README.md", "docs/accuracy.md", "tests/testdata/README.md"] {
        assert!(docs.contains(&doc), "{doc} not read: {docs:?}");
    }
    let mut missing = Vec::new();
    let mut seen = 0;
    for doc in docs {
        let text = fs::read_to_string(ws.join(doc)).unwrap();
        for (n, line) in text.lines().enumerate() {
            for p in paths_in(line, &top) {
                seen += 1;
                if !ws.join(&p).exists() {
                    missing.push(format!("{doc}:{}: `{p}`", n + 1));
                }
            }
        }
    }
    // Sanity: the docs do name many paths (a reader that finds none checks nothing).
    assert!(seen > 100, "only {seen} paths found");
    assert!(
        missing.is_empty(),
        "paths the docs name that do not exist:\n{}",
        missing.join("\n")
    );
}

#[test]
fn the_reader_takes_paths_and_leaves_placeholders() {
    let top: BTreeSet<String> = ["lpe", "fuzz", "target"].map(String::from).into();
    let line = "see `lpe/src/aov.rs`, `fuzz/corpus/TARGET/`, `lpe/src/*.rs`, \
                `target/release/x`, `--flag a/b` and `other/x.rs`";
    assert_eq!(paths_in(line, &top), ["lpe/src/aov.rs"]);
}

/// Planted fault: fails when the workspace's folders come from the directory listing
/// (every folder of the checkout) rather than the tracked files: checked by hand, passing
/// the listing's folders (with `out`) to `paths_in`. The same fault failed
/// `docs_name_only_paths_that_exist` on a checkout where `lpe-render` had written `out/`.
#[test]
fn an_untracked_output_folder_is_no_workspace_folder() {
    let tracked = ["docs/accuracy.md", "render/src/main.rs"].map(String::from);
    let top = top_folders(&tracked);
    let line = "writes `out/converge/table.md` from `render/src/main.rs`";
    assert_eq!(paths_in(line, &top), ["render/src/main.rs"]);
}
