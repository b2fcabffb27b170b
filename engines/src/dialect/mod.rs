//! What the engines and the harnesses need of a dialect beyond [`lpe::Dialect`], one
//! trait per concern, each in its own file:
//!
//! - [`ReferenceDialect`] ([`reference`]): the reference front end's tree of an
//!   expression and the backtracking matcher's verdict on it, what the `reference`
//!   engine runs;
//! - [`OracleDialect`] ([`oracle`]): the translation of a set to `regex-automata`
//!   patterns and the byte encoding of paths they read ([`Translation`]), what the
//!   `oracle` engine runs (a dialect without one keeps the default, which refuses);
//! - [`ShrinkDialect`] ([`shrink`]): one-step simplifications of expressions and paths,
//!   the moves of every minimizer;
//! - [`WireDialect`] ([`wire`]): a case as text outside the process: its registration in
//!   a report line, in an external-protocol request ([`WireRegistration`]) and on the
//!   first line of a fuzz input; a parse error as position and message; whether a tree
//!   survives its printed text.
//!
//! [`EngineDialect`] is all four together, what the tools that run every engine on
//! generated cases ask (the registry, the differential and external harnesses, the fuzz
//! bodies). It is implemented for every dialect that implements the four: a dialect
//! implements those, never this one. Each tool's code is written once over the traits
//! it uses; the two dialects of the workspace implement them in their own files,
//! [`crate::renderman`] and [`crate::osl`]. The case generators are one more trait,
//! [`crate::differential::Generate`], since a dialect runs through the engines and the
//! harness on hand-written cases without them.
//!
//! Design: the dialect is a type parameter (the zero-sized marker of `lpe`), and what a
//! case shares (RenderMan's parser, OSL's registered labels) is a value of
//! `D::Registration` passed beside the expressions, as `lpe` does. The types the traits
//! return live beside them, so that the engines and harnesses that call a trait and
//! the dialects that implement it both import this folder and it imports neither.

pub mod oracle;
pub mod reference;
pub mod shrink;
pub mod wire;

pub use oracle::{Encoder, OracleDialect, Translation};
pub use reference::ReferenceDialect;
pub use shrink::ShrinkDialect;
pub use wire::{WireDialect, WireRegistration};

/// A dialect as the tools that run every engine see it: each concern of this folder.
pub trait EngineDialect: ReferenceDialect + OracleDialect + ShrinkDialect + WireDialect {}

impl<D: ReferenceDialect + OracleDialect + ShrinkDialect + WireDialect> EngineDialect for D {}
