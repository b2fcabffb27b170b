//! Each engine's answers on one path: what the comparison ([`super::check`](mod@super::check))
//! and the minimizer ([`super::minimize`](mod@super::minimize)) both ask.

use lpe::renderman::{Lpe, Path};

use super::language::{Language, RenderMan};
use crate::engine::Engine;

/// Each engine's answers on one path, or its build error.
pub fn answers_of(
    engines: &[&dyn Engine],
    exprs: &[Lpe],
    path: &Path,
) -> Vec<(&'static str, Result<Vec<bool>, String>)> {
    answers_in(&RenderMan, engines, exprs, path)
}

/// Each engine's answers on one path of `lang`, or its build error.
pub fn answers_in<L: Language>(
    lang: &L,
    engines: &[&dyn Engine],
    exprs: &[L::Expr],
    path: &L::Path,
) -> Vec<(&'static str, Result<Vec<bool>, String>)> {
    engines
        .iter()
        .map(|e| {
            let answer = lang
                .compile(*e, exprs)
                .map(|m| m.which(path))
                .map_err(|why| why.to_string());
            (e.name(), answer)
        })
        .collect()
}
