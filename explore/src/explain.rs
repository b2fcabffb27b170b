//! The `explain` view: a path stepped through the list's automaton (lint's
//! [`lpe_lint::explain::walk`], as `lpe-check explain` steps it), each vertex with the
//! state before and after and the edge taken, named with the `graph` view's ids, where
//! the path dies, the AOVs it lands in, or the closest miss.

use lpe_lint::explain::{alone, walk};
use serde::Serialize;

use crate::automaton::{edge_id, state_id, Explored};
use crate::graph::DRAW_LIMIT;
use crate::list::{ExploreDialect, Parsed};
use crate::request::{ApiError, Request, Setting};

/// The `explain` view's answer.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct Explain {
    /// The path as the dialect prints it.
    pub path: String,
    /// One row per vertex.
    pub steps: Vec<ExplainStep>,
    /// The 1-based vertex after which no AOV can match, if the path dies.
    pub dies_at: Option<usize>,
    /// The AOVs the whole path lands in.
    pub landed: Vec<String>,
    /// For a path landing nowhere: the AOV that stayed reachable longest.
    pub closest: Option<Closest>,
}

/// One vertex of the path.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct ExplainStep {
    /// 1-based position in the path.
    pub index: usize,
    /// The vertex as the dialect prints it.
    pub vertex: String,
    /// Its class (an index into the `graph` view's `classes`).
    pub class: usize,
    /// The state before it (`sN`, as in `graph`).
    pub from: Option<String>,
    /// The state after it; `null` once dead, or for a state past the first 301 of the
    /// breadth-first order (the automaton is then too large to draw).
    pub to: Option<String>,
    /// The edge taken (`eA-B`, as in `graph`), if both states are live.
    pub edge: Option<String>,
    /// Whether no AOV can match any continuation after it.
    pub dead: bool,
    /// The AOVs that some continuation could still land in.
    pub reachable: Vec<String>,
}

/// The closest miss of a path that lands nowhere.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct Closest {
    /// The AOV.
    pub aov: String,
    /// How many vertices it stayed reachable through.
    pub alive_for: usize,
    /// Whether it was still reachable at the end (the path ends too early for it).
    pub ends_too_early: bool,
}

/// The `explain` view of a request: 400 without `path`, 422 for a path or list that
/// does not read.
pub(crate) fn explain_in<D: ExploreDialect>(
    request: &Request,
    setting: &Setting,
) -> Result<Explain, ApiError> {
    let text = request
        .path
        .as_deref()
        .ok_or_else(|| ApiError::bad_request("`explain` needs a `path`"))?;
    let path: D::Path = text
        .parse()
        .map_err(|e| ApiError::unprocessable(format!("`path`: {e}")))?;
    let parsed = Parsed::<D>::read(request, setting);
    let set = parsed.compile()?;
    let aovs = parsed.all()?;
    let alone = alone(&aovs, &parsed.registration)
        .map_err(|e| ApiError::unprocessable(format!("an AOV does not compile: {e}")))?;
    // Ids only matter where `graph` can draw: its first states in the same breadth-first
    // order (a lazy set's 20 000 would cost a third of a second for nothing).
    let explored = Explored::of(&set, DRAW_LIMIT + 1);
    let vertices = D::vertices(&path);
    let walked = walk(&set, &alone, vertices);
    let id = |s| explored.ids.get(&s).copied();
    let name = |i: usize| aovs[i].0.clone();
    let mut before = id(walked.start);
    let mut steps = Vec::with_capacity(vertices.len());
    for (k, (v, step)) in vertices.iter().zip(&walked.steps).enumerate() {
        let after = if step.dead { None } else { id(step.state) };
        steps.push(ExplainStep {
            index: k + 1,
            vertex: v.to_string(),
            class: step.class,
            from: before.map(state_id),
            to: after.map(state_id),
            edge: before.zip(after).map(|(a, b)| edge_id(a, b)),
            dead: step.dead,
            reachable: step.reachable.iter().map(|&i| name(i)).collect(),
        });
        before = after;
    }
    let dies_at = walked.steps.iter().position(|s| s.dead).map(|k| k + 1);
    Ok(Explain {
        path: path.to_string(),
        steps,
        dies_at,
        landed: walked.landed.iter().map(|&i| name(i)).collect(),
        closest: walked.closest().map(|(i, n)| Closest {
            aov: name(i),
            alive_for: n,
            ends_too_early: n == vertices.len(),
        }),
    })
}
