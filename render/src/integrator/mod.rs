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

use lpe::renderman::LobeMap;

use crate::aov::matcher::{MatcherError, RenderMatcher};
use crate::aov::plan::Plan;
use crate::aov::AovList;
use crate::camera::Camera;
use crate::film::{Accumulation, Film, Weighting};
use crate::scene::Scene;

mod contributions;
mod dispatch;
mod driver;
mod estimator;

use contributions::Vertices;
pub use dispatch::{render, render_announcing, render_with, ENGINE};

/// Why a render could not run.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    #[error("thread pool: {0}")]
    ThreadPool(#[from] rayon::ThreadPoolBuildError),
    #[error(transparent)]
    Matcher(#[from] MatcherError),
    /// The fast matcher refused the AOV set (only where no fallback is wanted).
    #[error("the fast matcher cannot compile this AOV set: {reason}")]
    Compile { reason: String },
    /// Under `--dialect osl`, a scene label that is one of OSL's built-in labels.
    #[error(
        "{owner} `{label}` is a built-in OSL label: under --dialect osl scene labels are \
         custom labels, and OSL's eater would not skip this one (so `L` or `R` would miss \
         its vertices); rename it"
    )]
    OslBuiltinLabel { owner: String, label: String },
}

/// Which strategies estimate direct lighting (`converge` compares them).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub enum Technique {
    /// Light sampling and BSDF sampling, power heuristic.
    Mis,
    /// BSDF sampling only: emitters count only when a path hits them (`unoccluded;` and
    /// `shadows;` AOVs then see what the rays see: there are no light samples to unshadow).
    BsdfOnly,
    /// Light sampling only: BSDF hits on lights NEE can sample count zero.
    LightOnly,
}

/// How to render.
#[derive(Clone, Debug)]
pub struct Settings {
    pub width: usize,
    pub height: usize,
    pub spp: u32,
    pub seed: u64,
    /// Worker threads (`None`: rayon's default, one per core).
    pub threads: Option<usize>,
    pub technique: Technique,
    pub russian_roulette: bool,
    /// How the film sums samples.
    pub accumulation: Accumulation,
    /// Force the generic path (`--all-effects`).
    pub all_effects: bool,
    /// Whether beauty is wanted (if not, paths dead for every AOV stop early).
    pub beauty: bool,
    pub progress: bool,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            width: 64,
            height: 64,
            spp: 4,
            seed: 0,
            threads: None,
            technique: Technique::Mis,
            russian_roulette: true,
            accumulation: Accumulation::F64,
            all_effects: false,
            beauty: true,
            progress: false,
        }
    }
}

/// What a render produced.
#[derive(Clone, Debug)]
pub struct Render {
    pub film: Film,
    pub plan: Plan,
    pub seconds: f64,
    /// CPU time of the whole process over the same span (every worker thread): what
    /// `lpe-render bench` compares, since on a shared machine it does not count the
    /// time a worker waits for a core.
    pub cpu_seconds: f64,
    /// Camera samples traced.
    pub paths: u64,
    /// Rays cast (camera, bounce and shadow rays).
    pub rays: u64,
}

/// Lobe-map names of the user signals, in `UserSignal::ALL` order (the CLI checks
/// them for lobe collisions).
pub const USER_SIGNALS: [&str; 3] = ["Albedo", "Position", "Normal"];

pub struct Integrator<'a, M: RenderMatcher> {
    scene: &'a Scene,
    matcher: &'a M,
    /// How contributions weigh into each AOV (handed to the film).
    weighting: Weighting,
    /// The dome light escaping rays see (looked up once, not per escaped ray).
    dome: Option<usize>,
    vertices: Vertices<M::Class>,
    plan: Plan,
    settings: &'a Settings,
    camera: Camera,
}

impl<'a, M: RenderMatcher> Integrator<'a, M> {
    pub fn new(
        scene: &'a Scene,
        aovs: &AovList,
        matcher: &'a M,
        lobes: &LobeMap,
        settings: &'a Settings,
    ) -> Self {
        let mut plan = if settings.all_effects {
            Plan::all_effects(aovs)
        } else {
            Plan::derive(scene, aovs, settings.beauty)
        };
        let vertices = Vertices::new(scene, matcher, lobes, plan.labels);
        if !settings.all_effects {
            plan.user_lobes = vertices.user.iter().flatten().any(|(_, m)| !m.is_empty());
        }
        let c = &scene.camera;
        let aspect = settings.width as f32 / settings.height as f32;
        Integrator {
            scene,
            matcher,
            weighting: Weighting::new(aovs, scene.settings.clamp),
            dome: scene.dome(),
            vertices,
            plan,
            settings,
            camera: Camera::new(c.position, c.look_at, c.up, c.fov, aspect),
        }
    }

    pub fn plan(&self) -> Plan {
        self.plan
    }
}
