//! The one list of engines: `lpe-check --engine`, the differential harness, the fuzz
//! targets and the renderer's `converge` all pick engines from here, by these names.

use crate::adapters::{BitsetNfa, Fast, Reference};
use crate::engine::Engine;
use crate::regex;

/// Every available engine, reference first: `reference`, `oracle` (regex-automata),
/// `fast`, `nfa`.
pub fn all() -> Vec<&'static dyn Engine> {
    vec![&Reference, &regex::LAZY, &Fast, &BitsetNfa]
}

/// The engine called `name`, if available.
pub fn by_name(name: &str) -> Option<&'static dyn Engine> {
    all().into_iter().find(|e| e.name() == name)
}

/// The names of [`all()`], in order.
pub fn names() -> Vec<&'static str> {
    all().iter().map(|e| e.name()).collect()
}
