//! The crate's top-level modules form layers: no module reaches, directly or through
//! others, back into itself. A cycle (such as the automata needing the facade that builds
//! them) makes the layers impossible to read or test bottom-up, so it fails here.
//!
//! Edges are every `crate::NAME` a file mentions outside comments and unit tests, `NAME`
//! a top-level module, or an item the crate root re-exports from one (`crate::AovSet` ->
//! `aov`).
//!
//! The dialects sit on top of the shared layers: no shared module (the automata, the
//! facade, the analyses, set algebra, the dialect trait) reaches a dialect's folder, so
//! a third dialect is a folder of its own and never a change below the seam.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The code of `src` without `//` comments (doc comments cite paths that are not uses)
/// and without its unit tests: a file's `#[cfg(test)] mod tests` (always its last item)
/// may use any layer, since tests of a shared layer need some dialect to build inputs.
fn code(src: &str) -> String {
    let lines: Vec<&str> = src.lines().collect();
    let end = lines
        .windows(2)
        .position(|w| w[0].trim() == "#[cfg(test)]" && w[1].trim_start().starts_with("mod tests"))
        .unwrap_or(lines.len());
    lines[..end]
        .iter()
        .map(|l| l.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n")
}

fn identifier_after<'a>(s: &'a str, prefix: &str) -> Vec<&'a str> {
    s.match_indices(prefix)
        .map(|(i, _)| {
            let rest = &s[i + prefix.len()..];
            let end = rest
                .find(|c: char| !(c.is_alphanumeric() || c == '_'))
                .unwrap_or(rest.len());
            &rest[..end]
        })
        .collect()
}

/// Top-level module of each file, and the modules each one's code names.
fn edges() -> BTreeMap<String, BTreeSet<String>> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let module_of = |f: &Path| {
        let rel = f.strip_prefix(&src).unwrap();
        let first = rel
            .components()
            .next()
            .unwrap()
            .as_os_str()
            .to_str()
            .unwrap();
        first.trim_end_matches(".rs").to_string()
    };
    let modules: BTreeSet<String> = files.iter().map(|f| module_of(f)).collect();
    // Root re-exports: `pub use module::{A, B};` or `pub use module::A;`.
    let lib = code(&fs::read_to_string(src.join("lib.rs")).unwrap());
    let mut reexport = BTreeMap::new();
    for stmt in lib.split(';') {
        let Some(rest) = stmt.trim().strip_prefix("pub use ") else {
            continue;
        };
        let module = rest.split("::").next().unwrap().to_string();
        let items = rest[module.len()..].trim_start_matches("::");
        for item in items.trim_matches(|c| c == '{' || c == '}').split(',') {
            let name = item.split("::").last().unwrap().trim().to_string();
            reexport.insert(name, module.clone());
        }
    }
    let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for f in &files {
        let from = module_of(f);
        let text = code(&fs::read_to_string(f).unwrap());
        let mut named: Vec<&str> = identifier_after(&text, "crate::");
        // `use crate::{a, b::C}` names several.
        for (i, _) in text.match_indices("use crate::{") {
            let group = &text[i + "use crate::{".len()..];
            let group = &group[..group.find(';').unwrap_or(group.len())];
            named.extend(group.split(',').map(|s| {
                s.trim()
                    .split(|c: char| !(c.is_alphanumeric() || c == '_'))
                    .next()
                    .unwrap()
            }));
        }
        for name in named {
            let to = if modules.contains(name) {
                name.to_string()
            } else if let Some(m) = reexport.get(name) {
                m.clone()
            } else {
                continue;
            };
            if to != from && from != "lib" {
                edges.entry(from.clone()).or_default().insert(to);
            }
        }
    }
    edges
}

#[test]
fn top_level_modules_have_no_cycles() {
    let edges = edges();
    // Sanity: the scan sees the layering it is meant to guard.
    assert!(edges["aov"].contains("automata"), "{edges:?}");
    assert!(edges["analysis"].contains("aov"), "{edges:?}");
    // Depth-first search with colours: reaching a module still on the stack is a cycle.
    fn visit<'a>(
        m: &'a str,
        edges: &'a BTreeMap<String, BTreeSet<String>>,
        stack: &mut Vec<&'a str>,
        done: &mut BTreeSet<&'a str>,
    ) {
        if done.contains(m) {
            return;
        }
        if let Some(at) = stack.iter().position(|s| *s == m) {
            panic!("module cycle: {} -> {m}", stack[at..].join(" -> "));
        }
        stack.push(m);
        for next in edges.get(m).into_iter().flatten() {
            visit(next, edges, stack, done);
        }
        stack.pop();
        done.insert(m);
    }
    let mut done = BTreeSet::new();
    for m in edges.keys() {
        visit(m, &edges, &mut Vec::new(), &mut done);
    }
}

/// The dialect folders and the run-time registry of them: what the shared layers must
/// never reach.
const DIALECT_MODULES: [&str; 3] = ["renderman", "osl", "registry"];

#[test]
fn shared_layers_know_no_dialect() {
    let edges = edges();
    // Sanity: the dialects do use the shared layers.
    assert!(edges["renderman"].contains("dialect"), "{edges:?}");
    assert!(edges["osl"].contains("automata"), "{edges:?}");
    // Reachability from every shared module.
    // The test generators write expressions of every dialect: they stand above them.
    let above = ["generate", "strategy"];
    for (from, _) in edges
        .iter()
        .filter(|(m, _)| !DIALECT_MODULES.contains(&m.as_str()) && !above.contains(&m.as_str()))
    {
        let mut seen = BTreeSet::new();
        let mut stack = vec![from.as_str()];
        while let Some(m) = stack.pop() {
            for next in edges.get(m).into_iter().flatten() {
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
