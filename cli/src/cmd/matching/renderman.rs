//! `lpe-check match` in the RenderMan dialect: `EXPR<TAB>PATH` batch lines (the
//! registration, `--ini`'s macros, is read as every subcommand reads it).

use lpe::renderman::{Parser, Path, RenderMan};

use super::answer::{BatchCache, LineOutcome};
use super::dialect::MatchDialect;

impl MatchDialect for RenderMan {
    const EXAMPLE_PATH: &'static str = "C RD L";

    /// Answers one `EXPR<TAB>PATH` line; the expression column is the cache's key.
    fn batch_line<'e>(
        parser: &Parser,
        line: &str,
        cache: &mut BatchCache<'e, RenderMan>,
    ) -> LineOutcome {
        let Some((expr, path)) = line.split_once('\t') else {
            return LineOutcome::Error("expected `EXPR<TAB>PATH`, found no tab".into());
        };
        let compiled = cache.get_or_compile(expr, || {
            let lpe = parser
                .parse(expr)
                .map_err(|e| format!("expression: {}", e.one_line()))?;
            Ok((parser.clone(), lpe))
        });
        let compiled = match compiled {
            Ok(c) => c,
            Err(e) => return LineOutcome::Error(e.to_string()),
        };
        match path.parse::<Path>() {
            Ok(p) => LineOutcome::Ran(compiled.verdict(&p)),
            Err(e) => LineOutcome::Error(format!("path: {e}")),
        }
    }
}
