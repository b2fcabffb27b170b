//! `lpe-check diff --external 'CMD ARGS'`: an external matcher against every engine.
//!
//! Prints each finding in full (a minimized disagreement with each side's answer and a
//! replay command, or a protocol fault with its request), then a summary of all of them.
//! Exit 0: agreement; 3: any finding; 2: bad input (the command cannot start, refuses
//! the hello, e.g. for a dialect it does not speak; a bad argument). `--dialect osl`
//! generates OSL cases, each with its own registration, sent with every `compile`.
//! `--suite DIR` replays the conformance suite instead ([`super::external_suite`]). The
//! replay command under each disagreement is written here, from the finding's set, path
//! and registration ([`super::replay`]).

use std::process::ExitCode;
use std::time::{Duration, Instant};

use lpe_engines::differential::Generate;
use lpe_engines::external::{self, Cases, Finding, Setup};

use super::args::Args;
use super::replay::replay;
use crate::dialect::CliDialect;
use crate::input::{bad_input, select_engines};

/// Runs `diff --external`.
pub fn run(args: &Args) -> ExitCode {
    let Some(command) = args.external.clone() else {
        return bad_input("error: --external needs a command");
    };
    if let Some(dir) = &args.suite {
        return super::external_suite::run(args, &command, dir);
    }
    // No `--ini` here: given RenderMan cases read with the default parser, as generated
    // ones are.
    lpe::with_dialect!(args.lang.dialect(), D => match args.lang.registration::<D>(None) {
        Ok(registration) => run_in::<D>(args, command, registration),
        Err(e) => bad_input(format!("error: {e}")),
    })
}

/// Runs `diff --external` in dialect `D`, given cases read under `registration`.
fn run_in<D: Generate + CliDialect>(
    args: &Args,
    command: String,
    registration: D::Registration,
) -> ExitCode {
    let engines = match select_engines::<D>(&args.engine) {
        Ok(e) => e,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    if !args.path.is_empty() && args.expr.is_empty() {
        return bad_input("error: --path needs --expr");
    }
    for p in &args.path {
        if let Err(e) = p.parse::<D::Path>() {
            return bad_input(format!("error: --path {p:?}: {e}"));
        }
    }
    let cases = if args.expr.is_empty() {
        Cases::Generated(args.run())
    } else {
        Cases::Given {
            exprs: args.expr.clone(),
            paths: args.path.clone(),
        }
    };
    let setup = Setup {
        command,
        registration,
        timeout: Duration::from_millis(args.timeout_ms),
        max_restarts: args.max_restarts,
        // The profile's name: a matcher that does not know it says `unsupported`.
        renderer: args.lang.renderer_profile().ok().flatten().map(|p| p.name),
    };
    let start = Instant::now();
    let report = match external::run(&setup, &cases, &engines) {
        Ok(r) => r,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    let secs = start.elapsed().as_secs_f64().max(1e-9);
    let names: Vec<&str> = engines.iter().map(|e| e.name()).collect();
    println!(
        "external: {} ({}, {} dialect); engines: {}",
        setup.command,
        report.name.as_deref().unwrap_or("unnamed"),
        args.lang.dialect(),
        names.join(", ")
    );
    if let Cases::Generated(run) = &cases {
        println!(
            "seed {}, cases {}..{}, max size {}, {} paths per case",
            run.seed,
            run.first,
            report.last_case.map_or(run.first, |last| last + 1),
            run.max_size,
            run.paths
        );
    }
    println!(
        "{} cases, {} AOV/path pairs in {:.2} s: {:.0} cases/s ({} matched)",
        report.cases,
        report.pairs,
        secs,
        report.cases as f64 / secs,
        report.matched
    );
    match &report.unsupported {
        (0, _) => println!("unsupported: none"),
        (n, first) => println!(
            "unsupported: {n} cases the external matcher does not implement (first: {})",
            first.as_deref().unwrap_or("?")
        ),
    }
    if report.uncompared > 0 {
        println!(
            "uncompared: {} cases no engine could build",
            report.uncompared
        );
    }
    for f in &report.findings {
        println!("\n{f}");
        if let Finding::Disagreement(d) = f {
            println!("  replay: {}", replay(&setup.command, d));
        }
    }
    if let Some(why) = &report.stopped {
        println!("\nstopped early: {why}");
    }
    if report.findings.is_empty() {
        println!("the external matcher agrees with every engine");
        return ExitCode::SUCCESS;
    }
    println!(
        "\nsummary: {} finding(s), {} disagreement(s), {} restart(s) of the external process",
        report.findings.len(),
        report.disagreements(),
        report.restarts
    );
    for (i, f) in report.findings.iter().enumerate() {
        println!("  {}. {}", i + 1, f.summary());
    }
    ExitCode::from(3)
}
