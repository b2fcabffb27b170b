//! The data-driven conformance suite's in-process runner: the cases of
//! `tests/testdata/**/*.toml` (loaded by [`lpe_testkit::suite`], which also documents the
//! format), each run against every registered engine and against lpe's [`AovSet`] under
//! every [`Options`] configuration in [`configs`], in the case's dialect (RenderMan or
//! OSL), the way regex-automata's `testdata/` drives its engines.
//!
//! A wrong vector must be loud: every mismatch becomes a [`Failure`] naming the file,
//! the case, the engine, the configuration, the path, what was expected and what came
//! back, and the runner never drops a case silently (an engine that refuses to build a
//! case is a failure too, unless the case lists it in `refused_by`).

use std::fmt;

use lpe::osl::Osl;
use lpe::renderman::{Parser, Path, RenderMan};
use lpe::{AovSet, DialectName, Options};
use lpe_engines::engine::bits;
use lpe_engines::EngineDialect;

pub use lpe_testkit::suite::{
    kind_name, load_dir, load_str, testdata_dir, Aov, BadPath, Case, ExpectedError, Landing,
    LoadError, Loaded, Plan,
};

// The one line to change when the engine registry moves crates.
use lpe_engines as registry;

/// An `Options` configuration lpe's [`AovSet`] is checked under.
#[derive(Clone, Debug)]
pub struct Config {
    /// As failures name it.
    pub name: &'static str,
    /// The compile options.
    pub options: Options,
}

/// `max_path_len` of the configurations that set it. Under it `e{n,m}` with
/// `m >= max_path_len` compiles as `e{n,}`, which is exact only on paths of at most that
/// many vertices, so those configurations check only such paths (the longer ones of a
/// case are skipped for them, and counted).
pub const MAX_PATH_LEN: u32 = 6;

/// Every configuration: the default, the NFA forced (DFA budget 0, no lazy cache: every
/// step runs the bitset NFA), the lazy DFA (DFA budget 0 with its cache, default-sized
/// and two rows, which clears on nearly every new transition), and the default and the
/// NFA with [`MAX_PATH_LEN`].
pub fn configs() -> Vec<Config> {
    let nfa = Options {
        dfa_budget: 0,
        lazy_cache: 0,
        ..Options::default()
    };
    let lazy = |lazy_cache| Options {
        dfa_budget: 0,
        lazy_cache,
        ..Options::default()
    };
    let short = |o: &Options| Options {
        max_path_len: Some(MAX_PATH_LEN),
        ..o.clone()
    };
    vec![
        Config {
            name: "default",
            options: Options::default(),
        },
        Config {
            name: "dfa-budget-0",
            options: nfa.clone(),
        },
        Config {
            name: "lazy",
            options: lazy(Options::default().lazy_cache),
        },
        Config {
            name: "lazy-2-rows",
            options: lazy(1),
        },
        Config {
            name: "max-path-len-6",
            options: short(&Options::default()),
        },
        Config {
            name: "max-path-len-6+dfa-budget-0",
            options: short(&nfa),
        },
    ]
}

/// What a case runs on: a registered engine, or lpe's [`AovSet`] under one [`Config`].
pub enum Subject {
    /// An engine of the registry, as registered, by name (the registry holds it for
    /// every dialect).
    Engine(&'static str),
    /// lpe's AOV set compiled with these options.
    AovSet(Config),
}

impl Subject {
    /// The engine's name (`aovset` for the configured AOV sets).
    pub fn engine(&self) -> &'static str {
        match self {
            Subject::Engine(name) => name,
            Subject::AovSet(_) => "aovset",
        }
    }

    /// The configuration's name (`registered` for a registry engine, which brings its
    /// own).
    pub fn config(&self) -> &'static str {
        match self {
            Subject::Engine(_) => "registered",
            Subject::AovSet(c) => c.name,
        }
    }

    fn max_path_len(&self) -> Option<usize> {
        match self {
            Subject::Engine(_) => None,
            Subject::AovSet(c) => c.options.max_path_len.map(|n| n as usize),
        }
    }

    /// For each expression, whether it matches each path, or why the subject refused.
    fn answer<D: EngineDialect>(
        &self,
        registration: &D::Registration,
        exprs: &[D::Lpe],
        paths: &[&D::Path],
    ) -> Result<Vec<Vec<bool>>, String> {
        match self {
            Subject::Engine(name) => {
                let engine = registry::by_name::<D>(name).expect("a registered name");
                let m = engine
                    .compile(exprs, registration)
                    .map_err(|e| e.to_string())?;
                Ok(paths
                    .iter()
                    .map(|p| bits(m.which(p), exprs.len()))
                    .collect())
            }
            Subject::AovSet(c) => {
                let set = AovSet::<D>::compile_under(&numbered(exprs), registration, &c.options)
                    .map_err(|e| e.to_string())?;
                Ok(paths
                    .iter()
                    .map(|p| bits(set.match_path(p), exprs.len()))
                    .collect())
            }
        }
    }
}

/// The expressions named `0`, `1`, ... as an AOV list.
fn numbered<E: Clone>(exprs: &[E]) -> Vec<(String, E)> {
    exprs
        .iter()
        .enumerate()
        .map(|(i, e)| (i.to_string(), e.clone()))
        .collect()
}

/// Every registered engine, then the AOV set under every configuration.
pub fn subjects() -> Vec<Subject> {
    registry::names()
        .into_iter()
        .map(Subject::Engine)
        .chain(configs().into_iter().map(Subject::AovSet))
        .collect()
}

/// One wrong answer.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Failure {
    /// The case file.
    pub file: String,
    /// The case name.
    pub case: String,
    /// The engine (`parser` for parse and path-text checks, which no engine runs).
    pub engine: String,
    /// The configuration.
    pub config: String,
    /// The expression (or AOV set) checked.
    pub expr: String,
    /// The path, if the check was about one.
    pub path: Option<String>,
    /// What the case expects.
    pub expected: String,
    /// What came back.
    pub got: String,
}

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: case `{}`: engine {}, config {}: `{}`",
            self.file, self.case, self.engine, self.config, self.expr
        )?;
        if let Some(p) = &self.path {
            write!(f, " on `{p}`")?;
        }
        write!(f, ": expected {}, got {}", self.expected, self.got)
    }
}

/// What a run checked and what went wrong.
#[derive(Debug, Default)]
pub struct Report {
    /// Cases run.
    pub cases: usize,
    /// Individual answers compared (per engine and configuration).
    pub checks: usize,
    /// Answers not compared because the path is longer than a configuration's
    /// `max_path_len`.
    pub too_long: usize,
    /// Refusals the cases allow, as `(file, case, engine, config)`.
    pub allowed_refusals: Vec<(String, String, &'static str, &'static str)>,
    /// Every wrong answer, refusal not allowed, or malformed vector.
    pub failures: Vec<Failure>,
}

impl Report {
    /// All failures, one per line.
    pub fn failures_text(&self) -> String {
        self.failures
            .iter()
            .map(|f| format!("{f}\n"))
            .collect::<String>()
    }
}

/// Runs `cases` against `subjects`.
pub fn run(cases: &[Loaded], subjects: &[Subject]) -> Report {
    let mut report = Report::default();
    for c in cases {
        report.cases += 1;
        run_case(c, subjects, &mut report);
    }
    report
}

fn answer_text(m: bool) -> String {
    if m { "match" } else { "no-match" }.to_string()
}

/// A failure of `loaded`'s case.
fn failure(
    loaded: &Loaded,
    (engine, config): (&str, &str),
    expr: &str,
    path: Option<&str>,
    expected: String,
    got: String,
) -> Failure {
    Failure {
        file: loaded.file.clone(),
        case: loaded.case.name.clone(),
        engine: engine.to_string(),
        config: config.to_string(),
        expr: expr.to_string(),
        path: path.map(str::to_string),
        expected,
        got,
    }
}

fn run_case(loaded: &Loaded, subjects: &[Subject], report: &mut Report) {
    let case = &loaded.case;
    let fail = |engine: &str, config: &str, expr: &str, path: Option<&str>, expected, got| {
        failure(loaded, (engine, config), expr, path, expected, got)
    };
    let parser = match &case.ini {
        None => Parser::default(),
        Some(text) => match lpe::renderman::Config::from_ini(text) {
            Ok(c) => c.parser(),
            Err(e) => {
                report.failures.push(fail(
                    "parser",
                    "-",
                    "(ini)",
                    None,
                    "a valid ini".into(),
                    format!("ini error: {e}"),
                ));
                return;
            }
        },
    };

    for bad in &case.bad_path {
        report.checks += 1;
        let expected = match bad.at {
            Some(at) => format!("a path error at vertex {} (byte {at})", bad.vertex),
            None => format!("a path error at vertex {} (no span)", bad.vertex),
        };
        let got = match bad.path.parse::<Path>() {
            Ok(_) => "a valid path".to_string(),
            Err(e) if e.vertex == bad.vertex && e.span.as_ref().map(|s| s.start) == bad.at => {
                continue
            }
            Err(e) => format!("`{e}`"),
        };
        let expr = case.expr.as_deref().unwrap_or("-");
        report
            .failures
            .push(fail("parser", "-", expr, Some(&bad.path), expected, got));
    }

    if let Some(want) = &case.error {
        report.checks += 1;
        let expr = case.expr.as_deref().unwrap_or_default();
        let expected = format!("a {} error at byte {}", want.kind, want.at);
        let got = match parser.parse(expr) {
            Ok(l) => format!("a valid expression `{l}`"),
            Err(e) => {
                let text = e.to_string();
                let needle_ok = want.says.as_ref().is_none_or(|s| text.contains(s.as_str()));
                if kind_name(e.kind()) == want.kind && e.span().start == want.at && needle_ok {
                    return;
                }
                let expected = match &want.says {
                    Some(s) => format!("{expected} saying `{s}`"),
                    None => expected.clone(),
                };
                report.failures.push(fail(
                    "parser",
                    "-",
                    expr,
                    None,
                    expected,
                    format!(
                        "a {} error at byte {}: {text:?}",
                        kind_name(e.kind()),
                        e.span().start
                    ),
                ));
                return;
            }
        };
        report
            .failures
            .push(fail("parser", "-", expr, None, expected, got));
        return;
    }

    // The one place a case's dialect picks its type and registration (RenderMan: the
    // case's parser, with its `ini` macros; OSL: its registered labels).
    match loaded.dialect {
        DialectName::RenderMan => answer_case::<RenderMan>(&parser, loaded, subjects, report),
        DialectName::Osl => answer_case::<Osl>(&loaded.registered, loaded, subjects, report),
    }
}

/// Runs the case's paths on every subject, in dialect `D` under `registration`.
fn answer_case<D: EngineDialect>(
    registration: &D::Registration,
    loaded: &Loaded,
    subjects: &[Subject],
    report: &mut Report,
) {
    let case = &loaded.case;
    let fail = |engine: &str, config: &str, expr: &str, path: Option<&str>, expected, got| {
        failure(loaded, (engine, config), expr, path, expected, got)
    };
    let Plan {
        sources,
        label,
        expected,
    } = Plan::of(case);
    if expected.is_empty() {
        return;
    }

    let mut exprs = Vec::new();
    for src in &sources {
        report.checks += 1;
        match D::parse(src, registration).map_err(|e| format!("{:?}", e.to_string())) {
            Ok(l) => exprs.push(l),
            Err(e) => {
                report.failures.push(fail(
                    "parser",
                    "-",
                    src,
                    None,
                    "a valid expression".into(),
                    e,
                ));
                return;
            }
        }
    }
    let mut paths = Vec::new();
    for (text, _) in &expected {
        report.checks += 1;
        match text.parse::<D::Path>().map_err(|e| format!("`{e}`")) {
            Ok(p) => paths.push(p),
            Err(e) => {
                report.failures.push(fail(
                    "parser",
                    "-",
                    &label,
                    Some(text),
                    "a valid path".into(),
                    e,
                ));
                return;
            }
        }
    }

    let mut answered = 0;
    for subject in subjects {
        let (engine, config) = (subject.engine(), subject.config());
        // Paths over the configuration's `max_path_len` have unspecified answers.
        let keep: Vec<usize> = (0..paths.len())
            .filter(|&i| {
                subject
                    .max_path_len()
                    .is_none_or(|n| D::vertices(&paths[i]).len() <= n)
            })
            .collect();
        report.too_long += paths.len() - keep.len();
        let kept: Vec<&D::Path> = keep.iter().map(|&i| &paths[i]).collect();
        let answers = match subject.answer::<D>(registration, &exprs, &kept) {
            Ok(a) => a,
            Err(why) => {
                let allowed = |n: &String| n == engine || *n == format!("{engine}/{config}");
                if case.refused_by.iter().any(allowed) {
                    report.allowed_refusals.push((
                        loaded.file.clone(),
                        case.name.clone(),
                        engine,
                        config,
                    ));
                } else {
                    report.failures.push(fail(
                        engine,
                        config,
                        &label,
                        None,
                        "a matcher".into(),
                        format!("a refusal: {why}"),
                    ));
                }
                continue;
            }
        };
        answered += 1;
        for (&i, got) in keep.iter().zip(answers) {
            let (text, want) = &expected[i];
            report.checks += 1;
            if got.len() != want.len() {
                report.failures.push(fail(
                    engine,
                    config,
                    &label,
                    Some(text),
                    format!("{} answers", want.len()),
                    format!("{} answers", got.len()),
                ));
                continue;
            }
            if case.expr.is_some() {
                for (j, (&g, &w)) in got.iter().zip(want).enumerate() {
                    if g != w {
                        report.failures.push(fail(
                            engine,
                            config,
                            sources[j],
                            Some(text),
                            answer_text(w),
                            answer_text(g),
                        ));
                    }
                }
            } else if &got != want {
                let names = |hit: &[bool]| {
                    let n: Vec<&str> = case
                        .aovs
                        .iter()
                        .zip(hit)
                        .filter(|(_, &h)| h)
                        .map(|(a, _)| a.name.as_str())
                        .collect();
                    format!("[{}]", n.join(", "))
                };
                report.failures.push(fail(
                    engine,
                    config,
                    &label,
                    Some(text),
                    names(want),
                    names(&got),
                ));
            }
        }
    }
    // Allowed refusals must leave someone to check the vectors.
    if answered == 0 && !subjects.is_empty() {
        report.failures.push(fail(
            "-",
            "-",
            &label,
            None,
            "answers from at least one engine".into(),
            "a refusal from every engine".into(),
        ));
    }
}
