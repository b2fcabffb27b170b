//! HTML fragments for notebooks: a compiled set as its drawing and a table of its AOVs
//! ([`aov_set`]), a partition check as a table of findings ([`partition`]). The Python
//! package's `AovSet._repr_html_` and `Partition._repr_html_` return them; they are
//! built from the views' own answers ([`crate::graph::graph_of`],
//! [`crate::partition::PartitionRow`]), so a notebook shows what the explorer shows.

use std::fmt::Write as _;

use lpe::{AovSet, Dialect};

use crate::draw::escape;
use crate::graph::graph_of;
use crate::partition::PartitionRow;

/// A compiled set: how many AOVs, states and edges, the drawing (or why there is
/// none), and one table row per AOV with its expression and the states accepting it.
pub fn aov_set<D: Dialect>(set: &AovSet<D>) -> String {
    let graph = graph_of(set);
    let mut out = format!(
        "<div class=\"lpe-aovset\"><p>{} AOVs ({}), {} states, {} edges</p>",
        set.len(),
        escape(set.dialect()),
        graph.state_count,
        graph.edge_count
    );
    match &graph.svg {
        Some(svg) => out.push_str(svg),
        None => {
            let _ = write!(
                out,
                "<p>The automaton is too large to draw (over {} states, {} edges or {} \
                 layout nodes).</p>",
                graph.limit, graph.edge_limit, graph.layout_limit
            );
        }
    }
    out.push_str(
        "<table><thead><tr><th>AOV</th><th>expression</th><th>accepted in</th></tr></thead><tbody>",
    );
    for (name, lpe) in set.names().iter().zip(set.lpes()) {
        let states: Vec<&str> = graph
            .states
            .iter()
            .filter(|s| s.accepts.contains(name))
            .map(|s| s.id.as_str())
            .collect();
        let _ = write!(
            out,
            "<tr><td>{}</td><td><code>{}</code></td><td>{}</td></tr>",
            escape(name),
            escape(&lpe.to_string()),
            states.join(" ")
        );
    }
    out.push_str("</tbody></table></div>");
    out
}

/// A partition check of `universe`: a line saying whether it is clean, one table row
/// per finding (`overlap`, `gap`, `outside`; the AOVs; the witness), and the remainder
/// AOV that closes a gap.
pub fn partition(universe: &str, rows: &[PartitionRow], remainder: Option<&str>) -> String {
    let verdict = if rows.is_empty() {
        "clean".to_string()
    } else {
        format!("{} findings", rows.len())
    };
    let mut out = format!(
        "<div class=\"lpe-partition\"><p>partition of <code>{}</code>: {verdict}</p>",
        escape(universe)
    );
    if !rows.is_empty() {
        out.push_str(
            "<table><thead><tr><th>finding</th><th>AOVs</th><th>witness</th></tr></thead><tbody>",
        );
        for r in rows {
            let _ = write!(
                out,
                "<tr><td>{}</td><td>{}</td><td><code>{}</code></td></tr>",
                r.kind,
                escape(&r.aovs.join(", ")),
                escape(&r.witness)
            );
        }
        out.push_str("</tbody></table>");
    }
    if let Some(rest) = remainder {
        let _ = write!(out, "<p>remainder: <code>{}</code></p>", escape(rest));
    }
    out.push_str("</div>");
    out
}
