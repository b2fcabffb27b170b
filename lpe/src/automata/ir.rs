//! The intermediate form every dialect lowers to, and the only one the shared layers
//! read: an expression tree seen node by node ([`Regex`], [`Node`], [`Repetition`]), and
//! the vertex classes that tell which atom accepts which vertex ([`VertexClasses`]), with
//! the places a vertex can take in a path ([`Place`], [`PathShape`]).
//!
//! A dialect's tree implements [`Regex`]; its compiled class table implements
//! [`VertexClasses`]. The NFA, DFA, lazy DFA, emptiness and every analysis are built from
//! these alone (regex-automata's model: every engine sees the parsed intermediate form,
//! never surface syntax), so they are written once for every dialect.

use std::fmt;
use std::hash::Hash;

use crate::automata::mask::Class;

/// A quantifier: `min..=max` repetitions (`max = None` is unbounded).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Repetition {
    /// Fewest repetitions.
    pub min: u32,
    /// Most repetitions, or unbounded.
    pub max: Option<u32>,
}

impl Repetition {
    /// `*`
    pub const STAR: Repetition = Repetition { min: 0, max: None };
    /// `+`
    pub const PLUS: Repetition = Repetition { min: 1, max: None };
    /// `?`
    pub const OPTIONAL: Repetition = Repetition {
        min: 0,
        max: Some(1),
    };

    /// The repetition an automaton for paths of at most `max_path_len` vertices builds:
    /// `e{n,m}` with `m >= max_path_len` becomes `e{n,}`. Exact on such paths: at most
    /// `max_path_len` iterations consume a vertex and empty iterations can be dropped
    /// down to `n`, so any number of iterations beyond `m` shortens to at most
    /// `max(n, max_path_len) <= m`.
    pub(crate) fn bounded(self, max_path_len: Option<u32>) -> Repetition {
        match (self.max, max_path_len) {
            (Some(m), Some(l)) if m >= l && m >= self.min => Repetition {
                min: self.min,
                max: None,
            },
            _ => self,
        }
    }

    /// How many copies of the body an unrolled automaton needs.
    pub fn copies(self) -> u64 {
        match self.max {
            Some(m) => u64::from(m.max(self.min)),
            None => u64::from(self.min) + 1,
        }
    }
}

impl fmt::Display for Repetition {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.min, self.max) {
            (0, None) => f.write_str("*"),
            (1, None) => f.write_str("+"),
            (0, Some(1)) => f.write_str("?"),
            (n, None) => write!(f, "{{{n},}}"),
            (n, Some(m)) if n == m => write!(f, "{{{n}}}"),
            (n, Some(m)) => write!(f, "{{{n},{m}}}"),
        }
    }
}

/// One node of an expression tree, as the Glushkov construction sees it: the seam that
/// lets each dialect's tree build the same NFA. An atom reads exactly one vertex.
pub enum Node<'a, E: Regex> {
    /// One vertex pattern.
    Atom(&'a E::Atom),
    /// A sequence.
    Concat(&'a [E]),
    /// An alternation; no alternatives matches nothing.
    Alt(&'a [E]),
    /// A counted repetition.
    Repeat(&'a E, Repetition),
    /// The empty sequence.
    Empty,
}

/// An expression tree the NFA can be built from.
pub trait Regex: Sized {
    /// What one position reads; equal atoms share one alphabet column.
    type Atom: Eq + Hash + fmt::Display;
    /// The node at the root of this tree.
    fn node(&self) -> Node<'_, Self>;

    /// Calls `f` on every atom, left to right (an atom repeated by a quantifier once).
    fn each_atom<'a>(&'a self, f: &mut impl FnMut(&'a Self::Atom)) {
        match self.node() {
            Node::Atom(a) => f(a),
            Node::Concat(es) | Node::Alt(es) => es.iter().for_each(|e| e.each_atom(f)),
            Node::Repeat(e, _) => e.each_atom(f),
            Node::Empty => {}
        }
    }
}

/// The three places a vertex can take in a path: the camera, a scattering vertex in the
/// middle, an emitter at the end. Searches over paths of a fixed shape step on
/// `(class, place)` letters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Place {
    /// The first vertex.
    Camera,
    /// A vertex between the first and the last.
    Scatter,
    /// The last vertex.
    Emitter,
}

impl Place {
    /// The three places, in path order.
    pub const ALL: [Place; 3] = [Place::Camera, Place::Scatter, Place::Emitter];

    /// `0..3`, in path order.
    pub fn index(self) -> usize {
        self as usize
    }
}

/// What a dialect's paths look like, as far as the searches of emptiness, comparison and
/// partition need to know: they only visit sequences of this shape.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PathShape {
    /// A camera vertex, scattering vertices, one emitter, each vertex only at its places
    /// ([`VertexClasses::representative`] says which): RenderMan's path model.
    CameraScattersEmitter,
    /// Any non-empty sequence of vertices, every vertex at [`Place::Scatter`]: OSL, whose
    /// paths have no fixed shape (a dialect restricts the domain with an expression
    /// instead, `Dialect::domain`).
    Any,
}

impl PathShape {
    /// The places the searches build letters for.
    pub fn places(self) -> &'static [Place] {
        match self {
            PathShape::CameraScattersEmitter => &Place::ALL,
            PathShape::Any => &[Place::Scatter],
        }
    }
}

/// A dialect's compiled vertex classes: every vertex folded into the few classes the
/// compiled atoms can tell apart. Built from the distinct atoms of a set, in the order
/// the NFA numbers them (`Dialect::classes`).
pub trait VertexClasses: Clone + fmt::Debug + Send + Sync + 'static {
    /// The dialect's vertex.
    type Vertex;
    /// The class of a vertex; `0..class_count()`.
    fn classify(&self, v: &Self::Vertex) -> Class;
    /// Number of classes.
    fn class_count(&self) -> usize;
    /// Whether distinct atom `a` accepts the vertices of class `c`.
    fn accepts(&self, c: usize, a: usize) -> bool;
    /// A vertex of class `c` that can stand at place `p` of a path, if there is one;
    /// under [`PathShape::Any`] only [`Place::Scatter`] is asked. Witnesses of the
    /// analyses are built from these.
    fn representative(&self, c: usize, p: Place) -> Option<Self::Vertex>;
    /// Whether some vertex of class `c` can stand at place `p`: what
    /// [`VertexClasses::representative`] answers, without building the vertex.
    fn occurs_in(&self, c: usize, p: Place) -> bool {
        self.representative(c, p).is_some()
    }
    /// Bytes held by the tables.
    fn memory_bytes(&self) -> usize;
}
