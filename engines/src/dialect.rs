//! What the engines and the harnesses need of a dialect beyond [`lpe::Dialect`]:
//! [`EngineDialect`], the one tool-side trait of this crate.
//!
//! Everything else in the crate is written once over it: the engines ([`crate::Engine`]
//! is implemented once per engine for every `D: EngineDialect`), the differential
//! harness ([`crate::differential`]), the external harness ([`crate::external`]) and
//! the fuzz bodies ([`crate::fuzzing`]). The two dialects that ship with the workspace
//! implement it in their own files, [`crate::renderman`] and [`crate::osl`]; the case
//! generators are a second trait, [`crate::differential::Generate`], since a dialect can
//! run through the engines and the harness on hand-written cases without one.
//!
//! Design: the dialect is a type parameter (the zero-sized marker of `lpe`), and what a
//! case shares (RenderMan's parser, OSL's registered labels) is a value of
//! `D::Registration` passed beside the expressions, as `lpe` does. The harnesses used
//! to carry their own dialect values for that; with the registration they need none.

use lpe::Dialect;

use crate::error::EngineError;
use crate::external::protocol::Registration;
use crate::regex::translation::Translation;

/// A dialect as the engines, the harnesses and the fuzz bodies see it.
pub trait EngineDialect: Dialect {
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

    /// The backtracking reference matcher's verdict (the executable semantics) on its
    /// own tree: whether it matches the whole `path`.
    fn reference(tree: &Self::ReferenceTree, path: &Self::Path) -> bool;

    /// The `oracle` engine's translation of a set to `regex-automata`: one anchored
    /// pattern per operand, and the encoding of paths they read. A dialect without one
    /// keeps the default, which refuses ([`EngineError::Unsupported`]).
    fn oracle(exprs: &[Self::Lpe]) -> Result<Translation<Self>, EngineError> {
        let _ = exprs;
        Err(EngineError::unsupported::<Self>())
    }

    /// One-step simplifications of an expression parsed under `registration`, each
    /// strictly simpler (the minimizer's moves).
    fn shrink_expr(e: &Self::Lpe, registration: &Self::Registration) -> Vec<Self::Lpe>;

    /// One-step simplifications of a path.
    fn shrink_path(p: &Self::Path) -> Vec<Self::Path>;

    /// The registration as one line of a report (empty: nothing to say).
    fn context(registration: &Self::Registration) -> String {
        let _ = registration;
        String::new()
    }

    /// What a `compile` request of the external protocol carries besides the AOVs
    /// (docs/protocol.md); `None`: nothing.
    fn wire_registration(registration: &Self::Registration) -> Option<Registration> {
        let _ = registration;
        None
    }

    /// `lpe-check diff` arguments that restore `registration` in a replay command.
    fn replay_args(registration: &Self::Registration) -> Vec<String> {
        let _ = registration;
        Vec::new()
    }

    /// A parse error's byte position and message, as the external protocol compares
    /// rejections.
    fn parse_error(e: &Self::ParseError) -> (usize, String);

    /// A registration written on the first line of a fuzz input, if the line is one
    /// (`None`, the default: the whole input is the expression).
    fn registration_line(line: &str) -> Option<Self::Registration> {
        let _ = line;
        None
    }

    /// Whether two parses are the same tree, as the `parse` fuzz property compares an
    /// expression with the parse of its printed text (equality unless the tree carries
    /// source positions that reprinting moves).
    fn same_tree(a: &Self::Lpe, b: &Self::Lpe) -> bool {
        a == b
    }
}
