//! Equivalence and inclusion of two expressions, with shortest witnesses.

use super::search::{analysis_options, explore, explore_osl, AnalysisError};
use crate::aov::AovSet;
use crate::automata::mask::AovMask;
use crate::path::Path;
use crate::{osl, Lpe};

/// How two expressions relate: on paths (RenderMan), or on every vertex sequence (OSL,
/// whose paths have no fixed shape; witnesses are [`osl::Path`]s).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Comparison<P = Path> {
    /// A shortest path matched by the first and not the second.
    pub first_only: Option<P>,
    /// A shortest path matched by the second and not the first.
    pub second_only: Option<P>,
}

impl<P> Comparison<P> {
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
    differences(|visit| explore(&set, visit))
}

/// [`compare`] for two OSL expressions parsed under `registered`, on every sequence of
/// vertices.
///
/// ```
/// use lpe::analysis::compare_osl;
/// use lpe::osl::{parse, Registered};
///
/// let reg = Registered::none();
/// let c = compare_osl(
///     &parse("C<RD>[LO]", &reg).unwrap(),
///     &parse("(C<RD>L)|(C<RD>O)", &reg).unwrap(),
///     &reg,
/// )
/// .unwrap();
/// assert!(c.equivalent());
/// ```
pub fn compare_osl(
    a: &osl::Lpe,
    b: &osl::Lpe,
    registered: &osl::Registered,
) -> Result<Comparison<osl::Path>, AnalysisError> {
    let set = AovSet::compile_osl(
        &[("A".into(), a.clone()), ("B".into(), b.clone())],
        registered,
        &analysis_options(),
    )?;
    differences(|visit| explore_osl(&set, visit))
}

/// The first shortest witness each way, from a search over the set of `A` (AOV 0) and
/// `B` (AOV 1).
fn differences<P>(
    run: impl FnOnce(&mut dyn FnMut(AovMask, &dyn Fn() -> P) -> bool) -> Result<(), AnalysisError>,
) -> Result<Comparison<P>, AnalysisError> {
    let mut out = Comparison {
        first_only: None,
        second_only: None,
    };
    run(&mut |m, witness| {
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

    fn osl(s: &str) -> osl::Lpe {
        osl::parse(s, &osl::Registered::none()).unwrap()
    }

    fn cmp_osl(a: &str, b: &str) -> Comparison<osl::Path> {
        compare_osl(&osl(a), &osl(b), &osl::Registered::none()).unwrap()
    }

    #[test]
    fn osl_comparisons() {
        assert!(cmp_osl("C<RD>[LO]", "(C<RD>L)|(C<RD>O)").equivalent());
        assert!(cmp_osl("CD|GL", "C(D|G)L").equivalent());
        assert!(cmp_osl("C{0}L", "L").equivalent());
        // `|` takes one item each side: this is `C<RD>(L|C)<RD>O`. Witnesses are
        // shortest, built from each class's shortest vertex: NONE comes first, then
        // labels in byte order, so the camera is `C,~`.
        let c = cmp_osl("C<RD>[LO]", "C<RD>L|C<RD>O");
        assert_eq!(c.first_only.unwrap().to_string(), "C,~ R,D L,~");
        assert_eq!(c.second_only.unwrap().to_string(), "C,~ R,D C,~ R,D O,~");
        // The eater: `R` skips non-basic custom labels only.
        let c = cmp_osl("C<R.>L", "CRL");
        assert!(c.equivalent());
        let c = cmp_osl("C<R.'a'>L", "CRL");
        assert_eq!(c.first_only, None);
        assert_eq!(c.second_only.unwrap().to_string(), "C,~ R,~ L,~");
        // `.+L` needs two vertices; `.*L` does not.
        let c = cmp_osl(".+L", ".*L");
        assert_eq!(c.first_only, None);
        assert_eq!(c.second_only.unwrap().to_string(), "L,~");
    }
}
