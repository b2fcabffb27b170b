//! `lpe-check match`: match expressions against paths with every selected engine.
//!
//! `match EXPR PATH...` prints `match` or `no-match` per path. `match --batch` reads
//! one case per stdin line and prints exactly one line per input line: `match`,
//! `no-match`, `error: <message>`, or `disagree: <engine=answer ...>` when engines
//! differ (the process then exits 3 at the end). Blank lines and `#` comments are echoed
//! as they are.
//!
//! The command is written once over [`MatchDialect`]; what differs per dialect (where
//! the registration comes from, how an argument expression reads, a batch line's
//! columns) is in the dialect's file: [`renderman`] (`EXPR<TAB>PATH` lines, `--ini`
//! macros) and [`osl`] (`--dialect osl`: `EXPR<TAB>REGISTERED<TAB>PATH` lines).
//! [`answer`] holds the arguments, the verdict over every engine and the printing.
//!
//! `--batch` streams: one line in, one line out, with bounded memory. Each distinct
//! expression (with its registration) is parsed once and kept for the lines that repeat
//! it ([`BatchCache`], at most [`MAX_CACHED_EXPRESSIONS`] at a time): every engine
//! compiles it for a few paths, again for some once [`SOME_PATHS_AT`] lines have asked
//! for it, and in full at [`MANY_PATHS_AT`] lines. A long run reports its progress on stderr every few seconds.

use std::process::ExitCode;

use lpe::renderman::RenderMan;

use crate::input::{bad_input, select_engines};

pub mod answer;
pub mod dialect;
pub mod osl;
pub mod renderman;

pub use answer::{
    answer_paths, batch, verdict, Args, BatchCache, Compiled, Expected, LineOutcome, Verdict,
    MANY_PATHS_AT, MAX_CACHED_EXPRESSIONS, SOME_PATHS_AT,
};
pub use dialect::MatchDialect;

/// Runs `lpe-check match`.
pub fn run(args: Args) -> ExitCode {
    // The engine name is checked before the dialect arguments (the names are the same
    // in every dialect).
    if let Err(e) = select_engines::<RenderMan>(&args.engine) {
        return bad_input(format!("error: {e}"));
    }
    lpe::with_dialect!(args.lang.dialect(), D => run_in::<D>(&args))
}

/// Runs `lpe-check match` in dialect `D`.
fn run_in<D: MatchDialect>(args: &Args) -> ExitCode {
    let engines = match select_engines::<D>(&args.engine) {
        Ok(e) => e,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    let registration = match D::from_args(args) {
        Ok(r) => r,
        Err(e) => return bad_input(e),
    };
    if args.batch {
        let mut cache = BatchCache::new(&engines);
        return batch(|line| D::batch_line(&registration, line, &mut cache));
    }
    let lpe = match D::read_arg(args.expr.as_deref().unwrap_or_default(), &registration) {
        Ok(l) => l,
        Err(e) => return bad_input(e),
    };
    answer_paths(&args.paths, D::EXAMPLE_PATH, |text| {
        let p = text.parse::<D::Path>().map_err(|e| e.to_string())?;
        Ok(verdict(&engines, &registration, &lpe, &p))
    })
}
