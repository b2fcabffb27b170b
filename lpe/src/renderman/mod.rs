//! The RenderMan dialect: RenderMan's light path expressions (docs/language.md §1–§7)
//! behind [`RenderMan`], the [`crate::Dialect`] implementation.
//!
//! - [`path`]: the path model ([`Vertex`], [`Path`], [`Event`]) and its text notation;
//! - [`ast`]: the expression tree ([`Lpe`], [`Expr`], [`ast::Atom`]) and its printer;
//! - [`syntax`]: the front end (lexer, parser, errors with spans) under [`Limits`];
//! - [`prefix`]: the `lpe:`, `nothruput;` … prefixes; [`macros`]: the built-in and
//!   user macros; [`lobes`]: lobe-name mappings; [`ini`]: `rendermn.ini` loading;
//! - [`alphabet`]: the lowering of a set's atoms to vertex classes;
//! - `interned`: classification by interned label ids, RenderMan's hot path
//!   ([`AovSet::classify_interned`](crate::AovSet::classify_interned)).
//!
//! ```
//! use lpe::renderman::{parse, Path};
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

pub mod alphabet;
pub mod ast;
pub mod ini;
mod interned;
pub mod lobes;
pub mod macros;
pub mod path;
pub mod prefix;
pub mod syntax;

pub use ast::{Expr, Lpe};
pub use ini::{Config, IniError, IniErrorKind};
pub use lobes::{LobeCategory, LobeError, LobeMap};
pub use path::{Event, EventKind, Path, PathError, Vertex, VertexType};
pub use prefix::{Prefix, Prefixes};
pub use syntax::{parse, Error, ErrorKind, Limits, Parser};

use crate::algebra::Algebra;
use crate::automata::error::CompileError;
use crate::automata::ir::{Node, PathShape, Regex};
use crate::dialect::{Dialect, DialectLpe};
use alphabet::Alphabet;
use ast::Atom;

/// RenderMan's dialect: paths `C`, `R`/`T` vertices, one emitter; expressions with
/// prefixes, macros and lobe maps (the [`Parser`] is the registration).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct RenderMan;

impl Dialect for RenderMan {
    const NAME: &'static str = "renderman";
    const SHAPE: PathShape = PathShape::CameraScattersEmitter;
    const DEFAULT_UNIVERSE: &'static str = "C.*[<L.>O]";

    type Lpe = Lpe;
    type Expr = Expr;
    type Atom = Atom;
    type Vertex = Vertex;
    type Path = Path;
    type PathError = PathError;
    type Registration = Parser;
    type ParseError = Error;
    type Classes = Alphabet;

    fn parse(source: &str, registration: &Parser) -> Result<Lpe, Error> {
        registration.parse(source)
    }

    fn vertices(path: &Path) -> &[Vertex] {
        path.vertices()
    }

    fn path(vertices: Vec<Vertex>) -> Path {
        // The searches build witnesses along the path shape from vertices of the
        // alphabet's representatives, each at a place it can take: always a path.
        Path::new(vertices).expect("witnesses follow the path shape")
    }

    fn positions(e: &Expr, max_path_len: Option<u32>) -> u64 {
        e.positions_with(max_path_len)
    }

    fn classes(atoms: &[&Atom], operands: &[&Expr]) -> Result<Alphabet, CompileError> {
        // Duplicates across AOVs are fine: the alphabet's label table deduplicates.
        let labels: Vec<String> = operands.iter().flat_map(|e| e.labels()).collect();
        Ok(Alphabet::new(atoms, labels))
    }

    fn accepts(atom: &Atom, vertex: &Vertex) -> bool {
        alphabet::atom_accepts(atom, vertex)
    }

    fn alt(alternatives: Vec<Expr>) -> Expr {
        Expr::alt(alternatives)
    }

    fn from_algebra(tree: Algebra<Expr>) -> Lpe {
        Lpe::from_algebra(Prefixes::NONE, tree)
    }
}

impl DialectLpe for Lpe {
    type Dialect = RenderMan;
}

impl Regex for Expr {
    type Atom = Atom;
    fn node(&self) -> Node<'_, Expr> {
        match self {
            Expr::Atom(a) => Node::Atom(a),
            Expr::Concat(es) => Node::Concat(es),
            Expr::Alt(es) => Node::Alt(es),
            Expr::Repeat(e, r) => Node::Repeat(e, *r),
        }
    }
}
