//! `lpe.lint`'s native half: `lpe-check lint`'s run ([`lpe_lint::check::run`]) over
//! files, returned as its JSON report (schema `lpe-lint/1`, docs/lint.md) for
//! `lpe/__init__.py` to wrap. A stage exported to a temporary file is reported under
//! the name `rename` gives. A renderer's profile (`renderer=`, `profile=`, or, with
//! neither nor `dialect=`, the one the stages name) gives the dialect and registration,
//! and lint checks its rules too.

use std::path::PathBuf;

use lpe::with_dialect;
use std::borrow::Cow;

use lpe_lint::check::renderer::named_by;
use lpe_lint::check::run::{check, read, Inputs, Request, RunError};
use pyo3::prelude::*;

use crate::dialect::{Language, PyDialect};
use crate::error::{disagreement, value_error};

/// Lints `files` as `lpe-check lint --format json` does; returns the report's JSON text.
#[pyfunction]
#[pyo3(signature = (files, partitions = Vec::new(), universe = None, dialect = None, ini = None, register = None, rename = None, renderer = None, profile = None))]
#[allow(clippy::too_many_arguments)]
pub fn lint_json(
    py: Python<'_>,
    files: Vec<PathBuf>,
    partitions: Vec<String>,
    universe: Option<String>,
    dialect: Option<&str>,
    ini: Option<PathBuf>,
    register: Option<String>,
    rename: Option<(String, String)>,
    renderer: Option<&str>,
    profile: Option<PathBuf>,
) -> PyResult<String> {
    // No dialect and no renderer named: the renderer the stages name, else RenderMan's
    // with undeclared stages read both ways (as `lpe-check lint`).
    let mut lang = Language::of(dialect, renderer, profile.as_deref())?;
    let mut req = Request {
        files: &files,
        ini: ini.as_deref(),
        partitions: &partitions,
        universe: universe.as_deref(),
        // A renderer names its dialect: no stage is read both ways.
        dialect_given: dialect.is_some() || lang.profile.is_some(),
        profile: None,
    };
    let inputs = py.allow_threads(|| read(&req));
    if lang.profile.is_none() && dialect.is_none() {
        if let Some((p, _)) = named_by(&inputs.docs).map_err(value_error)? {
            lang.dialect = p.dialect();
            lang.profile = Some(Cow::Borrowed(p));
            req.dialect_given = true;
        }
    }
    req.profile = lang.profile.as_deref();
    let json = py.allow_threads(|| {
        with_dialect!(lang.dialect, D => lint_in::<D>(&req, inputs, &lang, register.as_deref(), rename.as_ref()))
    });
    match json {
        Ok(v) => Ok(v),
        Err(RunError::Disagreement(d)) => Err(disagreement(&d)),
        Err(e) => Err(value_error(e)),
    }
}

fn lint_in<D: PyDialect>(
    req: &Request<'_>,
    inputs: Inputs,
    lang: &Language,
    register: Option<&str>,
    rename: Option<&(String, String)>,
) -> Result<String, RunError> {
    let mut out = check::<D, _>(req, inputs, |ini| lang.registration_of::<D>(ini, register))?;
    if let Some((from, to)) = rename {
        out.rename_file(from, to);
    }
    Ok(out.json().to_string())
}
