//! `lpe-check match` in the RenderMan dialect: `EXPR<TAB>PATH` batch lines (the
//! registration, `--ini`'s macros, is read as every subcommand reads it).

use lpe::renderman::{Parser, Path, RenderMan};
use lpe_engines::Engine;

use super::answer::{verdict, LineOutcome};
use super::dialect::MatchDialect;

impl MatchDialect for RenderMan {
    const EXAMPLE_PATH: &'static str = "C RD L";

    /// Answers one `EXPR<TAB>PATH` line.
    fn batch_line(engines: &[&dyn Engine<RenderMan>], parser: &Parser, line: &str) -> LineOutcome {
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
}
