//! The minimizers' side of a dialect: [`ShrinkDialect`], the moves that the differential
//! harness ([`crate::differential::minimize_by`]) and the external harness take while a
//! disagreement persists.

use lpe::Dialect;

/// One-step simplifications of a dialect's expressions and paths.
pub trait ShrinkDialect: Dialect {
    /// One-step simplifications of an expression parsed under `registration`, each
    /// strictly simpler, so that repeated shrinking terminates.
    fn shrink_expr(e: &Self::Lpe, registration: &Self::Registration) -> Vec<Self::Lpe>;

    /// One-step simplifications of a path, each strictly shorter or less labelled.
    fn shrink_path(p: &Self::Path) -> Vec<Self::Path>;
}
