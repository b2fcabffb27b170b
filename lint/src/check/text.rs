//! The human report: one block per finding, then a summary line.

use crate::Location;

use super::{Finding, Outcome};

/// The text report.
pub fn render<E: std::fmt::Display>(out: &Outcome<E>) -> String {
    let mut s = String::new();
    for f in &out.findings {
        s.push_str(&block(f));
    }
    let files: std::collections::BTreeSet<&str> =
        out.aovs.iter().map(|a| a.file.as_str()).collect();
    let checked = out.partitions.iter().filter(|p| p.checked).count();
    let clean = out.partitions.iter().filter(|p| p.clean).count();
    let counts = format!(
        "{}, {}, {} checked ({clean} clean)",
        count(out.aovs.len(), "AOV"),
        count(files.len(), "file"),
        count(checked, "partition"),
    );
    if out.findings.is_empty() {
        s.push_str(&format!("clean: {counts}\n"));
    } else {
        s.push_str(&format!(
            "{}: {counts}\n",
            count(out.findings.len(), "finding")
        ));
    }
    s
}

fn count(n: usize, noun: &str) -> String {
    format!("{n} {noun}{}", if n == 1 { "" } else { "s" })
}

/// One finding: `FILE:WHERE: KIND: `SUBJECT`: MESSAGE`, then the expression with a caret
/// and the notes.
pub fn block(f: &Finding) -> String {
    let at = match &f.location {
        Location::Line { line, column } => format!("{line}:{column}"),
        loc @ Location::Prim { .. } => loc.to_string(),
    };
    let mut s = format!(
        "{}:{at}: {}: `{}`: {}\n",
        f.file,
        f.kind.name(),
        f.subject,
        f.message
    );
    if let Some((source, span)) = &f.caret {
        // Control characters would shift the caret: show them as spaces.
        let shown: String = source
            .chars()
            .map(|c| if c.is_control() { ' ' } else { c })
            .collect();
        let pad = source[..span.start].chars().count();
        let width = source[span.clone()].chars().count().max(1);
        s.push_str(&format!(
            "  | {shown}\n  | {}{}\n",
            " ".repeat(pad),
            "^".repeat(width)
        ));
    }
    for (label, value) in [
        ("witness", &f.witness),
        ("remainder", &f.remainder),
        ("help", &f.help),
    ] {
        if let Some(v) = value {
            s.push_str(&format!("  = {label}: {v}\n"));
        }
    }
    s
}
