//! `lpe-check match` in the RenderMan dialect: `--ini` macros, `EXPR<TAB>PATH` batch
//! lines.

use lpe::renderman::{Lpe, Parser, Path, RenderMan};
use lpe_engines::Engine;

use super::answer::{verdict, Args, LineOutcome};
use super::dialect::MatchDialect;
use crate::input::load_parser;

impl MatchDialect for RenderMan {
    const EXAMPLE_PATH: &'static str = "C RD L";

    /// The built-in macros, and `--ini`'s.
    fn registration(args: &Args) -> Result<Parser, String> {
        load_parser(args.ini.as_deref()).map_err(|e| format!("error: {e}"))
    }

    fn parse_arg(src: &str, parser: &Parser) -> Result<Lpe, String> {
        parser.parse(src).map_err(|e| e.to_string())
    }

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
