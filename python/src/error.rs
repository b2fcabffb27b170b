//! Python exceptions of Rust errors: [`LpeSyntaxError`] for an expression that does not
//! parse (its `message`, `position`, `hint`, `source` and `span` attributes, the caret
//! rendering as `str()`), `ValueError` for other bad values, `RuntimeError` for a
//! witness the reference matcher refused.

use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;

use lpe_lint::check::dialect::ParseFailure;
use lpe_lint::witness::Disagreement;

create_exception!(
    lpe,
    LpeSyntaxError,
    PyValueError,
    "An expression that does not parse: `message`, `position` (the character index in \
     `source`), `span` (start, end characters), `hint` (or None), `source`; `str()` is \
     the message with the expression and a caret."
);

/// The caret rendering of a parse failure: the message with its position, the source,
/// a caret under the span, and the hint.
pub fn render(f: &ParseFailure) -> String {
    let (start, end) = char_span(f);
    let shown: String = f
        .source
        .chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect();
    let mut s = format!(
        "{} (at character {start})\n  {shown}\n  {}{}",
        f.message,
        " ".repeat(start),
        "^".repeat((end - start).max(1))
    );
    if let Some(h) = &f.help {
        s.push_str(&format!("\n  hint: {h}"));
    }
    s
}

/// The span of a parse failure in characters of its source (Python string indices).
fn char_span(f: &ParseFailure) -> (usize, usize) {
    let at = |byte: usize| {
        f.source
            .get(..byte.min(f.source.len()))
            .map_or(byte, |s| s.chars().count())
    };
    (at(f.span.start), at(f.span.end))
}

/// `LpeSyntaxError` for a parse failure; `aov` names the AOV it belongs to, if any.
pub fn syntax_error(py: Python<'_>, f: &ParseFailure, aov: Option<&str>) -> PyErr {
    let rendering = match aov {
        Some(name) => format!("AOV `{name}`: {}", render(f)),
        None => render(f),
    };
    let err = LpeSyntaxError::new_err(rendering);
    let (start, end) = char_span(f);
    let value = err.value(py);
    let set = || -> PyResult<()> {
        value.setattr("message", &f.message)?;
        value.setattr("position", start)?;
        value.setattr("span", (start, end))?;
        value.setattr("hint", f.help.as_deref())?;
        value.setattr("source", &f.source)?;
        value.setattr("aov", aov)?;
        Ok(())
    };
    match set() {
        Ok(()) => err,
        Err(e) => e,
    }
}

/// `ValueError` with this message.
pub fn value_error(message: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(message.to_string())
}

/// `RuntimeError` for a witness the reference matcher refused: an engine bug.
pub fn disagreement(d: &Disagreement) -> PyErr {
    PyRuntimeError::new_err(d.to_string())
}
