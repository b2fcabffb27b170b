//! Each engine's answers on one path: what the comparison ([`super::check`](mod@super::check))
//! and the minimizer ([`super::minimize`](mod@super::minimize)) both ask.

use lpe::Dialect;

use crate::engine::{bits, Engine};

/// Each engine's answers (one per expression) on one path of `D`, or its build error.
pub fn answers_in<D: Dialect>(
    engines: &[&dyn Engine<D>],
    registration: &D::Registration,
    exprs: &[D::Lpe],
    path: &D::Path,
) -> Vec<(&'static str, Result<Vec<bool>, String>)> {
    engines
        .iter()
        .map(|e| {
            let answer = e
                .compile(exprs, registration)
                .map(|m| bits(m.which(path), exprs.len()))
                .map_err(|why| why.to_string());
            (e.name(), answer)
        })
        .collect()
}
