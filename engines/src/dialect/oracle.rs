//! The `oracle` engine's side of a dialect: [`OracleDialect`], and what it hands the
//! engine, a [`Translation`] (patterns, and the [`Encoder`] of its paths). The types sit
//! beside the trait, so that the engine ([`crate::regex`]) and the dialects' translations
//! (`regex/renderman/`, `regex/osl.rs`) both import this file and not each other.

use lpe::Dialect;
use regex_syntax::hir::Hir;

use crate::error::EngineError;

/// A dialect the `oracle` engine can translate to `regex-automata`.
pub trait OracleDialect: Dialect {
    /// The translation of a set: one anchored pattern per operand, and the encoding of
    /// paths they read. A dialect without one keeps the default, which refuses
    /// ([`EngineError::Unsupported`]): the `oracle` engine then skips its sets.
    fn oracle(exprs: &[Self::Lpe]) -> Result<Translation<Self>, EngineError> {
        let _ = exprs;
        Err(EngineError::unsupported::<Self>())
    }
}

/// The oracle's view of a set of `D`'s expressions ([`OracleDialect::oracle`]): one
/// anchored pattern per operand (in [`lpe::algebra::SetExpr::operands`] order), and the
/// byte encoding of the paths they are searched on.
pub struct Translation<D: Dialect> {
    /// How a path becomes the bytes the patterns read.
    pub encoder: Box<dyn Encoder<D>>,
    /// One pattern per operand, each ending in `$`.
    pub hirs: Vec<Hir>,
}

/// A dialect's path as the bytes its translated patterns read (RenderMan: fixed-width
/// vertices, `regex/renderman/encode.rs`; OSL: the symbol stream, `regex/osl.rs`).
pub trait Encoder<D: Dialect>: Send {
    /// The bytes of the whole path.
    fn encode(&self, path: &D::Path) -> Vec<u8>;
}
