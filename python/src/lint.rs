//! `lpe.lint`'s native half: `lpe-check lint`'s run ([`lpe_lint::check::run`]) over
//! files, returned as its JSON report (schema `lpe-lint/1`, docs/lint.md) for
//! `lpe/__init__.py` to wrap. A `pxr.Usd.Stage` comes as the facts `lpe/__init__.py`
//! collected by traversing it ([`lint_stage_json`]): the document is made from them by
//! the USD reader's own [`document`], so the conventions (attribute names, `sourceType`
//! spellings) are written once; what to collect is exported as `USD_READ_ATTRIBUTES`,
//! `USD_READ_PREFIX`, `USD_READ_PRIM_TYPES` and `USD_ORDERED_VARS`. A renderer's profile (`renderer=`, `profile=`, or, with
//! neither nor `dialect=`, the one the stages name) gives the dialect and registration,
//! and lint checks its rules too.

use std::path::PathBuf;

use lpe::with_dialect;
use std::borrow::Cow;

use lpe_lint::check::renderer::named_by;
use lpe_lint::check::run::{check, read, read_by, Inputs, Request, RunError};
use lpe_lint::read::usd::{document, PrimFacts, StageFacts};
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
    let options = Options {
        partitions,
        universe,
        dialect,
        ini,
        register,
        renderer,
        profile,
    };
    lint_in_py(py, files, &options, rename, None)
}

/// One prim as `lpe/__init__.py` collects it: path, type name, authored property
/// names, `(attribute, text or None)` for the attributes lint reads, and a
/// RenderProduct's `orderedVars` target names.
type PrimTuple = (
    String,
    String,
    Vec<String>,
    Vec<(String, Option<String>)>,
    Vec<String>,
);

/// Lints a composed stage from the facts `lpe/__init__.py` read of it through pxr:
/// `prims` (every prim of a `USD_READ_PRIM_TYPES` type or with an attribute lint reads,
/// in traversal order), `types` (every prim's type name) and `name` (the file the
/// findings name); the options are [`lint_json`]'s.
#[pyfunction]
#[pyo3(signature = (prims, types, name, partitions = Vec::new(), universe = None, dialect = None, ini = None, register = None, renderer = None, profile = None))]
#[allow(clippy::too_many_arguments)]
pub fn lint_stage_json(
    py: Python<'_>,
    prims: Vec<PrimTuple>,
    types: Vec<String>,
    name: String,
    partitions: Vec<String>,
    universe: Option<String>,
    dialect: Option<&str>,
    ini: Option<PathBuf>,
    register: Option<String>,
    renderer: Option<&str>,
    profile: Option<PathBuf>,
) -> PyResult<String> {
    let facts = StageFacts {
        prims: prims
            .into_iter()
            .map(
                |(path, type_name, properties, values, ordered_vars)| PrimFacts {
                    name: path.rsplit('/').next().unwrap_or_default().to_string(),
                    path,
                    type_name,
                    properties,
                    values,
                    ordered_vars,
                },
            )
            .collect(),
        types: types.into_iter().collect(),
    };
    let options = Options {
        partitions,
        universe,
        dialect,
        ini,
        register,
        renderer,
        profile,
    };
    // The run names the stage `stage.usda` (a USD file by its extension, as the files
    // it reads), then the report takes the stage's own name.
    let placeholder = String::from("stage.usda");
    let files = vec![PathBuf::from(&placeholder)];
    lint_in_py(py, files, &options, Some((placeholder, name)), Some(facts))
}

/// The options every lint call takes.
struct Options<'a> {
    partitions: Vec<String>,
    universe: Option<String>,
    dialect: Option<&'a str>,
    ini: Option<PathBuf>,
    register: Option<String>,
    renderer: Option<&'a str>,
    profile: Option<PathBuf>,
}

/// The run of both entry points: `files` read from disk, or (`stage` given) the one
/// file made from the stage's facts.
fn lint_in_py(
    py: Python<'_>,
    files: Vec<PathBuf>,
    o: &Options<'_>,
    rename: Option<(String, String)>,
    stage: Option<StageFacts>,
) -> PyResult<String> {
    let Options {
        partitions,
        universe,
        dialect,
        ini,
        register,
        renderer,
        profile,
    } = o;
    let (dialect, renderer) = (*dialect, *renderer);
    // No dialect and no renderer named: the renderer the stages name, else RenderMan's
    // with undeclared stages read both ways (as `lpe-check lint`).
    let mut lang = Language::of(dialect, renderer, profile.as_deref())?;
    let mut req = Request {
        files: &files,
        ini: ini.as_deref(),
        partitions,
        universe: universe.as_deref(),
        // A renderer names its dialect: no stage is read both ways.
        dialect_given: dialect.is_some() || lang.profile.is_some(),
        profile: None,
    };
    let inputs = py.allow_threads(|| match &stage {
        None => read(&req),
        Some(facts) => read_by(&req, &mut |file| document(file, facts)),
    });
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
