//! Subcommands of `lpe-check`, one module each; the binary only dispatches.

pub mod bench;
pub mod bench_analysis;
pub mod diff;
pub mod equiv;
pub mod equiv_cross;
pub mod explain;
pub mod lint;
pub mod matching;
pub mod parse;
pub mod partition;
pub mod report;
pub mod serve;
pub mod translate;
