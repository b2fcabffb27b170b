//! What every dialect of `lpe-check match` shares: the arguments, the verdict over every
//! engine, and the answering of paths and batch lines. Apart from the command, so that
//! the dialects' files ([`super::renderman`], [`super::osl`]) read it without importing
//! the command that dispatches to them.

use std::io::{BufRead, Write};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use lpe::fxhash::FxMap;
use lpe_engines::{Engine, EngineDialect, Matcher};

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

/// One expression compiled once by every selected engine (or each engine's reason it
/// could not), asked about any number of paths.
pub struct Compiled<'e, D: EngineDialect> {
    engines: Vec<(&'static str, Built<'e, D>)>,
}

/// One engine's matcher for an expression, or why it could not build one.
type Built<'e, D> = Result<Box<dyn Matcher<D> + 'e>, String>;

/// How many paths a compiled expression is expected to answer, which decides what an
/// engine builds ([`Engine::compile_for_few_paths`], [`Engine::compile_for_some_paths`]
/// or [`Engine::compile`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Expected {
    /// A batch expression seen fewer than [`SOME_PATHS_AT`] times.
    FewPaths,
    /// A batch expression seen [`SOME_PATHS_AT`] times, but fewer than [`MANY_PATHS_AT`].
    SomePaths,
    /// An expression argument, or a batch expression seen [`MANY_PATHS_AT`] times.
    ManyPaths,
}

impl<'e, D: EngineDialect> Compiled<'e, D> {
    /// Compiles `lpe`, parsed under `registration`, with each of `engines`.
    pub fn new(
        engines: &[&'e dyn Engine<D>],
        registration: &D::Registration,
        lpe: &D::Lpe,
        expected: Expected,
    ) -> Self {
        let engines = engines
            .iter()
            .map(|e| {
                let exprs = std::slice::from_ref(lpe);
                let built = match expected {
                    Expected::FewPaths => e.compile_for_few_paths(exprs, registration),
                    Expected::SomePaths => e.compile_for_some_paths(exprs, registration),
                    Expected::ManyPaths => e.compile(exprs, registration),
                }
                .map_err(|why| format!("skip({why})"));
                (e.name(), built)
            })
            .collect();
        Compiled { engines }
    }

    /// The engines' names, in order.
    pub fn engine_names(&self) -> impl Iterator<Item = &'static str> + '_ {
        self.engines.iter().map(|(name, _)| *name)
    }

    /// Every engine's answer on `path`. An engine that could not build the expression
    /// is reported but does not count as disagreeing.
    pub fn verdict(&self, path: &D::Path) -> Verdict {
        let mut answers = Vec::new();
        let mut skips = Vec::new();
        for (name, built) in &self.engines {
            match built {
                Ok(m) => answers.push((*name, m.which(path).contains(0))),
                Err(why) => skips.push((*name, why.clone())),
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
}

/// Runs every engine on one expression, parsed under `registration`, and one path.
pub fn verdict<D: EngineDialect>(
    engines: &[&dyn Engine<D>],
    registration: &D::Registration,
    lpe: &D::Lpe,
    path: &D::Path,
) -> Verdict {
    Compiled::new(engines, registration, lpe, Expected::ManyPaths).verdict(path)
}

/// Most distinct expressions `match --batch` keeps compiled at once. Past it the cache
/// starts afresh, so memory stays bounded on an input of millions of distinct
/// expressions, while a batch that repeats a few expressions (the usual shape: many
/// paths per AOV) compiles each of them once.
pub const MAX_CACHED_EXPRESSIONS: usize = 1024;

/// At which line of one expression `match --batch` compiles it again for some paths
/// ([`Expected::SomePaths`]), having answered the lines before with what the engines
/// build for a few ([`Expected::FewPaths`]). The fast engine's three compiles cost about
/// one line (its tree, evaluated per path at about the reference's cost), hundreds of
/// lines (its lazy DFA, whose cache then steps at table speed) and up to thousands (its
/// minimized DFA): an input whose expressions repeat a few hundred times at most pays
/// the first alone, and the usual shape (many paths per AOV) all three, once each
/// (`python/bench/batch_inputs.py` measures the shapes between).
pub const SOME_PATHS_AT: u32 = 256;

/// At which line of one expression `match --batch` compiles it in full
/// ([`Expected::ManyPaths`]); see [`SOME_PATHS_AT`].
pub const MANY_PATHS_AT: u32 = 4096;

/// What `match --batch` has compiled so far, by the columns of a line that decide the
/// compiled expression (the expression, and for OSL the registration): the parsed
/// expression compiled by every engine, or the line's error message when it does not
/// parse.
pub struct BatchCache<'e, D: EngineDialect> {
    engines: Vec<&'e dyn Engine<D>>,
    /// Keyed by a fast hash (an expression of 40 alternatives is 600 bytes, hashed per
    /// line): the keys are the user's own input, and one who crafts colliding lines
    /// slows only their own run.
    compiled: FxMap<String, Result<Entry<'e, D>, String>>,
}

/// One parsed expression of a batch, what it is compiled into now, and how many lines
/// have asked for it.
struct Entry<'e, D: EngineDialect> {
    registration: D::Registration,
    lpe: D::Lpe,
    compiled: Compiled<'e, D>,
    uses: u32,
}

impl<'e, D: EngineDialect> BatchCache<'e, D> {
    /// An empty cache compiling with `engines`.
    pub fn new(engines: &[&'e dyn Engine<D>]) -> Self {
        BatchCache {
            engines: engines.to_vec(),
            compiled: FxMap::default(),
        }
    }

    /// The compiled expression for `key`: `parse` gives the registration and expression
    /// the first time it is asked for (or the line's error); the expression is compiled
    /// for a few paths, for some at its [`SOME_PATHS_AT`]-th line and in full at its
    /// [`MANY_PATHS_AT`]-th.
    pub fn get_or_compile(
        &mut self,
        key: &str,
        parse: impl FnOnce() -> Result<(D::Registration, D::Lpe), String>,
    ) -> Result<&Compiled<'e, D>, &str> {
        if !self.compiled.contains_key(key) {
            if self.compiled.len() >= MAX_CACHED_EXPRESSIONS {
                self.compiled.clear();
            }
            let entry = parse().map(|(registration, lpe)| Entry {
                compiled: Compiled::new(&self.engines, &registration, &lpe, Expected::FewPaths),
                registration,
                lpe,
                uses: 0,
            });
            self.compiled.insert(key.to_string(), entry);
        }
        let engines = &self.engines;
        match self.compiled.get_mut(key).expect("inserted above") {
            Ok(entry) => {
                entry.uses = entry.uses.saturating_add(1);
                let expected = match entry.uses {
                    SOME_PATHS_AT => Some(Expected::SomePaths),
                    MANY_PATHS_AT => Some(Expected::ManyPaths),
                    _ => None,
                };
                if let Some(expected) = expected {
                    entry.compiled =
                        Compiled::new(engines, &entry.registration, &entry.lpe, expected);
                }
                Ok(&entry.compiled)
            }
            Err(e) => Err(e),
        }
    }

    /// How many expressions are compiled now.
    pub fn len(&self) -> usize {
        self.compiled.len()
    }

    /// Whether nothing is compiled yet.
    pub fn is_empty(&self) -> bool {
        self.compiled.is_empty()
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
    let mut progress = Progress::new();
    for line in std::io::stdin().lock().lines() {
        progress.line();
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

/// A line on stderr every [`PROGRESS_EVERY`] while a batch runs, so that a long run
/// shows it is alive and how far it got; a short run prints none.
struct Progress {
    lines: u64,
    next: Instant,
}

/// How often a long `match --batch` run reports its progress on stderr.
pub const PROGRESS_EVERY: Duration = Duration::from_secs(5);

impl Progress {
    fn new() -> Self {
        Progress {
            lines: 0,
            next: Instant::now() + PROGRESS_EVERY,
        }
    }

    /// Counts one input line, reporting when the interval has passed (the clock is read
    /// once every 4 096 lines: reading it per line would cost more than a cached answer).
    fn line(&mut self) {
        self.lines += 1;
        if self.lines.is_multiple_of(4096) && Instant::now() >= self.next {
            eprintln!("match --batch: {} lines answered", self.lines);
            self.next = Instant::now() + PROGRESS_EVERY;
        }
    }
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

#[cfg(test)]
mod tests {
    //! The batch cache, with an engine that counts its compiles. Checked against planted
    //! faults: a cache that never stores (every line compiles: the count test fails), a
    //! key without OSL's registration column (the second registration answers as the
    //! first: the OSL test fails), a cache that never clears (the bound test fails), either
    //! upgrade one line early or never, or on every line past its threshold (the upgrade
    //! test fails), and lines compiled in full from the start (both count tests fail).

    use std::sync::atomic::{AtomicUsize, Ordering};

    use lpe::osl::Osl;
    use lpe::renderman::{Parser, RenderMan};
    use lpe_engines::{Engine, EngineDialect, EngineError, Matcher};

    use super::{BatchCache, MANY_PATHS_AT, MAX_CACHED_EXPRESSIONS, SOME_PATHS_AT};
    use crate::cmd::matching::MatchDialect;

    /// The `fast` engine, counting how often it is asked to compile for a few paths, for
    /// some and in full.
    #[derive(Default)]
    struct Counting {
        few: AtomicUsize,
        some: AtomicUsize,
        full: AtomicUsize,
    }

    impl Counting {
        fn counts(&self) -> (usize, usize, usize) {
            (
                self.few.load(Ordering::Relaxed),
                self.some.load(Ordering::Relaxed),
                self.full.load(Ordering::Relaxed),
            )
        }
    }

    fn fast<D: EngineDialect>() -> &'static dyn Engine<D> {
        lpe_engines::by_name::<D>("fast").expect("the fast engine")
    }

    impl<D: EngineDialect> Engine<D> for Counting {
        fn name(&self) -> &'static str {
            "counting"
        }
        fn compile(
            &self,
            exprs: &[D::Lpe],
            registration: &D::Registration,
        ) -> Result<Box<dyn Matcher<D> + '_>, EngineError> {
            self.full.fetch_add(1, Ordering::Relaxed);
            fast::<D>().compile(exprs, registration)
        }
        fn compile_for_few_paths(
            &self,
            exprs: &[D::Lpe],
            registration: &D::Registration,
        ) -> Result<Box<dyn Matcher<D> + '_>, EngineError> {
            self.few.fetch_add(1, Ordering::Relaxed);
            fast::<D>().compile_for_few_paths(exprs, registration)
        }
        fn compile_for_some_paths(
            &self,
            exprs: &[D::Lpe],
            registration: &D::Registration,
        ) -> Result<Box<dyn Matcher<D> + '_>, EngineError> {
            self.some.fetch_add(1, Ordering::Relaxed);
            fast::<D>().compile_for_some_paths(exprs, registration)
        }
    }

    fn answers<D: MatchDialect>(
        engine: &Counting,
        registration: &D::Registration,
        lines: &[&str],
    ) -> Vec<String> {
        let engines: Vec<&dyn Engine<D>> = vec![engine];
        let mut cache = BatchCache::new(&engines);
        lines
            .iter()
            .map(|l| D::batch_line(registration, l, &mut cache).to_string())
            .collect()
    }

    #[test]
    fn each_distinct_expression_compiles_once() {
        let engine = Counting::default();
        let lines = [
            "C<RD>L\tC RD L",
            "C<RD>L\tC RS L",
            "C.*L\tC RS RD L",
            "C<RD>L\tC TD L",
            "C.*L\tC L",
            "C(\tC L",
            "C(\tC RD L",
        ];
        let got = answers::<RenderMan>(&engine, &Parser::default(), &lines);
        assert_eq!(
            got[..5],
            ["match", "no-match", "match", "no-match", "match"]
        );
        assert!(got[5].starts_with("error: expression:"), "{got:?}");
        assert_eq!(
            got[5], got[6],
            "a cached parse error answers as the first time"
        );
        assert_eq!(
            engine.counts(),
            (2, 0, 0),
            "two distinct expressions, each compiled for a few paths"
        );
    }

    #[test]
    fn an_expression_is_compiled_again_at_its_upgrade_lines_and_only_then() {
        let engine = Counting::default();
        let engines: Vec<&dyn Engine<RenderMan>> = vec![&engine];
        let mut cache = BatchCache::new(&engines);
        let parser = Parser::default();
        // Alternating answers, so that a matcher lost or mixed up in an upgrade shows.
        let line = |i: u32| {
            if i.is_multiple_of(2) {
                "C<RD>L\tC RD L"
            } else {
                "C<RD>L\tC RS L"
            }
        };
        for i in 1..2 * MANY_PATHS_AT {
            let got = RenderMan::batch_line(&parser, line(i), &mut cache).to_string();
            let want = if i.is_multiple_of(2) {
                "match"
            } else {
                "no-match"
            };
            assert_eq!(got, want, "line {i}");
            let compiled = match i {
                _ if i < SOME_PATHS_AT => (1, 0, 0),
                _ if i < MANY_PATHS_AT => (1, 1, 0),
                _ => (1, 1, 1),
            };
            assert_eq!(engine.counts(), compiled, "line {i}");
        }
    }

    #[test]
    fn a_line_is_cached_by_its_expression_and_its_registration() {
        let engine = Counting::default();
        // A registered `U` is a basic label, which the eater no longer skips: the same
        // expression text reads differently under the two registrations.
        let lines = [
            "CRL\tevents=U\tC,_ R,D,U L,_",
            "CRL\t-\tC,_ R,D,U L,_",
            "CRL\tevents=U\tC,_ R,D,U L,_",
        ];
        let got = answers::<Osl>(&engine, &Default::default(), &lines);
        assert_eq!(got, ["no-match", "match", "no-match"]);
        assert_eq!(engine.counts(), (2, 0, 0));
    }

    #[test]
    fn the_cache_holds_at_most_its_bound() {
        let engines: Vec<&dyn Engine<RenderMan>> = Vec::new();
        let mut cache: BatchCache<'_, RenderMan> = BatchCache::new(&engines);
        for i in 0..=MAX_CACHED_EXPRESSIONS {
            let text = format!("C<RD'l{i}'>L");
            let parsed = lpe::renderman::parse(&text).expect("parses");
            let _ = cache.get_or_compile(&text, || Ok((Parser::default(), parsed)));
            assert!(cache.len() <= MAX_CACHED_EXPRESSIONS);
        }
        assert_eq!(cache.len(), 1, "full, then started afresh");
        let empty = cache.get_or_compile("x", || Err("never".into()));
        assert!(matches!(empty, Err("never")));
    }
}
