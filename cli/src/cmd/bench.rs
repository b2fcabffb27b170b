//! `lpe-check bench`: the matcher benchmark as a Markdown table (see
//! [`lpe_bench`]: this module parses the arguments, runs it and prints). Build with `--release`; a debug build measures the debug build.
//! Exits 1 if any engine disagrees with the reference on the checked paths.

use std::process::ExitCode;

use lpe_bench::{self as bench, Config};

/// Arguments of `lpe-check bench`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Sample paths until they hold this many vertices.
    #[arg(long, default_value_t = 1_000_000)]
    pub vertices: usize,
    /// Paths the reference matcher runs on (every engine is checked on them).
    #[arg(long, default_value_t = 20_000)]
    pub reference_paths: usize,
    /// Timed runs per engine (the best counts).
    #[arg(long, default_value_t = 5)]
    pub reps: usize,
    /// Path sampler seed.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Run only these workloads (basic, per-lobe, groups, nested, blowup12, blowup20,
    /// wide, osl-basic).
    #[arg(long)]
    pub workload: Vec<String>,
    /// Instead: time the equivalence check of `C.*D.{k}L` against `C.*D.{k}[LO]` for
    /// k = 8..=24 on the NFA route and the lazy-DFA route ([`super::bench_analysis`]).
    #[arg(long)]
    pub analysis: bool,
}

/// Runs `lpe-check bench`.
pub fn run(args: Args) -> ExitCode {
    if args.analysis {
        print!("{}", super::bench_analysis::table(8..=24));
        return ExitCode::SUCCESS;
    }
    let mut names: Vec<&str> = bench::workload::all().iter().map(|w| w.name).collect();
    names.push(bench::osl::WORKLOAD);
    if let Some(bad) = args.workload.iter().find(|w| !names.contains(&w.as_str())) {
        eprintln!(
            "error: unknown workload `{bad}`: workloads are {}",
            names.join(", ")
        );
        return ExitCode::from(2);
    }
    let cfg = Config {
        vertices: args.vertices,
        reference_paths: args.reference_paths,
        reps: args.reps,
        seed: args.seed,
        workloads: args.workload,
    };
    if cfg!(debug_assertions) {
        eprintln!("warning: debug build; build with --release for meaningful numbers");
    }
    match bench::run(&cfg) {
        Ok(rows) => {
            print!("{}", bench::table(&rows));
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(1)
        }
    }
}
