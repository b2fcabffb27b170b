//! The `graph` view: the automaton a compiled list steps, explored from its start over
//! every vertex class ([`Explored`]), as states, transitions labelled with the classes'
//! representative vertices, and the AOVs each state accepts; drawn ([`crate::draw`]) when
//! it has at most [`DRAW_LIMIT`] states, [`DRAW_EDGE_LIMIT`] edges and its layout
//! [`LAYOUT_NODE_LIMIT`] nodes.
//!
//! The dead state (no AOV can match any continuation) and the transitions into it are
//! left out: every vertex not drawn leads there.

use lpe::{AovSet, Dialect};

use crate::automaton::{edge_id, state_id, Explored, Graph, GraphEdge, GraphState, EXPLORE_LIMIT};
use crate::draw;
use crate::list::{ExploreDialect, Parsed};
use crate::request::{ApiError, Request, Setting};

/// Most states the view draws: above it the reply has the counts and `too_large`, no
/// states, transitions or drawing. A drawing of 300 states is already more than a
/// person reads; the largest AOV lists renderers ship compile to well under 100.
pub const DRAW_LIMIT: usize = 300;

/// Most edges the view lays out: the library's first lowering step, which makes the
/// graph acyclic, searches the graph once per edge; above it the reply is `too_large`
/// without a layout.
pub const DRAW_EDGE_LIMIT: usize = 400;

/// Most nodes the layout may place ([`draw::layout_nodes`]: the states and a connector
/// per edge label and per rank a long edge crosses). A list of 193 states needs 521;
/// the dense `C.*<RD>.{5}L` (66 states) 1 809 and draws in 0.13 s; `C.*<RD>.{6}L` (130
/// states) 5 341 and is refused (`cargo bench -p lpe-bench --bench explore`). Above it
/// the reply is `too_large`.
pub const LAYOUT_NODE_LIMIT: usize = 2_000;

/// Representative vertices shown on an edge's label before `+N`.
const LABEL_VERTICES: usize = 3;

/// The `graph` view of a request: 422 when the list does not parse or compile.
pub(crate) fn graph_in<D: ExploreDialect>(
    request: &Request,
    setting: &Setting,
) -> Result<Graph, ApiError> {
    let set = Parsed::<D>::read(request, setting).compile()?;
    Ok(graph_of(&set))
}

/// The graph of a compiled set, drawn if it has at most [`DRAW_LIMIT`] states.
pub fn graph_of<D: Dialect>(set: &AovSet<D>) -> Graph {
    let explored = Explored::of(set, EXPLORE_LIMIT);
    let vertices: Vec<String> = (0..set.class_count())
        .map(|c| {
            set.class_vertex(c)
                .map_or_else(String::new, |v| v.to_string())
        })
        .collect();
    let state_count = explored.states.len();
    let edge_count = explored.edges.len();
    let too_large = state_count > DRAW_LIMIT || edge_count > DRAW_EDGE_LIMIT;
    let mut graph = Graph {
        state_count,
        edge_count,
        complete: explored.complete,
        dfa: set.uses_dfa(),
        too_large,
        limit: DRAW_LIMIT,
        edge_limit: DRAW_EDGE_LIMIT,
        layout_nodes: None,
        layout_limit: LAYOUT_NODE_LIMIT,
        classes: vertices.clone(),
        states: Vec::new(),
        edges: Vec::new(),
        svg: None,
    };
    if too_large {
        return graph;
    }
    graph.states = explored
        .states
        .iter()
        .enumerate()
        .map(|(n, &s)| GraphState {
            id: state_id(n),
            start: n == 0,
            accepts: set
                .matches(s)
                .iter()
                .filter_map(|i| set.names().get(i).cloned())
                .collect(),
        })
        .collect();
    graph.edges = explored
        .edges
        .iter()
        .map(|(&(a, b), classes)| {
            let shown: Vec<String> = classes.iter().map(|&c| vertices[c].clone()).collect();
            GraphEdge {
                id: edge_id(a, b),
                from: state_id(a),
                to: state_id(b),
                classes: classes.clone(),
                label: label(&shown),
                vertices: shown,
            }
        })
        .collect();
    let nodes = draw::layout_nodes(&graph);
    graph.layout_nodes = Some(nodes);
    if nodes > LAYOUT_NODE_LIMIT {
        graph.too_large = true;
        graph.states.clear();
        graph.edges.clear();
    } else {
        graph.svg = Some(draw::svg_with(&graph, nodes));
    }
    graph
}

/// An edge's label: its first [`LABEL_VERTICES`] vertices, `|`-separated, and `+N`.
fn label(vertices: &[String]) -> String {
    let mut out = vertices
        .iter()
        .take(LABEL_VERTICES)
        .cloned()
        .collect::<Vec<_>>()
        .join(" | ");
    if vertices.len() > LABEL_VERTICES {
        out.push_str(&format!(" +{}", vertices.len() - LABEL_VERTICES));
    }
    out
}
