//! The module maps stay in sync with the code, as `capi/tests/header.rs` keeps the C
//! header in sync: for every crate of the workspace (the root `Cargo.toml`'s `members`,
//! so a new crate is covered without touching this file), every top-level module its
//! `src/lib.rs` declares (`src/main.rs` for a crate without a library) must be named
//!
//! - in that file's `//!` crate doc, as `` `name` `` or `` [`name`] ``, and
//! - in the README's workspace table, in the row(s) whose first cell is the crate's
//!   folder (`` `lpe/` ``), as `` `name` `` or `` `name/` ``.
//!
//! A declaration is a line starting at column 0 with `mod x;`, `pub mod x;` or
//! `pub(crate) mod x;` (attributes such as `#[cfg(...)]` on the lines before are allowed).
//! Inline modules (`mod x { ... }`) and modules named `tests` are test scaffolding and
//! are skipped.

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
