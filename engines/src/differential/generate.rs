//! How a dialect's cases are generated: [`Generate`], the bridge from the harness to the
//! dialect's generators in `lpe_testkit::generate`.
//!
//! Apart from [`EngineDialect`] because a dialect runs through the engines and the
//! harness ([`check_in`](super::check_in), [`minimize_in`](super::minimize_in)) on
//! hand-written cases without generators; `lpe-check diff`, the external harness's
//! generated runs and the differential fuzz bodies need them.

use lpe_testkit::generate::Choices;

use crate::dialect::EngineDialect;

/// A dialect's generators: a registration, expressions under it, and paths aimed at an
/// operand. Every draw goes through `c`, so a case is a function of its PRNG stream or
/// fuzz input.
pub trait Generate: EngineDialect {
    /// Shape and size bounds of generated expressions and paths.
    type Config: Clone + Default;

    /// The default bounds with at most `max_size` atoms (vertex patterns) per
    /// expression, as `lpe-check diff --max-size` takes it.
    fn config(max_size: usize) -> Self::Config;

    /// `cfg` without set algebra, for matchers that do not speak this toolkit's
    /// extension.
    fn without_set_algebra(cfg: Self::Config) -> Self::Config;

    /// A registration the case's expressions share (a dialect with nothing to register
    /// draws nothing, so its streams are the expressions' alone).
    fn registration(c: &mut impl Choices) -> Self::Registration;

    /// An expression under `registration`.
    fn lpe(
        c: &mut impl Choices,
        registration: &Self::Registration,
        cfg: &Self::Config,
    ) -> Self::Lpe;

    /// A path aimed at `target` (walks of it, near misses, noise).
    fn biased_path(
        target: &Self::Expr,
        c: &mut impl Choices,
        registration: &Self::Registration,
        cfg: &Self::Config,
    ) -> Self::Path;
}
