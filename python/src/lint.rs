//! `lpe.lint`'s native half: `lpe-check lint`'s run ([`lpe_lint::check::run`]) over
//! files, returned as its JSON report (schema `lpe-lint/1`, docs/lint.md) for
//! `lpe/__init__.py` to wrap. A `pxr.Usd.Stage` comes as a [`StageReading`]: the facts
//! `lpe/__init__.py` collected by traversing it, as the USD reader's [`PrimReading`] said
//! which; the document is made from them by the USD reader's own [`document`]
//! ([`lint_stage_json`]), so the conventions (attribute names, `sourceType` spellings)
//! are written once. A renderer's profile (`renderer=`, `profile=`, or, with neither nor
//! `dialect=`, the one the stages name) gives the dialect and registration, and lint
//! checks its rules too.

use std::collections::BTreeSet;
use std::path::PathBuf;

use lpe::with_dialect;
use std::borrow::Cow;

use lpe_lint::check::renderer::named_by;
use lpe_lint::check::run::{check, read, read_by, Inputs, Request, RunError};
use lpe_lint::read::usd::{
    document, lint_reads, PrimFacts, PrimReading, StageFacts, READ_ATTRIBUTES,
};
use pyo3::prelude::*;
use pyo3::types::PyString;

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

/// What `lpe.lint(stage)` reads of a traversal of a composed stage, collected in the
/// order `lpe/__init__.py` queries pxr (`_stage_facts`): [`StageReading::new`] takes
/// every traversed prim's type name and authored property names and keeps what
/// [`PrimReading`] says lint reads; [`StageReading::wanted`] names the attributes whose
/// values to fetch; [`StageReading::complete`] takes those values, then the paths and
/// `orderedVars` of the prims that declare something (a few: RenderVars, RenderProducts,
/// RenderSettings, prims with `lpe:` attributes). Of the prims read for their values
/// only (every mesh of a shot may carry a group) nothing is kept but where each value
/// comes from and, once given, each distinct text ([`StageFacts::prims`] allows it).
#[pyclass(module = "lpe._lpe")]
pub struct StageReading {
    /// Every traversed prim's type name.
    types: BTreeSet<String>,
    /// The prims that declare something: traversal index and facts (path, name and
    /// values filled in by [`StageReading::complete`]).
    declaring: Vec<(usize, PrimFacts)>,
    /// Each value of the prims read for their values only: the prim's traversal index
    /// and the attribute's index in [`READ_ATTRIBUTES`].
    valued: Vec<(usize, usize)>,
    /// The facts, once [`StageReading::complete`] made them.
    facts: Option<StageFacts>,
}

/// One prim of a [`StageReading`] as `facts()` shows it: path, type name, property
/// names, `(attribute, text or None)` for the attributes lint reads, and a
/// RenderProduct's `orderedVars` target names.
type PrimTuple = (
    String,
    String,
    Vec<String>,
    Vec<(String, Option<String>)>,
    Vec<String>,
);

#[pymethods]
impl StageReading {
    /// `types` and `properties`: one item per traversed prim, in traversal order, its
    /// type name (`""` for none) and its authored property names.
    #[new]
    fn new(types: &Bound<'_, PyAny>, properties: &Bound<'_, PyAny>) -> PyResult<Self> {
        let mut reading = Self {
            types: BTreeSet::new(),
            declaring: Vec::new(),
            valued: Vec::new(),
            facts: None,
        };
        let (mut types, mut properties) = (types.try_iter()?, properties.try_iter()?);
        let mut names = Vec::new();
        for index in 0.. {
            let (type_name, properties) = match (types.next(), properties.next()) {
                (None, None) => break,
                (Some(t), Some(n)) => (t?, n?),
                _ => {
                    return Err(value_error(format!(
                        "a stage reading takes one type name and one list of property \
                         names per prim; one of them ended at prim {index}"
                    )))
                }
            };
            let type_name = type_name.downcast::<PyString>()?.to_str()?;
            if !reading.types.contains(type_name) {
                reading.types.insert(type_name.to_string());
            }
            names.clear();
            for n in properties.try_iter()? {
                names.push(n?.downcast_into::<PyString>()?);
            }
            let mut read = PrimReading::of_type(type_name);
            for n in &names {
                read = read.max(PrimReading::of_property(n.to_str()?));
            }
            match read {
                PrimReading::Nothing => {}
                PrimReading::Values => {
                    for n in &names {
                        // No `lpe:` name here (it would declare): a read one is one of these.
                        let n = n.to_str()?;
                        if let Some(a) = READ_ATTRIBUTES.iter().position(|a| *a == n) {
                            reading.valued.push((index, a));
                        }
                    }
                }
                PrimReading::Declarations => {
                    let mut prim = PrimFacts {
                        type_name: type_name.to_string(),
                        ..PrimFacts::default()
                    };
                    for n in &names {
                        let n = n.to_str()?;
                        if lint_reads(n) {
                            prim.values.push((n.to_string(), None));
                        }
                        prim.properties.push(n.to_string());
                    }
                    reading.declaring.push((index, prim));
                }
            }
        }
        Ok(reading)
    }

    /// The attributes whose values lint reads: the traversal index of each one's prim
    /// and its name, in the order [`StageReading::complete`] takes the values.
    fn wanted<'py>(&self, py: Python<'py>) -> (Vec<usize>, Vec<Bound<'py, PyString>>) {
        let mut at = Vec::new();
        let mut names = Vec::new();
        for (index, prim) in &self.declaring {
            for (name, _) in &prim.values {
                at.push(*index);
                names.push(PyString::new(py, name));
            }
        }
        // One Python string per attribute, however many prims carry it.
        let read = READ_ATTRIBUTES.map(|a| PyString::new(py, a));
        for &(index, a) in &self.valued {
            at.push(index);
            names.push(read[a].clone());
        }
        (at, names)
    }

    /// Makes the facts: `values`, one per [`StageReading::wanted`] attribute (a `str`,
    /// an object whose `path` is a `str` as an asset path's, or anything else: no text);
    /// `path_of(i)` and `ordered_vars_of(i)`, the path and the `orderedVars` target
    /// names of the traversal's prim `i`, are called for the prims that declare
    /// something (`ordered_vars_of` for RenderProducts only). A value that could not be
    /// fetched is a `ValueError` naming the prim and the attribute.
    fn complete(
        &mut self,
        values: &Bound<'_, PyAny>,
        path_of: &Bound<'_, PyAny>,
        ordered_vars_of: &Bound<'_, PyAny>,
    ) -> PyResult<()> {
        let mut values = values.try_iter()?;
        let mut fetched = 0;
        let mut next = |index: usize, name: &str| -> PyResult<Bound<'_, PyAny>> {
            let value = values.next().ok_or_else(|| {
                value_error(format!(
                    "fewer values ({fetched}) than attributes lint reads"
                ))
            })?;
            fetched += 1;
            value.map_err(|e| {
                let at = path_of
                    .call1((index,))
                    .and_then(|p| p.extract::<String>())
                    .unwrap_or_else(|_| format!("prim {index} of the traversal"));
                let err = value_error(format!("<{at}>.{name}: {e}"));
                err.set_cause(path_of.py(), Some(e));
                err
            })
        };
        let mut prims = Vec::with_capacity(self.declaring.len());
        for (index, prim) in &self.declaring {
            let mut prim = prim.clone();
            for (name, text) in &mut prim.values {
                *text = text_of(&next(*index, name)?);
            }
            prim.path = path_of.call1((*index,))?.extract()?;
            prim.name = prim.path.rsplit('/').next().unwrap_or_default().to_string();
            if prim.type_name == "RenderProduct" {
                prim.ordered_vars = ordered_vars_of.call1((*index,))?.extract()?;
            }
            prims.push(prim);
        }
        // The texts of the prims read for their values: each distinct one once.
        let mut texts = vec![BTreeSet::<String>::new(); READ_ATTRIBUTES.len()];
        for &(index, a) in &self.valued {
            let value = next(index, READ_ATTRIBUTES[a])?;
            if let Some(text) = as_str(&value) {
                if !texts[a].contains(text.as_ref()) {
                    texts[a].insert(text.into_owned());
                }
            }
        }
        if values.next().is_some() {
            return Err(value_error(format!(
                "more values than the {} attributes lint reads",
                self.declaring
                    .iter()
                    .map(|(_, p)| p.values.len())
                    .sum::<usize>()
                    + self.valued.len()
            )));
        }
        for (a, texts) in texts.into_iter().enumerate() {
            prims.extend(texts.into_iter().map(|text| PrimFacts {
                values: vec![(READ_ATTRIBUTES[a].to_string(), Some(text))],
                ..PrimFacts::default()
            }));
        }
        self.facts = Some(StageFacts {
            prims,
            types: self.types.clone(),
        });
        Ok(())
    }

    /// The facts, for tests (empty before [`StageReading::complete`]): each prim read
    /// as a `(path, type, property names, [(attribute, text)], orderedVars)` tuple (the
    /// prims that declare, in traversal order, then each distinct text of the others,
    /// with its attribute alone), and every traversed prim's type name once, sorted.
    fn facts(&self) -> (Vec<PrimTuple>, Vec<String>) {
        let Some(facts) = &self.facts else {
            return (Vec::new(), Vec::new());
        };
        let prims = facts.prims.iter().map(|p| {
            (
                p.path.clone(),
                p.type_name.clone(),
                p.properties.clone(),
                p.values.clone(),
                p.ordered_vars.clone(),
            )
        });
        (prims.collect(), facts.types.iter().cloned().collect())
    }
}

/// An attribute's value as lint reads it: a `str` (a string or token) or an asset
/// path's authored path (an object whose `path` is a `str`); `None` for any other value.
fn text_of(value: &Bound<'_, PyAny>) -> Option<String> {
    as_str(value).map(Cow::into_owned)
}

/// [`text_of`], borrowed where the value is a `str`.
fn as_str<'a>(value: &'a Bound<'_, PyAny>) -> Option<Cow<'a, str>> {
    if let Ok(s) = value.downcast::<PyString>() {
        return s.to_str().ok().map(Cow::Borrowed);
    }
    if value.is_none() {
        return None;
    }
    let path = value.getattr("path").ok()?;
    let path = path.downcast::<PyString>().ok()?;
    path.to_str().ok().map(|p| Cow::Owned(p.to_string()))
}

/// Lints a composed stage from what `lpe/__init__.py` read of it through pxr: `reading`
/// (a completed [`StageReading`]) and `name` (the file the findings name); the options
/// are [`lint_json`]'s.
#[pyfunction]
#[pyo3(signature = (reading, name, partitions = Vec::new(), universe = None, dialect = None, ini = None, register = None, renderer = None, profile = None))]
#[allow(clippy::too_many_arguments)]
pub fn lint_stage_json(
    py: Python<'_>,
    reading: PyRef<'_, StageReading>,
    name: String,
    partitions: Vec<String>,
    universe: Option<String>,
    dialect: Option<&str>,
    ini: Option<PathBuf>,
    register: Option<String>,
    renderer: Option<&str>,
    profile: Option<PathBuf>,
) -> PyResult<String> {
    let Some(facts) = &reading.facts else {
        return Err(value_error(
            "the stage reading is not complete: its values were not given",
        ));
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
    stage: Option<&StageFacts>,
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
    let inputs = py.allow_threads(|| match stage {
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
