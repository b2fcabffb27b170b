//! `lpe-render`: a compact path tracer that routes every light path into AOVs through an
//! LPE matcher, and checks the invariants AOVs must satisfy (partitions of beauty sum to
//! it, results do not depend on threads or on which other AOVs were requested, the
//! furnace's closed form).
//!
//! Modules: [`geometry`] (shapes, BVH), [`camera`], [`material`] (named lobes),
//! [`light`], [`scene`] (TOML scene files and built-ins), [`matcher`] (the engine seam),
//! [`aovs`], [`plan`] (effects plan), [`integrator`], [`film`], [`output`] (EXR, PNG,
//! report), [`check`] (invariants).

// `!(x > 0.0)` is used on purpose throughout: it is true for NaN, which must take the
// rejecting branch; `x <= 0.0` would let NaN through.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod aovs;
pub mod app;
pub mod camera;
pub mod check;
pub mod chi2;
pub mod converge;
pub mod film;
pub mod geometry;
pub mod integrator;
pub mod light;
pub mod matcher;
pub mod material;
pub mod output;
pub mod plan;
pub mod plot;
pub mod rng;
pub mod sampling;
pub mod scene;
pub mod stress;
