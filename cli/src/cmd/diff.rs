//! `lpe-check diff`: the differential harness on generated cases.
//!
//! Each case is one expression (or, one time in five, an AOV set of 2-5 expressions
//! compiled at once) and `--paths` paths generated *from* it; see
//! `lpe_engines::differential::cases`. Every engine answers; the first disagreements are
//! minimized and printed, and the process exits 3.
//!
//! Half the expressions are written as text from the dialect's grammar
//! (`lpe_testkit::grammar`) and parsed: the report says how many of the grammar's
//! productions the run wrote (`--coverage` lists each with its count), and a text the
//! parser rejects is a finding (exit 3), printed with the parser's error.
//!
//! `--dialect osl` generates OSL cases instead: each with its own registration (often
//! none, else some user event and scattering labels), expressions of up to
//! `--max-size` vertex patterns, and paths over their labels, NONE, `_`, registered and
//! unmentioned labels.
//!
//! Then the two front ends are compared (`lpe_engines::differential::front`): lpe's
//! parser and the reference's own, on the text of every generated expression (lpe's
//! canonical print of the generated tree; for one written from the grammar, also the
//! grammar text and a near miss of it) under its case's registration, and on every
//! corpus expression (the conformance suites and fuzz corpora under `--corpus-root`,
//! default the checkout the binary was built from, and the hand-written constructs).
//! The report says how many expressions were compared and how many disagree; a
//! disagreement is printed minimized and makes the exit code 3, like any other finding.
//!
//! With `--external 'CMD ARGS'` the cases go to an external matcher over the protocol of
//! docs/protocol.md instead (see [`external`]), each finding printed with the command
//! that replays it ([`replay`]); with `--suite DIR` as well, the conformance suite's
//! cases instead of generated ones (see [`external_suite`]). The arguments are
//! [`args`], which every one of them reads.

use std::process::ExitCode;
use std::time::Instant;

use lpe::with_dialect;
use lpe_engines::differential::front::{self, FrontCase, FrontEnds, FrontTotals};
use lpe_engines::differential::{case_rng, generate_case, run_cases, Generate, Totals};
use lpe_testkit::grammar;

use crate::input::{bad_input, select_engines};

pub mod args;
pub mod external;
pub mod external_suite;
pub mod replay;

pub use args::Args;

/// Runs `lpe-check diff`.
pub fn run(args: Args) -> ExitCode {
    if args.lang.register.is_some() && args.expr.is_empty() {
        return bad_input(
            "error: --register is for a given case (--external with --expr); \
             generated OSL cases register their own labels",
        );
    }
    if args.external.is_some() {
        return external::run(&args);
    }
    with_dialect!(args.lang.dialect(), D => run_in::<D>(&args))
}

/// Runs the generated cases of dialect `D` on the selected engines.
fn run_in<D: FrontEnds>(args: &Args) -> ExitCode {
    let engines = match select_engines::<D>(&args.engine) {
        Ok(e) => e,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    if engines.len() < 2 {
        eprintln!("error: a differential run needs at least two engines; use --engine all");
        return ExitCode::from(2);
    }
    let names: Vec<&str> = engines.iter().map(|e| e.name()).collect();
    let start = Instant::now();
    let totals = run_cases(&args.run(), &engines);
    let engines_code = report(args, &names, totals, start);
    let fronts = match compare_front_ends::<D>(args) {
        Ok(t) => t,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    println!("{}", fronts.summary());
    for e in &fronts.position_examples {
        println!("  both reject {e}");
    }
    for d in &fronts.disagreements {
        println!("\n{d}");
    }
    if fronts.count() > 0 {
        return ExitCode::from(3);
    }
    engines_code
}

/// The front-end comparison on the run's generated expressions: each as lpe prints it,
/// and, for those written from the grammar, the grammar text itself, one near miss of it
/// (one character deleted, doubled or inserted: the error paths) and any grammar text
/// lpe rejected; then the corpora.
fn compare_front_ends<D: FrontEnds>(args: &Args) -> Result<FrontTotals, String> {
    let cfg = D::config(args.max_size);
    let mut cases: Vec<FrontCase<D>> = Vec::new();
    for index in args.first..args.first.saturating_add(args.cases) {
        let case = generate_case::<D>(args.seed, index, &cfg, 0);
        // The near misses draw from a stream of their own, so the cases stay those of
        // the engines' run.
        let mut near = case_rng(args.seed ^ NEAR_MISS_STREAM, index);
        let mut push = |text: String, what: &str| {
            cases.push(FrontCase {
                text,
                registration: case.registration.clone(),
                origin: format!("generated case {index} ({what})"),
            })
        };
        for (e, text) in case.exprs.iter().zip(&case.texts) {
            push(e.to_string(), "as lpe prints it");
            if let Some(text) = text {
                push(text.clone(), "grammar text");
                push(
                    grammar::mutate(&mut near, text),
                    "near miss of a grammar text",
                );
            }
        }
        for (text, _) in &case.rejected {
            push(text.clone(), "grammar text lpe rejects");
        }
    }
    let root = args.corpus_root.clone().unwrap_or_else(|| {
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .parent()
            .map(|p| p.to_path_buf())
            .unwrap_or_default()
    });
    cases.extend(front::corpus::<D>(&root)?);
    Ok(front::run::<D>(cases, args.seed, args.max_failures))
}

/// Mixed into the seed for the near misses' streams.
const NEAR_MISS_STREAM: u64 = 0x6E65_6172_6D69_7373;

/// Prints a run's totals and disagreements; the exit code.
fn report<D: Generate>(args: &Args, names: &[&str], t: Totals<D>, start: Instant) -> ExitCode {
    let secs = start.elapsed().as_secs_f64().max(1e-9);
    println!(
        "{} dialect, engines: {}; seed {}, cases {}..{}, max size {}, {} paths per case",
        args.lang.dialect(),
        names.join(", "),
        args.seed,
        args.first,
        args.first + t.cases,
        args.max_size,
        args.paths
    );
    println!(
        "{} cases, {} expression/path pairs in {:.2} s: {:.0} cases/s, {:.0} pairs/s",
        t.cases,
        t.pairs,
        secs,
        t.cases as f64 / secs,
        t.pairs as f64 / secs
    );
    let rate = if t.pairs == 0 {
        0.0
    } else {
        100.0 * t.matched as f64 / t.pairs as f64
    };
    println!(
        "match rate: {rate:.1}% ({} of {} pairs)",
        t.matched, t.pairs
    );
    if t.skips.is_empty() {
        println!("skips: none");
    }
    for (name, n, why) in &t.skips {
        println!("skips: {name} could not build {n} cases (first: {why})");
    }
    println!(
        "grammar coverage: {} of {} productions ({} dialect){}",
        t.coverage.exercised(),
        t.coverage.total(),
        args.lang.dialect(),
        match t.coverage.missing().as_slice() {
            [] => String::new(),
            missing => format!("; never written: {}", missing.join(", ")),
        }
    );
    if args.coverage {
        for (production, n) in t.coverage.counts() {
            println!("  {production:<36} {n}");
        }
    }
    if t.uncompared > 0 {
        println!(
            "uncompared: {} cases had fewer than two engines",
            t.uncompared
        );
    }
    for r in &t.rejected {
        println!(
            "\ncase {}: the parser rejects a text of the documented grammar:\n  text:  {}\n  error: {}",
            r.case, r.text, r.error
        );
    }
    if t.failures.is_empty() && t.rejected.is_empty() {
        println!("all engines agree");
        return ExitCode::SUCCESS;
    }
    if t.failures.is_empty() {
        println!(
            "all engines agree; {} grammar text(s) rejected",
            t.rejected.len()
        );
        return ExitCode::from(3);
    }
    for (index, c) in &t.failures {
        println!(
            "\ncase {index} (regenerate: lpe-check diff --dialect {} --seed {} --first {index} --cases 1 --max-size {} --paths {}):\n{c}",
            args.lang.dialect(), args.seed, args.max_size, args.paths
        );
    }
    ExitCode::from(3)
}
