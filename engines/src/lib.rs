//! LPE matching engines behind one trait, and the tools that run them side by side.
//!
//! - [`dialect`]: what the engines and harnesses need of a dialect beyond
//!   `lpe::Dialect`, one trait per concern (the reference matcher, the oracle's
//!   translation, the minimizer's moves, a case as text on the wire), and
//!   [`EngineDialect`], all four; [`renderman`] and [`osl`]: their two
//!   implementations, with the dialects' case generators and front ends.
//! - [`engine`]: the seam, [`Engine<D>`] compiles a set of `D`'s expressions into a
//!   [`Matcher<D>`] that answers, per whole path, which of them match (an
//!   `lpe::AovMask`); [`error`]: [`EngineError`], why an engine refused a set (a leaf
//!   every other module may name).
//! - [`adapters`]: the workspace's own matchers behind that seam, the backtracking
//!   [`Reference`], lpe's [`Fast`] matcher (minimized DFA, NFA over budget) and its
//!   [`BitsetNfa`] alone.
//! - [`regex`]: the independent second engine, LPE translated to `regex-automata`
//!   ([`regex::RegexEngine`], registered as `oracle`), one translation per dialect
//!   beside the engine.
//! - [`registry`]: [`all()`] and [`by_name()`] (per dialect), the one list of engines every tool uses;
//!   the names (`reference`, `oracle`, `fast`, `nfa`) are what `lpe-check --engine` takes.
//! - [`differential`]: the differential harness, generated cases, and the shrinker that
//!   minimizes a disagreement before it is printed.
//! - [`external`]: external matchers over the JSON Lines protocol (docs/protocol.md),
//!   compared with the engines by `lpe-check diff --external`.
//! - [`fuzzing`]: the bodies of the cargo-fuzz targets in `fuzz/`, as plain functions
//!   that `cargo test` also replays.

#![forbid(unsafe_code)]

pub mod adapters;
pub mod dialect;
pub mod differential;
pub mod engine;
pub mod error;
pub mod external;
pub mod fuzzing;
pub mod osl;
pub mod regex;
pub mod registry;
pub mod renderman;

pub use adapters::{BitsetNfa, Fast, Reference};
pub use dialect::{
    EngineDialect, OracleDialect, ReferenceDialect, ShrinkDialect, WireDialect, WireRegistration,
};
pub use engine::{Engine, EngineError, Matcher};
pub use registry::{all, by_name, names};
