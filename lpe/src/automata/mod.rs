//! The automata a set of expressions compiles into, bottom-up:
//! - [`mask`]: the shared ids ([`Class`](mask::Class), [`State`](mask::State),
//!   [`AovMask`](mask::AovMask)), a leaf every other layer uses;
//! - [`ir`]: the intermediate form every dialect lowers to: expression trees seen node by
//!   node, and the vertex classes a dialect compiles for a set;
//! - [`options`]: [`Options`](options::Options), a compile's budgets;
//! - [`error`]: [`CompileError`](error::CompileError), why a set did not compile;
//! - `nfa`: the bitset Glushkov NFA of all AOVs at once, with `coactive` merging the
//!   positions that are always active together;
//! - `dfa`: the minimized dense DFA built from it, when it fits its budget;
//! - `visible`: the visible AOV masks of a set with set algebra, as formulas over the
//!   hidden operand AOVs the NFA holds;
//! - [`lazy`]: the lazy DFA of sets over that budget (a registry of NFA states, per-thread
//!   transition caches);
//! - [`wide`]: the bitset NFA stepped on its wide state, behind `PathMatcher`;
//! - [`automaton`]: what a set steps, whatever its dialect: the DFA or the lazy DFA,
//!   with the visible masks of set algebra;
//! - `shape`: small DFAs over vertex places (camera, scatter, emitter) that searches run in
//!   product with, so they visit only sequences of a path's shape;
//! - `direct`: a whole path matched on the expression trees themselves, with no
//!   automaton built, for a set asked about a few paths;
//! - `emptiness`: which AOVs can match no path, a search on the NFA alone (no DFA, no
//!   `AovSet`), so compiling a set can warn about them.
//!
//! [`crate::aov`] is the facade that builds and steps them.

pub mod automaton;
pub(crate) mod coactive;
pub(crate) mod dfa;
pub(crate) mod direct;
pub(crate) mod emptiness;
pub mod error;
pub mod ir;
pub mod lazy;
pub mod mask;
pub(crate) mod nfa;
pub mod options;
pub(crate) mod shape;
pub(crate) mod visible;
pub mod wide;
