//! The data-driven conformance suite: the cases in `tests/testdata/*.toml`, each run
//! in-process against every registered engine and against lpe's [`AovSet`] under every
//! [`Options`] configuration in [`configs`], the way regex-automata's `testdata/` drives
//! its engines. `tests/testdata/README.md` describes the case format.
//!
//! A wrong vector must be loud: every mismatch becomes a [`Failure`] naming the file,
//! the case, the engine, the configuration, the path, what was expected and what came
//! back, and the runner never drops a case silently (an engine that refuses to build a
//! case is a failure too, unless the case lists it in `refused_by`).

use std::collections::BTreeSet;
use std::fmt;
use std::path::{Path as FsPath, PathBuf};

use lpe::renderman::{ErrorKind, Lpe, Parser, Path};
use lpe::{AovSet, Options};
use serde::Deserialize;

// The one line to change when the engine registry moves crates.
use engines as registry;

/// One `tests/testdata/*.toml` file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct CaseFile {
    #[serde(rename = "case", default)]
    cases: Vec<Case>,
}

/// One case: an expression (or an AOV set) with its expected answers, or an expected
/// error. See `tests/testdata/README.md`.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Case {
    /// Unique within its file.
    pub name: String,
    /// The expression under test.
    pub expr: Option<String>,
    /// Expressions that must answer exactly like `expr` on every path of the case.
    #[serde(default)]
    pub same_as: Vec<String>,
    /// An AOV set (instead of `expr`), compiled as one set.
    #[serde(default)]
    pub aovs: Vec<Aov>,
    /// `rendermn.ini` text whose macros the expressions may use.
    pub ini: Option<String>,
    /// Paths the expression matches.
    #[serde(default, rename = "match")]
    pub matches: Vec<String>,
    /// Paths the expression does not match.
    #[serde(default)]
    pub no_match: Vec<String>,
    /// For an AOV set: each path and the names of the AOVs it lands in.
    #[serde(default)]
    pub lands: Vec<Landing>,
    /// `expr` must fail to parse, with this kind at this byte.
    pub error: Option<ExpectedError>,
    /// Path texts that must fail to parse.
    #[serde(default)]
    pub bad_path: Vec<BadPath>,
    /// Subjects that may refuse to build this case (over a size budget), as an engine
    /// name (`aovset` for lpe's AOV set under every configuration) or `engine/config`;
    /// their refusal is then counted, not a failure.
    #[serde(default)]
    pub refused_by: Vec<String>,
}

impl Case {
    /// Expectations the case states: one per (expression, path) answer, per landing,
    /// per expected error and per malformed path.
    pub fn vectors(&self) -> usize {
        (self.matches.len() + self.no_match.len()) * (1 + self.same_as.len())
            + self.lands.len()
            + usize::from(self.error.is_some())
            + self.bad_path.len()
    }
}

/// One AOV of a set.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Aov {
    /// The AOV's name, as `lands` refers to it.
    pub name: String,
    /// Its expression.
    pub expr: String,
}

/// A path and the AOVs of the case's set it lands in.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Landing {
    /// The path text.
    pub path: String,
    /// Names of the AOVs that match it (any order; empty for none).
    #[serde(rename = "in")]
    pub aovs: Vec<String>,
}

/// The parse error a case expects.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ExpectedError {
    /// The [`ErrorKind`] variant's name, e.g. `"Quantifier"`.
    pub kind: String,
    /// Byte offset where the error's span starts.
    pub at: usize,
    /// Text the rendered error (message, caret, help) must contain.
    pub says: Option<String>,
}

/// A malformed path and where its parser must put the blame.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BadPath {
    /// The path text.
    pub path: String,
    /// Zero-based index of the offending vertex (the vertex count when a vertex is
    /// missing at the end).
    pub vertex: usize,
    /// Byte offset where the offending vertex starts; absent when there is no such
    /// vertex in the text.
    pub at: Option<usize>,
}

/// A case with the file it came from.
#[derive(Clone, Debug)]
pub struct Loaded {
    /// File name, e.g. `atoms.toml`.
    pub file: String,
    /// The case.
    pub case: Case,
}

/// Why the suite could not be loaded.
#[derive(Debug)]
pub enum LoadError {
    /// The directory or a file could not be read.
    Io {
        /// The file or directory.
        path: PathBuf,
        /// The underlying error.
        source: std::io::Error,
    },
    /// A file is not valid TOML for the case format.
    Toml {
        /// The file name.
        file: String,
        /// The parser's message, with line and column.
        source: Box<toml::de::Error>,
    },
    /// A case is well-formed TOML but not a well-formed case.
    Case {
        /// The file name.
        file: String,
        /// The case name.
        case: String,
        /// What is wrong with it.
        problem: String,
    },
}

impl fmt::Display for LoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LoadError::Io { path, source } => write!(f, "cannot read {}: {source}", path.display()),
            LoadError::Toml { file, source } => write!(f, "{file}: {source}"),
            LoadError::Case {
                file,
                case,
                problem,
            } => write!(f, "{file}: case `{case}`: {problem}"),
        }
    }
}

impl std::error::Error for LoadError {}

/// The directory holding the suite.
pub fn testdata_dir() -> PathBuf {
    FsPath::new(env!("CARGO_MANIFEST_DIR")).join("testdata")
}

/// Every case of every `*.toml` file in `dir`, files in name order.
pub fn load_dir(dir: &FsPath) -> Result<Vec<Loaded>, LoadError> {
    let io = |path: &FsPath| {
        let path = path.to_path_buf();
        move |source| LoadError::Io { path, source }
    };
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(io(dir))?
        .map(|e| e.map(|e| e.path()))
        .collect::<Result<_, _>>()
        .map_err(io(dir))?;
    files.retain(|p| p.extension().is_some_and(|e| e == "toml"));
    files.sort();
    let mut out = Vec::new();
    for path in files {
        let text = std::fs::read_to_string(&path).map_err(io(&path))?;
        let name = path.file_name().unwrap_or_default().to_string_lossy();
        out.extend(load_str(&name, &text)?);
    }
    Ok(out)
}

/// The cases of one file's text; `file` names it in errors and failures.
pub fn load_str(file: &str, text: &str) -> Result<Vec<Loaded>, LoadError> {
    let parsed: CaseFile = toml::from_str(text).map_err(|e| LoadError::Toml {
        file: file.to_string(),
        source: Box::new(e),
    })?;
    let mut names = BTreeSet::new();
    let mut out = Vec::new();
    for case in parsed.cases {
        let bad = |problem: &str| LoadError::Case {
            file: file.to_string(),
            case: case.name.clone(),
            problem: problem.to_string(),
        };
        if !names.insert(case.name.clone()) {
            return Err(bad("the name is used twice in this file"));
        }
        validate(&case).map_err(|p| bad(&p))?;
        out.push(Loaded {
            file: file.to_string(),
            case,
        });
    }
    Ok(out)
}

fn validate(case: &Case) -> Result<(), String> {
    let answers = !case.matches.is_empty() || !case.no_match.is_empty();
    match (&case.expr, case.aovs.is_empty()) {
        (Some(_), false) => return Err("give `expr` or `aovs`, not both".into()),
        (None, true) if !case.bad_path.is_empty() => {
            return if answers || case.error.is_some() || !case.lands.is_empty() {
                Err("a case without `expr` or `aovs` only checks `bad_path`".into())
            } else {
                Ok(())
            };
        }
        (None, true) => return Err("give `expr`, `aovs` or `bad_path`".into()),
        _ => {}
    }
    if case.expr.is_some() {
        if !case.lands.is_empty() {
            return Err("`lands` is for AOV sets; use `match` / `no_match`".into());
        }
        if case.error.is_some() && (answers || !case.same_as.is_empty()) {
            return Err("an `error` case has no paths to answer".into());
        }
        if case.error.is_none() && !answers && case.bad_path.is_empty() {
            return Err("no expectation: add `match`, `no_match`, `error` or `bad_path`".into());
        }
    } else {
        if answers || !case.same_as.is_empty() || case.error.is_some() {
            return Err("an AOV set case answers with `lands`".into());
        }
        if case.lands.is_empty() {
            return Err("no expectation: add `lands`".into());
        }
        let names: BTreeSet<&str> = case.aovs.iter().map(|a| a.name.as_str()).collect();
        if names.len() != case.aovs.len() {
            return Err("two AOVs share a name".into());
        }
        for l in &case.lands {
            if let Some(n) = l.aovs.iter().find(|n| !names.contains(n.as_str())) {
                return Err(format!("`lands` names `{n}`, which is not in `aovs`"));
            }
        }
    }
    if let Some(e) = &case.error {
        if kind_by_name(&e.kind).is_none() {
            return Err(format!("`{}` is not an error kind", e.kind));
        }
    }
    if let Some(p) = case.matches.iter().find(|p| case.no_match.contains(p)) {
        return Err(format!("`{p}` is in both `match` and `no_match`"));
    }
    Ok(())
}

/// The name a case file uses for each [`ErrorKind`]; exhaustive, so a new kind cannot be
/// left out of the suite's vocabulary.
pub fn kind_name(kind: ErrorKind) -> &'static str {
    match kind {
        ErrorKind::Empty => "Empty",
        ErrorKind::Syntax => "Syntax",
        ErrorKind::TriplePosition => "TriplePosition",
        ErrorKind::Quantifier => "Quantifier",
        ErrorKind::Lobe => "Lobe",
        ErrorKind::UnknownMacro => "UnknownMacro",
        ErrorKind::UnknownPrefix => "UnknownPrefix",
        ErrorKind::Limit => "Limit",
    }
}

fn kind_by_name(name: &str) -> Option<ErrorKind> {
    [
        ErrorKind::Empty,
        ErrorKind::Syntax,
        ErrorKind::TriplePosition,
        ErrorKind::Quantifier,
        ErrorKind::Lobe,
        ErrorKind::UnknownMacro,
        ErrorKind::UnknownPrefix,
        ErrorKind::Limit,
    ]
    .into_iter()
    .find(|&k| kind_name(k) == name)
}

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
    /// An engine of the registry, as registered.
    Engine(&'static dyn registry::Engine),
    /// lpe's AOV set compiled with these options.
    AovSet(Config),
}

impl Subject {
    /// The engine's name (`aovset` for the configured AOV sets).
    pub fn engine(&self) -> &'static str {
        match self {
            Subject::Engine(e) => e.name(),
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
    fn answer(&self, exprs: &[Lpe], paths: &[&Path]) -> Result<Vec<Vec<bool>>, String> {
        match self {
            Subject::Engine(e) => {
                let m = e.compile(exprs).map_err(|e| e.to_string())?;
                Ok(paths.iter().map(|p| m.which(p)).collect())
            }
            Subject::AovSet(c) => {
                let named: Vec<(String, Lpe)> = exprs
                    .iter()
                    .enumerate()
                    .map(|(i, e)| (i.to_string(), e.clone()))
                    .collect();
                let set = AovSet::compile_with(&named, &c.options).map_err(|e| e.to_string())?;
                Ok(paths
                    .iter()
                    .map(|p| {
                        let hit = set.match_path(p);
                        (0..exprs.len()).map(|i| hit.contains(i)).collect()
                    })
                    .collect())
            }
        }
    }
}

/// Every registered engine, then the AOV set under every configuration.
pub fn subjects() -> Vec<Subject> {
    registry::all()
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

/// What a case compiles and asks: the expressions (compiled together, as one set), a
/// label for failures, and per path the expected answer of each expression.
struct Plan<'a> {
    sources: Vec<&'a str>,
    label: String,
    expected: Vec<(&'a str, Vec<bool>)>,
}

impl<'a> Plan<'a> {
    fn of(case: &'a Case) -> Plan<'a> {
        if let Some(expr) = &case.expr {
            let mut sources = vec![expr.as_str()];
            sources.extend(case.same_as.iter().map(String::as_str));
            let n = sources.len();
            let expected = case
                .matches
                .iter()
                .map(|p| (p.as_str(), vec![true; n]))
                .chain(case.no_match.iter().map(|p| (p.as_str(), vec![false; n])))
                .collect();
            return Plan {
                sources,
                label: expr.clone(),
                expected,
            };
        }
        let label = case
            .aovs
            .iter()
            .map(|a| format!("{}={}", a.name, a.expr))
            .collect::<Vec<_>>()
            .join(", ");
        Plan {
            sources: case.aovs.iter().map(|a| a.expr.as_str()).collect(),
            label: format!("{{{label}}}"),
            expected: case
                .lands
                .iter()
                .map(|l| {
                    let hit = case.aovs.iter().map(|a| l.aovs.contains(&a.name)).collect();
                    (l.path.as_str(), hit)
                })
                .collect(),
        }
    }
}

fn run_case(loaded: &Loaded, subjects: &[Subject], report: &mut Report) {
    let case = &loaded.case;
    let fail =
        |engine: &str, config: &str, expr: &str, path: Option<&str>, expected, got| Failure {
            file: loaded.file.clone(),
            case: case.name.clone(),
            engine: engine.to_string(),
            config: config.to_string(),
            expr: expr.to_string(),
            path: path.map(str::to_string),
            expected,
            got,
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
        match parser.parse(src) {
            Ok(l) => exprs.push(l),
            Err(e) => {
                report.failures.push(fail(
                    "parser",
                    "-",
                    src,
                    None,
                    "a valid expression".into(),
                    format!("{:?}", e.to_string()),
                ));
                return;
            }
        }
    }
    let mut paths = Vec::new();
    for (text, _) in &expected {
        report.checks += 1;
        match text.parse::<Path>() {
            Ok(p) => paths.push(p),
            Err(e) => {
                report.failures.push(fail(
                    "parser",
                    "-",
                    &label,
                    Some(text),
                    "a valid path".into(),
                    format!("`{e}`"),
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
            .filter(|&i| subject.max_path_len().is_none_or(|n| paths[i].len() <= n))
            .collect();
        report.too_long += paths.len() - keep.len();
        let kept: Vec<&Path> = keep.iter().map(|&i| &paths[i]).collect();
        let answers = match subject.answer(&exprs, &kept) {
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
