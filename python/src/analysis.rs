//! `lpe.parse`, `lpe.equiv` and `lpe.partition`: one expression's canonical text, the
//! shortest path telling two expressions apart, a set of AOVs checked as a partition
//! of the universe. Witnesses are re-checked with the reference matcher
//! (`lpe_lint::witness`, the partition report of `lpe-check partition`) before they are
//! returned. Each is written once over [`PyDialect`] and dispatched on the dialect
//! `dialect=` or the renderer's profile (`renderer=`, `profile=`) names.

use std::path::PathBuf;

use lpe::analysis;
use lpe::with_dialect;
use lpe_lint::check::dialect::Lint;
use lpe_lint::check::partition::report;
use lpe_lint::witness::{recheck, Expect};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyString;

use crate::dialect::{self, Language, PyDialect};
use crate::error::{disagreement, value_error};

/// A parsed expression: its canonical text.
#[pyclass(module = "lpe", frozen, get_all)]
pub struct Lpe {
    /// The canonical text (macros expanded, as `lpe-check parse` prints it).
    pub text: String,
    /// The source as given.
    pub source: String,
    /// The name of the dialect it was read in (a renderer's base dialect).
    pub dialect: &'static str,
}

#[pymethods]
impl Lpe {
    fn __str__(&self) -> String {
        self.text.clone()
    }

    fn __repr__(&self) -> String {
        format!("<lpe.Lpe {:?} ({})>", self.text, self.dialect)
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .downcast::<Lpe>()
            .is_ok_and(|o| o.get().text == self.text && o.get().dialect == self.dialect)
    }

    fn __hash__(&self) -> u64 {
        use std::hash::{Hash, Hasher};
        let mut h = std::collections::hash_map::DefaultHasher::new();
        (&self.text, self.dialect).hash(&mut h);
        h.finish()
    }
}

/// Parses `expr` and returns it with its canonical text (`.text`, macros expanded).
/// `dialect` is "renderman" (the default) or "osl"; `renderer` a shipped profile's name
/// (`"karma"`, `"arnold"`, ...) or `profile` a profile TOML file: its base dialect, and
/// its letters, prefixes and built-in names registered. `ini` is a rendermn.ini file
/// (RenderMan macros and lobe mappings), `register` OSL's user labels
/// (`events=U;scatters=Y`). Raises `LpeSyntaxError` (`message`, `position`, `hint`;
/// `str()` shows a caret) when it does not parse, `ValueError` for a bad dialect,
/// renderer, profile, ini or registration, or a dialect other than the renderer's.
#[pyfunction]
#[pyo3(signature = (expr, dialect = None, ini = None, register = None, renderer = None, profile = None))]
pub fn parse(
    py: Python<'_>,
    expr: &str,
    dialect: Option<&str>,
    ini: Option<PathBuf>,
    register: Option<&str>,
    renderer: Option<&str>,
    profile: Option<PathBuf>,
) -> PyResult<Lpe> {
    let lang = Language::of(dialect, renderer, profile.as_deref())?;
    let text = with_dialect!(lang.dialect, D => {
        let reg = lang.registration::<D>(ini.as_ref(), register)?;
        dialect::parse::<D>(py, expr, &reg, None)?.to_string()
    });
    Ok(Lpe {
        text,
        source: expr.to_string(),
        dialect: lang.dialect.name(),
    })
}

/// What `equiv` and `partition` return when the analysis ran out of its budget
/// (`max_steps=`, `max_seconds=`) before deciding: not an answer, and not an error in
/// the input. Truthy, so `if lpe.equiv(a, b):` ("not proved equivalent") stays on the
/// safe side; test with `isinstance(r, lpe.Undecided)`.
#[pyclass(module = "lpe", frozen, get_all)]
pub struct Undecided {
    /// Why: the limit reached, as `lpe-check` prints it after `undecided: `.
    pub reason: String,
}

#[pymethods]
impl Undecided {
    fn __str__(&self) -> String {
        self.reason.clone()
    }

    fn __repr__(&self) -> String {
        format!("<lpe.Undecided {:?}>", self.reason)
    }

    fn __bool__(&self) -> bool {
        true
    }
}

impl Undecided {
    fn of(u: &analysis::Undecided) -> Undecided {
        Undecided {
            reason: u.to_string(),
        }
    }
}

/// The analysis budget from `max_steps=` and `max_seconds=`.
fn budget(
    max_steps: Option<usize>,
    max_seconds: Option<f64>,
) -> PyResult<analysis::AnalysisBudget> {
    let time = match max_seconds {
        None => None,
        Some(s) => Some(
            std::time::Duration::try_from_secs_f64(s)
                .map_err(|_| value_error("max_seconds must be a non-negative number"))?,
        ),
    };
    Ok(analysis::AnalysisBudget {
        steps: max_steps.unwrap_or(analysis::DEFAULT_STEPS),
        time,
    })
}

/// The answer of `equiv`: a witness (or `None`), or `Undecided`.
#[derive(IntoPyObject)]
pub enum EquivAnswer {
    /// `None` when equivalent, else a shortest path telling them apart.
    Decided(Option<String>),
    /// The budget ran out first.
    Undecided(Undecided),
}

/// `None` when expressions `a` and `b` match exactly the same paths, else the shortest
/// path (as text) one matches and the other does not, re-checked with the reference
/// matcher; an `Undecided` when the analysis did not decide within `max_steps` search
/// steps (default 4 000 000) or `max_seconds`. `dialect`, `renderer`, `profile`, `ini`
/// and `register` are `parse`'s. Raises `LpeSyntaxError` when either does not parse.
#[pyfunction]
#[pyo3(signature = (a, b, dialect = None, ini = None, register = None, max_steps = None, max_seconds = None, renderer = None, profile = None))]
#[allow(clippy::too_many_arguments)]
pub fn equiv(
    py: Python<'_>,
    a: &str,
    b: &str,
    dialect: Option<&str>,
    ini: Option<PathBuf>,
    register: Option<&str>,
    max_steps: Option<usize>,
    max_seconds: Option<f64>,
    renderer: Option<&str>,
    profile: Option<PathBuf>,
) -> PyResult<EquivAnswer> {
    let budget = budget(max_steps, max_seconds)?;
    let lang = Language::of(dialect, renderer, profile.as_deref())?;
    with_dialect!(lang.dialect, D => {
        let reg = lang.registration::<D>(ini.as_ref(), register)?;
        equiv_in::<D>(py, a, b, &reg, &budget)
    })
}

fn equiv_in<D: PyDialect>(
    py: Python<'_>,
    a: &str,
    b: &str,
    reg: &D::Registration,
    budget: &analysis::AnalysisBudget,
) -> PyResult<EquivAnswer> {
    let (ea, eb) = (
        dialect::parse::<D>(py, a, reg, None)?,
        dialect::parse::<D>(py, b, reg, None)?,
    );
    let c = match analysis::compare_within(&ea, &eb, budget).map_err(value_error)? {
        analysis::Decision::Decided(c) => c,
        analysis::Decision::Undecided(u) => return Ok(EquivAnswer::Undecided(Undecided::of(&u))),
    };
    let mut shortest: Option<D::Path> = None;
    for (path, in_a) in [(&c.first_only, true), (&c.second_only, false)] {
        let Some(p) = path else { continue };
        let expects = [
            Expect {
                name: a,
                lpe: &ea,
                matches: in_a,
            },
            Expect {
                name: b,
                lpe: &eb,
                matches: !in_a,
            },
        ];
        recheck(p, &expects).map_err(|d| disagreement(&d))?;
        if shortest
            .as_ref()
            .map_or(true, |s| D::vertices(p).len() < D::vertices(s).len())
        {
            shortest = Some(p.clone());
        }
    }
    Ok(EquivAnswer::Decided(shortest.map(|p| p.to_string())))
}

/// A partition check: overlaps, the gap, paths outside the universe, with witnesses.
#[pyclass(module = "lpe", frozen, get_all)]
pub struct Partition {
    /// The universe, canonical.
    pub universe: String,
    /// `(a, b, witness)` for every pair of members matching a common path.
    pub overlaps: Vec<(String, String, String)>,
    /// The shortest universe path no member matches (at most one), as a list.
    pub gaps: Vec<String>,
    /// `(member, witness)` for every member matching a path outside the universe.
    pub outside: Vec<(String, String)>,
    /// With a gap: an AOV expression matching exactly the missing paths, when it could
    /// be written and checked.
    pub remainder: Option<String>,
    /// No overlap, gap or path outside.
    pub clean: bool,
    /// The report `lpe-check partition` prints.
    pub text: String,
}

#[pymethods]
impl Partition {
    fn __str__(&self) -> String {
        self.text.clone()
    }

    fn __repr__(&self) -> String {
        format!(
            "<lpe.Partition clean={} overlaps={} gaps={} outside={}>",
            self.clean,
            self.overlaps.len(),
            self.gaps.len(),
            self.outside.len()
        )
    }

    fn __bool__(&self) -> bool {
        self.clean
    }

    /// The check as a notebook shows it: the explorer's table of findings (overlaps,
    /// the gap, paths outside) with their witnesses, and the remainder.
    fn _repr_html_(&self) -> String {
        use lpe_explore::partition::PartitionRow;
        let mut rows: Vec<PartitionRow> = self
            .overlaps
            .iter()
            .map(|(a, b, w)| PartitionRow {
                kind: "overlap",
                aovs: vec![a.clone(), b.clone()],
                witness: w.clone(),
            })
            .collect();
        rows.extend(self.gaps.iter().map(|w| PartitionRow {
            kind: "gap",
            aovs: Vec::new(),
            witness: w.clone(),
        }));
        rows.extend(self.outside.iter().map(|(a, w)| PartitionRow {
            kind: "outside",
            aovs: vec![a.clone()],
            witness: w.clone(),
        }));
        lpe_explore::html::partition(&self.universe, &rows, self.remainder.as_deref())
    }
}

/// The members of `partition`: a dict `{name: expr}`, or a list of expressions (each
/// named by its text) or `(name, expr)` pairs.
fn members(obj: &Bound<'_, PyAny>) -> PyResult<Vec<(String, String)>> {
    let bad = || {
        PyTypeError::new_err(
            "partition members are a dict {name: expression}, or a list of expressions or \
             (name, expression) pairs of str",
        )
    };
    if obj.is_instance_of::<PyString>() {
        return Err(bad());
    }
    let items = if obj.hasattr("items")? {
        obj.call_method0("items")?
    } else {
        obj.clone()
    };
    items
        .try_iter()
        .map_err(|_| bad())?
        .map(|i| {
            let i = i?;
            if let Ok(s) = i.extract::<String>() {
                return Ok((s.clone(), s));
            }
            i.extract::<(String, String)>().map_err(|_| bad())
        })
        .collect()
}

/// Checks that `members` (a dict `{name: expr}`, or a list of expressions or
/// `(name, expr)` pairs) split `universe` (default: the dialect's, `C.*[<L.>O]` or
/// `C<[RT][DGS]>*[LO]`) into disjoint parts covering it. Returns a `Partition`:
/// `overlaps` `(a, b, witness)`, `gaps` (the shortest uncovered path, at most one),
/// `outside` `(member, witness)`, `remainder` (an expression closing the gap), `clean`
/// and `text` (`lpe-check partition`'s report).
///
/// Returns an `Undecided` instead when the analysis did not decide within `max_steps`
/// search steps (default 4 000 000) or `max_seconds`. `dialect`, `renderer`, `profile`,
/// `ini` and `register` are `parse`'s.
#[pyfunction]
#[pyo3(signature = (members, universe = None, dialect = None, ini = None, register = None, max_steps = None, max_seconds = None, renderer = None, profile = None))]
#[allow(clippy::too_many_arguments)]
pub fn partition(
    py: Python<'_>,
    members: &Bound<'_, PyAny>,
    universe: Option<&str>,
    dialect: Option<&str>,
    ini: Option<PathBuf>,
    register: Option<&str>,
    max_steps: Option<usize>,
    max_seconds: Option<f64>,
    renderer: Option<&str>,
    profile: Option<PathBuf>,
) -> PyResult<PartitionAnswer> {
    let budget = budget(max_steps, max_seconds)?;
    let named = self::members(members)?;
    if named.is_empty() {
        return Err(value_error("partition needs at least one member"));
    }
    let lang = Language::of(dialect, renderer, profile.as_deref())?;
    with_dialect!(lang.dialect, D => {
        let reg = lang.registration::<D>(ini.as_ref(), register)?;
        partition_in::<D>(py, &named, universe, &reg, &budget)
    })
}

/// The answer of `partition`: the check, or `Undecided`.
#[derive(IntoPyObject)]
pub enum PartitionAnswer {
    /// Decided.
    Decided(Partition),
    /// The budget ran out first.
    Undecided(Undecided),
}

fn partition_in<D: PyDialect>(
    py: Python<'_>,
    named: &[(String, String)],
    universe: Option<&str>,
    reg: &D::Registration,
    budget: &analysis::AnalysisBudget,
) -> PyResult<PartitionAnswer> {
    let aovs = named
        .iter()
        .map(|(n, e)| Ok((n.clone(), dialect::parse::<D>(py, e, reg, Some(n))?)))
        .collect::<PyResult<Vec<_>>>()?;
    let universe = dialect::parse::<D>(py, universe.unwrap_or(D::DEFAULT_UNIVERSE), reg, None)?;
    let p = match analysis::partition_within(&aovs, &universe, reg, budget).map_err(value_error)? {
        analysis::Decision::Decided(p) => p,
        analysis::Decision::Undecided(u) => {
            return Ok(PartitionAnswer::Undecided(Undecided::of(&u)))
        }
    };
    let text = report(&aovs, &universe, &p).map_err(|d| disagreement(&d))?;
    let lobes = D::Lobes::default();
    let lint = Lint::<D> {
        registration: reg,
        lobes: &lobes,
        budget: lpe::analysis::AnalysisBudget::default(),
    };
    let name = |i: usize| aovs[i].0.clone();
    Ok(PartitionAnswer::Decided(Partition {
        universe: universe.to_string(),
        overlaps: p
            .overlaps
            .iter()
            .map(|(i, j, w)| (name(*i), name(*j), w.to_string()))
            .collect(),
        gaps: p.gap.iter().map(ToString::to_string).collect(),
        outside: p
            .outside
            .iter()
            .map(|(i, w)| (name(*i), w.to_string()))
            .collect(),
        remainder: p
            .gap
            .as_ref()
            .and_then(|_| lint.remainder(&aovs, &universe)),
        clean: p.is_clean(),
        text,
    }))
}
