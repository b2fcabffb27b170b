//! The automaton a compiled list steps, explored from its start over every vertex class
//! ([`Explored`]), and what the `graph` view says of it ([`Graph`], [`GraphState`],
//! [`GraphEdge`]) with the ids the drawing and `explain` share: states numbered in
//! breadth-first order from the start (`s0`), classes in order, so a list gives the
//! same ids on every run.

use std::collections::{BTreeMap, HashMap, VecDeque};

use lpe::{AovSet, Class, Dialect, State};
use serde::Serialize;

/// Most states the exploration visits: a set over its DFA budget steps a lazy DFA whose
/// states are made on demand, so its count is only known up to this bound.
pub const EXPLORE_LIMIT: usize = 20_000;

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
    /// The most states drawn (`crate::graph::DRAW_LIMIT`).
    pub limit: usize,
    /// The most edges drawn (`crate::graph::DRAW_EDGE_LIMIT`).
    pub edge_limit: usize,
    /// The nodes the layout places, when the states and edges are within their limits.
    pub layout_nodes: Option<usize>,
    /// The most layout nodes drawn (`crate::graph::LAYOUT_NODE_LIMIT`).
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
