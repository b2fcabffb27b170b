//! Engines, differential checking and the `lpe-check` command line.
//!
//! [`engine`] puts every matcher behind one trait so the CLI and the harness run them
//! side by side on the same inputs.

pub mod cli;
pub mod engine;
