//! The `graph` view: the automaton a compiled list steps, explored from its start over
//! every vertex class ([`Explored`]), as states, transitions labelled with the classes'
//! representative vertices, and the AOVs each state accepts; drawn ([`crate::draw`]) when
//! it has at most [`DRAW_LIMIT`] states, [`DRAW_EDGE_LIMIT`] edges and its layout
//! [`LAYOUT_NODE_LIMIT`] nodes.
//!
//! The states are numbered in breadth-first order from the start (`s0`), classes in
//! order, so a list gives the same numbers on every run; `explain` names the states of
//! a trace with the same ids. The dead state (no AOV can match any continuation) and the
//! transitions into it are left out: every vertex not drawn leads there.

use std::collections::{BTreeMap, HashMap, VecDeque};

use lpe::{AovSet, Class, Dialect, State};
use serde::Serialize;

use crate::draw;
use crate::list::{ExploreDialect, Parsed};
use crate::request::{ApiError, Request, Setting};

/// Most states the view draws: above it the reply has the counts and `too_large`, no
/// states, transitions or drawing. A drawing of 300 states is already more than a
/// person reads; the largest AOV lists renderers ship compile to well under 100.
pub const DRAW_LIMIT: usize = 300;

/// Most edges the view lays out: the library's first lowering step, which makes the
/// graph acyclic, searches the graph once per edge (a dense 258-state automaton of 641
/// edges takes 2.6 s there); above it the reply is `too_large` without a layout.
pub const DRAW_EDGE_LIMIT: usize = 400;

/// Most nodes the layout may place ([`draw::layout_nodes`]: the states and a connector
/// per edge label and per rank a long edge crosses): about 0.1 s of placement. A list
/// of 193 states needs 521; a dense automaton of 66 states (`C.*<RD>.{5}L`) 1 809, and
/// one of 130 states 5 341 (1.6 s). Above it the reply is `too_large`.
pub const LAYOUT_NODE_LIMIT: usize = 2_000;

/// Most states the exploration visits: a set over its DFA budget steps a lazy DFA whose
/// states are made on demand, so its count is only known up to this bound.
pub const EXPLORE_LIMIT: usize = 20_000;

/// Representative vertices shown on an edge's label before `+N`.
const LABEL_VERTICES: usize = 3;

/// The automaton of a compiled set, explored from its start.
pub struct Explored {
    /// The live states in breadth-first order; index = the id's number.
    pub states: Vec<State>,
    /// The id of each live state.
    pub ids: HashMap<State, usize>,
    /// `(from, to) -> classes` of every transition between live states.
    pub edges: BTreeMap<(usize, usize), Vec<usize>>,
    /// Whether every reachable state was visited (else [`EXPLORE_LIMIT`] stopped it).
    pub complete: bool,
}

impl Explored {
    /// Explores `set` breadth-first from its start, over every class, up to `limit`
    /// live states.
    pub fn of<D: Dialect>(set: &AovSet<D>, limit: usize) -> Explored {
        let classes = classes(set);
        let mut states = vec![set.start()];
        let mut ids = HashMap::from([(set.start(), 0)]);
        let mut edges: BTreeMap<(usize, usize), Vec<usize>> = BTreeMap::new();
        let mut queue = VecDeque::from([0usize]);
        let mut complete = true;
        while let Some(from) = queue.pop_front() {
            for (c, &class) in classes.iter().enumerate() {
                let next = set.step_class(states[from], class);
                if set.is_dead(next) {
                    continue;
                }
                let to = match ids.get(&next) {
                    Some(&to) => to,
                    None if states.len() >= limit => {
                        complete = false;
                        continue;
                    }
                    None => {
                        states.push(next);
                        ids.insert(next, states.len() - 1);
                        queue.push_back(states.len() - 1);
                        states.len() - 1
                    }
                };
                edges.entry((from, to)).or_default().push(c);
            }
        }
        Explored {
            states,
            ids,
            edges,
            complete,
        }
    }
}

/// Every class of `set`, in order: each through its representative vertex (a class is
/// only made by classifying).
pub fn classes<D: Dialect>(set: &AovSet<D>) -> Vec<Class> {
    (0..set.class_count())
        .filter_map(|c| set.class_vertex(c))
        .map(|v| set.classify(&v))
        .collect()
}

/// The `graph` view's answer.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Graph {
    /// Live states (the dead state left out); a lower bound when `complete` is false.
    pub state_count: usize,
    /// Transitions between live states, one per pair of states (its classes merged).
    pub edge_count: usize,
    /// Whether every reachable state was counted.
    pub complete: bool,
    /// Whether the set steps an eager minimized DFA (else a lazy DFA, over its budget).
    pub dfa: bool,
    /// Whether the automaton has more than `limit` states or `edge_limit` edges, or its
    /// layout more than `layout_limit` nodes: then `states`, `edges` and `svg` are empty.
    pub too_large: bool,
    /// [`DRAW_LIMIT`].
    pub limit: usize,
    /// [`DRAW_EDGE_LIMIT`].
    pub edge_limit: usize,
    /// The nodes the layout places, when the states and edges are within their limits.
    pub layout_nodes: Option<usize>,
    /// [`LAYOUT_NODE_LIMIT`].
    pub layout_limit: usize,
    /// The vertex classes: `classes[c]` is class `c`'s representative vertex.
    pub classes: Vec<String>,
    /// The live states, `s0` the start.
    pub states: Vec<GraphState>,
    /// The transitions between live states.
    pub edges: Vec<GraphEdge>,
    /// The drawing: an SVG document whose state shapes have `id="sN"` and whose edge
    /// paths have `id="eA-B"`.
    pub svg: Option<String>,
}

/// One live state.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct GraphState {
    /// `sN`, as in the drawing.
    pub id: String,
    /// Whether it is the start.
    pub start: bool,
    /// The AOVs a path ending here lands in.
    pub accepts: Vec<String>,
}

/// The transition from one state to another, all its classes merged.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct GraphEdge {
    /// `eA-B`, as in the drawing.
    pub id: String,
    /// The state it leaves.
    pub from: String,
    /// The state it enters.
    pub to: String,
    /// The classes it is taken on.
    pub classes: Vec<usize>,
    /// Their representative vertices.
    pub vertices: Vec<String>,
    /// The label drawn: the first vertices and `+N` for the rest.
    pub label: String,
}

/// The id of state number `n`.
pub fn state_id(n: usize) -> String {
    format!("s{n}")
}

/// The id of the edge from state `a` to state `b`.
pub fn edge_id(a: usize, b: usize) -> String {
    format!("e{a}-{b}")
}

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
