//! One lint run over files, as `lpe-check lint` and the Python package (`lpe.lint`)
//! make it: the ini files first (for a dialect that reads them), the registration the
//! caller builds from the ini file it names, every file read, the universe parsed, the
//! checks run; [`Run`] holds the outcome with each file's status, and prints both
//! reports.

use std::fmt;
use std::path::{Path, PathBuf};

use serde_json::Value;

use super::ambiguity::BothDialects;
use super::dialect::{Lint, LintDialect};
pub use super::inputs::Inputs;
use super::json::{self, FileStatus};
use super::{inputs, text, Outcome};
use crate::read::Limits;
use crate::witness::Disagreement;

/// What to lint.
pub struct Request<'a> {
    /// The files (USD, RIB, ini), in order.
    pub files: &'a [PathBuf],
    /// One more ini file, read first (`--ini`).
    pub ini: Option<&'a Path>,
    /// AOV names that must partition the universe, each list comma-separated.
    pub partitions: &'a [String],
    /// The universe partitions split (`None`: the dialect's default).
    pub universe: Option<&'a str>,
    /// Whether the user named the dialect (`--dialect`, `dialect=`): every file is then
    /// read in it and none is ambiguous, so `ambiguous_dialect` is not checked. When the
    /// dialect is only the default, a stage that declares none is read both ways.
    pub dialect_given: bool,
    /// The renderer's profile (`--renderer`, `--profile`): its rules are checked too
    /// (module `renderer`).
    pub profile: Option<&'a lpe_profile::Profile>,
}

/// Why a run could not check anything.
#[derive(Debug)]
pub enum RunError {
    /// The registration could not be built (a bad ini file, OSL labels, ...).
    Registration {
        /// The ini file it was built from, if any.
        file: Option<PathBuf>,
        /// Why.
        message: String,
    },
    /// The universe does not parse.
    Universe(String),
    /// A witness the reference matcher refused: an engine bug.
    Disagreement(Disagreement),
}

impl fmt::Display for RunError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RunError::Registration {
                file: Some(p),
                message,
            } => {
                write!(f, "{}: {message}", p.display())
            }
            RunError::Registration {
                file: None,
                message,
            } => f.write_str(message),
            RunError::Universe(message) => write!(f, "--universe: {message}"),
            RunError::Disagreement(d) => d.fmt(f),
        }
    }
}

impl std::error::Error for RunError {}

/// A finished run: what the checks found and each file's status.
pub struct Run<E> {
    /// The AOVs, partitions and findings.
    pub outcome: Outcome<E>,
    /// One per file, in reading order (an unreadable file has its error here).
    pub statuses: Vec<FileStatus>,
}

impl<E: fmt::Display> Run<E> {
    /// The JSON report (schema `lpe-lint/1`).
    pub fn json(&self) -> Value {
        json::render(&self.outcome, &self.statuses)
    }

    /// The text report (without the unreadable files' errors: [`Run::read_errors`]).
    pub fn text(&self) -> String {
        text::render(&self.outcome)
    }

    /// The errors of the files that could not be read.
    pub fn read_errors(&self) -> impl Iterator<Item = &str> {
        self.statuses.iter().filter_map(|s| s.error.as_deref())
    }

    /// Names the file `from` `to` in every status (its error's leading file name too),
    /// AOV, partition and finding (a stage read under a placeholder name is reported
    /// under its own).
    pub fn rename_file(&mut self, from: &str, to: &str) {
        let rename = |f: &mut String| {
            if f == from {
                *f = to.to_string();
            }
        };
        for s in &mut self.statuses {
            if s.file == from {
                if let Some(e) = &mut s.error {
                    if let Some(rest) = e.strip_prefix(from).filter(|r| r.starts_with(": ")) {
                        *e = format!("{to}{rest}");
                    }
                }
            }
            rename(&mut s.file);
        }
        self.outcome
            .aovs
            .iter_mut()
            .for_each(|a| rename(&mut a.file));
        self.outcome
            .partitions
            .iter_mut()
            .for_each(|p| rename(&mut p.file));
        self.outcome
            .findings
            .iter_mut()
            .for_each(|f| rename(&mut f.file));
    }
}

/// Reads and lints `req`'s files in dialect `D` ([`read`], then [`check`]).
/// `registration` builds the dialect's registration from the ini file it is given
/// (`None` for a dialect that reads ini files with the others, or when there is none); a
/// dialect that does not read ini files gets the first one there is, and decides
/// whether that is an error.
pub fn run<D, X>(
    req: &Request<'_>,
    registration: impl FnOnce(Option<&Path>) -> Result<D::Registration, X>,
) -> Result<Run<D::Lpe>, RunError>
where
    D: LintDialect,
    X: fmt::Display,
{
    check::<D, X>(req, read(req), registration)
}

/// Reads `req`'s files (ini files first), before any dialect is chosen: the renderer the
/// stages name ([`super::renderer::named_by`]) can then choose it.
pub fn read(req: &Request<'_>) -> Inputs {
    let (inis, others) = inputs::split(req.ini, req.files);
    inputs::read_all(&inis, &others, &Limits::default())
}

/// [`read`], with the files other than ini files read by `read_other`: `lpe.lint(stage)`
/// makes the document of a stage from what it read through Pixar's USD.
pub fn read_by(
    req: &Request<'_>,
    read_other: &mut dyn FnMut(&Path) -> Result<crate::Document, crate::ReadError>,
) -> Inputs {
    let (inis, others) = inputs::split(req.ini, req.files);
    inputs::read_all_by(&inis, &others, &Limits::default(), read_other)
}

/// Lints what [`read`] read, in dialect `D`; `registration` as for [`run`].
pub fn check<D, X>(
    req: &Request<'_>,
    read: Inputs,
    registration: impl FnOnce(Option<&Path>) -> Result<D::Registration, X>,
) -> Result<Run<D::Lpe>, RunError>
where
    D: LintDialect,
    X: fmt::Display,
{
    let (inis, _) = inputs::split(req.ini, req.files);
    let ini = if D::READS_INI {
        None
    } else {
        inis.first().copied()
    };
    let registration = registration(ini).map_err(|e| RunError::Registration {
        file: ini.map(Path::to_path_buf),
        message: e.to_string(),
    })?;
    // Unless the user named the dialect, undeclared stages are read in both, RenderMan
    // with the ini files' macros.
    let both = (!req.dialect_given).then(|| BothDialects::new(read.config.parser()));
    let (registration, lobes) = D::configured(registration, &read.config);
    let dialect = Lint::<D> {
        registration: &registration,
        lobes: &lobes,
        budget: lpe::analysis::AnalysisBudget::default(),
    };
    let universe = req.universe.unwrap_or(D::DEFAULT_UNIVERSE);
    let universe = dialect
        .parse(universe)
        .map_err(|e| RunError::Universe(e.message))?;
    let extra = inputs::command_line_partitions(req.partitions);
    let outcome = super::lint(
        &read.docs,
        &dialect,
        both.as_ref(),
        req.profile,
        &universe,
        &extra,
    )
    .map_err(RunError::Disagreement)?;
    Ok(Run {
        outcome,
        statuses: read.statuses,
    })
}
