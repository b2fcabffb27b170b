//! The workspace's file-level import graph, read from the source text: each source file
//! under a member crate's `src/` is a node; an edge `a.rs -> b.rs` means `a.rs` names
//! something that `b.rs` defines. `tests/tests/layering.rs` checks it for loops and for
//! the layers of `lpe`.
//!
//! How the files are read (as text: no compiler is involved, so this is an approximation,
//! kept close where it is cheap):
//! - The module tree is followed from each crate root (`[lib] path` or `src/lib.rs`,
//!   every `[[bin]] path` or `src/main.rs`, `src/bin/*.rs`) through `mod name;`
//!   declarations: `a/b.rs` and `a/b/mod.rs` are `a::b`. Every `.rs` file under `src/`
//!   must be reached (a file outside the tree would escape the check).
//! - Comments, string and character literals are dropped before anything is read.
//! - Paths are those starting with `crate::`, `$crate::`, `super::`, `self::`, a child
//!   module's name, or a name a `use` bound to something of the crate: in `use`
//!   declarations (grouped and nested groups, `self`, `as`, globs) and inline in code.
//! - A path resolves to the longest prefix that is a module, then, for the next segment,
//!   through that module's `use` bindings (a `pub use x::Item` re-export leads to the file
//!   that defines `Item`), then through its glob imports when one of them leads to a
//!   definition of that name; else to the module's own file.
//! - A `use` that binds a module (`use crate::automata;`, `use super::{self, ..}`) is no
//!   edge by itself: the paths through that name are. A glob import (`use super::*`) is
//!   an edge to the module it empties.
//! - `mod` declarations are no edges: a parent declaring its children does not import
//!   them, and a child is not tied to its parent by being declared there.
//! - Test-only code is not part of the layering: files declared under `#[cfg(test)]`
//!   (`#[cfg(test)] mod tests;`, with everything below them), files named `tests.rs` or
//!   `*_tests.rs`, and items under a plain `#[cfg(test)]` attribute (inline
//!   `#[cfg(test)] mod tests { .. }` blocks, test-only helpers) are skipped.
//!
//! Not read: `#[...]` attributes (a path in one is no edge); `pub(in path)` is not used
//! in the workspace, and would be read as an edge.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

// ---------------------------------------------------------------------------------------
// Tokens

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Ident(String),
    /// `::`
    Sep,
    Punct(char),
}

/// The tokens of `src` that matter here, each with its line, without comments and
/// literals.
fn lex(src: &str) -> Vec<(Tok, usize)> {
    let c: Vec<char> = src.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    let mut line = 1;
    let at = |i: usize| c.get(i).copied().unwrap_or('\0');
    // Skip a (possibly raw) string whose opening quote is at `i`, `hashes` `#`s after it
    // close it; returns the index after it, counting lines.
    let skip_string = |mut i: usize, raw: bool, hashes: usize, line: &mut usize| -> usize {
        i += 1;
        while i < c.len() {
            match c[i] {
                '\n' => *line += 1,
                '\\' if !raw => {
                    if at(i + 1) == '\n' {
                        *line += 1;
                    }
                    i += 1;
                }
                '"' if (1..=hashes).all(|k| at(i + k) == '#') => return i + 1 + hashes,
                _ => {}
            }
            i += 1;
        }
        i
    };
    while i < c.len() {
        let ch = c[i];
        if ch == '\n' {
            line += 1;
            i += 1;
        } else if ch.is_whitespace() {
            i += 1;
        } else if ch == '/' && at(i + 1) == '/' {
            while i < c.len() && c[i] != '\n' {
                i += 1;
            }
        } else if ch == '/' && at(i + 1) == '*' {
            let mut depth = 0;
            while i < c.len() {
                if c[i] == '/' && at(i + 1) == '*' {
                    depth += 1;
                    i += 2;
                } else if c[i] == '*' && at(i + 1) == '/' {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    if c[i] == '\n' {
                        line += 1;
                    }
                    i += 1;
                }
            }
        } else if ch == '"' {
            i = skip_string(i, false, 0, &mut line);
        } else if ch == '\'' {
            if at(i + 1) == '\\' {
                // An escaped character literal (`'\''`, `'\u{..}'`): past the escaped
                // character, then up to the closing quote.
                i += 3;
                while i < c.len() && c[i] != '\'' {
                    i += 1;
                }
                i += 1;
            } else if at(i + 2) == '\'' {
                i += 3;
            } else {
                // A lifetime or a label: its name lexes as an identifier, harmlessly.
                i += 1;
            }
        } else if ch == '$' && c[i + 1..].starts_with(&['c', 'r', 'a', 't', 'e']) {
            out.push((Tok::Ident("crate".into()), line));
            i += 6;
        } else if ch.is_alphanumeric() || ch == '_' {
            let start = i;
            while i < c.len() && (c[i].is_alphanumeric() || c[i] == '_') {
                i += 1;
            }
            let word: String = c[start..i].iter().collect();
            let prefix = matches!(word.as_str(), "r" | "b" | "br" | "c" | "cr");
            if prefix && at(i) == '"' {
                i = skip_string(i, word.contains('r'), 0, &mut line);
            } else if prefix && word.contains('r') && at(i) == '#' {
                let mut h = 0;
                while at(i + h) == '#' {
                    h += 1;
                }
                if at(i + h) == '"' {
                    i = skip_string(i + h, true, h, &mut line);
                } else {
                    // A raw identifier, `r#type`.
                    i += 1;
                }
            } else if word == "b" && at(i) == '\'' {
                i += if at(i + 1) == '\\' { 4 } else { 3 };
                while at(i - 1) != '\'' && i < c.len() {
                    i += 1;
                }
            } else {
                out.push((Tok::Ident(word), line));
            }
        } else if ch == ':' && at(i + 1) == ':' {
            out.push((Tok::Sep, line));
            i += 2;
        } else {
            out.push((Tok::Punct(ch), line));
            i += 1;
        }
    }
    out
}

// ---------------------------------------------------------------------------------------
// One file's structure: module scopes, their children, definitions, `use`s and paths

type ModPath = Vec<String>;

/// A path as written, and the scope it was written in.
#[derive(Clone, Debug)]
struct Written {
    scope: ModPath,
    segs: Vec<String>,
    line: usize,
}

#[derive(Default, Debug)]
struct Scope {
    children: BTreeSet<String>,
    test_children: BTreeSet<String>,
    defs: BTreeSet<String>,
    /// Name bound by a `use` -> the path it was bound to, as written.
    binds: BTreeMap<String, Written>,
    globs: Vec<Written>,
}

#[derive(Default, Debug)]
struct FileScan {
    /// Every scope (the file's module, and inline modules in it) by full module path.
    scopes: BTreeMap<ModPath, Scope>,
    /// Paths written in `use` declarations that bind an item or a glob, and inline paths.
    refs: Vec<(Written, bool)>,
    /// `#![cfg(test)]` at the top: the whole file is test-only.
    test_only: bool,
}

fn ident(t: Option<&(Tok, usize)>) -> Option<&str> {
    match t {
        Some((Tok::Ident(s), _)) => Some(s),
        _ => None,
    }
}

fn is(t: Option<&(Tok, usize)>, ch: char) -> bool {
    matches!(t, Some((Tok::Punct(p), _)) if *p == ch)
}

/// The index after the bracket group opening at `i` (`open` at `toks[i]`).
fn close_of(toks: &[(Tok, usize)], i: usize, open: char, close: char) -> usize {
    let mut depth = 0;
    let mut j = i;
    while j < toks.len() {
        if is(toks.get(j), open) {
            depth += 1;
        } else if is(toks.get(j), close) {
            depth -= 1;
            if depth == 0 {
                return j + 1;
            }
        }
        j += 1;
    }
    j
}

/// The index after the item starting at `i`: its `;`, or the `}` closing its body.
fn item_end(toks: &[(Tok, usize)], i: usize) -> usize {
    let mut depth = 0i32;
    let mut j = i;
    while j < toks.len() {
        match &toks[j].0 {
            Tok::Punct('{' | '(' | '[') => depth += 1,
            Tok::Punct('}' | ')' | ']') => {
                depth -= 1;
                if depth == 0 && toks[j].0 == Tok::Punct('}') {
                    return j + 1;
                }
            }
            Tok::Punct(';') if depth == 0 => return j + 1,
            _ => {}
        }
        j += 1;
    }
    j
}

/// Parses the `use` tree at `i` under `prefix`; pushes its leaves as (segments, binding
/// name, glob) and returns the index after the tree.
fn use_tree(
    toks: &[(Tok, usize)],
    mut i: usize,
    prefix: &[String],
    leaves: &mut Vec<(Vec<String>, Option<String>, bool)>,
) -> usize {
    let mut segs = prefix.to_vec();
    if toks.get(i).map(|t| &t.0) == Some(&Tok::Sep) {
        // `::name`: an extern crate path; leave it out.
        segs.push("::".into());
        i += 1;
    }
    loop {
        if is(toks.get(i), '{') {
            i += 1;
            while i < toks.len() && !is(toks.get(i), '}') {
                i = use_tree(toks, i, &segs, leaves);
                if is(toks.get(i), ',') {
                    i += 1;
                }
            }
            return i + 1;
        }
        if is(toks.get(i), '*') {
            leaves.push((segs, None, true));
            return i + 1;
        }
        let Some(name) = ident(toks.get(i)) else {
            return i;
        };
        i += 1;
        if name != "self" || segs.is_empty() {
            segs.push(name.to_string());
        }
        if toks.get(i).map(|t| &t.0) == Some(&Tok::Sep) {
            i += 1;
            continue;
        }
        let mut bind = segs.last().cloned();
        if ident(toks.get(i)) == Some("as") {
            bind = ident(toks.get(i + 1)).map(str::to_string);
            i += 2;
        }
        leaves.push((segs, bind.filter(|b| b != "_"), false));
        return i;
    }
}

/// Reads one file whose module path is `module`.
fn scan(src: &str, module: &ModPath) -> FileScan {
    let toks = lex(src);
    let mut f = FileScan::default();
    f.scopes.entry(module.clone()).or_default();
    // Inline module scopes: (path, brace depth their body opened at).
    let mut stack: Vec<(ModPath, usize)> = vec![(module.clone(), 0)];
    let mut depth = 0usize;
    let mut cfg_test = false;
    let mut i = 0;
    while i < toks.len() {
        let scope = stack.last().unwrap().0.clone();
        let (tok, line) = &toks[i];
        match tok {
            Tok::Punct('#') => {
                let inner = is(toks.get(i + 1), '!');
                let open = i + 1 + inner as usize;
                if is(toks.get(open), '[') {
                    let end = close_of(&toks, open, '[', ']');
                    let body: Vec<&Tok> = toks[open + 1..end - 1].iter().map(|t| &t.0).collect();
                    let test = body
                        == [
                            &Tok::Ident("cfg".into()),
                            &Tok::Punct('('),
                            &Tok::Ident("test".into()),
                            &Tok::Punct(')'),
                        ];
                    if test && inner && depth == 0 {
                        f.test_only = true;
                    }
                    cfg_test |= test && !inner;
                    i = end;
                    continue;
                }
                i += 1;
            }
            Tok::Punct('{') => {
                depth += 1;
                i += 1;
            }
            Tok::Punct('}') => {
                if stack.len() > 1 && stack.last().unwrap().1 == depth {
                    stack.pop();
                }
                depth = depth.saturating_sub(1);
                i += 1;
            }
            Tok::Ident(w) if cfg_test && w == "pub" => {
                // The visibility of a test-only item: `pub`, `pub(crate)`.
                i += 1;
                if is(toks.get(i), '(') {
                    i = close_of(&toks, i, '(', ')');
                }
            }
            Tok::Ident(w) if cfg_test => {
                // A test-only item: skipped whole (a `mod x;` is recorded, its file
                // excluded).
                if w == "mod" && is(toks.get(i + 2), ';') {
                    let name = ident(toks.get(i + 1)).unwrap().to_string();
                    f.scopes.get_mut(&scope).unwrap().test_children.insert(name);
                }
                cfg_test = false;
                i = item_end(&toks, i);
            }
            Tok::Ident(w) if w == "mod" && ident(toks.get(i + 1)).is_some() => {
                let name = ident(toks.get(i + 1)).unwrap().to_string();
                let s = f.scopes.get_mut(&scope).unwrap();
                s.children.insert(name.clone());
                if is(toks.get(i + 2), '{') {
                    let mut inner = scope.clone();
                    inner.push(name);
                    f.scopes.entry(inner.clone()).or_default();
                    depth += 1;
                    stack.push((inner, depth));
                    i += 3;
                } else {
                    i += 2;
                }
            }
            Tok::Ident(w) if w == "use" => {
                let mut leaves = Vec::new();
                let end = use_tree(&toks, i + 1, &[], &mut leaves);
                for (segs, bind, glob) in leaves {
                    let written = Written {
                        scope: scope.clone(),
                        segs,
                        line: *line,
                    };
                    let s = f.scopes.get_mut(&scope).unwrap();
                    if glob {
                        s.globs.push(written.clone());
                    } else if let Some(b) = bind {
                        s.binds.insert(b, written.clone());
                    }
                    f.refs.push((written, true));
                }
                i = end;
            }
            Tok::Ident(w) => {
                const DEF: [&str; 8] = [
                    "fn", "struct", "enum", "trait", "type", "const", "static", "union",
                ];
                if DEF.contains(&w.as_str()) {
                    if let Some(name) = ident(toks.get(i + 1)) {
                        let s = f.scopes.get_mut(&scope).unwrap();
                        s.defs.insert(name.to_string());
                    }
                }
                if w == "macro_rules" && is(toks.get(i + 1), '!') {
                    if let Some(name) = ident(toks.get(i + 2)) {
                        let s = f.scopes.get_mut(&scope).unwrap();
                        s.defs.insert(name.to_string());
                    }
                }
                // An inline path: an identifier followed by `::`, not itself after one.
                let after_sep = i > 0 && toks[i - 1].0 == Tok::Sep;
                if !after_sep && toks.get(i + 1).map(|t| &t.0) == Some(&Tok::Sep) {
                    let mut segs = vec![w.clone()];
                    let mut j = i + 1;
                    while toks.get(j).map(|t| &t.0) == Some(&Tok::Sep) {
                        match ident(toks.get(j + 1)) {
                            Some(s) => segs.push(s.to_string()),
                            None => break,
                        }
                        j += 2;
                    }
                    f.refs.push((
                        Written {
                            scope: scope.clone(),
                            segs,
                            line: *line,
                        },
                        false,
                    ));
                    i = j;
                } else {
                    i += 1;
                }
            }
            _ => {
                cfg_test = false;
                i += 1;
            }
        }
    }
    f
}

// ---------------------------------------------------------------------------------------
// One crate root's module tree

struct Tree {
    /// Module path -> file.
    files: BTreeMap<ModPath, PathBuf>,
    /// Every scope (file modules and inline modules) -> its contents and file.
    scopes: BTreeMap<ModPath, (Scope, PathBuf)>,
    /// (file, written path, whether in a `use`).
    refs: Vec<(PathBuf, Written, bool)>,
    /// Files left out as test-only.
    test_files: BTreeSet<PathBuf>,
}

fn is_test_file(p: &Path) -> bool {
    let name = p.file_name().unwrap().to_str().unwrap();
    name == "tests.rs" || name.ends_with("_tests.rs")
}

/// The file of the module `name` declared in `file` (inside its inline modules `inline`):
/// `a/b/name.rs` or `a/b/name/mod.rs` for `a/b.rs`; next to `file` for a crate root or a
/// `mod.rs`.
fn child_file(file: &Path, is_root: bool, inline: &[String], name: &str) -> Option<PathBuf> {
    let stem = file.file_stem().unwrap().to_str().unwrap();
    let mut dir = file.parent().unwrap().to_path_buf();
    if !(is_root || stem == "mod") {
        dir.push(stem);
    }
    for m in inline {
        dir.push(m);
    }
    [
        dir.join(format!("{name}.rs")),
        dir.join(name).join("mod.rs"),
    ]
    .into_iter()
    .find(|p| p.is_file())
}

fn tree(root: &Path) -> Tree {
    let mut t = Tree {
        files: BTreeMap::new(),
        scopes: BTreeMap::new(),
        refs: Vec::new(),
        test_files: BTreeSet::new(),
    };
    let mut todo: Vec<(ModPath, PathBuf, bool)> = vec![(Vec::new(), root.to_path_buf(), true)];
    while let Some((module, file, is_root)) = todo.pop() {
        let f = scan(&fs::read_to_string(&file).unwrap(), &module);
        let test_only = f.test_only || is_test_file(&file);
        for (scope, s) in &f.scopes {
            let inline = &scope[module.len()..];
            for (name, test) in s
                .children
                .iter()
                .map(|c| (c, false))
                .chain(s.test_children.iter().map(|c| (c, true)))
            {
                let declared = child_file(&file, is_root, inline, name);
                if let Some(child) = declared {
                    let mut path = scope.clone();
                    path.push(name.clone());
                    if test || test_only {
                        mark_test(&child, &mut t.test_files);
                    } else {
                        todo.push((path, child, false));
                    }
                }
            }
        }
        if test_only {
            mark_test(&file, &mut t.test_files);
            continue;
        }
        t.files.insert(module.clone(), file.clone());
        for (written, in_use) in f.refs {
            t.refs.push((file.clone(), written, in_use));
        }
        for (scope, s) in f.scopes {
            t.scopes.insert(scope, (s, file.clone()));
        }
    }
    t
}

/// Marks `file` and every file under the directory its children would live in as
/// test-only.
fn mark_test(file: &Path, out: &mut BTreeSet<PathBuf>) {
    out.insert(file.to_path_buf());
    let stem = file.file_stem().unwrap().to_str().unwrap();
    let dir = if stem == "mod" {
        file.parent().unwrap().to_path_buf()
    } else {
        file.parent().unwrap().join(stem)
    };
    if dir.is_dir() {
        let mut under = Vec::new();
        rust_files(&dir, &mut under);
        out.extend(under);
    }
}

impl Tree {
    /// `segs` as written in `scope`, made absolute within the crate; `None` for a path
    /// that leaves the crate (or is not a path to anything of it).
    fn absolute(&self, scope: &ModPath, segs: &[String], depth: usize) -> Option<ModPath> {
        let first = segs.first()?;
        let mut base = scope.clone();
        let mut rest = segs;
        match first.as_str() {
            "crate" => {
                base.clear();
                rest = &segs[1..];
            }
            "self" => rest = &segs[1..],
            "super" => {
                while rest.first().map(String::as_str) == Some("super") {
                    base.pop()?;
                    rest = &rest[1..];
                }
            }
            "::" => return None,
            name => {
                let s = &self.scopes.get(scope)?.0;
                if s.children.contains(name) {
                    // `child::x`: relative to this scope.
                } else if let Some(b) = s.binds.get(name) {
                    if depth > 16 || (b.segs.len() == 1 && b.scope == *scope) {
                        return None;
                    }
                    let mut abs = self.absolute(&b.scope, &b.segs, depth + 1)?;
                    abs.extend(segs[1..].iter().cloned());
                    return Some(abs);
                } else {
                    return None;
                }
            }
        }
        base.extend(rest.iter().cloned());
        Some(base)
    }

    /// The file that defines what the absolute path `abs` names, and whether it was
    /// found as a definition (or a module) rather than assumed.
    fn resolve(&self, abs: &[String], depth: usize) -> Option<(PathBuf, bool)> {
        let mut n = abs.len();
        while !self.scopes.contains_key(&abs[..n]) {
            n -= 1;
        }
        let (scope, file) = &self.scopes[&abs[..n]];
        let Some(name) = abs.get(n) else {
            return Some((file.clone(), true));
        };
        if depth < 16 {
            if let Some(b) = scope.binds.get(name) {
                // Through a `use` (a re-export, say) to where the name is defined.
                if let Some(mut target) = self.absolute(&b.scope, &b.segs, 0) {
                    target.extend(abs[n + 1..].iter().cloned());
                    if let Some(found) = self.resolve(&target, depth + 1) {
                        return Some(found);
                    }
                }
                return Some((file.clone(), false));
            }
        }
        if scope.defs.contains(name) {
            return Some((file.clone(), true));
        }
        if depth < 16 {
            for g in &scope.globs {
                if let Some(mut target) = self.absolute(&g.scope, &g.segs, 0) {
                    target.extend(abs[n..].iter().cloned());
                    if let Some((f, true)) = self.resolve(&target, depth + 1) {
                        return Some((f, true));
                    }
                }
            }
        }
        Some((file.clone(), false))
    }

    /// Edges `from -> to` with the first path (and its line) that makes each.
    fn edges(&self, out: &mut BTreeMap<(PathBuf, PathBuf), String>) {
        for (from, w, in_use) in &self.refs {
            let Some(abs) = self.absolute(&w.scope, &w.segs, 0) else {
                continue;
            };
            let mut n = abs.len();
            while !self.scopes.contains_key(&abs[..n]) {
                n -= 1;
            }
            // A `use` binding a module is no edge of itself; a glob of one is.
            let glob = self.scopes[&w.scope]
                .0
                .globs
                .iter()
                .any(|g| g.segs == w.segs && g.line == w.line);
            if *in_use && n == abs.len() && !glob {
                continue;
            }
            let Some((to, _)) = self.resolve(&abs, 0) else {
                continue;
            };
            if &to != from {
                out.entry((from.clone(), to))
                    .or_insert_with(|| format!("{} (line {})", w.segs.join("::"), w.line));
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// The workspace

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

pub fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

/// Each member crate's directory and its roots (library, binaries).
fn crates() -> Vec<(PathBuf, Vec<PathBuf>)> {
    let ws = workspace();
    let manifest: toml::Table = fs::read_to_string(ws.join("Cargo.toml"))
        .unwrap()
        .parse()
        .unwrap();
    let members = manifest["workspace"]["members"].as_array().unwrap();
    members
        .iter()
        .map(|m| {
            let dir = ws.join(m.as_str().unwrap());
            let krate: toml::Table = fs::read_to_string(dir.join("Cargo.toml"))
                .unwrap()
                .parse()
                .unwrap();
            let mut roots = BTreeSet::new();
            let lib = krate
                .get("lib")
                .and_then(|l| l.get("path"))
                .and_then(|p| p.as_str())
                .unwrap_or("src/lib.rs");
            roots.insert(dir.join(lib));
            for bin in krate
                .get("bin")
                .and_then(|b| b.as_array())
                .into_iter()
                .flatten()
            {
                if let Some(p) = bin.get("path").and_then(|p| p.as_str()) {
                    roots.insert(dir.join(p));
                }
            }
            roots.insert(dir.join("src/main.rs"));
            if dir.join("src/bin").is_dir() {
                for e in fs::read_dir(dir.join("src/bin")).unwrap() {
                    let p = e.unwrap().path();
                    roots.insert(if p.is_dir() { p.join("main.rs") } else { p });
                }
            }
            let roots = roots.into_iter().filter(|r| r.is_file()).collect();
            (dir, roots)
        })
        .collect()
}

/// Every file-level edge of the workspace (paths relative to it), with what makes it,
/// and the files read.
pub fn graph() -> (BTreeMap<(String, String), String>, BTreeSet<String>) {
    let ws = workspace();
    let rel = |p: &Path| p.strip_prefix(&ws).unwrap().display().to_string();
    let mut edges = BTreeMap::new();
    let mut read = BTreeSet::new();
    let mut uncovered = Vec::new();
    let crates = crates();
    for (dir, roots) in &crates {
        assert!(!roots.is_empty(), "{}: no crate root found", dir.display());
        let mut reached = BTreeSet::new();
        let mut tests = BTreeSet::new();
        for root in roots {
            let t = tree(root);
            let mut e = BTreeMap::new();
            t.edges(&mut e);
            for ((a, b), why) in e {
                edges.entry((rel(&a), rel(&b))).or_insert(why);
            }
            reached.extend(t.files.values().cloned());
            tests.extend(t.test_files);
        }
        let mut all = Vec::new();
        rust_files(&dir.join("src"), &mut all);
        for f in all {
            if reached.contains(&f) {
                read.insert(rel(&f));
            } else if !tests.contains(&f) {
                uncovered.push(rel(&f));
            }
        }
    }
    assert!(
        uncovered.is_empty(),
        "files under src/ that no crate root's module tree reaches (so no loop through them \
         could be seen); declare them, or teach this test how they are built: {uncovered:#?}"
    );
    (edges, read)
}

/// Strongly connected components of more than one file (Tarjan's algorithm).
pub fn loops(edges: &BTreeMap<(String, String), String>) -> Vec<Vec<String>> {
    let mut next: BTreeMap<&str, Vec<&str>> = BTreeMap::new();
    for (a, b) in edges.keys() {
        next.entry(a).or_default().push(b);
        next.entry(b).or_default();
    }
    struct St<'a> {
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        on: BTreeSet<&'a str>,
        out: Vec<Vec<String>>,
    }
    fn visit<'a>(v: &'a str, next: &BTreeMap<&'a str, Vec<&'a str>>, st: &mut St<'a>) {
        let n = st.index.len();
        st.index.insert(v, n);
        st.low.insert(v, n);
        st.stack.push(v);
        st.on.insert(v);
        for &w in &next[v] {
            if !st.index.contains_key(w) {
                visit(w, next, st);
                let l = st.low[w].min(st.low[v]);
                st.low.insert(v, l);
            } else if st.on.contains(w) {
                let l = st.index[w].min(st.low[v]);
                st.low.insert(v, l);
            }
        }
        if st.low[v] == st.index[v] {
            let mut comp = Vec::new();
            loop {
                let w = st.stack.pop().unwrap();
                st.on.remove(w);
                comp.push(w.to_string());
                if w == v {
                    break;
                }
            }
            if comp.len() > 1 {
                comp.sort();
                st.out.push(comp);
            }
        }
    }
    let mut st = St {
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on: BTreeSet::new(),
        out: Vec::new(),
    };
    for &v in next.keys() {
        if !st.index.contains_key(v) {
            visit(v, &next, &mut st);
        }
    }
    st.out.sort();
    st.out
}
