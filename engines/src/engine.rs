//! The seam between engines and the tools that run them.
//!
//! Each engine compiles a *set* of expressions (a single expression is a set of one) and
//! then answers, per path, which of them match, as an [`AovMask`] (bit `i`: expression
//! `i`). An engine that cannot build a set (a size limit, a dialect it has no
//! translation for) says so with an [`EngineError`]; callers count such skips and report
//! them, never hide them.
//!
//! The seam is generic over the dialect: [`Engine<D>`] compiles `D`'s expressions under
//! `D`'s registration into a [`Matcher<D>`] over `D`'s paths. Every engine of the
//! workspace implements it once for every dialect with what it runs on (the reference
//! for a [`ReferenceDialect`](crate::dialect::ReferenceDialect), the oracle for an
//! [`OracleDialect`](crate::dialect::OracleDialect), lpe's automata for any), so a
//! dialect joins the registry by implementing those traits, not by a method per dialect
//! here.

use lpe::{AovMask, Dialect, MAX_AOVS};

pub use crate::error::EngineError;

/// A compiled expression set over `D`'s paths. `Send`, so a multi-threaded caller (the
/// renderer's `converge`) can keep one per thread; not `Sync`, since matchers may keep
/// a mutable cache.
pub trait Matcher<D: Dialect>: Send {
    /// Which compiled expressions match the whole path: bit `i` is expression `i`.
    fn which(&self, path: &D::Path) -> AovMask;
}

/// A matching engine for dialect `D`.
pub trait Engine<D: Dialect>: Sync {
    /// Short name, as given to `--engine`.
    fn name(&self) -> &'static str;
    /// Compiles a set of expressions, parsed under `registration`.
    fn compile(
        &self,
        exprs: &[D::Lpe],
        registration: &D::Registration,
    ) -> Result<Box<dyn Matcher<D> + '_>, EngineError>;

    /// Compiles a set that will answer only a few paths (a batch line whose expression
    /// has not repeated yet): an engine whose [`Engine::compile`] pays up front for fast
    /// steps may build something cheaper to compile here, with the same answers. By
    /// default the same as [`Engine::compile`].
    fn compile_for_few_paths(
        &self,
        exprs: &[D::Lpe],
        registration: &D::Registration,
    ) -> Result<Box<dyn Matcher<D> + '_>, EngineError> {
        self.compile(exprs, registration)
    }

    /// Compiles a set that will answer some hundreds of paths (a batch expression that
    /// has repeated, but not yet thousands of times): cheap to compile and fast to step
    /// once warm, where [`Engine::compile`] may spend as much as thousands of lines to
    /// step fastest. By default the same as [`Engine::compile`].
    fn compile_for_some_paths(
        &self,
        exprs: &[D::Lpe],
        registration: &D::Registration,
    ) -> Result<Box<dyn Matcher<D> + '_>, EngineError> {
        self.compile(exprs, registration)
    }
}

/// Refuses a set wider than an [`AovMask`]: the engines that answer one expression at a
/// time have no limit of their own, but their answers must fit the mask.
pub(crate) fn fits_mask(exprs: usize) -> Result<(), EngineError> {
    if exprs > MAX_AOVS {
        return Err(lpe::CompileError::TooManyAovs(exprs).into());
    }
    Ok(())
}

/// The first `n` bits of `mask`, as the reports print them (one answer per expression).
pub fn bits(mask: AovMask, n: usize) -> Vec<bool> {
    (0..n).map(|i| mask.contains(i)).collect()
}

#[cfg(test)]
mod tests {
    use lpe::renderman::{Parser, RenderMan};

    use super::*;
    use crate::registry;

    /// Answers are `AovMask`s: a set wider than one is refused by every engine, those
    /// that answer one expression at a time too (as the reference and the oracle do on
    /// a set that fits).
    #[test]
    fn a_set_wider_than_a_mask_is_refused_by_every_engine() {
        let cl = lpe::renderman::parse("CL").unwrap();
        let path = "C L".parse().unwrap();
        for e in registry::all::<RenderMan>() {
            let why = match e.compile(&vec![cl.clone(); MAX_AOVS + 1], &Parser::default()) {
                Ok(_) => panic!("{} built a set wider than a mask", e.name()),
                Err(why) => why,
            };
            assert!(why.to_string().contains("257 AOVs"), "{}: {why}", e.name());
            if ["reference", "oracle"].contains(&e.name()) {
                let m = e
                    .compile(&vec![cl.clone(); MAX_AOVS], &Parser::default())
                    .unwrap();
                assert_eq!(m.which(&path).count(), MAX_AOVS, "{}", e.name());
            }
        }
    }
}
