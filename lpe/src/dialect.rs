//! The seam between dialects and every layer above them: the [`Dialect`] trait.
//!
//! A dialect is a surface syntax with its path model: RenderMan's
//! ([`crate::renderman::RenderMan`]) and Open Shading Language's ([`crate::osl::Osl`]).
//! Each brings its expression tree, parser and printer, vertex and path with their text,
//! what a renderer registers (RenderMan's macros and limits, OSL's user labels), and the
//! lowering of its trees to the shared intermediate form ([`crate::automata::ir`]). Everything
//! above the trait is written once: [`crate::AovSet`] compiles and steps any dialect's
//! set, [`crate::analysis`] compares and partitions any dialect's expressions, and the
//! workspace's engines, harnesses, CLI, C ABI and renderer are generic over it.
//!
//! A tool that takes the dialect from its arguments dispatches once with
//! [`with_dialect!`](crate::with_dialect) ([`crate::registry`]) and is generic from there
//! on.

use std::error::Error;
use std::fmt;
use std::hash::Hash;
use std::str::FromStr;

use crate::algebra::{Algebra, SetExpr};
use crate::automata::error::CompileError;
use crate::automata::ir::{PathShape, Regex, VertexClasses};

/// A dialect of light path expressions. Implemented by zero-sized marker types; every
/// item is an associated type or function, so `D` names the dialect in generic code
/// (`AovSet<D>`, `analysis::compare::<D>`).
pub trait Dialect: Copy + Default + fmt::Debug + Send + Sync + 'static {
    /// The name `--dialect` takes and [`crate::DialectName`] prints.
    const NAME: &'static str;
    /// The dialect's path model, as far as the analyses' searches need it.
    const SHAPE: PathShape;
    /// The universe a partition check covers unless told otherwise.
    const DEFAULT_UNIVERSE: &'static str;
    /// Most bytes a set's eager DFA may take before it goes lazy, whatever the caller's
    /// budget (a dialect with many classes per set caps it so that a blow-up gives up
    /// quickly).
    const DFA_ATTEMPT_BUDGET: usize = usize::MAX;

    /// A whole expression, as one AOV declares it (set algebra included).
    type Lpe: DialectLpe<Dialect = Self>
        + SetExpr<Operand = Self::Expr>
        + Clone
        + fmt::Debug
        + fmt::Display
        + PartialEq
        + Send
        + Sync;
    /// One operand: a regular expression over vertex patterns.
    type Expr: Regex<Atom = Self::Atom> + Clone + fmt::Debug + fmt::Display + Send + Sync;
    /// One vertex pattern.
    type Atom: Eq + Hash + Clone + fmt::Debug + fmt::Display + Send + Sync;
    /// One vertex of a path.
    type Vertex: Clone + fmt::Debug + fmt::Display + PartialEq + Send + Sync;
    /// A path, with its text notation.
    type Path: Clone
        + fmt::Debug
        + fmt::Display
        + PartialEq
        + FromStr<Err = Self::PathError>
        + Send
        + Sync;
    /// Why a path's text did not read.
    type PathError: Error + Clone + Send + Sync + 'static;
    /// What a renderer registers that changes how expressions read or match.
    type Registration: Clone + fmt::Debug + Default + Send + Sync + 'static;
    /// Why an expression did not parse, with its position.
    type ParseError: Error + Clone + Send + Sync + 'static;
    /// A set's compiled vertex classes.
    type Classes: VertexClasses<Vertex = Self::Vertex>;

    /// Parses one expression under `registration`.
    fn parse(
        source: &str,
        registration: &Self::Registration,
    ) -> Result<Self::Lpe, Self::ParseError>;
    /// The vertices of a path, camera first.
    fn vertices(path: &Self::Path) -> &[Self::Vertex];
    /// The path of `vertices`, which follow [`Dialect::SHAPE`] (the searches build their
    /// witnesses from class representatives at their places).
    fn path(vertices: Vec<Self::Vertex>) -> Self::Path;
    /// Atom positions of `e` once unrolled, repetitions bounded by `max_path_len` as the
    /// NFA builds them; saturating.
    fn positions(e: &Self::Expr, max_path_len: Option<u32>) -> u64;
    /// The vertex classes of the distinct `atoms` of a set (in the NFA's numbering),
    /// whose operands are `operands`.
    fn classes(
        atoms: &[&Self::Atom],
        operands: &[&Self::Expr],
    ) -> Result<Self::Classes, CompileError>;
    /// Whether `atom` accepts `vertex`: what [`Dialect::classes`] tabulates for a whole
    /// set, decided for one vertex from the two alone. For matching a few paths
    /// ([`crate::DirectSet`]), where building the classes costs more than asking about
    /// the vertices of the paths.
    fn accepts(atom: &Self::Atom, vertex: &Self::Vertex) -> bool;
    /// An expression every path the analyses report must also match, for a dialect whose
    /// [`Dialect::SHAPE`] alone admits sequences that are no paths; `None`: the shape
    /// is the whole domain.
    fn domain(registration: &Self::Registration) -> Option<Self::Lpe> {
        let _ = registration;
        None
    }
    /// The alternation of `alternatives`, as the dialect's printer reads it back.
    fn alt(alternatives: Vec<Self::Expr>) -> Self::Expr;
    /// A whole expression from set algebra over operands (no prefixes or other
    /// decorations: they never change what matches).
    fn from_algebra(tree: Algebra<Self::Expr>) -> Self::Lpe;
}

/// A whole expression that knows its dialect: lets `AovSet::compile(&aovs)` infer the
/// dialect from the expressions' type.
pub trait DialectLpe: Sized {
    /// The dialect this expression is written in.
    type Dialect: Dialect<Lpe = Self>;
}
