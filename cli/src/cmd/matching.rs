//! `lpe-check match`: match expressions against paths with every selected engine.
//!
//! `match EXPR PATH...` prints `match` or `no-match` per path. `match --batch` reads
//! `EXPR<TAB>PATH` lines from stdin and prints exactly one line per input line:
//! `match`, `no-match`, `error: <message>`, or `disagree: <engine=answer ...>` when
//! engines differ (the process then exits 3 at the end). Blank lines and `#` comments
//! are echoed as they are.
//!
//! `--dialect osl` reads OSL expressions and paths instead ([`super::match_osl`]).

use std::process::ExitCode;

use lpe::renderman::{Parser, Path, RenderMan};

use lpe_engines::Engine;

use crate::input::{bad_input, load_parser, select_engines};

pub mod answer;
pub use answer::{answer_paths, batch, verdict, Args, LineOutcome, Verdict};

/// Answers one `EXPR<TAB>PATH` line (not blank, not a comment).
pub fn batch_line(parser: &Parser, engines: &[&dyn Engine<RenderMan>], line: &str) -> LineOutcome {
    let Some((expr, path)) = line.split_once('\t') else {
        return LineOutcome::Error("expected `EXPR<TAB>PATH`, found no tab".into());
    };
    let lpe = match parser.parse(expr) {
        Ok(l) => l,
        Err(e) => return LineOutcome::Error(format!("expression: {}", e.one_line())),
    };
    match path.parse::<Path>() {
        Ok(p) => LineOutcome::Ran(verdict(engines, parser, &lpe, &p)),
        Err(e) => LineOutcome::Error(format!("path: {e}")),
    }
}

/// Runs `lpe-check match`.
pub fn run(args: Args) -> ExitCode {
    // The engine name is checked before the dialect arguments, in either dialect.
    let engines = match select_engines::<RenderMan>(&args.engine) {
        Ok(e) => e,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    match args.lang.is_osl() {
        Ok(true) => return super::match_osl::run(&args),
        Ok(false) => {}
        Err(e) => return bad_input(format!("error: {e}")),
    }
    let parser = match load_parser(args.ini.as_deref()) {
        Ok(p) => p,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    if args.batch {
        return batch(|line| batch_line(&parser, &engines, line));
    }
    let lpe = match parser.parse(args.expr.as_deref().unwrap_or_default()) {
        Ok(l) => l,
        Err(e) => return bad_input(e),
    };
    answer_paths(&args.paths, "C RD L", |text| {
        let p = text.parse::<Path>().map_err(|e| e.to_string())?;
        Ok(verdict(&engines, &parser, &lpe, &p))
    })
}
