//! # lpe-python — the native module `lpe._lpe` of the Python package `lpe`
//!
//! Thin over the Rust library: every function parses its arguments, calls `lpe`
//! (parsing, [`lpe::AovSet`], [`lpe::analysis`]) or `lpe-lint` (the lint run, `explain`,
//! the partition report, the reference re-check of witnesses) and converts the answer.
//! The Python sources (`python/python/lpe/`) wrap it: `__init__.py` (the public API and
//! its docstrings), `__init__.pyi` (the stubs), `usd_validation.py` (the UsdValidation
//! plugin, declared in `plugInfo.json`). docs/python.md documents both.
//!
//! Modules: [`dialect`] (what a dialect must say to Python: [`dialect::PyDialect`],
//! implemented once per dialect; the argument conversions written once over it, the
//! dialect and renderer's profile of `dialect=`, `renderer=` and `profile=` among them),
//! [`error`] (`LpeSyntaxError` and the conversion of every Rust error into a Python
//! exception), [`set`] (`AovSet`: match, match_many, explain), [`analysis`] (`parse`,
//! `equiv`, `partition`), [`lint`] (`lpe-check lint`'s run, as JSON, over files or the
//! facts of a composed stage, collected in a `StageReading`).
//!
//! Every fallible call returns a Python exception: bad arguments raise `TypeError` or
//! `ValueError`, an expression that does not parse raises `LpeSyntaxError` (a
//! `ValueError`), an analysis witness the reference matcher refuses raises
//! `RuntimeError`. Nothing here panics on any input.

use pyo3::prelude::*;

pub mod analysis;
pub mod dialect;
pub mod error;
pub mod lint;
pub mod set;

/// The native module; `lpe/__init__.py` re-exports it.
#[pymodule]
fn _lpe(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("LpeSyntaxError", m.py().get_type::<error::LpeSyntaxError>())?;
    m.add_class::<analysis::Lpe>()?;
    m.add_class::<analysis::Partition>()?;
    m.add_class::<analysis::Undecided>()?;
    m.add_class::<set::AovSet>()?;
    m.add_class::<set::Explanation>()?;
    m.add_function(wrap_pyfunction!(analysis::parse, m)?)?;
    m.add_function(wrap_pyfunction!(analysis::equiv, m)?)?;
    m.add_function(wrap_pyfunction!(analysis::partition, m)?)?;
    m.add_function(wrap_pyfunction!(lint::lint_json, m)?)?;
    m.add_function(wrap_pyfunction!(lint::lint_stage_json, m)?)?;
    m.add_class::<lint::StageReading>()?;
    // The relationship `lpe.lint(stage)` asks a RenderProduct for.
    m.add("USD_ORDERED_VARS", lpe_lint::read::usd::ORDERED_VARS)?;
    m.add("DIALECTS", lpe::DialectName::ALL.map(|d| d.name()).to_vec())?;
    Ok(())
}
