//! What a render is asked for and gives back, and why it could not run: a leaf below
//! the integrator's parts, which all read it.

use crate::aov::matcher::MatcherError;
use crate::aov::plan::Plan;
use crate::film::{Accumulation, Film, MAX_FILM_BYTES};

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
    /// A scene label the AOVs' dialect cannot show (`why` is the dialect's reason).
    #[error("{owner} `{label}` {why}")]
    SceneLabel {
        owner: String,
        label: String,
        why: &'static str,
    },
    /// The film would not fit in memory: refused rather than aborting on allocation.
    #[error("{width}x{height} with {aovs} AOVs needs {:.1} GiB of film; at most {} GiB", *bytes as f64 / (1u64 << 30) as f64, MAX_FILM_BYTES >> 30)]
    FilmTooLarge {
        width: usize,
        height: usize,
        aovs: usize,
        bytes: u128,
    },
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
    /// The scattering a scattering vertex shows an OSL-based matcher, by the RenderMan
    /// lobe it scatters off: a renderer's correspondence (`lpe-render --renderer karma`:
    /// every specular lobe is `G`). `None`: by the lobe's model (`G` for GGX, `S` for the
    /// dielectric), as plain OSL.
    pub scattering: Option<lpe::translate::Correspondence>,
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
            scattering: None,
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
