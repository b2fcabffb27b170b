//! `lpe.AovSet`: named AOVs of one dialect compiled into one automaton, matched one
//! path at a time (`match`), in a batch (`match_many`, parsing and matching with the
//! GIL released), or explained vertex by vertex (`explain`, `lpe_lint::explain`); in a
//! notebook, drawn (`_repr_html_`, `lpe_explore::html`).
//! The set is generic over the dialect ([`Compiled`]); the Python class holds one of
//! any dialect behind [`AnySet`].

use std::borrow::Cow;
use std::collections::HashMap;
use std::path::PathBuf;

use lpe::{with_dialect, AovMask, Options};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyList, PyString, PyTuple};

use crate::dialect::{self, Language, PyDialect};
use crate::error::value_error;

/// A compiled set of dialect `D`, with its AOVs and registration (for `explain`).
pub struct Compiled<D: PyDialect> {
    set: lpe::AovSet<D>,
    aovs: Vec<(String, D::Lpe)>,
    registration: D::Registration,
}

impl<D: PyDialect> Compiled<D> {
    fn new(
        py: Python<'_>,
        named: &[(String, String)],
        registration: D::Registration,
    ) -> PyResult<Compiled<D>> {
        let aovs = named
            .iter()
            .map(|(n, e)| {
                Ok((
                    n.clone(),
                    dialect::parse::<D>(py, e, &registration, Some(n))?,
                ))
            })
            .collect::<PyResult<Vec<_>>>()?;
        let set = lpe::AovSet::<D>::compile_under(&aovs, &registration, &Options::default())
            .map_err(value_error)?;
        Ok(Compiled {
            set,
            aovs,
            registration,
        })
    }
}

/// Parses and matches every path of `texts`, on as many threads as there are cores for
/// a long list (the answers in order).
fn match_all<D: PyDialect>(
    set: &lpe::AovSet<D>,
    texts: &[Cow<'_, str>],
) -> Vec<Result<AovMask, String>> {
    let one = |t: &Cow<'_, str>| dialect::parse_path::<D>(t).map(|p| set.match_path(&p));
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get().min(8));
    if threads == 1 || texts.len() < 4096 {
        return texts.iter().map(one).collect();
    }
    let chunk = texts.len().div_ceil(threads);
    std::thread::scope(|scope| {
        let workers: Vec<_> = texts
            .chunks(chunk)
            .map(|part| scope.spawn(move || part.iter().map(one).collect::<Vec<_>>()))
            .collect();
        workers
            .into_iter()
            .flat_map(|w| w.join().unwrap_or_else(|e| std::panic::resume_unwind(e)))
            .collect()
    })
}

/// A compiled set of any dialect: what `AovSet` asks of its [`Compiled`].
///
/// A trait object, because a Python class cannot be generic: `AovSet` holds a
/// `Compiled<D>` whose `D` is a run-time choice. That choice is made once, in
/// `AovSet.__new__`, by `lpe::registry` (`DialectName` from the `dialect=` name or the
/// renderer's base dialect, `with_dialect!` to the type), the one place names map to
/// types; nothing here names a dialect, so a new one needs no change to this file.
trait AnySet: Send + Sync {
    /// The AOV names, in order.
    fn names(&self) -> &[String];
    /// The number of AOVs.
    fn len(&self) -> usize;
    /// `AovSet.match`: the names of the AOVs one path lands in.
    fn match_one(&self, path: &Bound<'_, PyAny>) -> PyResult<Vec<String>>;
    /// `AovSet.match_many`: one tuple of names per path.
    fn match_many<'py>(
        &self,
        py: Python<'py>,
        paths: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyList>>;
    /// `AovSet.explain`: how one path went through the set.
    fn explain(&self, path: &Bound<'_, PyAny>) -> PyResult<Explanation>;
    /// `AovSet._repr_html_`: the explorer's drawing and table of the set.
    fn html(&self) -> String;
}

impl<D: PyDialect> AnySet for Compiled<D>
where
    Compiled<D>: Send + Sync,
{
    fn names(&self) -> &[String] {
        self.set.names()
    }

    fn len(&self) -> usize {
        self.set.len()
    }

    fn match_one(&self, path: &Bound<'_, PyAny>) -> PyResult<Vec<String>> {
        let p = dialect::path::<D>(path)?;
        Ok(names_in(self.set.names(), self.set.match_path(&p)))
    }

    fn match_many<'py>(
        &self,
        py: Python<'py>,
        paths: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyList>> {
        let items = paths
            .try_iter()
            .map_err(|_| PyTypeError::new_err("match_many takes an iterable of paths"))?
            .collect::<PyResult<Vec<Bound<'py, PyAny>>>>()?;
        // Text paths are borrowed from their Python strings; tuple paths are written out.
        let texts = items
            .iter()
            .map(|p| match p.downcast::<PyString>() {
                Ok(s) => s.to_str().map(Cow::Borrowed),
                Err(_) => dialect::path_text::<D>(p).map(Cow::Owned),
            })
            .collect::<PyResult<Vec<Cow<'_, str>>>>()?;
        let set = &self.set;
        let masks = py.allow_threads(|| match_all::<D>(set, &texts));
        // Equal answers share one tuple of interned names.
        let names: Vec<Bound<'py, PyString>> =
            set.names().iter().map(|n| PyString::new(py, n)).collect();
        let mut answers: HashMap<AovMask, Bound<'py, PyTuple>> = HashMap::new();
        let mut out = Vec::with_capacity(masks.len());
        for (i, m) in masks.into_iter().enumerate() {
            let m = m.map_err(|e| value_error(format!("paths[{i}]: {e}")))?;
            let answer = match answers.get(&m) {
                Some(t) => t.clone(),
                None => {
                    let landed: Vec<&Bound<'py, PyString>> = m.iter().map(|k| &names[k]).collect();
                    let t = PyTuple::new(py, landed)?;
                    answers.insert(m, t.clone());
                    t
                }
            };
            out.push(answer);
        }
        PyList::new(py, out)
    }

    fn explain(&self, path: &Bound<'_, PyAny>) -> PyResult<Explanation> {
        let p = dialect::path::<D>(path)?;
        let e = lpe_lint::explain::explain::<D>(&self.aovs, &self.registration, &p)
            .map_err(value_error)?;
        Ok(Explanation {
            landed: e.landed.iter().map(|&i| self.aovs[i].0.clone()).collect(),
            text: e.text,
        })
    }

    fn html(&self) -> String {
        lpe_explore::html::aov_set(&self.set)
    }
}

/// The names of the AOVs in `mask`, in set order.
fn names_in(names: &[String], mask: AovMask) -> Vec<String> {
    mask.iter().map(|i| names[i].clone()).collect()
}

/// Named AOVs (a dict `{name: expr}` or a list of `(name, expr)` pairs) of one dialect
/// compiled into one automaton. A path is text (`"C RD2'floor' L'key'"`, OSL:
/// `"C,_ R,D L,_"`) or a list of `(type, event, label)` tuples (event and label may be
/// None). `dialect`, `renderer`, `profile`, `ini` and `register` are `parse`'s: a
/// renderer's set reads its letters and built-in names (`renderer="karma"`: `A`).
/// Raises `LpeSyntaxError` (with `.aov`) for an AOV that does not parse.
#[pyclass(module = "lpe", frozen)]
pub struct AovSet {
    inner: Box<dyn AnySet>,
    dialect: &'static str,
}

/// The `(name, expression)` pairs of a mapping or a sequence of pairs.
fn named_pairs(aovs: &Bound<'_, PyAny>) -> PyResult<Vec<(String, String)>> {
    let items = if aovs.hasattr("items")? {
        aovs.call_method0("items")?
    } else {
        aovs.clone()
    };
    let bad = || {
        PyTypeError::new_err(
            "AovSet takes a dict {name: expression} or a list of (name, expression) pairs of str",
        )
    };
    if items.is_instance_of::<PyString>() {
        return Err(bad());
    }
    items
        .try_iter()
        .map_err(|_| bad())?
        .map(|i| i?.extract::<(String, String)>().map_err(|_| bad()))
        .collect()
}

#[pymethods]
impl AovSet {
    #[new]
    #[pyo3(signature = (aovs, dialect = None, ini = None, register = None, renderer = None, profile = None))]
    fn new(
        py: Python<'_>,
        aovs: &Bound<'_, PyAny>,
        dialect: Option<&str>,
        ini: Option<PathBuf>,
        register: Option<&str>,
        renderer: Option<&str>,
        profile: Option<PathBuf>,
    ) -> PyResult<AovSet> {
        let named = named_pairs(aovs)?;
        let lang = Language::of(dialect, renderer, profile.as_deref())?;
        let inner = with_dialect!(lang.dialect, D => {
            let reg = lang.registration::<D>(ini.as_ref(), register)?;
            Box::new(Compiled::<D>::new(py, &named, reg)?) as Box<dyn AnySet>
        });
        Ok(AovSet {
            inner,
            dialect: lang.dialect.name(),
        })
    }

    /// The AOV names, in order.
    #[getter]
    fn names(&self) -> Vec<String> {
        self.inner.names().to_vec()
    }

    /// The name of the dialect the AOVs were read in (a renderer's base dialect).
    #[getter]
    fn dialect(&self) -> &'static str {
        self.dialect
    }

    fn __len__(&self) -> usize {
        self.inner.len()
    }

    fn __repr__(&self) -> String {
        format!("<lpe.AovSet {} AOVs ({})>", self.__len__(), self.dialect)
    }

    /// The names of the AOVs `path` lands in, in set order. Raises `ValueError` for a
    /// path that is not one of the dialect, `TypeError` for a value that is no path.
    #[pyo3(name = "match")]
    fn match_(&self, path: &Bound<'_, PyAny>) -> PyResult<Vec<String>> {
        self.inner.match_one(path)
    }

    /// `match` of every path of the iterable `paths`, one tuple of names per path (equal
    /// answers share one tuple): the batch form. The paths are parsed and matched with
    /// the GIL released, on every core for a long list. A bad path raises `ValueError`
    /// naming its index.
    fn match_many<'py>(
        &self,
        py: Python<'py>,
        paths: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyList>> {
        self.inner.match_many(py, paths)
    }

    /// How `path` went through the set, vertex by vertex (`lpe-check explain`'s report).
    fn explain(&self, path: &Bound<'_, PyAny>) -> PyResult<Explanation> {
        self.inner.explain(path)
    }

    /// The set as a notebook shows it: the drawing of its automaton (SVG, states `sN`,
    /// edges `eA-B`) and a table of its AOVs, as the explorer (`lpe-check serve`) draws
    /// them; the GIL is released while the layout runs.
    fn _repr_html_(&self, py: Python<'_>) -> String {
        let inner = &self.inner;
        py.allow_threads(|| inner.html())
    }
}

/// What `AovSet.explain` found.
#[pyclass(module = "lpe", frozen, get_all)]
pub struct Explanation {
    /// The AOVs the whole path lands in.
    pub landed: Vec<String>,
    /// The report, one row per vertex (as `lpe-check explain` prints it).
    pub text: String,
}

#[pymethods]
impl Explanation {
    fn __str__(&self) -> String {
        self.text.clone()
    }

    fn __repr__(&self) -> String {
        format!("<lpe.Explanation landed={:?}>", self.landed)
    }
}
