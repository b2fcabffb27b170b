//! `lpe-check match --dialect osl`: OSL expressions against OSL paths, every engine.
//!
//! `match --dialect osl [--register 'events=U;scatters=Y'] EXPR PATH...` prints `match`
//! or `no-match` per path. `--batch` reads `EXPR<TAB>REGISTERED<TAB>PATH` lines (the
//! notation of OSL's own unit test: vertices separated by spaces, labels in a vertex by
//! commas, `~` NONE, `'a b'` a quoted label; REGISTERED is `-` or
//! `events=A,B;scatters=Y`) and prints one line per input line, as the RenderMan batch
//! does. A fourth column, if present, is the expected answer (`MATCH` or `NOMATCH`, as
//! in accum_test.tsv): when the engines agree on the other answer the line is a
//! `disagree: expected=… <engine>=…` (exit 3), so the test file itself is a check. Any
//! further column is an error; blank lines and `#` comments are echoed.

use lpe::osl::{self, Osl, Registered};

use super::answer::{Args, BatchCache, LineOutcome, Verdict};
use super::dialect::MatchDialect;

impl MatchDialect for Osl {
    const EXAMPLE_PATH: &'static str = "C,_ R,D L,_";

    /// `--register`'s labels; with `--batch` each line brings its own, and the flag is
    /// refused.
    fn from_args(args: &Args) -> Result<Registered, String> {
        let registered = args
            .lang
            .registration::<Osl>(args.ini.as_deref())
            .map_err(|e| format!("error: {e}"))?;
        if args.batch && args.lang.register.is_some() {
            return Err(
                "error: --batch reads the registration from each line's second column".into(),
            );
        }
        Ok(registered)
    }

    /// Each line's labels are registered on top of the renderer's profile, if one is
    /// named (`--renderer`): its letters, prefixes and built-in names.
    fn batch_line<'e>(
        base: &Registered,
        line: &str,
        cache: &mut BatchCache<'e, Osl>,
    ) -> LineOutcome {
        batch_line(base, line, cache)
    }
}

/// Answers one `EXPR<TAB>REGISTERED<TAB>PATH[<TAB>MATCH|NOMATCH]` line, under the
/// line's own registration on top of `base`; the first two columns are the cache's key.
fn batch_line<'e>(base: &Registered, line: &str, cache: &mut BatchCache<'e, Osl>) -> LineOutcome {
    let cols: Vec<&str> = line.split('\t').collect();
    let (expr, reg, path, expected) = match cols[..] {
        [e, r, p] => (e, r, p, None),
        [e, r, p, x] => (e, r, p, Some(x)),
        _ => {
            return LineOutcome::Error(format!(
                "expected `EXPR<TAB>REGISTERED<TAB>PATH[<TAB>MATCH|NOMATCH]`, found {} column(s)",
                cols.len()
            ))
        }
    };
    let expected = match expected.map(str::trim) {
        None => None,
        Some("MATCH") => Some(true),
        Some("NOMATCH") => Some(false),
        Some(other) => {
            return LineOutcome::Error(format!("expected answer `{other}`: write MATCH or NOMATCH"))
        }
    };
    let compiled = cache.get_or_compile(&format!("{expr}\t{reg}"), || {
        let own: Registered = reg.parse().map_err(|e| format!("registered: {e}"))?;
        let mut registered = base.clone();
        registered.events.extend(own.events);
        registered.scatters.extend(own.scatters);
        let lpe = osl::parse(expr, &registered).map_err(|e| format!("expression: {e}"))?;
        Ok((registered, lpe))
    });
    let compiled = match compiled {
        Ok(c) => c,
        Err(e) => return LineOutcome::Error(e.to_string()),
    };
    let path = match path.parse::<osl::Path>() {
        Ok(p) => p,
        Err(e) => return LineOutcome::Error(format!("path: {e}")),
    };
    let v = compiled.verdict(&path);
    LineOutcome::Ran(match (expected, &v) {
        (Some(want), Verdict::Match | Verdict::NoMatch) if want != (v == Verdict::Match) => {
            let shown = |b: bool| if b { "match" } else { "no-match" }.to_string();
            let mut answers = vec![("expected", shown(want))];
            answers.extend(compiled.engine_names().map(|e| (e, shown(!want))));
            Verdict::Disagree(answers)
        }
        _ => v,
    })
}
