//! No import loops between files, in any crate of the workspace, and `lpe`'s layers.
//!
//! Every crate named in the root `Cargo.toml`'s `members` is read (so a new crate is
//! covered without touching this file). Within a crate, each source file under `src/` is a
//! node; an edge `a.rs -> b.rs` means `a.rs` names something that `b.rs` defines. A loop
//! of such edges (files that need each other, directly or through others) fails the test,
//! with every loop listed as its files and the paths that tie them.
//!
//! A child that takes an item from its parent module (`use super::Error`) while the
//! parent calls into the child (`child::run()`, `pub use child::Item`) is a loop like any
//! other: the shared item belongs in a leaf both import.
//!
//! Loops known and not yet cleared are listed in [`NOT_YET_CLEARED`]; the test fails on
//! any other loop, and on an entry there that no longer is one (so the list only shrinks).
//!
//! `LAYERING_EDGES=1 cargo test -p lpe-tests --test layering -- --nocapture` prints every
//! edge with the path that makes it.
//!
//! `lpe`'s top-level modules form layers of their own: no module reaches, directly or
//! through others, back into itself (such as the automata needing the facade that builds
//! them), and no shared module (the automata, the facade, the analyses, set algebra, the
//! dialect trait) reaches a dialect's folder, so a third dialect is a folder of its own and
//! never a change below the seam. These read the same file graph, each file standing for
//! its top-level module (`lpe/src/lib.rs`, which declares and re-exports them all, is
//! left out).

use std::collections::{BTreeMap, BTreeSet};

use lpe_tests::imports::{graph, loops};

#[test]
fn no_file_imports_itself_through_others() {
    let (edges, read) = graph();
    // Sanity: the scan covers every member and sees edges of each kind it claims to.
    for krate in [
        "lpe",
        "engines",
        "cli",
        "render",
        "lint",
        "capi",
        "reference",
    ] {
        assert!(
            read.iter().any(|f| f.starts_with(&format!("{krate}/src/"))),
            "{krate}: {read:#?}"
        );
    }
    let has = |a: &str, b: &str| edges.contains_key(&(a.to_string(), b.to_string()));
    // `use crate::{..}` groups, `super::`, re-exports resolved to the defining file.
    assert!(
        has("lpe/src/aov.rs", "lpe/src/automata/mask.rs"),
        "{edges:#?}"
    );
    if std::env::var_os("LAYERING_EDGES").is_some() {
        for ((a, b), why) in &edges {
            println!("{a} -> {b}: {why}");
        }
    }
    let test_file = "lpe/src/renderman/syntax/tests.rs";
    assert!(
        lpe_tests::imports::workspace().join(test_file).is_file(),
        "{test_file} moved: name another test file here"
    );
    assert!(!read.contains(test_file), "test files are left out");
    let found = loops(&edges);
    let known: Vec<Vec<String>> = NOT_YET_CLEARED
        .iter()
        .map(|l| l.iter().map(|f| f.to_string()).collect())
        .collect();
    let new: Vec<&Vec<String>> = found.iter().filter(|l| !known.contains(l)).collect();
    let mut msg = String::new();
    if !new.is_empty() {
        msg += &format!("{} import loop(s) between files:\n", new.len());
        for comp in &new {
            msg += &format!("- loop of {} files: {}\n", comp.len(), comp.join(", "));
            for ((a, b), why) in &edges {
                if comp.contains(a) && comp.contains(b) {
                    msg += &format!("    {a} -> {b}: {why}\n");
                }
            }
        }
    }
    for gone in known.iter().filter(|l| !found.contains(l)) {
        msg += &format!(
            "not a loop (any more), take it off NOT_YET_CLEARED: {}\n",
            gone.join(", ")
        );
    }
    assert!(msg.is_empty(), "{msg}");
}

/// Loops that stand today and are to be cleared, each as its files in sorted order; the
/// test fails on any other loop, and on an entry here that is no loop any more.
const NOT_YET_CLEARED: &[&[&str]] = &[];

/// `lpe`'s top-level modules and, for each, the ones its files name (itself left out).
fn lpe_modules() -> BTreeMap<String, BTreeSet<String>> {
    let (edges, read) = graph();
    let module = |file: &str| -> Option<String> {
        let rel = file.strip_prefix("lpe/src/")?;
        let first = rel.split('/').next()?;
        (first != "lib.rs").then(|| first.trim_end_matches(".rs").to_string())
    };
    let mut out: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for f in &read {
        if let Some(m) = module(f) {
            out.entry(m).or_default();
        }
    }
    for (a, b) in edges.keys() {
        if let (Some(from), Some(to)) = (module(a), module(b)) {
            if from != to {
                out.entry(from).or_default().insert(to);
            }
        }
    }
    out
}

#[test]
fn lpe_top_level_modules_have_no_cycles() {
    let modules = lpe_modules();
    // Sanity: the graph sees the layering it is meant to guard.
    assert!(modules["aov"].contains("automata"), "{modules:#?}");
    assert!(modules["analysis"].contains("aov"), "{modules:#?}");
    let mut edges = BTreeMap::new();
    for (from, tos) in &modules {
        for to in tos {
            edges.insert((from.clone(), to.clone()), String::new());
        }
    }
    let cycles = loops(&edges);
    assert!(
        cycles.is_empty(),
        "lpe's top-level modules that reach each other: {cycles:?}"
    );
}

/// The dialect folders, the run-time registry of them and the translation between them:
/// what the shared layers must never reach.
const DIALECT_MODULES: [&str; 4] = ["renderman", "osl", "registry", "translate"];

#[test]
fn lpe_shared_layers_know_no_dialect() {
    let modules = lpe_modules();
    // Sanity: the dialects do use the shared layers.
    assert!(modules["renderman"].contains("dialect"), "{modules:#?}");
    assert!(modules["osl"].contains("automata"), "{modules:#?}");
    for from in modules
        .keys()
        .filter(|m| !DIALECT_MODULES.contains(&m.as_str()))
    {
        let mut seen = BTreeSet::new();
        let mut stack = vec![from.as_str()];
        while let Some(m) = stack.pop() {
            for next in modules.get(m).into_iter().flatten() {
                assert!(
                    !DIALECT_MODULES.contains(&next.as_str()),
                    "the shared module `{from}` reaches the dialect module `{next}` (via `{m}`)"
                );
                if seen.insert(next.as_str()) {
                    stack.push(next);
                }
            }
        }
    }
}
