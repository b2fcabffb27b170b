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

use std::process::ExitCode;

use lpe::osl::{self, Osl, Registered};
use lpe_engines::Engine;

use super::matching::answer::{answer_paths, batch, verdict, Args, LineOutcome, Verdict};
use crate::input::{bad_input, osl_error, select_engines};

/// Runs `lpe-check match --dialect osl`.
pub fn run(args: &Args) -> ExitCode {
    let engines = match select_engines::<Osl>(&args.engine) {
        Ok(e) => e,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    let engines = &engines;
    let registered = match args.lang.registered(args.ini.as_deref()) {
        Ok(r) => r,
        Err(e) => return bad_input(format!("error: {e}")),
    };
    if args.batch {
        if args.lang.register.is_some() {
            return bad_input(
                "error: --batch reads the registration from each line's second column",
            );
        }
        return batch(|line| batch_line(engines, line));
    }
    let expr = args.expr.as_deref().unwrap_or_default();
    let lpe = match osl::parse_source(expr, &registered) {
        Ok(l) => l,
        Err(e) => return bad_input(osl_error(expr, &e)),
    };
    for w in &lpe.warnings {
        eprintln!("warning: {w}");
    }
    answer_paths(&args.paths, "C,_ R,D L,_", |text| {
        let p = text.parse::<osl::Path>().map_err(|e| e.to_string())?;
        Ok(verdict(engines, &registered, &lpe, &p))
    })
}

/// Answers one `EXPR<TAB>REGISTERED<TAB>PATH[<TAB>MATCH|NOMATCH]` line.
pub fn batch_line(engines: &[&dyn Engine<Osl>], line: &str) -> LineOutcome {
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
    let registered: Registered = match reg.parse() {
        Ok(r) => r,
        Err(e) => return LineOutcome::Error(format!("registered: {e}")),
    };
    let lpe = match osl::parse(expr, &registered) {
        Ok(l) => l,
        Err(e) => return LineOutcome::Error(format!("expression: {e}")),
    };
    let path = match path.parse::<osl::Path>() {
        Ok(p) => p,
        Err(e) => return LineOutcome::Error(format!("path: {e}")),
    };
    let v = verdict(engines, &registered, &lpe, &path);
    LineOutcome::Ran(match (expected, &v) {
        (Some(want), Verdict::Match | Verdict::NoMatch) if want != (v == Verdict::Match) => {
            let shown = |b: bool| if b { "match" } else { "no-match" }.to_string();
            let mut answers = vec![("expected", shown(want))];
            answers.extend(engines.iter().map(|e| (e.name(), shown(!want))));
            Verdict::Disagree(answers)
        }
        _ => v,
    })
}
