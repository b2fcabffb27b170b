//! `lpe-render [OPTIONS]`: render a scene into beauty + AOVs and write the outputs.

use std::path::PathBuf;
use std::time::Instant;

use lpe::translate::Scattering as OslScattering;
use lpe_profile::Profile;
use lpe_render::aov::SceneDialect;
use lpe_render::inputs::{self, Inputs, Sources};
use lpe_render::integrator::{self, Settings};
use lpe_render::invariant::Invariant;
use lpe_render::output::{self, Report};
use lpe_render::verify::invariants;

use crate::args::{parse_res, positive_u32, positive_usize, InputError};

/// Arguments of a render (no subcommand).
#[derive(clap::Args)]
pub struct RenderArgs {
    /// Built-in scene (cornell, still-life, furnace) or a TOML scene file.
    #[arg(long, default_value = "cornell")]
    pub scene: String,
    /// Samples per pixel.
    #[arg(long, default_value_t = 64, value_parser = positive_u32)]
    pub spp: u32,
    /// Image size, WIDTHxHEIGHT.
    #[arg(long, default_value = "256x256", value_parser = parse_res)]
    pub res: (usize, usize),
    /// Worker threads (default: one per core).
    #[arg(long, value_parser = positive_usize)]
    pub threads: Option<usize>,
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// An AOV as NAME=LPE (repeatable), e.g. --aov 'key=C.*<L.'"'"'key'"'"'>'.
    #[arg(long = "aov", value_name = "NAME=LPE")]
    pub aovs: Vec<String>,
    /// RenderMan DisplayChannel lines to read AOVs from.
    #[arg(long, value_name = "FILE")]
    pub display: Option<PathBuf>,
    /// A USD stage (.usda/.usdc/.usdz) to take AOVs from: its RenderVars with
    /// `sourceType = "lpe"`, picked and ordered by the first RenderProduct's `orderedVars`
    /// when it has them; each becomes an EXR layer named after the RenderVar prim.
    #[arg(long, value_name = "FILE")]
    pub usd: Option<PathBuf>,
    /// rendermn.ini with user macros and lobe mappings (RenderMan dialect only).
    #[arg(long, value_name = "FILE")]
    pub ini: Option<PathBuf>,
    /// The language of every AOV (--aov, --display, --usd): `renderman` or `osl`.
    /// OSL: no prefixes, macros, lobe numbers or user lobes; vertices are `C`, `R`/`T`
    /// with `D` (diffuse), `G` (glossy) or `S` (delta), `L`, `O`, labelled with the
    /// object's lpegroup or the light's group; the defaults are the OSL basic set.
    #[arg(long)]
    pub dialect: Option<lpe::DialectName>,
    /// Render as this renderer shows its vertices and reads its AOVs (docs/profiles.md):
    /// `karma` (every specular lobe is `G`), `arnold` (every specular lobe is `S`), ...;
    /// its dialect, letters, prefixes and built-in names apply to every AOV.
    #[arg(long, value_name = "NAME")]
    pub renderer: Option<String>,
    /// Output directory.
    #[arg(long, default_value = "out")]
    pub out: PathBuf,
    /// Simulate every effect (the generic path), ignoring the effects plan.
    #[arg(long)]
    pub all_effects: bool,
}

pub fn print_invariants(list: &[Invariant]) -> bool {
    for i in list {
        eprintln!("  {}", i.line());
        if i.passed != Some(true) && !i.formal {
            eprintln!("         {}", i.detail);
        }
    }
    !list.iter().any(Invariant::failed)
}

impl RenderArgs {
    /// The renderer's profile `--renderer` names, checked against `--dialect` and against
    /// what the renderer's vertices can show.
    pub fn profile(&self) -> Result<Option<&'static Profile>, InputError> {
        let Some(name) = &self.renderer else {
            return Ok(None);
        };
        let p = lpe_profile::by_name(name).map_err(|e| InputError::Renderer(e.to_string()))?;
        if let Some(d) = self.dialect.filter(|d| *d != p.dialect()) {
            return Err(InputError::Renderer(format!(
                "--dialect {d} contradicts --renderer {name}, which reads {}'s dialect; drop --dialect",
                p.dialect()
            )));
        }
        if p.correspondence().shows(OslScattering::Straight) {
            return Err(InputError::Renderer(format!(
                "--renderer {name} shows some lobes as `s` (straight), which no lobe of \
                 lpe-render's materials is"
            )));
        }
        Ok(Some(p))
    }

    /// The dialect of every AOV: the renderer's, else `--dialect`, else RenderMan's.
    pub fn dialect(&self) -> lpe::DialectName {
        match self.profile() {
            Ok(Some(p)) => p.dialect(),
            _ => self.dialect.unwrap_or_default(),
        }
    }
}

/// Renders in dialect `D`: reads the inputs, renders, checks the invariants and writes
/// the outputs, printing as it goes.
pub fn run<D: SceneDialect>(args: &RenderArgs) -> Result<bool, InputError> {
    let t0 = Instant::now();
    let profile = args.profile()?;
    let Inputs {
        scene,
        lobes,
        aovs,
        warnings,
    } = inputs::gather::<D>(&Sources {
        scene: &args.scene,
        ini: args.ini.as_deref(),
        display: args.display.as_deref(),
        usd: args.usd.as_deref(),
        aovs: &args.aovs,
        profile,
    })?;
    for w in warnings {
        eprintln!("warning: {w}");
    }
    let settings = Settings {
        width: args.res.0,
        height: args.res.1,
        spp: args.spp,
        seed: args.seed,
        threads: args.threads,
        all_effects: args.all_effects,
        progress: true,
        scattering: profile
            .filter(|p| p.dialect() == lpe::DialectName::Osl)
            .map(Profile::correspondence),
        ..Settings::default()
    };
    let threads = args.threads.unwrap_or_else(rayon::current_num_threads);
    eprintln!(
        "lpe-render: scene `{}`, {}x{}, {} spp, {} AOVs ({}), {} threads, matcher: {}",
        scene.name,
        settings.width,
        settings.height,
        settings.spp,
        aovs.aovs.len(),
        match profile {
            Some(p) => format!("{} dialect, as {}", D::NAME, p.title),
            None => format!("{} dialect", D::NAME),
        },
        threads,
        integrator::ENGINE
    );
    let all = args.all_effects;
    let render = integrator::render_announcing(&scene, &aovs, &lobes, &settings, &mut |plan| {
        eprintln!("effects plan{}:", if all { " (--all-effects)" } else { "" });
        for line in plan.describe() {
            eprintln!("  {line}");
        }
    })?;
    let mut invariants = invariants::formal_partition(&aovs);
    invariants.extend(invariants::invariants(&scene, &aovs, &render));
    eprintln!(
        "rendered in {:.2}s: {:.0} paths/s, {:.0} rays/s",
        render.seconds,
        render.paths as f64 / render.seconds,
        render.rays as f64 / render.seconds
    );
    eprintln!("invariants:");
    let ok = print_invariants(&invariants);

    let mut report = Report::new(&scene, &settings, threads, &aovs, &render, invariants);
    report.timing.total_seconds = t0.elapsed().as_secs_f64();
    let files = output::write_all(&args.out, &render.film, &aovs, &mut report)?;
    eprintln!(
        "wrote {} files to {} ({} EXR layers + beauty) in {:.2}s total",
        files.len(),
        args.out.display(),
        aovs.aovs.len(),
        t0.elapsed().as_secs_f64()
    );
    Ok(ok)
}
