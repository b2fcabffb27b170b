//! The engine registered as `oracle`: light path expressions translated to
//! `regex-automata`, an independent second engine to check lpe's automata against.
//!
//! The engine ([`engine`]) is written once, for every dialect: it asks the dialect for a
//! [`Translation`](crate::dialect::Translation) of its set ([`OracleDialect::oracle`]:
//! patterns, one per operand, and the encoding of paths they read), builds one
//! multi-pattern automaton (`MatchKind::All`, anchored start, `$` at the end of every
//! pattern), and answers each path with one overlapping search, then combines set
//! algebra per expression. A dialect without a translation is refused.
//!
//! Each dialect's translation is a sibling here, over the pattern pieces they share
//! ([`hir`]):
//!
//! - [`renderman`]: RenderMan over a fixed-width byte encoding of vertices
//!   ([`renderman::encode`]), by set algebra over the finite vertex universe
//!   ([`renderman::translate`](mod@renderman::translate));
//! - [`osl`]: OSL over a byte encoding of the path's *symbol stream*, a different model
//!   from the fast matcher's vertex classes, so the two check each other.
//!
//! [`OracleDialect::oracle`]: crate::dialect::OracleDialect::oracle

pub mod engine;
pub mod hir;
pub mod osl;
pub mod renderman;

pub use engine::{is_match, RegexEngine, SizeLimits, EAGER, LAZY};
