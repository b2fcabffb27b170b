//! Verification: invariants a render must satisfy, the statistics behind them, the
//! chi-square tests of the lobes' samplers, the known-answer scenes, and the `check`,
//! `converge` and `stress` runs with their plots and tables.

pub mod chi2;
pub mod converge;
pub mod invariants;
pub mod known;
pub mod matcher_row;
pub mod plot;
pub mod stats;
pub mod stress;
pub mod suite;
pub mod tables;

use crate::aov::matcher::MatcherError;
use crate::aov::AovError;
use crate::integrator::RenderError;
use crate::output::OutputError;
use crate::scene::SceneError;

/// Why a verification run (check suite, converge, stress, a known-answer scene) could
/// not produce its measurements.
#[derive(Debug, thiserror::Error)]
pub enum VerifyError {
    #[error(transparent)]
    Scene(#[from] SceneError),
    #[error(transparent)]
    Aov(#[from] AovError),
    #[error(transparent)]
    Matcher(#[from] MatcherError),
    #[error(transparent)]
    Render(#[from] RenderError),
    #[error(transparent)]
    Output(#[from] OutputError),
    #[error("{samples} samples rejected as non-finite")]
    Rejected { samples: u64 },
    #[error("`{scene}` is not a furnace (one material, one Lambert lobe, grey glow)")]
    NotAFurnace { scene: String },
    #[error("a render thread panicked")]
    Panicked,
}
