//! The automata a set of expressions compiles into, bottom-up:
//! - [`mask`]: the shared ids ([`Class`](mask::Class), [`State`](mask::State),
//!   [`AovMask`](mask::AovMask)), a leaf every other layer uses;
//! - `alphabet`: vertices folded into the classes the compiled atoms can tell apart;
//! - `nfa`: the bitset Glushkov NFA of all AOVs at once;
//! - `dfa`: the minimized dense DFA built from it, when it fits its budget.
//!
//! [`crate::aov`] is the facade that builds and steps them.

pub(crate) mod alphabet;
pub(crate) mod dfa;
pub mod mask;
pub(crate) mod nfa;
