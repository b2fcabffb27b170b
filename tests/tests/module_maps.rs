//! The module maps stay in sync with the code, as `capi/tests/header.rs` keeps the C
//! header in sync: for every crate of the workspace (the root `Cargo.toml`'s `members`,
//! so a new crate is covered without touching this file), every top-level module its
//! `src/lib.rs` declares (`src/main.rs` for a crate without a library) must be named
//!
//! - in that file's `//!` crate doc, as `` `name` `` or `` [`name`] ``, and
//! - in the README's workspace table, in the row(s) whose first cell is the crate's
//!   folder (`` `lpe/` ``), as `` `name` `` or `` `name/` ``.
//!
//! and the other way: every entry of a README row names a module or folder that exists.
//! An entry is a backquoted lowercase identifier, with or without a trailing `/`, outside
//! parentheses (`` `automata/` (`mask`: ...) `` has the entry `automata/`; what the
//! parentheses hold describes it: features, engine names, functions) and after the first
//! cell. It exists when a file `name.rs` or a folder `name/` is anywhere under the crate's
//! `src/`, a file or folder of that name is in the crate's folder (`benches/`), or it
//! names a workspace crate by its folder (`lpe`). So a module that moved to another crate
//! leaves no stale row. The `//!` docs are not read that way: they are prose naming
//! functions, C symbols and features beside the modules, and their `` [`x`] `` links are
//! rustdoc's to resolve.
//!
//! A declaration is a line starting at column 0 with `mod x;`, `pub mod x;` or
//! `pub(crate) mod x;` (attributes such as `#[cfg(...)]` on the lines before are allowed).
//! Inline modules (`mod x { ... }`) and modules named `tests` are test scaffolding and
//! are skipped.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the tests crate sits in the workspace root")
        .to_path_buf()
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("read {}: {e}", path.display()))
}

/// The workspace members, from the root `Cargo.toml`.
fn members() -> Vec<String> {
    let manifest: toml::Table = read(&root().join("Cargo.toml"))
        .parse()
        .expect("the root Cargo.toml parses");
    let members = manifest["workspace"]["members"]
        .as_array()
        .expect("workspace.members is an array");
    members
        .iter()
        .map(|m| m.as_str().expect("a member is a path").to_string())
        .collect()
}

/// The top-level modules a crate root declares, skipping inline modules and `tests`.
fn declared_modules(source: &str) -> Vec<String> {
    let mut modules = Vec::new();
    for line in source.lines() {
        // Top-level items start at column 0 in formatted code; nested ones are indented.
        let rest = if let Some(r) = line.strip_prefix("pub(crate) mod ") {
            r
        } else if let Some(r) = line.strip_prefix("pub(super) mod ") {
            r
        } else if let Some(r) = line.strip_prefix("pub mod ") {
            r
        } else if let Some(r) = line.strip_prefix("mod ") {
            r
        } else {
            continue;
        };
        let name: String = rest
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        let after = rest[name.len()..].trim_start();
        if name.is_empty() || !after.starts_with(';') || name == "tests" {
            continue; // an inline `mod x { ... }` body, or test scaffolding
        }
        modules.push(name);
    }
    modules
}

/// The text of the `//!` crate doc.
fn crate_doc(source: &str) -> String {
    source
        .lines()
        .filter_map(|l| l.trim_start().strip_prefix("//!"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The README's workspace table rows for the crate in folder `member`.
fn readme_rows<'a>(readme: &'a str, member: &str) -> Vec<&'a str> {
    let folder = format!("`{member}/");
    readme
        .lines()
        .filter(|l| l.starts_with('|'))
        .filter(|l| {
            let first = l[1..].split('|').next().unwrap_or("").trim();
            first.starts_with(&folder)
        })
        .collect()
}

/// The entries of a README row: backquoted lowercase identifiers (a trailing `/` kept)
/// outside parentheses, after the first cell.
fn row_entries(row: &str) -> Vec<String> {
    let rest = row
        .trim_start_matches('|')
        .split_once('|')
        .map_or("", |(_, r)| r);
    let mut depth = 0usize;
    let mut out = Vec::new();
    for (i, piece) in rest.split('`').enumerate() {
        if i % 2 == 1 {
            let name = piece.strip_suffix('/').unwrap_or(piece);
            let ident = name.starts_with(|c: char| c.is_ascii_lowercase() || c == '_')
                && name
                    .chars()
                    .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_');
            if depth == 0 && ident {
                out.push(piece.to_string());
            }
        } else {
            for c in piece.chars() {
                match c {
                    '(' => depth += 1,
                    ')' => depth = depth.saturating_sub(1),
                    _ => {}
                }
            }
        }
    }
    out
}

/// The names of every file (without `.rs`) and folder under `dir`.
fn names_under(dir: &Path, out: &mut BTreeSet<String>) {
    for entry in std::fs::read_dir(dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        if path.is_dir() {
            names_under(&path, out);
            out.insert(name);
        } else if let Some(stem) = name.strip_suffix(".rs") {
            out.insert(stem.to_string());
        }
    }
}

fn crate_root(member: &str) -> PathBuf {
    let dir = root().join(member).join("src");
    let lib = dir.join("lib.rs");
    if lib.exists() {
        lib
    } else {
        dir.join("main.rs")
    }
}

#[test]
fn the_parser_of_declarations_sees_what_it_should() {
    let source = "//! doc\n\
                  pub mod a;\n\
                  mod b;\n\
                  pub(crate) mod c;\n\
                  #[cfg(feature = \"x\")]\n\
                  pub mod d;\n\
                  #[cfg(test)]\n\
                  mod tests;\n\
                  #[cfg(test)]\n\
                  mod inline {\n    mod nested;\n}\n\
                  // mod commented;\n";
    assert_eq!(declared_modules(source), ["a", "b", "c", "d"]);
    let readme = "| path | what |\n|---|---|\n| `lpe/` | `a`, `b/` |\n| `lpe-x/` | `c` |\n";
    assert_eq!(readme_rows(readme, "lpe"), ["| `lpe/` | `a`, `b/` |"]);
}

/// Planted fault: fails when parenthesised names count as entries (then `mask`, a
/// feature and `Dialect`'s neighbours would have to be modules): checked by hand, not
/// counting `(`.
#[test]
fn row_entries_are_the_names_outside_parentheses() {
    let row = "| `lpe/` | `dialect` (the `Dialect` trait), `automata/` (`mask`: ids, \
               `ir`), generators `generate` (features `arbitrary`) and `x::y`, `lpe-check` |";
    assert_eq!(row_entries(row), ["dialect", "automata/", "generate"]);
}

#[test]
fn every_module_is_in_its_crate_doc_and_in_the_readme_table() {
    let readme = read(&root().join("README.md"));
    let members = members();
    assert!(
        members.len() >= 8,
        "the root Cargo.toml lists the workspace"
    );
    let mut missing = Vec::new();
    for member in &members {
        let path = crate_root(member);
        let source = read(&path);
        let modules = declared_modules(&source);
        let doc = crate_doc(&source);
        let rows = readme_rows(&readme, member).join("\n");
        if rows.is_empty() {
            missing.push(format!(
                "README.md's workspace table has no row for crate `{member}/`"
            ));
        }
        for module in &modules {
            if !doc.contains(&format!("`{module}`")) {
                missing.push(format!(
                    "module `{module}` of crate `{member}` is missing from the module map \
                     in the `//!` doc of {member}/src/{}",
                    path.file_name().unwrap().to_string_lossy()
                ));
            }
            if !rows.is_empty()
                && !rows.contains(&format!("`{module}`"))
                && !rows.contains(&format!("`{module}/`"))
            {
                missing.push(format!(
                    "module `{module}` of crate `{member}` is missing from README.md's \
                     workspace table row for `{member}/`"
                ));
            }
        }
    }
    assert!(missing.is_empty(), "{}", missing.join("\n"));
}

/// Planted fault: fails when a README row names a module the crate no longer has (as
/// `lpe/`'s row named `generate` and `strategy` after they moved to `testkit/`):
/// checked by hand, putting `generate` back in that row.
#[test]
fn every_readme_row_entry_exists() {
    let readme = read(&root().join("README.md"));
    let members = members();
    let crate_folders: BTreeSet<&str> = members.iter().map(String::as_str).collect();
    let mut stale = Vec::new();
    let mut seen = 0;
    for member in &members {
        let dir = root().join(member);
        let mut names = BTreeSet::new();
        names_under(&dir.join("src"), &mut names);
        for entry in readme_rows(&readme, member)
            .iter()
            .flat_map(|r| row_entries(r))
        {
            seen += 1;
            let name = entry.trim_end_matches('/');
            let exists =
                names.contains(name) || dir.join(&entry).exists() || crate_folders.contains(name);
            if !exists {
                stale.push(format!(
                    "README.md's workspace row for `{member}/` names `{entry}`, which is no \
                     module, file or folder of the crate"
                ));
            }
        }
    }
    // Sanity: the rows do hold entries (a reader that finds none checks nothing).
    assert!(seen > 50, "only {seen} entries read");
    assert!(stale.is_empty(), "{}", stale.join("\n"));
}
