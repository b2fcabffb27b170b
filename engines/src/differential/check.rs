//! Running engines side by side and comparing their answers.

use lpe::{Dialect, DialectLpe};

use super::answers::answers_in;
use super::counterexample::Counterexample;
use super::minimize::minimize_in;
use crate::dialect::{EngineDialect, ShrinkDialect};
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
#[derive(Clone, Debug)]
pub enum Outcome<D: Dialect> {
    /// All engines that could build agree on every path.
    Agree(Agreement),
    /// Two engines differ; minimized.
    Disagree(Box<Counterexample<D>>),
}

impl<D: Dialect> Outcome<D> {
    /// True for [`Outcome::Agree`].
    pub fn is_agreement(&self) -> bool {
        matches!(self, Outcome::Agree(_))
    }
}

/// The path type of an expression's dialect.
type PathOf<L> = <<L as DialectLpe>::Dialect as Dialect>::Path;

/// Runs every engine on one expression (its dialect's default registration).
pub fn check<L>(expr: &L, paths: &[PathOf<L>]) -> Outcome<L::Dialect>
where
    L: DialectLpe,
    L::Dialect: EngineDialect,
{
    check_set(std::slice::from_ref(expr), paths)
}

/// Runs every engine on an AOV set compiled as one (its dialect's default
/// registration).
pub fn check_set<L>(exprs: &[L], paths: &[PathOf<L>]) -> Outcome<L::Dialect>
where
    L: DialectLpe,
    L::Dialect: EngineDialect,
{
    check_with(&registry::all::<L::Dialect>(), exprs, paths)
}

/// Runs the given engines on an AOV set compiled as one, under the dialect's default
/// registration.
pub fn check_with<D: ShrinkDialect>(
    engines: &[&dyn Engine<D>],
    exprs: &[D::Lpe],
    paths: &[D::Path],
) -> Outcome<D> {
    check_in(engines, &D::Registration::default(), exprs, paths)
}

/// Runs the given engines on a set of expressions parsed under `registration`,
/// compiled as one.
pub fn check_in<D: ShrinkDialect>(
    engines: &[&dyn Engine<D>],
    registration: &D::Registration,
    exprs: &[D::Lpe],
    paths: &[D::Path],
) -> Outcome<D> {
    let mut built = Vec::new();
    let mut skipped = Vec::new();
    for e in engines {
        match e.compile(exprs, registration) {
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
        let answers: Vec<lpe::AovMask> = built.iter().map(|(_, m)| m.which(path)).collect();
        if answers.windows(2).any(|w| w[0] != w[1]) {
            let original = (exprs.to_vec(), path.clone());
            let (exprs, path) = minimize_in(engines, registration, exprs.to_vec(), path.clone());
            return Outcome::Disagree(Box::new(Counterexample {
                answers: answers_in(engines, registration, &exprs, &path),
                registration: registration.clone(),
                exprs,
                path,
                original,
            }));
        }
        if let Some(first) = answers.first() {
            agreement.pairs += exprs.len();
            agreement.matched += first.count();
        }
    }
    Outcome::Agree(agreement)
}

#[cfg(test)]
mod tests {
    use super::*;
    use lpe::renderman::{Path, RenderMan};

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
                assert_eq!(a.engines, registry::all::<RenderMan>().len());
            }
            Outcome::Disagree(c) => panic!("{c}"),
        }
    }
}
