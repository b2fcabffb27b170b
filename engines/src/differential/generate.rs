//! How a dialect's cases are generated: [`Generate`], the bridge from the harness to the
//! dialect's generators in `lpe_testkit::generate`.
//!
//! Apart from [`EngineDialect`] because a dialect runs through the engines and the
//! harness ([`check_in`](super::check_in), [`minimize_in`](super::minimize_in)) on
//! hand-written cases without generators; `lpe-check diff`, the external harness's
//! generated runs and the differential fuzz bodies need them.

use lpe::Dialect;
use lpe_testkit::generate::Choices;
use lpe_testkit::grammar::Coverage;

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

    /// The productions of the dialect's grammar that [`Generate::text`] writes
    /// (`lpe_testkit::grammar`).
    fn productions() -> &'static [&'static str];

    /// Expression text under `registration`, drawn from the dialect's documented
    /// grammar (not printed from a tree: it reaches what no tree or printer writes),
    /// within `cfg`'s size and set-algebra bounds; each production written is counted
    /// in `coverage`.
    fn text(
        c: &mut impl Choices,
        registration: &Self::Registration,
        cfg: &Self::Config,
        coverage: &mut Coverage,
    ) -> String;

    /// A path aimed at `target` (walks of it, near misses, noise).
    fn biased_path(
        target: &Self::Expr,
        c: &mut impl Choices,
        registration: &Self::Registration,
        cfg: &Self::Config,
    ) -> Self::Path;
}

/// One generated expression: half the time written as text from the grammar and
/// parsed, otherwise drawn as a tree. A text the parser rejects is returned as `Err`
/// (text, error), with a tree drawn in its place so the case still runs.
pub struct Drawn<D: Dialect> {
    /// The expression.
    pub lpe: D::Lpe,
    /// Its source text when it was written from the grammar.
    pub text: Option<String>,
    /// A grammar text the parser rejected on the way: (text, error).
    pub rejected: Option<(String, String)>,
}

/// Draws one expression under `registration` (see [`Drawn`]); the grammar productions
/// written are counted in `coverage`.
pub fn draw<D: Generate>(
    c: &mut impl Choices,
    registration: &D::Registration,
    cfg: &D::Config,
    coverage: &mut Coverage,
) -> Drawn<D> {
    let mut rejected = None;
    if c.chance(50) {
        let text = D::text(c, registration, cfg, coverage);
        match D::parse(&text, registration) {
            Ok(lpe) => {
                return Drawn {
                    lpe,
                    text: Some(text),
                    rejected,
                }
            }
            Err(e) => rejected = Some((text, e.to_string())),
        }
    }
    Drawn {
        lpe: D::lpe(c, registration, cfg),
        text: None,
        rejected,
    }
}
