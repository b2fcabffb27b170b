//! An AOV list read in one dialect: every line parsed ([`Parsed`]), and the list
//! compiled into one [`AovSet`] for the views that need the whole list to parse.

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
