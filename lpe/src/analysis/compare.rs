//! Equivalence and inclusion of two expressions, with shortest witnesses.

use super::search::{analysis_options, explore, AnalysisError};
use crate::aov::AovSet;
use crate::path::Path;
use crate::Lpe;

/// How two expressions relate on paths.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Comparison {
    /// A shortest path matched by the first and not the second.
    pub first_only: Option<Path>,
    /// A shortest path matched by the second and not the first.
    pub second_only: Option<Path>,
}

impl Comparison {
    /// Both match the same paths.
    pub fn equivalent(&self) -> bool {
        self.first_only.is_none() && self.second_only.is_none()
    }
}

/// Compares two expressions on every path: equivalence, inclusion, and shortest
/// witnesses of the differences.
pub fn compare(a: &Lpe, b: &Lpe) -> Result<Comparison, AnalysisError> {
    let set = AovSet::compile_with(
        &[("A".into(), a.clone()), ("B".into(), b.clone())],
        &analysis_options(),
    )?;
    let mut out = Comparison {
        first_only: None,
        second_only: None,
    };
    explore(&set, |m, witness| {
        match (m.contains(0), m.contains(1)) {
            (true, false) if out.first_only.is_none() => out.first_only = Some(witness()),
            (false, true) if out.second_only.is_none() => out.second_only = Some(witness()),
            _ => {}
        }
        out.first_only.is_some() && out.second_only.is_some()
    })?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse;

    fn lpe(s: &str) -> Lpe {
        parse(s).unwrap()
    }

    #[test]
    fn comparisons() {
        let c = compare(&lpe("C.*L"), &lpe("C.*L")).unwrap();
        assert!(c.equivalent());
        let c = compare(&lpe("CD|(SD)L"), &lpe("C(D|(SD))L")).unwrap();
        assert!(c.equivalent());
        // `|` binds only its neighbours: `C(D|SD)L` is `C(D|S)DL`.
        let c = compare(&lpe("CD|(SD)L"), &lpe("C(D|SD)L")).unwrap();
        assert_eq!(c.first_only.unwrap().to_string(), "C RD1 L");
        assert_eq!(c.second_only.unwrap().to_string(), "C RD1 RD1 L");
        let c = compare(&lpe("C.+L"), &lpe("C.*L")).unwrap();
        assert_eq!(c.first_only, None);
        assert_eq!(c.second_only.unwrap().to_string(), "C L");
    }

    #[test]
    fn set_algebra_compares_by_its_paths() {
        let c = compare(&lpe("C.*L - C.*DL"), &lpe("C.*L & ^C.*DL")).unwrap();
        assert!(c.equivalent());
        // The universe of `^` is every path of the model: the complement of the
        // light-transport paths is the paths with a user-lobe vertex (`.` never matches
        // one), however many.
        let c = compare(&lpe("^C.*[<L.>O]"), &lpe("C(.|U)*U(.|U)*[<L.>O]")).unwrap();
        assert!(c.equivalent(), "{c:?}");
        let c = compare(&lpe("C.*L - C<RD>L"), &lpe("C.*L")).unwrap();
        assert_eq!(c.first_only, None);
        assert_eq!(c.second_only.unwrap().to_string(), "C RD1 L");
    }
}
