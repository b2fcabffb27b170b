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
//! - [`parse`]: the parser, with OSL's error messages ([`Error`]);
//! - `classes`: the lowering of a set's vertex patterns to vertex classes
//!   ([`VertexClasses`]);
//! - [`Osl`]: the [`crate::Dialect`] implementation over them.

pub mod ast;
mod classes;
mod error;
mod parse;
#[cfg(test)]
mod parse_tests;
pub mod path;
pub mod symbol;

pub use ast::{Expr, Lpe, SymbolPattern, VertexPattern, Warning, WarningKind};
pub use classes::{VertexClasses, MAX_VERTEX_STATES};

/// The OSL basic set: the counterpart of [`crate::renderman::macros::BASIC`] under the same names,
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

pub use error::{Error, ErrorKind};
pub use parse::{parse, parse_source, parse_with, SOURCE_MARK};
pub use path::{Path, PathError, PathErrorKind, Vertex};
pub use symbol::{LabelKind, Registered, RegisteredError, Symbol, EVENT_LABELS, SCATTERING_LABELS};

use crate::algebra::Algebra;
use crate::automata::error::CompileError;
use crate::automata::ir::{Node, PathShape, Regex};
use crate::dialect::{Dialect, DialectLpe};

/// The default universe of an OSL partition check, and the domain of every OSL analysis:
/// the paths a renderer feeds with the built-in labels, a camera, scattering vertices
/// (event `R` or `T`, scattering `D`, `G` or `S`, any non-basic custom labels), then a
/// light or an emitting object. RenderMan's searches run over its path shape; OSL paths
/// have none, so this expression plays that part.
pub const UNIVERSE: &str = "C<[RT][DGS]>*[LO]";

/// OSL's dialect: paths are sequences of vertices, each a sequence of symbols (event,
/// scattering, custom labels) over an open alphabet; the labels a renderer registers
/// ([`Registered`]) change how expressions read.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Osl;

impl Dialect for Osl {
    const NAME: &'static str = "osl";
    const SHAPE: PathShape = PathShape::Any;
    const DEFAULT_UNIVERSE: &'static str = UNIVERSE;
    /// About 3 000 states at OSL's typical 33-64 classes, far above what real AOV sets
    /// need (the OSL basic set: 16 states), while a blow-up gives up within milliseconds
    /// (OSL sets have several times RenderMan's classes, so a blow-up reaches a large
    /// budget slowly: OSL's own ReDoS expression took a second for 16 MiB).
    const DFA_ATTEMPT_BUDGET: usize = 1 << 20;

    type Lpe = Lpe;
    type Expr = Expr;
    type Atom = VertexPattern;
    type Vertex = Vertex;
    type Path = Path;
    type PathError = PathError;
    type Registration = Registered;
    type ParseError = Error;
    type Classes = VertexClasses;

    fn parse(source: &str, registration: &Registered) -> Result<Lpe, Error> {
        parse(source, registration)
    }

    fn vertices(path: &Path) -> &[Vertex] {
        &path.vertices
    }

    fn path(vertices: Vec<Vertex>) -> Path {
        Path::new(vertices)
    }

    /// OSL's repetitions unroll fully whatever the path length (a bound for the budget
    /// check, which `max_path_len` could only lower).
    fn positions(e: &Expr, _: Option<u32>) -> u64 {
        e.positions()
    }

    fn classes(atoms: &[&VertexPattern], _: &[&Expr]) -> Result<VertexClasses, CompileError> {
        VertexClasses::new(atoms).map_err(|classes::TooManyVertexStates| {
            CompileError::TooManyVertexStates {
                max: MAX_VERTEX_STATES,
            }
        })
    }

    fn accepts(atom: &VertexPattern, vertex: &Vertex) -> bool {
        atom.accepts(&vertex.symbols)
    }

    fn domain(registration: &Registered) -> Option<Lpe> {
        Some(parse(UNIVERSE, registration).expect("the OSL domain parses"))
    }

    fn alt(alternatives: Vec<Expr>) -> Expr {
        Expr::alt(alternatives)
    }

    fn from_algebra(tree: Algebra<Expr>) -> Lpe {
        Lpe::from_algebra(tree)
    }
}

impl DialectLpe for Lpe {
    type Dialect = Osl;
}

impl Regex for Expr {
    type Atom = VertexPattern;
    fn node(&self) -> Node<'_, Expr> {
        match self {
            Expr::Vertex(v) => Node::Atom(v),
            Expr::Concat(es) => Node::Concat(es),
            Expr::Alt(es) => Node::Alt(es),
            Expr::Repeat(e, r) => Node::Repeat(e, *r),
            Expr::Empty => Node::Empty,
            Expr::Nothing => Node::Alt(&[]),
        }
    }
}
