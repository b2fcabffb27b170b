//! `lpe-render`: a compact path tracer that routes every light path into AOVs through an
//! LPE matcher, and checks the invariants AOVs must satisfy (partitions of beauty sum to
//! it, results do not depend on threads or on which other AOVs were requested, the
//! furnace's closed form).
//!
//! Modules, by pipeline stage:
//! - [`scene`]: the in-memory scene and the TOML scene file format;
//! - [`geometry`] (shapes, BVH), [`camera`], [`material`] (named lobes), [`light`],
//!   [`sampling`] (frames, MIS heuristics), [`rng`] (per-sample random streams);
//! - [`aov`]: the AOV list, what the renderer needs of a dialect (one file per
//!   dialect), the matchers and the effects plan;
//! - [`inputs`]: what a render reads first (scene, `rendermn.ini`, AOVs from display
//!   files, USD stages and arguments);
//! - [`integrator`]: render dispatch, the row loop, the path estimator and the
//!   contributions it hands the film;
//! - [`film`]: accumulation of samples and prefix weighting of contributions;
//! - [`invariant`]: one checked property and its outcome, as verification gives it and
//!   the console and the report print it;
//! - [`output`]: EXR, PNG, contact sheet and the report;
//! - [`verify`]: invariants, statistics, chi-square tests, known-answer scenes, the
//!   `check` suite, `converge`, `stress`, plots and tables;
//! - [`bench`](mod@bench): the cost of LPE tracking.

// `!(x > 0.0)` is used on purpose throughout: it is true for NaN, which must take the
// rejecting branch; `x <= 0.0` would let NaN through.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod aov;
pub mod bench;
pub mod camera;
pub mod film;
pub mod geometry;
pub mod inputs;
pub mod integrator;
pub mod invariant;
pub mod light;
pub mod material;
pub mod output;
pub mod rng;
pub mod sampling;
pub mod scene;
pub mod verify;
