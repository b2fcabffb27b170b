//! The reference matcher's side of a dialect: [`ReferenceDialect`], what the `reference`
//! engine ([`crate::Reference`]) and the front-end comparison run.

use lpe::Dialect;

use crate::error::EngineError;

/// A dialect's expressions as the reference front end reads them, and the backtracking
/// matcher (the executable semantics) on them.
pub trait ReferenceDialect: Dialect {
    /// The reference front end's own tree of one expression (`lpe_reference`'s, sharing
    /// no type with lpe's parser), what the `reference` engine matches.
    type ReferenceTree: Send + Sync;

    /// Reads `lpe` with the reference's own front end, under `registration` given as
    /// plain data. The engines receive lpe's trees, not source text, so the text read is
    /// lpe's canonical print of the tree (`Display`, docs/language.md §15): this is the
    /// one thing the `reference` engine shares with lpe's front end, its printer. The
    /// front-end comparison (`differential::front`) reads the source text itself.
    /// A refusal is [`EngineError::Reference`].
    fn reference_tree(
        lpe: &Self::Lpe,
        registration: &Self::Registration,
    ) -> Result<Self::ReferenceTree, EngineError>;

    /// The backtracking reference matcher's verdict on its own tree: whether it matches
    /// the whole `path`.
    fn reference(tree: &Self::ReferenceTree, path: &Self::Path) -> bool;
}
