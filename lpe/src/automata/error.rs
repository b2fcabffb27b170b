//! Why a set did not compile: the one error of the compile step, shared by every dialect
//! (a dialect's vertex classes report through it too), with the numbers in it.

use std::fmt;

use crate::automata::mask::MAX_AOVS;

/// Why a set did not compile.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CompileError {
    /// More than [`MAX_AOVS`] expressions.
    TooManyAovs(usize),
    /// More than [`MAX_AOVS`] AOVs once every set-algebra operand counts as a hidden
    /// AOV of its own (a plain AOV is one).
    TooManyOperands {
        /// AOVs in the set.
        aovs: usize,
        /// Hidden AOVs: operands of set algebra plus plain AOVs.
        hidden: usize,
    },
    /// The NFA's follow sets alone (one row per position: `positions^2 / 8` bytes) would
    /// exceed [`crate::Options::nfa_budget`].
    NfaOverBudget {
        /// NFA positions the set unrolls to, the start included.
        positions: u64,
        /// Bytes the follow sets would take; `None` when that overflows `u64`.
        bytes: Option<u64>,
        /// [`crate::Options::nfa_budget`].
        budget: usize,
    },
    /// The set's vertex patterns need more states than the dialect's vertex classes
    /// allow to classify a vertex (OSL's [`crate::osl::MAX_VERTEX_STATES`]).
    TooManyVertexStates {
        /// The dialect's limit.
        max: usize,
    },
}

impl fmt::Display for CompileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CompileError::TooManyAovs(n) => {
                write!(
                    f,
                    "{n} AOVs in one set, over the limit of {MAX_AOVS}: split the set"
                )
            }
            CompileError::TooManyOperands { aovs, hidden } => write!(
                f,
                "{aovs} AOVs in one set compile to {hidden} hidden AOVs (each operand of \
                 `&`, `-`, `^` is one), over the limit of {MAX_AOVS}: split the set"
            ),
            CompileError::NfaOverBudget {
                positions,
                bytes,
                budget,
            } => {
                let need = bytes.map_or("more than 2^64 bytes".into(), |b| {
                    format!("{} MiB", b >> 20)
                });
                write!(
                    f,
                    "the set unrolls to {positions} NFA positions; its follow sets would need \
                     {need}, over the NFA budget of {} MiB (lower the repetition counts, \
                     or set `max_path_len` so long bounded repeats compile as unbounded)",
                    budget >> 20
                )
            }
            CompileError::TooManyVertexStates { max } => write!(
                f,
                "the set's vertex patterns need more than {max} states to classify a vertex \
                 (many long `<...>` groups with negations): split the set"
            ),
        }
    }
}

impl std::error::Error for CompileError {}
