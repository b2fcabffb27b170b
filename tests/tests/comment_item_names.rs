//! Every `Owner::member` that a comment names in backquotes is still there: a method or
//! field renamed or removed leaves no stale name in the comments that explain the code.
//!
//! Read as text over every tracked `.rs` file (`git ls-files`): the types are the names
//! after `struct`, `enum`, `trait`, `type` and `union`; the members are the names after
//! `fn` and the field names (`name:` opening a line, after any `pub`). In a comment (from
//! `//` on), each backquoted span is read for `Owner::member` pairs, a capitalised name
//! then a lowercase one (`lpe::AovSet::compile_with(..)` holds `AovSet::compile_with`).
//! A pair counts when `Owner` is a workspace type, and is stale when no workspace type has
//! a member of that name: which type defines it is not checked (cheap, and a renamed
//! member rarely keeps its name on another type). `Owner::Variant` (capitalised) and types
//! from outside the workspace (`Vec::with_capacity`) are left out.

use std::collections::BTreeSet;
use std::fs;

use lpe_tests::imports::workspace;
use lpe_tests::tracked::tracked_files;

/// The identifiers of `text` in order, each with the byte after it.
fn words(text: &str) -> Vec<(&str, usize)> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, c) in text
        .char_indices()
        .chain(std::iter::once((text.len(), ' ')))
    {
        let part = c.is_alphanumeric() || c == '_';
        match (start, part) {
            (None, true) => start = Some(i),
            (Some(s), false) => {
                out.push((&text[s..i], i));
                start = None;
            }
            _ => {}
        }
    }
    out
}

/// The types and the members (methods, fields) `source` defines, its comments left out
/// (they name types in prose: "a `type` alias").
fn definitions(source: &str, types: &mut BTreeSet<String>, members: &mut BTreeSet<String>) {
    let code: String = source
        .lines()
        .map(|l| l.find("//").map_or(l, |at| &l[..at]))
        .collect::<Vec<_>>()
        .join("\n");
    let source = code.as_str();
    let w = words(source);
    for pair in w.windows(2) {
        match pair[0].0 {
            "struct" | "enum" | "trait" | "type" | "union" => {
                types.insert(pair[1].0.to_string());
            }
            "fn" => {
                members.insert(pair[1].0.to_string());
            }
            _ => {}
        }
    }
    for line in source.lines() {
        let mut rest = line.trim_start();
        for vis in ["pub(crate) ", "pub(super) ", "pub "] {
            rest = rest.strip_prefix(vis).unwrap_or(rest);
        }
        let name: String = rest
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        let after = &rest[name.len()..];
        if !name.is_empty() && after.starts_with(':') && !after.starts_with("::") {
            members.insert(name);
        }
    }
}

fn is_type_name(s: &str) -> bool {
    s.starts_with(|c: char| c.is_ascii_uppercase())
}

fn is_member_name(s: &str) -> bool {
    s.starts_with(|c: char| c.is_ascii_lowercase() || c == '_')
}

/// The `Owner::member` pairs in the backquoted spans of the comment on `line`.
fn named_members(line: &str) -> Vec<(String, String)> {
    let Some(at) = line.find("//") else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for span in line[at..].split('`').skip(1).step_by(2) {
        let w = words(span);
        for pair in w.windows(2) {
            let ((ty, end), (member, _)) = (pair[0], pair[1]);
            if span[end..].starts_with("::") && is_type_name(ty) && is_member_name(member) {
                out.push((ty.to_string(), member.to_string()));
            }
        }
    }
    out
}

/// Stale names that stand today and are to be cleared, as `Owner::member`; the test
/// fails on any other, and on an entry here that no comment names any more.
const NOT_YET_CLEARED: &[&str] = &[];

/// Planted fault: fails on a comment naming a member that no type has: checked by hand,
/// naming `compile_rib` of `AovSet` (as one backquoted path) in a comment of
/// `lpe/src/aov.rs`.
#[test]
fn comments_name_only_members_that_exist() {
    let ws = workspace();
    let sources: Vec<(String, String)> = tracked_files()
        .into_iter()
        .filter(|p| p.ends_with(".rs"))
        .map(|p| {
            let text = fs::read_to_string(ws.join(&p)).unwrap_or_else(|e| panic!("{p}: {e}"));
            (p, text)
        })
        .collect();
    let (mut types, mut members) = (BTreeSet::new(), BTreeSet::new());
    for (_, text) in &sources {
        definitions(text, &mut types, &mut members);
    }
    // Sanity: the definitions read include a type, a method and a field of lpe.
    for (set, name) in [
        (&types, "AovSet"),
        (&members, "compile_with"),
        (&members, "dfa_budget"),
    ] {
        assert!(set.contains(name), "{name} not read as defined");
    }
    let mut stale = Vec::new();
    let mut seen_stale = BTreeSet::new();
    let mut checked = 0;
    for (path, text) in &sources {
        for (n, line) in text.lines().enumerate() {
            for (ty, member) in named_members(line) {
                if !types.contains(&ty) {
                    continue;
                }
                checked += 1;
                if members.contains(&member) {
                    continue;
                }
                let name = format!("{ty}::{member}");
                if !NOT_YET_CLEARED.contains(&name.as_str()) {
                    stale.push(format!("{path}:{}: `{name}`", n + 1));
                }
                seen_stale.insert(name);
            }
        }
    }
    assert!(checked > 100, "only {checked} names checked");
    for gone in NOT_YET_CLEARED.iter().filter(|n| !seen_stale.contains(**n)) {
        stale.push(format!(
            "no comment names `{gone}` any more: take it off NOT_YET_CLEARED"
        ));
    }
    assert!(
        stale.is_empty(),
        "comments name members that no type has:\n{}",
        stale.join("\n")
    );
}

/// Planted fault: fails when spans are read outside the comment (code names `Owner::x`
/// all the time) or when a capitalised second name counts: checked by hand, dropping
/// the `find("//")` cut and the `is_member_name` test.
#[test]
fn the_reader_takes_pairs_from_comments_only() {
    let line = "let x = \"`Foo::bar`\"; // `lpe::AovSet::compile_with(..)` not `Kind::Variant`";
    assert_eq!(
        named_members(line),
        [("AovSet".to_string(), "compile_with".to_string())]
    );
    let (mut types, mut members) = (BTreeSet::new(), BTreeSet::new());
    definitions(
        "pub struct Opts {\n    pub budget: usize,\n}\nimpl Opts { fn run(&self) {} }",
        &mut types,
        &mut members,
    );
    assert_eq!(types.into_iter().collect::<Vec<_>>(), ["Opts"]);
    assert_eq!(members.into_iter().collect::<Vec<_>>(), ["budget", "run"]);
}
