//! Every file or folder of the workspace that the user-facing docs name in backquotes
//! (`README.md`, `docs/*.md`, each folder's `README.md`) exists: a file that moved leaves
//! no stale path in the docs (the mutation-testing commands of docs/testing.md, for
//! instance, are run as written).
//!
//! A path counts when its first segment is a folder of the workspace. Left out: paths
//! with a placeholder segment in capitals (`fuzz/corpus/TARGET/`), globs, and what a build
//! writes (`target/`, a `build/` folder).

use std::fs;
use std::path::{Path, PathBuf};

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

/// The markdown files users read.
fn docs(ws: &Path) -> Vec<PathBuf> {
    let mut out = vec![ws.join("README.md")];
    let mut dirs: Vec<PathBuf> = fs::read_dir(ws)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_dir())
        .collect();
    dirs.sort();
    for d in &dirs {
        if d.join("README.md").is_file() {
            out.push(d.join("README.md"));
        }
    }
    for e in fs::read_dir(ws.join("docs")).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_some_and(|x| x == "md") {
            out.push(p);
        }
    }
    out.push(ws.join("tests/testdata/README.md"));
    out
}

/// The backquoted spans of `text` that look like workspace paths.
fn paths_in(text: &str, top: &[String]) -> Vec<String> {
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
        if top.iter().any(|t| t == segs[0]) && !placeholder && !built {
            out.push(span.to_string());
        }
    }
    out
}

#[test]
fn docs_name_only_paths_that_exist() {
    let ws = workspace();
    let top: Vec<String> = fs::read_dir(&ws)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_dir())
        .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
        .filter(|n| !n.starts_with('.') && n != "target")
        .collect();
    let mut missing = Vec::new();
    let mut seen = 0;
    for doc in docs(&ws) {
        let text = fs::read_to_string(&doc).unwrap();
        for (n, line) in text.lines().enumerate() {
            for p in paths_in(line, &top) {
                seen += 1;
                if !ws.join(&p).exists() {
                    let rel = doc.strip_prefix(&ws).unwrap().display().to_string();
                    missing.push(format!("{rel}:{}: `{p}`", n + 1));
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
    let top = vec!["lpe".to_string(), "fuzz".to_string(), "target".to_string()];
    let line = "see `lpe/src/aov.rs`, `fuzz/corpus/TARGET/`, `lpe/src/*.rs`, \
                `target/release/x`, `--flag a/b` and `other/x.rs`";
    assert_eq!(paths_in(line, &top), ["lpe/src/aov.rs"]);
}
