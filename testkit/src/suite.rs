//! The conformance suite's case format and loader: every `*.toml` file under a
//! directory (`tests/testdata`, subdirectories included: `osl/` holds the OSL dialect's
//! files), each a list of `[[case]]` tables. `tests/testdata/README.md` describes the
//! format; this module parses and validates it, and gives each runner the same flat view
//! of what a case expects ([`Plan`], [`Row`]).
//!
//! A case is in the RenderMan dialect unless its file (a top-level `dialect = "osl"`) or
//! the case itself says `dialect = "osl"`; OSL cases may give the user labels registered
//! before their expressions are parsed (`registered = { events = ["U"], scatters = ["Y"] }`,
//! also at the top of a file). A file may instead name a renderer profile
//! (`profile = "karma"`, docs/profiles.md), which gives both. Every load error names the file and, when it is about one,
//! the case.

use std::collections::BTreeSet;
use std::fmt;
use std::path::{Path as FsPath, PathBuf};

use lpe::osl::Registered;
use lpe::renderman::ErrorKind;
use lpe::DialectName;
use serde::Deserialize;

/// One case file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct CaseFile {
    /// The dialect of every case that does not name its own.
    dialect: Option<String>,
    /// OSL user labels of every case that does not give its own.
    registered: Option<Registration>,
    /// The renderer profile every case is read under (docs/profiles.md): it gives the
    /// dialect and the registration, so neither `dialect` nor `registered` goes with it.
    profile: Option<String>,
    #[serde(rename = "case", default)]
    cases: Vec<Case>,
}

/// OSL user labels as a case file spells them: `{ events = ["U"], scatters = ["Y"] }`
/// (`events=U;scatters=Y` in `lpe-check`'s and the protocol's notation).
#[derive(Clone, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(deny_unknown_fields)]
pub struct Registration {
    /// Extra event types.
    #[serde(default)]
    pub events: Vec<String>,
    /// Extra scattering types.
    #[serde(default)]
    pub scatters: Vec<String>,
}

impl From<Registration> for Registered {
    fn from(r: Registration) -> Registered {
        Registered {
            events: r.events,
            scatters: r.scatters,
            ..Registered::default()
        }
    }
}

/// One case: an expression (or an AOV set) with its expected answers, or an expected
/// error. See `tests/testdata/README.md`.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Case {
    /// Unique within its file.
    pub name: String,
    /// `"renderman"` or `"osl"`; the file's dialect when absent (see [`Loaded::dialect`]).
    pub dialect: Option<String>,
    /// OSL only: user labels registered before the expressions are parsed; the file's
    /// when absent (see [`Loaded::registered`]).
    pub registered: Option<Registration>,
    /// The expression under test.
    pub expr: Option<String>,
    /// Expressions that must answer exactly like `expr` on every path of the case.
    #[serde(default)]
    pub same_as: Vec<String>,
    /// An AOV set (instead of `expr`), compiled as one set.
    #[serde(default)]
    pub aovs: Vec<Aov>,
    /// RenderMan only: `rendermn.ini` text whose macros the expressions may use.
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
    /// RenderMan only: `expr` must fail to parse, with this kind at this byte.
    pub error: Option<ExpectedError>,
    /// RenderMan only: path texts that must fail to parse.
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

/// A case with the file it came from and its resolved dialect and registration.
#[derive(Clone, Debug)]
pub struct Loaded {
    /// File name relative to the loaded directory, `/`-separated, e.g. `atoms.toml` or
    /// `osl/extra.toml`.
    pub file: String,
    /// The case.
    pub case: Case,
    /// The case's dialect (its own, else its file's, else RenderMan).
    pub dialect: DialectName,
    /// OSL user labels (the case's own, else its file's, else none); under a profile,
    /// the profile's letters, prefixes and built-in names.
    pub registered: Registered,
    /// The renderer profile of the case's file, if any.
    pub profile: Option<String>,
}

impl Loaded {
    /// `file: case `name``, as failures start.
    pub fn location(&self) -> String {
        format!("{}: case `{}`", self.file, self.case.name)
    }
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
    /// A file's top-level keys are wrong (an unknown dialect).
    File {
        /// The file name.
        file: String,
        /// What is wrong.
        problem: String,
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
            LoadError::File { file, problem } => write!(f, "{file}: {problem}"),
            LoadError::Case {
                file,
                case,
                problem,
            } => write!(f, "{file}: case `{case}`: {problem}"),
        }
    }
}

impl std::error::Error for LoadError {}

/// The workspace's suite: `tests/testdata`.
pub fn testdata_dir() -> PathBuf {
    FsPath::new(env!("CARGO_MANIFEST_DIR")).join("../tests/testdata")
}

/// The `*.toml` files under `dir` (recursively), sorted by their path relative to it.
pub fn discover(dir: &FsPath) -> Result<Vec<PathBuf>, LoadError> {
    let io = |path: &FsPath| {
        let path = path.to_path_buf();
        move |source| LoadError::Io { path, source }
    };
    let mut out = Vec::new();
    let mut pending = vec![dir.to_path_buf()];
    while let Some(d) = pending.pop() {
        for entry in std::fs::read_dir(&d).map_err(io(&d))? {
            let path = entry.map_err(io(&d))?.path();
            if path.is_dir() {
                pending.push(path);
            } else if path.extension().is_some_and(|e| e == "toml") {
                out.push(path);
            }
        }
    }
    out.sort();
    Ok(out)
}

/// Every case of every `*.toml` file under `dir` ([`discover`]), files in name order,
/// each named by its path relative to `dir`.
pub fn load_dir(dir: &FsPath) -> Result<Vec<Loaded>, LoadError> {
    let mut out = Vec::new();
    for path in discover(dir)? {
        let text = std::fs::read_to_string(&path).map_err(|source| LoadError::Io {
            path: path.clone(),
            source,
        })?;
        let rel = path.strip_prefix(dir).unwrap_or(&path);
        let name: Vec<String> = rel
            .components()
            .map(|c| c.as_os_str().to_string_lossy().into_owned())
            .collect();
        out.extend(load_str(&name.join("/"), &text)?);
    }
    Ok(out)
}

/// The cases of one file of the workspace's suite, e.g. `osl/accum_test.toml`.
pub fn load_file(name: &str) -> Result<Vec<Loaded>, LoadError> {
    let path = testdata_dir().join(name);
    let text = std::fs::read_to_string(&path).map_err(|source| LoadError::Io { path, source })?;
    load_str(name, &text)
}

fn dialect_named(name: &str) -> Result<DialectName, String> {
    name.parse()
        .map_err(|_| format!("dialect `{name}`: expected \"renderman\" or \"osl\""))
}

/// The cases of one file's text; `file` names it in errors and failures.
pub fn load_str(file: &str, text: &str) -> Result<Vec<Loaded>, LoadError> {
    let parsed: CaseFile = toml::from_str(text).map_err(|e| LoadError::Toml {
        file: file.to_string(),
        source: Box::new(e),
    })?;
    let file_error = |problem: String| LoadError::File {
        file: file.to_string(),
        problem,
    };
    let profile = match &parsed.profile {
        None => None,
        Some(name) => {
            if parsed.dialect.is_some() || parsed.registered.is_some() {
                return Err(file_error(
                    "a `profile` gives the dialect and the registration: drop `dialect` and `registered`".into(),
                ));
            }
            Some(lpe_profile::by_name(name).map_err(|e| file_error(e.to_string()))?)
        }
    };
    let file_dialect = match (&parsed.dialect, profile) {
        (_, Some(p)) => p.dialect(),
        (None, None) => DialectName::RenderMan,
        (Some(d), None) => dialect_named(d).map_err(file_error)?,
    };
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
        if profile.is_some() && (case.dialect.is_some() || case.registered.is_some()) {
            return Err(bad(
                "the file's `profile` gives the dialect and the registration",
            ));
        }
        let dialect = match &case.dialect {
            None => file_dialect,
            Some(d) => dialect_named(d).map_err(|p| bad(&p))?,
        };
        let registration = case.registered.clone().or(parsed.registered.clone());
        validate(&case, dialect).map_err(|p| bad(&p))?;
        let registered = registration.map(Registered::from).unwrap_or_default();
        out.push(Loaded {
            file: file.to_string(),
            case,
            dialect,
            registered: match profile {
                Some(p) => {
                    <lpe::osl::Osl as lpe_profile::ProfileDialect>::with_profile(p, registered)
                }
                None => registered,
            },
            profile: profile.map(|p| p.name.clone()),
        });
    }
    Ok(out)
}

fn validate(case: &Case, dialect: DialectName) -> Result<(), String> {
    match dialect {
        DialectName::RenderMan if case.registered.is_some() => {
            return Err("`registered` is for the OSL dialect".into())
        }
        DialectName::Osl
            if case.ini.is_some() || case.error.is_some() || !case.bad_path.is_empty() =>
        {
            return Err("`ini`, `error` and `bad_path` are for the RenderMan dialect".into())
        }
        // A file-wide registration in a file of mixed dialects is for its OSL cases
        // only; its RenderMan cases ignore it.
        _ => {}
    }
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

/// What a case compiles and asks: the expressions (compiled together, as one set), a
/// label for failures, and per path the expected answer of each expression. Empty
/// `expected` for a case that only checks errors.
#[derive(Clone, Debug)]
pub struct Plan<'a> {
    /// `expr` then `same_as`, or the AOVs' expressions in order.
    pub sources: Vec<&'a str>,
    /// The expression, or `{name=expr, ...}` for an AOV set.
    pub label: String,
    /// Each path text and, per source, whether it must match.
    pub expected: Vec<(&'a str, Vec<bool>)>,
}

impl<'a> Plan<'a> {
    /// The plan of `case`.
    pub fn of(case: &'a Case) -> Plan<'a> {
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

    /// The number of answers the plan asks for (paths times sources).
    pub fn answers(&self) -> usize {
        self.expected.len() * self.sources.len()
    }
}

/// One verdict of a case: one expression on one path, as the OSL verdict tables were
/// written (`EXPR`, `REGISTERED`, `PATH`, `MATCH|NOMATCH`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Row {
    /// The case file.
    pub file: String,
    /// The case name.
    pub case: String,
    /// The expression, unparsed.
    pub expr: String,
    /// OSL user labels (none for RenderMan).
    pub registered: Registered,
    /// The path text.
    pub path: String,
    /// Whether the expression matches the path.
    pub matches: bool,
}

/// Every single-expression verdict of `cases`, in order: per case, per path, `expr`
/// then each `same_as`. AOV-set cases and error cases give none.
pub fn rows(cases: &[Loaded]) -> Vec<Row> {
    let mut out = Vec::new();
    for l in cases.iter().filter(|l| l.case.expr.is_some()) {
        let plan = Plan::of(&l.case);
        for (path, want) in &plan.expected {
            for (src, &m) in plan.sources.iter().zip(want) {
                out.push(Row {
                    file: l.file.clone(),
                    case: l.case.name.clone(),
                    expr: src.to_string(),
                    registered: l.registered.clone(),
                    path: path.to_string(),
                    matches: m,
                });
            }
        }
    }
    out
}

/// The distinct expressions of `rows`, in first-seen order (a file's rule set, as OSL
/// compiles it into one automaton).
pub fn distinct_rules(rows: &[Row]) -> Vec<String> {
    let mut rules: Vec<String> = Vec::new();
    for r in rows {
        if !rules.contains(&r.expr) {
            rules.push(r.expr.clone());
        }
    }
    rules
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dialect_and_registration_resolve_per_file_and_per_case() {
        let text = r#"
dialect = "osl"
registered = { events = ["U"] }

[[case]]
name = "file's"
expr = "CUL"
match = ["C,_ U,_ L,_"]

[[case]]
name = "own"
expr = "CYL"
registered = { scatters = ["Y"] }
no_match = ["C,_ L,_"]

[[case]]
name = "renderman"
dialect = "renderman"
expr = "C<RD>L"
match = ["C RD L"]
"#;
        let cases = load_str("x.toml", text).unwrap();
        assert_eq!(cases[0].dialect, DialectName::Osl);
        assert_eq!(cases[0].registered.to_string(), "events=U");
        assert_eq!(cases[1].registered.to_string(), "scatters=Y");
        assert_eq!(cases[2].dialect, DialectName::RenderMan);
        let rows = rows(&cases);
        assert_eq!(rows.len(), 3);
        assert!(rows[0].matches && !rows[1].matches);
        assert_eq!(distinct_rules(&rows), ["CUL", "CYL", "C<RD>L"]);
    }

    #[test]
    fn load_errors_name_the_file_and_the_case() {
        let e = load_str("a.toml", "dialect = \"cycles\"\n").unwrap_err();
        assert_eq!(
            e.to_string(),
            "a.toml: dialect `cycles`: expected \"renderman\" or \"osl\""
        );
        let osl_ini = "[[case]]\nname = \"n\"\ndialect = \"osl\"\nexpr = \"CL\"\nini = \"\"\nmatch = [\"C,_ L,_\"]\n";
        let e = load_str("b.toml", osl_ini).unwrap_err().to_string();
        assert!(e.starts_with("b.toml: case `n`: `ini`"), "{e}");
        let rm_reg = "[[case]]\nname = \"r\"\nexpr = \"CL\"\nregistered = { events = [\"U\"] }\nmatch = [\"C L\"]\n";
        let e = load_str("c.toml", rm_reg).unwrap_err().to_string();
        assert_eq!(e, "c.toml: case `r`: `registered` is for the OSL dialect");
        let typo = "[[case]]\nname = \"t\"\nexpr = \"CL\"\nmatches = [\"C L\"]\n";
        let e = load_str("d.toml", typo).unwrap_err().to_string();
        assert!(e.starts_with("d.toml:") && e.contains("matches"), "{e}");
    }

    #[test]
    fn the_workspace_suite_holds_both_dialects_and_names_files_by_relative_path() {
        let cases = load_dir(&testdata_dir()).unwrap();
        assert!(cases.iter().any(|c| c.file == "osl/accum_test.toml"));
        assert!(cases
            .iter()
            .filter(|c| c.file.starts_with("osl/"))
            .all(|c| c.dialect == DialectName::Osl));
        assert!(cases
            .iter()
            .filter(|c| !c.file.contains('/'))
            .all(|c| c.dialect == DialectName::RenderMan));
        // OSL's own unit test, expanded per (rule, path): 130 verdicts.
        assert_eq!(rows(&load_file("osl/accum_test.toml").unwrap()).len(), 130);
    }
}
