//! `lpe-check`: parse light path expressions and match them against paths with every
//! engine side by side. See the README for usage.

use std::process::ExitCode;

use clap::{Parser, Subcommand};
use lpe_cli::cmd;

#[derive(Parser, Debug)]
#[command(
    name = "lpe-check",
    version,
    about = "Check light path expressions: parse, match, compare engines"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Print the canonical form of an expression, or the error with a caret (exit 2).
    Parse(cmd::parse::Args),
    /// Match an expression against paths (or `--batch` lines from stdin) with every engine.
    Match(cmd::matching::Args),
    /// Are two expressions equivalent? Else the shortest path telling them apart.
    Equiv(cmd::equiv::Args),
    /// Do AOVs partition a universe? Overlaps, gaps and leaks with shortest paths.
    Partition(cmd::partition::Args),
    /// Benchmark the matchers (fast DFA/NFA, regex-automata, reference) as a table.
    Bench(cmd::bench::Args),
    /// Run every engine on generated cases; print minimized disagreements (exit 3).
    Diff(cmd::diff::Args),
    /// Check the LPE AOVs of USD stages, RIB files and rendermn.ini (exit 1 on findings).
    Lint(cmd::lint::Args),
    /// Which AOVs a path lands in, vertex by vertex, and the closest miss.
    Explain(cmd::explain::Args),
    /// Carry expressions between the RenderMan and OSL dialects, with a proved verdict.
    Translate(cmd::translate::Args),
    /// Serve the LPE explorer page on 127.0.0.1 (the URL is printed; Ctrl-C stops it).
    Serve(cmd::serve::Args),
    /// Write one self-contained HTML page of files' AOVs, findings and explorer views.
    Report(cmd::report::Args),
}

fn main() -> ExitCode {
    lpe_cli::pipe::quiet_on_closed_pipe();
    let cli = Cli::parse();
    // The reference matcher recurses a few frames per path vertex: give it room for
    // paths far longer than any renderer records.
    let worker = std::thread::Builder::new()
        .stack_size(512 << 20)
        .spawn(move || match cli.command {
            Command::Parse(a) => cmd::parse::run(a),
            Command::Match(a) => cmd::matching::run(a),
            Command::Equiv(a) => cmd::equiv::run(a),
            Command::Translate(a) => cmd::translate::run(a),
            Command::Partition(a) => cmd::partition::run(a),
            Command::Bench(a) => cmd::bench::run(a),
            Command::Diff(a) => cmd::diff::run(a),
            Command::Lint(a) => cmd::lint::run(a),
            Command::Explain(a) => cmd::explain::run(a),
            Command::Serve(a) => cmd::serve::run(a),
            Command::Report(a) => cmd::report::run(a),
        });
    match worker.map(|w| w.join()) {
        Ok(Ok(code)) => code,
        _ => {
            eprintln!("error: internal failure (please report it with the input)");
            ExitCode::from(101)
        }
    }
}
