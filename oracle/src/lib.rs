//! Engines, differential checking and the `lpe-check` command line.
//!
//! [`engine`] puts every matcher behind one trait so the CLI and the harness run them
//! side by side on the same inputs; [`regex_oracle`] is the second, independent engine
//! (LPE -> regex-automata); [`bench`](mod@bench) measures the fast matcher against regex-automata.

pub mod bench;
pub mod cli;
pub mod differential;
pub mod engine;
pub mod fuzzing;
pub mod regex_oracle;
