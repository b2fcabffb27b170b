//! The JSON report (schema `lpe-lint/1`, documented in docs/lint.md): stable keys, every
//! key always present (`null` when it does not apply).

use crate::Location;
use serde_json::{json, Value};

use super::Outcome;

/// Version tag of the schema; bumped on any incompatible change.
pub const SCHEMA: &str = "lpe-lint/1";

/// `{file, format, error}` of one input file.
pub struct FileStatus {
    /// The file, as given.
    pub file: String,
    /// `usd`, `rib`, `ini`, or `null` when the extension named none.
    pub format: Option<&'static str>,
    /// Why it could not be read.
    pub error: Option<String>,
}

/// The JSON report.
pub fn render<E: std::fmt::Display>(out: &Outcome<E>, files: &[FileStatus]) -> Value {
    let files: Vec<Value> = files
        .iter()
        .map(|f| json!({"file": f.file, "format": f.format, "error": f.error}))
        .collect();
    let aovs: Vec<Value> = out
        .aovs
        .iter()
        .map(|a| {
            json!({
                "file": a.file,
                "name": a.decl.name,
                "location": location(&a.decl.location),
                "source": a.decl.source,
                "source_type": a.decl.source_type,
                "expression": a.lpe.as_ref().map(ToString::to_string),
            })
        })
        .collect();
    let partitions: Vec<Value> = out
        .partitions
        .iter()
        .map(|p| {
            json!({
                "file": p.file,
                "name": p.decl.name,
                "location": location(&p.decl.location),
                "members": p.decl.members,
                "checked": p.checked,
                "clean": p.clean,
            })
        })
        .collect();
    let findings: Vec<Value> = out
        .findings
        .iter()
        .map(|f| {
            let (source, span) = match &f.caret {
                Some((s, r)) => (Some(s.clone()), Some([r.start, r.end])),
                None => (None, None),
            };
            json!({
                "kind": f.kind.name(),
                "file": f.file,
                "subject": f.subject,
                "location": location(&f.location),
                "message": f.message,
                "source": source,
                "span": span,
                "help": f.help,
                "other": f.other,
                "witness": f.witness,
                "remainder": f.remainder,
            })
        })
        .collect();
    json!({
        "schema": SCHEMA,
        "files": files,
        "aovs": aovs,
        "partitions": partitions,
        "findings": findings,
    })
}

fn location(l: &Location) -> Value {
    match l {
        Location::Line { line, column } => {
            json!({"line": line, "column": column, "prim": null, "attribute": null})
        }
        Location::Prim { prim, attribute } => {
            json!({"line": null, "column": null, "prim": prim, "attribute": attribute})
        }
    }
}
