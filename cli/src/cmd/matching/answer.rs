//! What every dialect of `lpe-check match` shares: the arguments, the verdict over every
//! engine, and the answering of paths and batch lines. Apart from the command, so that
//! the dialects' files ([`super::renderman`], [`super::osl`]) read it without importing
//! the command that dispatches to them.

use std::io::{BufRead, Write};
use std::process::ExitCode;

use lpe_engines::{Engine, EngineDialect};

use crate::input::{bad_input, DialectArgs};
use crate::pipe::write_failed;

/// Arguments of `lpe-check match`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Read `EXPR<TAB>PATH` lines from stdin instead of arguments.
    #[arg(long)]
    pub batch: bool,
    /// Engine to run: a name or `all`.
    #[arg(long, default_value = "all")]
    pub engine: String,
    /// `--dialect` and `--register`.
    #[command(flatten)]
    pub lang: DialectArgs,
    /// A rendermn.ini-style file with user macros and lobe mappings.
    #[arg(long)]
    pub ini: Option<std::path::PathBuf>,
    /// The expression (not with --batch).
    #[arg(required_unless_present = "batch", conflicts_with = "batch")]
    pub expr: Option<String>,
    /// Paths in text form, e.g. `C RD2'floor' L'key'` (quote each path).
    #[arg(conflicts_with = "batch")]
    pub paths: Vec<String>,
}

/// One answer for one expression and path, over all engines.
#[derive(Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Every engine that could build said yes.
    Match,
    /// Every engine that could build said no.
    NoMatch,
    /// Engines differ: `(engine, answer)` for each, answer `match`/`no-match`/`skip: ...`.
    Disagree(Vec<(&'static str, String)>),
    /// No engine could build the expression.
    Skipped(Vec<(&'static str, String)>),
}

impl std::fmt::Display for Verdict {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let list = |v: &[(&str, String)]| {
            v.iter()
                .map(|(e, a)| format!("{e}={a}"))
                .collect::<Vec<_>>()
                .join(" ")
        };
        match self {
            Verdict::Match => f.write_str("match"),
            Verdict::NoMatch => f.write_str("no-match"),
            Verdict::Disagree(v) => write!(f, "disagree: {}", list(v)),
            Verdict::Skipped(v) => write!(f, "error: no engine could build: {}", list(v)),
        }
    }
}

/// Runs every engine on one expression, parsed under `registration`, and one path. An
/// engine that cannot build the expression is reported but does not count as
/// disagreeing.
pub fn verdict<D: EngineDialect>(
    engines: &[&dyn Engine<D>],
    registration: &D::Registration,
    lpe: &D::Lpe,
    path: &D::Path,
) -> Verdict {
    let mut answers = Vec::new();
    let mut skips = Vec::new();
    for e in engines {
        match e.compile(std::slice::from_ref(lpe), registration) {
            Ok(m) => answers.push((e.name(), m.which(path).contains(0))),
            Err(why) => skips.push((e.name(), format!("skip({why})"))),
        }
    }
    let shown = |b: bool| if b { "match" } else { "no-match" }.to_string();
    match answers.first() {
        None => Verdict::Skipped(skips),
        Some(&(_, first)) if answers.iter().all(|(_, a)| *a == first) => {
            if first {
                Verdict::Match
            } else {
                Verdict::NoMatch
            }
        }
        Some(_) => Verdict::Disagree(answers.into_iter().map(|(e, a)| (e, shown(a))).collect()),
    }
}

/// The outcome of one batch line.
#[derive(Debug, PartialEq, Eq)]
pub enum LineOutcome {
    /// The engines ran.
    Ran(Verdict),
    /// The line, expression or path is malformed.
    Error(String),
}

impl std::fmt::Display for LineOutcome {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            LineOutcome::Ran(v) => write!(f, "{v}"),
            LineOutcome::Error(e) => write!(f, "error: {e}"),
        }
    }
}

/// Answers stdin line by line with `answer`, echoing blank and `#` lines: exit 3 if any
/// line was a disagreement, else 2 if any line was an error (malformed, or no engine
/// could build its expression) or stdin or stdout failed.
pub fn batch(mut answer: impl FnMut(&str) -> LineOutcome) -> ExitCode {
    let mut disagreed = false;
    let mut failed = false;
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    for line in std::io::stdin().lock().lines() {
        let line = match line {
            Ok(l) => l,
            Err(e) => return bad_input(format!("error: reading stdin: {e}")),
        };
        let trimmed = line.trim();
        let shown = if trimmed.is_empty() || trimmed.starts_with('#') {
            line.clone()
        } else {
            let v = answer(&line);
            disagreed |= matches!(v, LineOutcome::Ran(Verdict::Disagree(_)));
            failed |= matches!(
                v,
                LineOutcome::Error(_) | LineOutcome::Ran(Verdict::Skipped(_))
            );
            v.to_string()
        };
        if let Err(e) = writeln!(out, "{shown}") {
            return write_failed(&e);
        }
    }
    finish(out, disagreed, failed)
}

/// Prints `answer`'s verdict for each path text: exit 2 at the first path that does not
/// parse (`answer` gives the message); at the end 3 if any verdict was a disagreement,
/// else 2 if no engine could build the expression.
pub fn answer_paths(
    paths: &[String],
    example: &str,
    mut answer: impl FnMut(&str) -> Result<Verdict, String>,
) -> ExitCode {
    if paths.is_empty() {
        return bad_input(format!(
            "error: give at least one path after the expression, e.g. \"{example}\""
        ));
    }
    let mut disagreed = false;
    let mut failed = false;
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    for text in paths {
        let v = match answer(text) {
            Ok(v) => v,
            Err(e) => {
                let _ = out.flush();
                return bad_input(format!("error: path `{text}`: {e}"));
            }
        };
        disagreed |= matches!(v, Verdict::Disagree(_));
        failed |= matches!(v, Verdict::Skipped(_));
        if let Err(e) = writeln!(out, "{v}") {
            return write_failed(&e);
        }
    }
    finish(out, disagreed, failed)
}

/// Exit 3 on a disagreement, else 2 on an error, else 0; the output's last buffered
/// write failing decides first ([`write_failed`]).
fn finish(mut out: impl Write, disagreed: bool, failed: bool) -> ExitCode {
    if let Err(e) = out.flush() {
        return write_failed(&e);
    }
    if disagreed {
        ExitCode::from(3)
    } else if failed {
        ExitCode::from(2)
    } else {
        ExitCode::SUCCESS
    }
}
