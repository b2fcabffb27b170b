//! What a dialect hands the oracle ([`crate::EngineDialect::oracle`]): a
//! [`Translation`] of its set, patterns and the [`Encoder`] of its paths. Apart from the
//! engine ([`super`]) so that the dialects' trait names it without importing the engine
//! that calls the trait.

use lpe::Dialect;
use regex_syntax::hir::Hir;

/// The oracle's view of a set of `D`'s expressions ([`EngineDialect::oracle`](crate::EngineDialect::oracle)): one
/// anchored pattern per operand (in [`lpe::algebra::SetExpr::operands`] order), and the
/// byte encoding of the paths they are searched on.
pub struct Translation<D: Dialect> {
    /// How a path becomes the bytes the patterns read.
    pub encoder: Box<dyn Encoder<D>>,
    /// One pattern per operand, each ending in `$`.
    pub hirs: Vec<Hir>,
}

/// A dialect's path as the bytes its translated patterns read (RenderMan: fixed-width
/// vertices, [`encode`](super::encode); OSL: the symbol stream, [`osl`](super::osl)).
pub trait Encoder<D: Dialect>: Send {
    /// The bytes of the whole path.
    fn encode(&self, path: &D::Path) -> Vec<u8>;
}
