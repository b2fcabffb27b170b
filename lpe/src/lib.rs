//! # lpe — Light Path Expressions, parsed and matched right
//!
//! Renderers route every light path into AOVs with expressions such as
//! `C<RD>.+[<L.>O]` ("indirect diffuse"). This crate holds the language: the path model
//! ([`path`]), the expression syntax tree ([`ast`]), the RenderMan-dialect front end
//! ([`syntax`]) with prefixes ([`prefix`]), macros ([`macros`]), lobe mappings
//! ([`lobes`]) and `rendermn.ini` loading ([`ini`]).
//!
//! The semantics are pinned down in the project's DESIGN.md and executed by the
//! `lpe-reference` crate; the decisions this crate makes where DESIGN.md is silent are
//! documented on the items that make them ([`path`], [`ast`], [`syntax`]).
//!
//! ```
//! use lpe::{parse, Path};
//!
//! let aov = parse("lpe:indirectDiffuse_key").unwrap();
//! assert_eq!(aov.to_string(), "C<RD>.+[<L.'key'>O]");
//!
//! let path: Path = "C RD2'floor' TS8 L'key'".parse().unwrap();
//! assert_eq!(path.len(), 4);
//!
//! let err = parse("C<L'key'>").unwrap_err();
//! assert_eq!(err.help(), Some("write `<L.'key'>`"));
//! ```

#![warn(missing_docs)]

pub mod ast;
pub mod ini;
pub mod lobes;
pub mod macros;
pub mod path;
pub mod prefix;
pub mod syntax;

#[cfg(any(feature = "arbitrary", feature = "proptest"))]
pub mod generate;
#[cfg(feature = "proptest")]
pub mod strategy;

pub use ast::{Expr, Lpe};
pub use ini::Config;
pub use lobes::{LobeCategory, LobeMap};
pub use path::{Event, EventKind, Path, PathError, Vertex, VertexType};
pub use prefix::{Prefix, Prefixes};
pub use syntax::{parse, Error, ErrorKind, Limits, Parser};
