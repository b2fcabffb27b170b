//! Verification: invariants a render must satisfy, the statistics behind them, the
//! chi-square tests of the lobes' samplers, the known-answer scenes, and the `check`,
//! `converge` and `stress` runs with their plots and tables.

pub mod chi2;
pub mod converge;
pub mod invariants;
pub mod known;
pub mod plot;
pub mod stats;
pub mod stress;
pub mod suite;
pub mod tables;
