//! Every test docs/testing.md names as a killer or a guard is defined somewhere in the
//! workspace: a test that was renamed, or never committed, leaves no claim in the docs
//! that nothing backs.
//!
//! A name counts when it is a backquoted snake_case word of four parts or more
//! (`the_restart_budget_is_exact`), alone or as the last segment of a module path
//! (`minimize::tests::the_failure_test_is_asked_at_most_the_try_budget`), in a span that
//! is no file path. It is defined
//! when some `.rs` file has `fn NAME` or some `.py` file has `def NAME`. Folders that a
//! build or a tool writes (`target`, dot folders, virtual environments) are not read.

use std::collections::BTreeSet;
use std::fs;
use std::path::{Path, PathBuf};

use lpe_tests::imports::workspace;

/// The test-like names in the backquoted spans of `text`.
fn names_in(text: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for (i, span) in text.split('`').enumerate() {
        // Odd pieces are inside backquotes; a path names a file, not a test.
        if i % 2 == 0 || span.contains('/') {
            continue;
        }
        for word in span.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')) {
            let parts: Vec<&str> = word.split('_').collect();
            let snake = parts.len() >= 4
                && word.starts_with(|c: char| c.is_ascii_lowercase())
                && parts.iter().all(|p| {
                    !p.is_empty()
                        && p.chars()
                            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit())
                });
            if snake {
                out.insert(word.to_string());
            }
        }
    }
    out
}

/// The `.rs` and `.py` files under `dir`, skipping build output and tool folders.
fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy();
        if path.is_dir() {
            let skipped = name.starts_with('.') || name == "target" || name.contains("venv");
            if !skipped {
                sources(&path, out);
            }
        } else if path.extension().is_some_and(|e| e == "rs" || e == "py") {
            out.push(path);
        }
    }
}

/// The names defined by `fn NAME` or `def NAME` in `text`.
fn defined_in(text: &str, out: &mut BTreeSet<String>) {
    for keyword in ["fn ", "def "] {
        for (at, _) in text.match_indices(keyword) {
            let before = text[..at].chars().next_back();
            if before.is_some_and(|c| c.is_alphanumeric() || c == '_') {
                continue;
            }
            let name: String = text[at + keyword.len()..]
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            out.insert(name);
        }
    }
}

#[test]
fn every_test_the_testing_doc_names_is_defined() {
    let ws = workspace();
    let mut named = names_in(&fs::read_to_string(ws.join("docs/testing.md")).unwrap());
    named.extend(names_in(
        &fs::read_to_string(ws.join("docs/mutants.toml")).unwrap(),
    ));
    // Sanity: the doc names many tests (a reader that finds none checks nothing).
    assert!(named.len() > 100, "only {} names found", named.len());
    let mut files = Vec::new();
    sources(&ws, &mut files);
    let mut defined = BTreeSet::new();
    for f in &files {
        defined_in(&fs::read_to_string(f).unwrap(), &mut defined);
    }
    let missing: Vec<&String> = named.difference(&defined).collect();
    assert!(
        missing.is_empty(),
        "tests docs/testing.md names that no `fn` or `def` defines:\n{missing:?}"
    );
}

#[test]
fn the_reader_takes_test_names_and_leaves_other_words() {
    let line = "`minimize::tests::the_failure_test_is_asked`, `a_b_c`, `lpe/src/x_y_z_w.rs`, \
                `Big_Name_Is_Not`, `two_words_only` and outside the_quote_is_not_read, \
                `cases_of_10_items`";
    let got: Vec<String> = names_in(line).into_iter().collect();
    assert_eq!(got, ["cases_of_10_items", "the_failure_test_is_asked"]);
    let mut defined = BTreeSet::new();
    defined_in(
        "fn a_b() {}\ndef test_c_d(x):\n    pass\nlet xfn q = 1;\npub(crate) fn e_f<T>()",
        &mut defined,
    );
    let got: Vec<String> = defined.into_iter().collect();
    assert_eq!(got, ["a_b", "e_f", "test_c_d"]);
}
