//! Bounds on what one expression may cost, shared by every dialect's parser: each bound
//! has its own error, with the numbers in it.

/// Bounds on what one expression may cost, each with its own error.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Largest `n` or `m` in `{n}`, `{n,}`, `{n,m}` (default 256).
    pub max_repeat: u32,
    /// Most atom positions after unrolling counted repetition (default 65 536).
    pub max_positions: usize,
    /// Deepest nesting of groups and classes (default 128).
    pub max_depth: usize,
    /// Deepest chain of macros naming macros (default 16).
    pub max_macro_depth: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_repeat: 256,
            max_positions: 65_536,
            max_depth: 128,
            max_macro_depth: 16,
        }
    }
}
