//! `lpe-check`: parse light path expressions and match them against paths with every
//! engine side by side. See README.md for usage.

use std::process::ExitCode;

use clap::{Parser, Subcommand};
use oracle::cli;

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
    Parse(cli::parse::Args),
    /// Match an expression against paths (or `--batch` lines from stdin) with every engine.
    Match(cli::matching::Args),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    // The reference matcher recurses a few frames per path vertex: give it room for
    // paths far longer than any renderer records.
    let worker = std::thread::Builder::new()
        .stack_size(512 << 20)
        .spawn(move || match cli.command {
            Command::Parse(a) => cli::parse::run(a),
            Command::Match(a) => cli::matching::run(a),
        });
    match worker.map(|w| w.join()) {
        Ok(Ok(code)) => code,
        _ => {
            eprintln!("error: internal failure (please report it with the input)");
            ExitCode::from(101)
        }
    }
}
