//! An AOV list read in one dialect: every line parsed ([`Parsed`]), and the list
//! compiled into one [`AovSet`] for the views that need the whole list to parse.

use std::time::Duration;

use lpe::analysis::{AnalysisBudget, DEFAULT_STEPS};
use lpe::{AovSet, Options};
use lpe_lint::check::dialect::{LintDialect, ParseFailure};
use lpe_profile::ProfileDialect;

use crate::lines::{self, Line};
use crate::request::{ApiError, Request, Setting};

/// What the explorer asks of a dialect: lint's parse with span and hint, a profile's
/// registration. Every dialect that has both is one.
pub trait ExploreDialect: LintDialect + ProfileDialect {}

impl<D: LintDialect + ProfileDialect> ExploreDialect for D {}

/// The lines of a request's list, each with its parse.
pub struct Parsed<D: ExploreDialect> {
    /// The registration the lines were read under.
    pub registration: D::Registration,
    /// The lines, in order, with their parses.
    pub lines: Vec<(Line, Result<D::Lpe, ParseFailure>)>,
}

impl<D: ExploreDialect> Parsed<D> {
    /// Parses every line of `request.aovs` under `setting`'s registration.
    pub fn read(request: &Request, setting: &Setting) -> Parsed<D> {
        let registration = setting.registration::<D>();
        let lines = lines::read(&request.aovs)
            .into_iter()
            .map(|l| {
                let parsed = D::parse_source(&l.source, &registration);
                (l, parsed)
            })
            .collect();
        Parsed {
            registration,
            lines,
        }
    }

    /// The `(name, expression)` pairs of the lines that parsed.
    pub fn parsed(&self) -> Vec<(String, D::Lpe)> {
        self.lines
            .iter()
            .filter_map(|(l, p)| p.as_ref().ok().map(|e| (l.name.clone(), e.clone())))
            .collect()
    }

    /// Every line's expression, or a 422 naming the first line that does not parse
    /// (and a 422 for a list with no AOV).
    pub fn all(&self) -> Result<Vec<(String, D::Lpe)>, ApiError> {
        if let Some((line, Err(e))) = self.lines.iter().find(|(_, p)| p.is_err()) {
            let at = line.offset + e.span.start.min(line.source.len());
            let column = line.text[..at].chars().count() + 1;
            return Err(ApiError::unprocessable(format!(
                "line {} column {column} (AOV `{}`): {}",
                line.number, line.name, e.message
            )));
        }
        if self.lines.is_empty() {
            return Err(ApiError::unprocessable("the list has no AOV"));
        }
        Ok(self.parsed())
    }

    /// The list compiled into one set: 422 when a line does not parse or the list does
    /// not compile (over lpe's limits: too many AOVs or positions).
    pub fn compile(&self) -> Result<AovSet<D>, ApiError> {
        compile(&self.all()?, &self.registration)
    }
}

/// `aovs` compiled under `registration` with default [`Options`]: a 422 with lpe's
/// reason when it does not compile.
pub fn compile<D: ExploreDialect>(
    aovs: &[(String, D::Lpe)],
    registration: &D::Registration,
) -> Result<AovSet<D>, ApiError> {
    AovSet::<D>::compile_under(aovs, registration, &Options::default())
        .map_err(|e| ApiError::unprocessable(format!("the list does not compile: {e}")))
}

/// Wall-clock time one analysis of a view may take (besides lpe's default step budget),
/// so that a page waits at most this long for `partition` or `equiv`; past either the
/// answer is undecided, a value of the reply, not an error.
pub const ANALYSIS_TIME: Duration = Duration::from_secs(2);

/// The budget of every analysis a view runs: lpe's default steps and [`ANALYSIS_TIME`].
pub fn budget() -> AnalysisBudget {
    AnalysisBudget {
        steps: DEFAULT_STEPS,
        time: Some(ANALYSIS_TIME),
    }
}

/// A witness the reference matcher does not confirm: a bug of lpe's, answered 500 so
/// that it is never shown as a fact about the user's expressions.
pub fn disagreement(e: lpe_lint::witness::Disagreement) -> ApiError {
    ApiError {
        status: 500,
        message: e.to_string(),
    }
}

impl<D: ExploreDialect> Parsed<D> {
    /// The expression of line `name`, if the list has a line of that name that parses.
    pub fn line(&self, name: &str) -> Option<&D::Lpe> {
        self.lines
            .iter()
            .find(|(l, _)| l.name == name)
            .and_then(|(_, p)| p.as_ref().ok())
    }
}

/// `text` parsed as one expression under `registration`: a 422 naming `field` and the
/// column on failure.
pub fn expression<D: ExploreDialect>(
    field: &str,
    text: &str,
    registration: &D::Registration,
) -> Result<D::Lpe, ApiError> {
    D::parse_source(text, registration).map_err(|e| {
        let column = e
            .source
            .get(..e.span.start)
            .map_or(0, |s| s.chars().count())
            + 1;
        ApiError::unprocessable(format!("`{field}` column {column}: {}", e.message))
    })
}
