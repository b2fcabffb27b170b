//! No import loops between files, no import running back up at any folder, in any crate
//! of the workspace, and `lpe`'s layers.
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
//! No import runs back up, in any crate, at any folder: at each folder under a crate's
//! `src/`, the graph among its children (a file `x.rs`, or a folder `x/` with its module
//! file, standing for everything beneath it; [`lpe_tests::folders`]) has no cycle. A
//! cycle fails the test as its folder, its children, an order of them as layers and the
//! file edges (with the paths that make them) that run back up against it. Cycles known
//! and not yet cleared are listed in [`FOLDER_CYCLES_NOT_YET_CLEARED`], which only
//! shrinks, as [`NOT_YET_CLEARED`] does.
//!
//! `lpe`'s top-level modules form layers of their own: no module reaches, directly or
//! through others, back into itself (such as the automata needing the facade that builds
//! them: the folder check at `lpe/src/`), and no shared module (the automata, the facade,
//! the analyses, set algebra, the dialect trait) reaches a dialect's folder, so a third
//! dialect is a folder of its own and never a change below the seam. The latter reads
//! the children of `lpe/src/` (`lpe/src/lib.rs`, which declares and re-exports them all,
//! left out).

use std::collections::{BTreeMap, BTreeSet};

use lpe_tests::folders::{child_graph, cycles};
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

/// `lpe`'s top-level modules and, for each, the ones its files name (itself left out):
/// the children of `lpe/src/` without their `.rs` or `/`, `lib.rs` (which declares and
/// re-exports them all) left out.
fn lpe_modules() -> BTreeMap<String, BTreeSet<String>> {
    let (edges, read) = graph();
    let module = |child: &str| -> Option<String> {
        let name = child.strip_suffix(".rs").or(child.strip_suffix('/'))?;
        (name != "lib").then(|| name.to_string())
    };
    let mut out: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for f in &read {
        let top = f
            .strip_prefix("lpe/src/")
            .map(|rel| match rel.split_once('/') {
                Some((dir, _)) => format!("{dir}/"),
                None => rel.to_string(),
            });
        if let Some(m) = top.as_deref().and_then(module) {
            out.entry(m).or_default();
        }
    }
    let children = child_graph(&edges, &read);
    for (from, to) in children.get("lpe/src/").into_iter().flat_map(|g| g.keys()) {
        if let (Some(from), Some(to)) = (module(from), module(to)) {
            out.entry(from).or_default().insert(to);
        }
    }
    out
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
    assert!(modules["analysis"].contains("aov"), "{modules:#?}");
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

/// Planted faults: fails on a new folder cycle (checked by hand: `lpe/src/automata/mask.rs`
/// naming `crate::aov::AovSet` in a function, so the automata reach back into the facade
/// built on them), and on an entry of
/// [`FOLDER_CYCLES_NOT_YET_CLEARED`] that is no cycle (checked by adding
/// `("lpe/src/", &["aov.rs", "automata/"])`).
#[test]
fn no_import_runs_back_up_at_any_folder() {
    let (edges, read) = graph();
    let graphs = child_graph(&edges, &read);
    // Sanity: every crate's `src/` and folders below it are seen, with their edges.
    for folder in [
        "lpe/src/",
        "lpe/src/automata/",
        "engines/src/",
        "cli/src/",
        "render/src/",
        "lint/src/",
    ] {
        assert!(
            graphs.get(folder).is_some_and(|g| !g.is_empty()),
            "no child edges seen at {folder}: {:#?}",
            graphs.keys().collect::<Vec<_>>()
        );
    }
    assert!(
        graphs["lpe/src/"].contains_key(&("aov.rs".to_string(), "automata/".to_string())),
        "{:#?}",
        graphs["lpe/src/"].keys().collect::<Vec<_>>()
    );
    let found = cycles(&edges, &read);
    let is_known = |folder: &str, members: &[String]| {
        FOLDER_CYCLES_NOT_YET_CLEARED
            .iter()
            .any(|(f, m)| *f == folder && m.iter().eq(members.iter()))
    };
    let mut msg = String::new();
    for c in found.iter().filter(|c| !is_known(&c.folder, &c.members)) {
        msg += &format!(
            "- in {}: {} reach each other; taken as layers {}, these imports run back up:\n",
            c.folder,
            c.members.join(", "),
            c.layers.join(" > "),
        );
        for (a, b, why) in &c.back_up {
            msg += &format!("    {a} -> {b}: {why}\n");
        }
        msg += &format!(
            "  ({} file edges among them in all; LAYERING_EDGES=1 prints every edge)\n",
            c.edges.len()
        );
    }
    for (folder, members) in FOLDER_CYCLES_NOT_YET_CLEARED {
        if !found
            .iter()
            .any(|c| c.folder == *folder && c.members.iter().eq(members.iter()))
        {
            msg += &format!(
                "not a cycle (any more), take it off FOLDER_CYCLES_NOT_YET_CLEARED: \
                 {folder} {members:?}\n"
            );
        }
    }
    assert!(msg.is_empty(), "{msg}");
}

/// Folder cycles that stand today and are to be cleared, each as its folder and its
/// children in sorted order; the test fails on any other, and on an entry here that is
/// no cycle any more.
const FOLDER_CYCLES_NOT_YET_CLEARED: &[(&str, &[&str])] = &[];
