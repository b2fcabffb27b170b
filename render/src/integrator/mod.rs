//! Unidirectional path tracing with next-event estimation and MIS, routing every
//! contribution into the AOVs whose expressions match its path.
//!
//! # Estimator
//! A path `C x1 ... xk` carries throughput `beta = prod f cos / (p_lobe pdf)` (with
//! Russian roulette's `1/q`). At each scattering vertex two strategies reach an emitter:
//! - light sampling (NEE): pick a light (probability `1/n`), sample a point; for **each
//!   non-delta lobe** `j` of the material this is a separate path `... x_k(j) L` with
//!   contribution `beta * f_j cos Le / p_light`, weighted by the power heuristic against
//!   the BSDF strategy's density for that lobe, `p_pick(j) pdf_j`;
//! - BSDF sampling: pick lobe `i`, sample a direction; if the ray hits an emitter the path
//!   `... x_k(i) E` gets `beta * (f_i cos / (p_pick(i) pdf_i)) Le`, MIS-weighted by the
//!   light-sampling density when NEE could have sampled that emitter.
//!
//! Each lobe term is thus estimated by two strategies whose weights sum to one, and each
//! contribution is attributed to exactly the lobe that scattered, so every path the
//! matcher sees is a real light path with its own value.
//!
//! # Prefixes (how an AOV weighs a contribution; docs/language.md §7)
//! Every contribution is an `Arrival`: the matcher state of its complete path, the
//! throughput `beta` up to its last scattering vertex, the `local` estimate at that vertex
//! (`f cos Le / pdf`, no MIS, no visibility) and its `Strategy`. An AOV's value is
//! `thru * local * weight` where
//! - `thru = beta`, or 1 with `nothruput;` (no accumulated throughput: only the last
//!   vertex's lighting);
//! - `weight` is the MIS weight times visibility; with `unoccluded;` light samples count
//!   with weight 1 whether or not they are blocked and BSDF hits NEE could have produced
//!   count 0 (light sampling alone estimates those connections, without shadowing); with
//!   `shadows;` the same unshadowed light samples count only when blocked, which is
//!   `unoccluded - occluded` in expectation;
//! - the scene's clamp (max component of one contribution) applies unless `noclamp;`;
//! - holdout paths (a vertex on a holdout object) go only to `holdouts;` AOVs, the others
//!   only to AOVs without it; beauty excludes holdout paths;
//! - a sample whose light transport is not finite is dropped from beauty and every AOV
//!   and counted, except for `noinfinitecheck;` AOVs, which keep it; `overwrite;` AOVs
//!   keep the last value written instead of the mean (user lobes); values only an AOV
//!   receives (other weights, `nothruput;`) that are not finite are dropped for that AOV
//!   alone and counted apart, so whether a sample is rejected never depends on which
//!   AOVs were requested.
//!
//! Beauty is `beta * local * weight` of every non-holdout transport contribution, added
//! independently of the matcher: that is what makes "AOVs sum to beauty" a real check.

mod contributions;
mod dispatch;
mod driver;
mod estimator;
mod settings;
mod setup;

pub use dispatch::{render, render_announcing, render_with, ENGINE};
pub use settings::{Render, RenderError, Settings, Technique, USER_SIGNALS};
pub use setup::Integrator;
