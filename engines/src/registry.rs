//! The one list of engines: `lpe-check --engine`, the differential harness, the fuzz
//! targets and the renderer's `converge` all pick engines from here, by these names.
//! The list is the same for every dialect: each engine is written once over the dialect
//! traits it runs on ([`ReferenceDialect`], [`OracleDialect`]), and one that has nothing
//! for a dialect refuses its sets ([`crate::EngineError::Unsupported`]) rather than
//! leaving the list.

use lpe::renderman::RenderMan;

use crate::adapters::{BitsetNfa, Fast, Reference};
use crate::dialect::{OracleDialect, ReferenceDialect};
use crate::engine::Engine;
use crate::regex;

/// Every available engine for dialect `D`, reference first: `reference`, `oracle`
/// (regex-automata), `fast`, `nfa`.
pub fn all<D: ReferenceDialect + OracleDialect>() -> Vec<&'static dyn Engine<D>> {
    vec![&Reference, &regex::LAZY, &Fast, &BitsetNfa]
}

/// The engine called `name`, if available.
pub fn by_name<D: ReferenceDialect + OracleDialect>(name: &str) -> Option<&'static dyn Engine<D>> {
    all::<D>().into_iter().find(|e| e.name() == name)
}

/// The names of [`all()`], in order (the same in every dialect).
pub fn names() -> Vec<&'static str> {
    all::<RenderMan>().iter().map(|e| e.name()).collect()
}
