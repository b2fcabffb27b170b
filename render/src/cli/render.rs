//! `lpe-render [OPTIONS]`: render a scene into beauty + AOVs and write the outputs.

use std::path::{Path, PathBuf};
use std::time::Instant;

use lpe::DialectName;
use lpe_render::aov::{
    parse_display_channels, split_aov_arg, usd_render_vars, AovList, DisplayChannels,
};
use lpe_render::integrator::{self, Settings};
use lpe_render::output::{self, Report};
use lpe_render::scene::Scene;
use lpe_render::verify::invariants::{self, Invariant};

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
    #[arg(long, default_value_t = lpe::DialectName::RenderMan)]
    pub dialect: lpe::DialectName,
    /// Output directory.
    #[arg(long, default_value = "out")]
    pub out: PathBuf,
    /// Simulate every effect (the generic path), ignoring the effects plan.
    #[arg(long)]
    pub all_effects: bool,
}

fn load_config(ini: Option<&PathBuf>) -> Result<lpe::renderman::Config, InputError> {
    let Some(path) = ini else {
        return Ok(lpe::renderman::Config::default());
    };
    let text = std::fs::read_to_string(path).map_err(|source| InputError::Read {
        path: path.clone(),
        source,
    })?;
    lpe::renderman::Config::from_ini(&text).map_err(|source| InputError::Ini {
        path: path.clone(),
        source,
    })
}

/// Prints the warnings of channels read from `path` and appends its AOVs.
fn push_channels(
    aovs: &mut AovList,
    read: DisplayChannels,
    path: &Path,
    parser: &lpe::renderman::Parser,
) -> Result<(), InputError> {
    for w in read.warnings {
        eprintln!("warning: {w}");
    }
    for c in read.channels {
        aovs.push(&c.name, &c.source, parser)
            .map_err(|source| InputError::DisplayAov {
                path: path.to_path_buf(),
                at: Box::new(c.location.clone()),
                source,
            })?;
    }
    Ok(())
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

pub fn run(args: &RenderArgs) -> Result<bool, InputError> {
    let t0 = Instant::now();
    if args.dialect == DialectName::Osl && args.ini.is_some() {
        return Err(InputError::IniWithOsl);
    }
    let config = load_config(args.ini.as_ref())?;
    let parser = lpe::renderman::Parser::new(config.limits.clone(), config.macros.clone());
    let scene = Scene::load(&args.scene, &config.lobes)?;

    let mut aovs = AovList::new(args.dialect);
    if let Some(path) = &args.display {
        let text = std::fs::read_to_string(path).map_err(|source| InputError::Read {
            path: path.clone(),
            source,
        })?;
        let read = parse_display_channels(&text, &path.display().to_string())?;
        push_channels(&mut aovs, read, path, &parser)?;
    }
    if let Some(path) = &args.usd {
        let stage = lpe_lint::read::usd::read(path, &lpe_lint::read::Limits::default())?;
        let mut read = usd_render_vars(&stage);
        for w in &mut read.warnings {
            *w = format!("{}: {w}", path.display());
        }
        push_channels(&mut aovs, read, path, &parser)?;
    }
    for arg in &args.aovs {
        let (name, source) = split_aov_arg(arg)?;
        aovs.push(name, source, &parser)?;
    }
    if args.display.is_none() && args.usd.is_none() && args.aovs.is_empty() {
        aovs = AovList::for_render_in(args.dialect, &scene, &parser)?;
    }
    for (lobe, names) in config.lobes.user_collisions(&integrator::USER_SIGNALS) {
        aovs.notes.push(format!(
            "user signals {} share lobe {lobe}: they overwrite each other",
            names.join(", ")
        ));
    }

    // The film holds f64 RGB per pixel per layer; refuse sizes that cannot fit rather
    // than abort on allocation.
    let film_bytes = (args.res.0 * args.res.1) as u128 * (1 + aovs.aovs.len()) as u128 * 24;
    if film_bytes > 8 << 30 {
        return Err(InputError::FilmTooLarge {
            width: args.res.0,
            height: args.res.1,
            aovs: aovs.aovs.len(),
            bytes: film_bytes,
        });
    }
    let settings = Settings {
        width: args.res.0,
        height: args.res.1,
        spp: args.spp,
        seed: args.seed,
        threads: args.threads,
        all_effects: args.all_effects,
        progress: true,
        ..Settings::default()
    };
    let threads = args.threads.unwrap_or_else(rayon::current_num_threads);
    eprintln!(
        "lpe-render: scene `{}`, {}x{}, {} spp, {} AOVs ({} dialect), {} threads, matcher: {}",
        scene.name,
        settings.width,
        settings.height,
        settings.spp,
        aovs.aovs.len(),
        aovs.dialect,
        threads,
        integrator::ENGINE
    );
    let all = args.all_effects;
    let render =
        integrator::render_announcing(&scene, &aovs, &config.lobes, &settings, &mut |plan| {
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
