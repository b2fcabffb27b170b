//! The RenderMan dialect's reference: an independent front end and the backtracking
//! matcher that runs on its tree.
//!
//! - [`ast`]: the front end's own tree (no type of lpe's parser);
//! - [`parse`]: the parser, written from docs/language.md §3–§10 alone;
//! - [`macros`]: the built-in macros of §6.1 and [`Registration`], user macros and
//!   limits as plain data;
//! - [`print`]: the tree as text lpe's parser reads (the front-end comparison re-parses
//!   it);
//! - [`matcher`]: the executable semantics of §4–§5 on that tree.
//!
//! Only paths are lpe's (`lpe::renderman::Path`): the path parser is not what this front
//! end checks.

pub mod ast;
pub mod macros;
pub mod matcher;
pub mod parse;
pub mod print;

pub use ast::Lpe;
pub use macros::Registration;
pub use matcher::is_match;
pub use parse::parse;
