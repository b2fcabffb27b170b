//! Running engines side by side and comparing their answers.

use lpe::renderman::{Lpe, Path};

use super::answers::answers_in;
use super::counterexample::Counterexample;
use super::language::{Language, RenderMan};
use super::minimize::minimize_in;
use crate::engine::Engine;
use crate::registry;

/// What agreeing engines found.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Agreement {
    /// Expression/path pairs compared.
    pub pairs: usize,
    /// Pairs that matched (by the agreed answer).
    pub matched: usize,
    /// Engines that could not build the set, with their reason.
    pub skipped: Vec<(&'static str, String)>,
    /// How many engines answered (built the set).
    pub engines: usize,
}

/// The result of a differential check.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome<L: Language = RenderMan> {
    /// All engines that could build agree on every path.
    Agree(Agreement),
    /// Two engines differ; minimized.
    Disagree(Box<Counterexample<L>>),
}

impl<L: Language> Outcome<L> {
    /// True for [`Outcome::Agree`].
    pub fn is_agreement(&self) -> bool {
        matches!(self, Outcome::Agree(_))
    }
}

/// Runs every engine on one expression.
pub fn check(expr: &Lpe, paths: &[Path]) -> Outcome {
    check_set(std::slice::from_ref(expr), paths)
}

/// Runs every engine on an AOV set compiled as one.
pub fn check_set(exprs: &[Lpe], paths: &[Path]) -> Outcome {
    check_with(&registry::all(), exprs, paths)
}

/// Runs the given engines on an AOV set compiled as one.
pub fn check_with(engines: &[&dyn Engine], exprs: &[Lpe], paths: &[Path]) -> Outcome {
    check_in(&RenderMan, engines, exprs, paths)
}

/// Runs the given engines on a set of `lang` expressions compiled as one.
pub fn check_in<L: Language>(
    lang: &L,
    engines: &[&dyn Engine],
    exprs: &[L::Expr],
    paths: &[L::Path],
) -> Outcome<L> {
    let mut built = Vec::new();
    let mut skipped = Vec::new();
    for e in engines {
        match lang.compile(*e, exprs) {
            Ok(m) => built.push((e.name(), m)),
            Err(why) => skipped.push((e.name(), why.to_string())),
        }
    }
    let mut agreement = Agreement {
        skipped,
        engines: built.len(),
        ..Agreement::default()
    };
    for path in paths {
        let answers: Vec<Vec<bool>> = built.iter().map(|(_, m)| m.which(path)).collect();
        if answers.windows(2).any(|w| w[0] != w[1]) {
            let original = (exprs.to_vec(), path.clone());
            let (exprs, path) = minimize_in(lang, engines, exprs.to_vec(), path.clone());
            return Outcome::Disagree(Box::new(Counterexample {
                answers: answers_in(lang, engines, &exprs, &path),
                lang: lang.clone(),
                exprs,
                path,
                original,
            }));
        }
        if let Some(first) = answers.first() {
            agreement.pairs += first.len();
            agreement.matched += first.iter().filter(|&&b| b).count();
        }
    }
    Outcome::Agree(agreement)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agreement_counts_pairs_and_matches() {
        let e = lpe::renderman::parse("C<RD>[<L.>O]").unwrap();
        let paths: Vec<Path> = ["C RD L", "C RS L", "C RD O'x'"]
            .iter()
            .map(|p| p.parse().unwrap())
            .collect();
        match check(&e, &paths) {
            Outcome::Agree(a) => {
                assert_eq!(a.pairs, 3);
                assert_eq!(a.matched, 2);
                assert!(a.skipped.is_empty());
                assert_eq!(a.engines, registry::all().len());
            }
            Outcome::Disagree(c) => panic!("{c}"),
        }
    }
}
