//! The knobs of compiling a set: memory budgets of the DFA, the lazy DFA's cache and the
//! NFA, the longest path the caller will step, and whether it will step only a few.

/// Compile-time knobs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Options {
    /// Most bytes the DFA may take (transition table, per-state masks and construction
    /// scratch). Over it, the set is a lazy DFA. Default 16 MiB. `0` forces the lazy
    /// DFA.
    pub dfa_budget: usize,
    /// Bytes of transition rows one lazy [`Cache`] may hold (per thread; a row is
    /// `4 * stride + 40` bytes), cleared whole when full. `0` turns caching off: every
    /// step of a lazy set runs the bitset NFA. Default 2 MiB. Unused by sets with a DFA.
    pub lazy_cache: usize,
    /// Most bytes the NFA may take. It needs one follow row per position
    /// (`positions^2 / 8` bytes; over the budget, compilation fails: about 11 000
    /// positions at the default), and steps fast with per-byte tables of up to `16 KiB *
    /// words^2` for states of `words` 64-bit words, built when they fit (about 2 000
    /// positions); without them it only serves to build the DFA. Default 16 MiB.
    pub nfa_budget: usize,
    /// The longest path the caller will ever step, in vertices, if known. With it,
    /// `e{n,m}` with `m >= max_path_len` compiles as `e{n,}` (fewer positions, smaller
    /// automata); answers for longer paths are then unspecified. Default `None`: exact
    /// on every path.
    pub max_path_len: Option<u32>,
    /// The caller will step only some hundreds of paths with the set (`lpe-check match
    /// --batch` on an expression's 256th to 4 095th lines) and wants only their answers, so compiling skips the work that
    /// only many steps repay: the NFA's per-byte step tables (its steps OR the follow
    /// rows of the active positions instead), the merging of positions always active
    /// together, and the search for AOVs that can match no path
    /// ([`crate::AovSet::warnings`] is then empty). Answers are the same either way;
    /// [`crate::automata::automaton::Automaton::nfa_positions`] counts the unmerged
    /// positions. With `dfa_budget: 0` as well, a compile is little more than the
    /// Glushkov construction. Default `false`.
    pub few_paths: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            dfa_budget: 16 << 20,
            lazy_cache: 2 << 20,
            nfa_budget: 16 << 20,
            max_path_len: None,
            few_paths: false,
        }
    }
}

pub use crate::automata::error::CompileError;
