//! The reference: an independent front end per dialect and the matchers that execute
//! docs/language.md on its trees, as plainly as possible.
//!
//! Every other engine runs on the tree `lpe`'s parser builds, so a parser misreading
//! would make them all agree on the wrong answer. The reference therefore reads the
//! source text itself, with a parser written from docs/language.md alone that shares no
//! code or types with lpe's parser, and its matchers run on that parser's own trees.
//!
//! - [`renderman`]: RenderMan's front end (tree, parser, macros as plain data, printer)
//!   and its backtracking matcher (§4–§5);
//! - [`osl`]: OSL's front end (§18) and its symbol-stream matcher;
//! - [`algebra`]: set algebra over whole expressions (§5.5, §18.5), shared by both;
//! - [`error`]: the front ends' errors (kind, byte position, message) and limits;
//! - [`scanner`]: the cursor both parsers read their text with;
//! - [`lpe_tree`]: the matchers on lpe's trees for callers that hold one, through lpe's
//!   canonical printer (what that shares with lpe is said there).
//!
//! Paths are lpe's types (`lpe::renderman::Path`, `lpe::osl::Path`): the path parser is
//! not what the reference front end checks.
//!
//! The root re-exports [`is_match`], [`is_expr_match`] and [`atom_matches`] on lpe's
//! RenderMan trees (through [`lpe_tree`]), as callers used them before the front end
//! existed.

#![forbid(unsafe_code)]

pub mod algebra;
pub mod error;
pub mod lpe_tree;
pub mod osl;
pub mod renderman;
pub mod scanner;

pub use error::{ErrorKind, FrontError, Limits};
pub use lpe_tree::{atom_matches, is_expr_match, is_match};
