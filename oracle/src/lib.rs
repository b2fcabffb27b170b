//! Engines, differential checking and the `lpe-check` command line.
//!
//! [`engine`] puts every matcher behind one trait so the CLI and the harness run them
//! side by side on the same inputs; [`bench`] measures the fast matcher against
//! regex-automata.

pub mod bench;
pub mod cli;
pub mod engine;
