//! `lpe-render`: render a scene into beauty + LPE AOVs, check invariants, write EXR,
//! PNGs and a report. `lpe-render check` runs the invariant suite on small renders;
//! `lpe-render bench` measures what LPE tracking costs.
//!
//! Exit status: 0 success, 1 an invariant failed, 2 bad input.

use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use lpe_render::aovs::{parse_display_channels, split_aov_arg, AovList};
use lpe_render::app;
use lpe_render::check::Invariant;
use lpe_render::integrator::Settings;
use lpe_render::output::{self, AovEntry, Report, Timing};
use lpe_render::scene::Scene;

#[derive(Parser)]
#[command(
    name = "lpe-render",
    version,
    about = "Path tracer routing light paths into LPE AOVs"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    #[command(flatten)]
    render: RenderArgs,
}

#[derive(Subcommand)]
enum Command {
    /// Run the invariant suite on small renders of the built-in scenes (CI).
    Check {
        #[arg(long, value_parser = positive_usize)]
        threads: Option<usize>,
    },
    /// Measure the cost of LPE tracking: 32 AOVs vs beauty only, same run.
    Bench {
        #[arg(long, default_value = "cornell")]
        scene: String,
        #[arg(long, default_value_t = 8, value_parser = positive_u32)]
        spp: u32,
        #[arg(long, default_value = "96x96", value_parser = parse_res)]
        res: (usize, usize),
        /// One thread by default: a single worker is the least disturbed by other load.
        #[arg(long, default_value_t = 1, value_parser = positive_usize)]
        threads: usize,
        /// Rounds, each rendering both configurations back to back.
        #[arg(long, default_value_t = 15, value_parser = positive_usize)]
        rounds: usize,
    },
    /// Accuracy vs time: MSE, relMSE, log-log slope and efficiency per technique and
    /// AOV on scenes with known answers; CSV, Markdown and plots in --out.
    Converge {
        /// A small run for CI (seconds).
        #[arg(long)]
        quick: bool,
        #[arg(long, default_value = "out/converge")]
        out: PathBuf,
        #[arg(long, value_parser = positive_usize)]
        threads: Option<usize>,
    },
    /// The hard-case scene set (tiny lights, extreme intensities and pdfs, 10^7-sample
    /// film, degenerate input): one table row per case.
    Stress {
        /// Fewer samples (seconds instead of about a minute).
        #[arg(long)]
        quick: bool,
    },
}

#[derive(Args)]
struct RenderArgs {
    /// Built-in scene (cornell, still-life, furnace) or a TOML scene file.
    #[arg(long, default_value = "cornell")]
    scene: String,
    /// Samples per pixel.
    #[arg(long, default_value_t = 64, value_parser = positive_u32)]
    spp: u32,
    /// Image size, WIDTHxHEIGHT.
    #[arg(long, default_value = "256x256", value_parser = parse_res)]
    res: (usize, usize),
    /// Worker threads (default: one per core).
    #[arg(long, value_parser = positive_usize)]
    threads: Option<usize>,
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// An AOV as NAME=LPE (repeatable), e.g. --aov 'key=C.*<L.'"'"'key'"'"'>'.
    #[arg(long = "aov", value_name = "NAME=LPE")]
    aovs: Vec<String>,
    /// RenderMan DisplayChannel lines to read AOVs from.
    #[arg(long, value_name = "FILE")]
    display: Option<PathBuf>,
    /// rendermn.ini with user macros and lobe mappings.
    #[arg(long, value_name = "FILE")]
    ini: Option<PathBuf>,
    /// Output directory.
    #[arg(long, default_value = "out")]
    out: PathBuf,
    /// Simulate every effect (the generic path), ignoring the effects plan.
    #[arg(long)]
    all_effects: bool,
}

fn parse_res(s: &str) -> Result<(usize, usize), String> {
    let bad = || format!("`{s}`: expected WIDTHxHEIGHT, e.g. 256x256 (each 1..=16384)");
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    let w: usize = w.trim().parse().map_err(|_| bad())?;
    let h: usize = h.trim().parse().map_err(|_| bad())?;
    if !(1..=16384).contains(&w) || !(1..=16384).contains(&h) {
        return Err(bad());
    }
    Ok((w, h))
}

/// A positive integer no larger than `max`.
fn positive_at_most<T: std::str::FromStr + PartialOrd + From<u8> + std::fmt::Display>(
    s: &str,
    max: T,
) -> Result<T, String> {
    match s.parse::<T>() {
        Ok(n) if n >= T::from(1) && n <= max => Ok(n),
        _ => Err(format!(
            "`{s}`: expected a positive integer (at most {max})"
        )),
    }
}

/// Samples per pixel.
fn positive_u32(s: &str) -> Result<u32, String> {
    positive_at_most(s, u32::MAX)
}

/// Threads and rounds: more than a few thousand is a typo, not a request.
fn positive_usize(s: &str) -> Result<usize, String> {
    positive_at_most(s, 4096)
}

/// Input problems: printed, exit status 2.
struct InputError(String);

impl<E: std::fmt::Display> From<E> for InputError {
    fn from(e: E) -> Self {
        InputError(e.to_string())
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        None => run_render(&cli.render),
        Some(Command::Check { threads }) => run_check(threads),
        Some(Command::Bench {
            scene,
            spp,
            res,
            threads,
            rounds,
        }) => run_bench(&scene, spp, res, Some(threads), rounds),
        Some(Command::Converge {
            quick,
            out,
            threads,
        }) => run_converge(quick, &out, threads),
        Some(Command::Stress { quick }) => run_stress(quick),
    };
    match result {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        Err(InputError(e)) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

fn load_config(ini: Option<&PathBuf>) -> Result<lpe::Config, InputError> {
    let Some(path) = ini else {
        return Ok(lpe::Config::default());
    };
    let text = std::fs::read_to_string(path)
        .map_err(|e| InputError(format!("{}: {e}", path.display())))?;
    lpe::Config::from_ini(&text).map_err(|e| InputError(format!("{}:{e}", path.display())))
}

fn print_invariants(list: &[Invariant]) -> bool {
    let mut ok = true;
    for i in list {
        let tag = match i.passed {
            Some(true) => "pass",
            Some(false) => {
                ok = false;
                "FAIL"
            }
            None => "skip",
        };
        eprintln!(
            "  [{tag}] {} — measured {:.3e} (tolerance {:.3e})",
            i.name, i.measured, i.tolerance
        );
        if i.passed != Some(true) {
            eprintln!("         {}", i.detail);
        }
    }
    ok
}

fn run_render(args: &RenderArgs) -> Result<bool, InputError> {
    let t0 = Instant::now();
    let config = load_config(args.ini.as_ref())?;
    let parser = lpe::Parser::new(config.limits.clone(), config.macros.clone());
    let scene = Scene::load(&args.scene, &config.lobes)?;

    let mut aovs = AovList::default();
    if let Some(path) = &args.display {
        let text = std::fs::read_to_string(path)
            .map_err(|e| InputError(format!("{}: {e}", path.display())))?;
        let read = parse_display_channels(&text, &path.display().to_string())?;
        for w in read.warnings {
            eprintln!("warning: {w}");
        }
        for (name, source) in read.channels {
            aovs.push(&name, &source, &parser)
                .map_err(|e| InputError(format!("{}: {e}", path.display())))?;
        }
    }
    for arg in &args.aovs {
        let (name, source) = split_aov_arg(arg)?;
        aovs.push(name, source, &parser)?;
    }
    if args.display.is_none() && args.aovs.is_empty() {
        aovs = app::default_aovs(&scene, &parser)?;
    }
    for (lobe, names) in config
        .lobes
        .user_collisions(&lpe_render::integrator::USER_SIGNALS)
    {
        aovs.notes.push(format!(
            "user signals {} share lobe {lobe}: they overwrite each other",
            names.join(", ")
        ));
    }

    // The film holds f64 RGB per pixel per layer; refuse sizes that cannot fit rather
    // than abort on allocation.
    let film_bytes = (args.res.0 * args.res.1) as u128 * (1 + aovs.aovs.len()) as u128 * 24;
    if film_bytes > 8 << 30 {
        return Err(InputError(format!(
            "{}x{} with {} AOVs needs {:.1} GiB of film; at most 8 GiB",
            args.res.0,
            args.res.1,
            aovs.aovs.len(),
            film_bytes as f64 / (1u64 << 30) as f64
        )));
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
        "lpe-render: scene `{}`, {}x{}, {} spp, {} AOVs, {} threads, matcher: {}",
        scene.name,
        settings.width,
        settings.height,
        settings.spp,
        aovs.aovs.len(),
        threads,
        app::ENGINE
    );
    let all = args.all_effects;
    let render = app::render_announcing(&scene, &aovs, &config.lobes, &settings, &mut |plan| {
        eprintln!("effects plan{}:", if all { " (--all-effects)" } else { "" });
        for line in plan.describe() {
            eprintln!("  {line}");
        }
    })?;
    let mut invariants = lpe_render::check::formal_partition(&aovs);
    invariants.extend(app::invariants(&scene, &aovs, &render));
    eprintln!(
        "rendered in {:.2}s: {:.0} paths/s, {:.0} rays/s",
        render.seconds,
        render.paths as f64 / render.seconds,
        render.rays as f64 / render.seconds
    );
    eprintln!("invariants:");
    let ok = print_invariants(&invariants);

    let mut report = Report {
        scene: scene.name.clone(),
        width: settings.width,
        height: settings.height,
        spp: settings.spp,
        seed: settings.seed,
        threads,
        matcher: app::ENGINE.into(),
        timing: Timing {
            render_seconds: render.seconds,
            total_seconds: 0.0,
            paths: render.paths,
            rays: render.rays,
            paths_per_second: render.paths as f64 / render.seconds,
            rays_per_second: render.rays as f64 / render.seconds,
        },
        effects_plan: render.plan.describe(),
        effects: render.plan,
        aovs: aovs
            .aovs
            .iter()
            .map(|a| AovEntry {
                name: a.name.clone(),
                source: a.source.clone(),
                expression: a.lpe.to_string(),
            })
            .collect(),
        invariants,
        notes: aovs.notes.clone(),
        rejected_samples: render.film.rejected,
        rejected_aov_values: render.film.aov_rejected,
        files: Vec::new(),
        contact_sheet_order: Vec::new(),
    };
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

fn run_check(threads: Option<usize>) -> Result<bool, InputError> {
    let t0 = Instant::now();
    let list = app::check_suite(threads, &mut |s| eprintln!("  rendered {s}"))?;
    eprintln!("invariants:");
    let ok = print_invariants(&list);
    let failed = list.iter().filter(|i| i.failed()).count();
    eprintln!(
        "{} invariants, {} failed, {} not checked, in {:.1}s",
        list.len(),
        failed,
        list.iter().filter(|i| i.passed.is_none()).count(),
        t0.elapsed().as_secs_f64()
    );
    Ok(ok)
}

fn run_bench(
    scene: &str,
    spp: u32,
    res: (usize, usize),
    threads: Option<usize>,
    rounds: usize,
) -> Result<bool, InputError> {
    let config = lpe::Config::default();
    let parser = lpe::Parser::new(config.limits.clone(), config.macros.clone());
    let scene = Scene::load(scene, &config.lobes)?;
    let settings = Settings {
        width: res.0,
        height: res.1,
        spp,
        threads,
        ..Settings::default()
    };
    let b = app::bench(&scene, &config.lobes, &parser, &settings, rounds)?;
    println!(
        "bench `{}` {}x{} {} spp, {} thread(s), {rounds} rounds, matcher: {}",
        scene.name,
        res.0,
        res.1,
        spp,
        threads.map_or("all".to_string(), |t| t.to_string()),
        app::ENGINE
    );
    println!(
        "  beauty only: best {:.3}s ({:.0} paths/s)",
        b.beauty_seconds,
        b.paths as f64 / b.beauty_seconds
    );
    println!(
        "  {} AOVs:     best {:.3}s ({:.0} paths/s)",
        b.aov_count,
        b.aov_seconds,
        b.paths as f64 / b.aov_seconds
    );
    println!(
        "  LPE tracking overhead (median of {rounds} paired rounds): {:+.1}%",
        b.overhead * 100.0
    );
    Ok(true)
}

fn run_converge(
    quick: bool,
    out: &std::path::Path,
    threads: Option<usize>,
) -> Result<bool, InputError> {
    let mut cfg = if quick {
        lpe_render::converge::Config::quick()
    } else {
        lpe_render::converge::Config::default_run()
    };
    cfg.threads = threads;
    let t0 = Instant::now();
    let o = lpe_render::converge::run(&cfg, out, &mut |s| eprintln!("  {s}"))?;
    println!(
        "{}",
        lpe_render::converge::markdown(
            &o.summary,
            &["beauty", "direct", "bounce3", "directDiffuse"]
        )
    );
    println!("{}", o.accumulation);
    if !o.plot_text {
        eprintln!("note: no TrueType font found (set LPE_PLOT_FONT): plots drawn without text");
    }
    eprintln!(
        "converge: {} series in {:.1}s; wrote {}",
        o.summary.len(),
        t0.elapsed().as_secs_f64(),
        o.files
            .iter()
            .map(|f| f.display().to_string())
            .collect::<Vec<_>>()
            .join(", ")
    );
    Ok(true)
}

fn run_stress(quick: bool) -> Result<bool, InputError> {
    let rows = lpe_render::stress::run(quick)?;
    println!("{}", lpe_render::stress::markdown(&rows));
    Ok(rows.iter().all(|r| r.passed))
}
