//! Formal analysis on the automata, for any [`crate::Dialect`]: emptiness, equivalence
//! and inclusion, partition checks, each with the shortest witness path.
//!
//! All searches run over the dialect's paths only ([`crate::Dialect::SHAPE`]: RenderMan's
//! `C`, then `R`/`T` vertices, then one `L` or `O`, docs/language.md §2.2; OSL's any
//! sequence, with [`crate::Dialect::domain`] for partitions), as the product of the set's
//! automaton with that path shape:
//! - emptiness ([`crate::aov::AovSet::warnings`], computed in the automata layer when a set
//!   compiles) needs no determinization: a breadth-first search
//!   over `(NFA position, shape state)` pairs, linear in the NFA;
//! - comparisons, partitions and set-algebra emptiness ask formulas over the operands
//!   ("a path `A` matches and `B` does not"): in disjunctive normal form (`dnf`), each
//!   conjunction searched on the Glushkov NFA of all operands (`problem`, `antichain`):
//!   one NFA position per operand that must match, a subset of positions of those that
//!   must not, subsumed nodes dropped, breadth-first by groups of one word, so the first
//!   witness is the first shortest one in letter order; set algebra with many
//!   conjunctions, and what that route leaves undecided on half the budget, searches the
//!   set's [`crate::State`]s instead (the DFA's when it was built, else NFA subsets made
//!   on the fly, `search`), the same way;
//! - every call runs within an [`AnalysisBudget`] (`budget`) and answers
//!   [`Decision::Undecided`] past it: `compare_within`, `partition_within`,
//!   `warnings_within`. `compare` and `partition` keep their signatures and turn it into
//!   [`AnalysisError::TooLarge`].
//!
//! A witness is built from one representative vertex per class (an unmentioned label
//! becomes a fresh name such as `other`). Callers that print witnesses should re-check
//! them with an independent matcher; `lpe-check` does, with the reference matcher.

mod antichain;
mod budget;
mod compare;
#[cfg(test)]
mod differential;
mod dnf;
mod partition;
mod problem;
mod search;
mod unmatched;

pub use crate::automata::emptiness::Warning;
pub use budget::{AnalysisBudget, Decision, Limit, Undecided, DEFAULT_STEPS};
pub use compare::{compare, compare_by_lazy_dfa, compare_within, Comparison};
pub use partition::{
    default_universe, partition, partition_by_lazy_dfa, partition_within, remainder, Partition,
};
pub(crate) use search::analysis_options;
pub use search::{AnalysisError, MAX_SEARCH_STATES};
pub use unmatched::{warnings, warnings_within};
