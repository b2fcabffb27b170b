//! The OSL-dialect front end: Open Shading Language's light path expressions (the dialect
//! Arnold, Karma, MoonRay and appleseed derive from), parsed into their own tree and
//! compiled into the same [`crate::AovSet`] automata as RenderMan's.
//!
//! An OSL path is a stream of interned symbols: per vertex an event label, a scattering
//! label (or NONE), zero or more custom labels, then an implied STOP. The alphabet is open
//! (any string is a label), and the labels a renderer registers ([`Registered`]) change
//! how expressions match. docs/language.md's OSL chapter specifies the dialect and lists
//! where this front end differs from OSL's code (where OSL crashes or truncates).
//!
//! - [`symbol`]: [`Symbol`], the built-in labels, [`Registered`];
//! - [`path`]: [`Vertex`], [`Path`] and their text notation;
//! - [`ast`]: the expanded tree ([`Expr`] of [`VertexPattern`]s) and [`Lpe`];
//! - [`parse`]: the parser, with OSL's error messages ([`Error`]).

pub mod ast;
mod classes;
mod compile;
mod error;
mod parse;
#[cfg(test)]
mod parse_tests;
pub mod path;
pub mod symbol;

pub use ast::{Expr, Lpe, SymbolPattern, VertexPattern, Warning, WarningKind};
pub(crate) use classes::TooManyVertexStates;
pub use classes::MAX_VERTEX_STATES;

/// The OSL basic set: the counterpart of [`crate::macros::BASIC`] under the same names,
/// partitioning [`crate::analysis::DEFAULT_OSL_UNIVERSE`] (glossy and singular lobes go
/// where RenderMan's specular ones do).
pub const BASIC: [(&str, &str); 7] = [
    ("directDiffuse", "C<RD>[LO]"),
    ("indirectDiffuse", "C<RD>.+[LO]"),
    ("subsurface", "C<TD>.*[LO]"),
    ("directSpecular", "C<R[GS]>[LO]"),
    ("indirectSpecular", "C<R[GS]>.+[LO]"),
    ("transmissive", "C<T[GS]>.*[LO]"),
    ("emissive", "C[LO]"),
];

/// Most bytes an OSL set's eager DFA may take (see [`crate::AovSet::compile_osl`]): about
/// 3 000 states at OSL's typical 33-64 classes, far above what real AOV sets need (the
/// OSL basic set: 16 states), while a blow-up gives up within milliseconds.
pub const DFA_ATTEMPT_BUDGET: usize = 1 << 20;
pub(crate) use compile::Compiled;
pub use error::{Error, ErrorKind};
pub use parse::{parse, parse_source, parse_with, SOURCE_MARK};
pub use path::{Path, PathError, PathErrorKind, Vertex};
pub use symbol::{LabelKind, Registered, RegisteredError, Symbol};
