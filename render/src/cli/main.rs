//! `lpe-render`: render a scene into beauty + LPE AOVs, check invariants, write EXR,
//! PNGs and a report. `lpe-render check` runs the invariant suite on small renders;
//! `lpe-render bench` measures what LPE tracking costs.
//!
//! Exit status: 0 success, 1 an invariant failed, 2 bad input.
//!
//! The dialect of the AOVs is read here and turned into a type once
//! ([`lpe::with_dialect!`]); every subcommand is generic over it from there on.

use clap::{Parser, Subcommand};
use lpe::with_dialect;
use std::path::PathBuf;
use std::process::ExitCode;

mod args;
mod bench;
mod check;
mod converge;
mod render;
mod stress;

use args::{parse_res, positive_u32, positive_usize};
use render::RenderArgs;

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
        /// `osl`: the checks that depend on the dialect, with the OSL basic set (its
        /// sums to beauty, its formal partition, the same images as RenderMan's).
        #[arg(long, default_value_t = lpe::DialectName::RenderMan)]
        dialect: lpe::DialectName,
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
        /// The dialect of the 32 AOVs: `osl` starts from the OSL basic set.
        #[arg(long, default_value_t = lpe::DialectName::RenderMan)]
        dialect: lpe::DialectName,
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

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        None => with_dialect!(cli.render.dialect(), D => render::run::<D>(&cli.render)),
        Some(Command::Check { threads, dialect }) => {
            with_dialect!(dialect, D => check::run::<D>(threads))
        }
        Some(Command::Bench {
            scene,
            spp,
            res,
            threads,
            rounds,
            dialect,
        }) => with_dialect!(dialect, D => bench::run::<D>(&scene, spp, res, Some(threads), rounds)),
        Some(Command::Converge {
            quick,
            out,
            threads,
        }) => converge::run(quick, &out, threads),
        Some(Command::Stress { quick }) => stress::run(quick),
    };
    match result {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}
