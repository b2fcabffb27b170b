//! Random expressions, AOV sets and paths for testing matchers, one file per dialect:
//! [`renderman`] and [`osl`], each with its own `Config`.
//!
//! Differential testing needs cases where the answer is interesting: when the paths are
//! uniform noise nearly every comparison is "no match" against "no match" and proves
//! nothing. So each dialect's generators build, besides random trees, **paths from an
//! expression** (a walk choosing a vertex each pattern accepts and a count for each
//! quantifier), near misses of such paths (one vertex changed, dropped or duplicated),
//! and noise; `biased_path` mixes the three.
//!
//! Every function draws its decisions from a [`Choices`] source: a seeded
//! `lpe::rng::SplitMix64`, or a fuzzer's `arbitrary::Unstructured`. What the dialects
//! share lives in leaves beside them: `choices` ([`Choices`]) and `set_algebra` (the
//! shapes of `&`, `-` and `^` over operands of any dialect).
//!
//! The generators only *aim* at the expression: they do not decide whether a path
//! matches (that is the engines' job), so a bug here costs match rate, not correctness.
//!
//! RenderMan's `Config`, `lpe` and `biased_path` are re-exported here: the engines'
//! generators, the fuzz bodies and the third-dialect test name them by these paths.

mod choices;
pub mod osl;
pub mod renderman;
mod set_algebra;

pub use choices::Choices;
pub use renderman::{biased_path, lpe, Config};
