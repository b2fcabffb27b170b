//! Equivalence and inclusion of two expressions, with shortest witnesses.

use super::budget::{AnalysisBudget, Decision, Meter, Undecided};
use super::problem::Problem;
use super::search::{analysis_options, explore_metered, AnalysisError};
use crate::algebra::Algebra;
use crate::aov::AovSet;
use crate::automata::mask::AovMask;
use crate::dialect::{Dialect, DialectLpe};

/// How two expressions relate, with witnesses of dialect paths `P`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Comparison<P> {
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

/// Compares two expressions of one dialect on every path of its path model (OSL's: every
/// sequence of vertices): equivalence, inclusion, and shortest witnesses of the
/// differences. [`compare_within`] with the default [`AnalysisBudget`]; past it, the
/// error [`AnalysisError::TooLarge`] (use [`compare_within`] to tell an undecided
/// question from a failed compile).
///
/// ```
/// use lpe::analysis::compare;
/// use lpe::osl::{parse, Registered};
///
/// let reg = Registered::none();
/// let c = compare(
///     &parse("C<RD>[LO]", &reg).unwrap(),
///     &parse("(C<RD>L)|(C<RD>O)", &reg).unwrap(),
/// )
/// .unwrap();
/// assert!(c.equivalent());
/// ```
pub fn compare<D, L>(a: &L, b: &L) -> Result<Comparison<D::Path>, AnalysisError>
where
    L: DialectLpe<Dialect = D>,
    D: Dialect<Lpe = L>,
{
    let budget = AnalysisBudget::default();
    match compare_in::<D>(a, b, &budget)? {
        Decision::Decided(c) => Ok(c),
        Decision::Undecided(_) => Err(AnalysisError::TooLarge(budget.steps)),
    }
}

/// [`compare`] within `budget`: [`Decision::Undecided`] when it runs out first.
///
/// Plain expressions and set algebra whose questions have few conjuncts are decided on
/// the NFA of both, without determinizing either (module `antichain`): `C.*D.{k}L`
/// against `C.*D.{k}[LO]` in `O(k^2)` nodes, where their DFAs have `2^k` states. That
/// route gets half the budget; other set algebra, and what it leaves undecided, goes to
/// a breadth-first search of the lazy DFA of both ([`compare_by_lazy_dfa`]) on the rest.
/// Either way the witnesses are the first shortest paths in the order of the set's
/// vertex classes.
///
/// ```
/// use lpe::analysis::{compare_within, AnalysisBudget, Decision};
/// use lpe::renderman::parse;
///
/// let (a, b) = (parse("C.*D.{24}L").unwrap(), parse("C.*D.{24}[LO]").unwrap());
/// let Decision::Decided(c) = compare_within(&a, &b, &AnalysisBudget::default()).unwrap() else {
///     panic!("undecided")
/// };
/// assert_eq!((c.first_only, c.second_only.map(|p| p.len())), (None, Some(27)));
/// // A budget of 10 search steps is not enough.
/// let tiny = compare_within(&a, &b, &AnalysisBudget::steps(10)).unwrap();
/// assert!(matches!(tiny, Decision::Undecided(_)));
/// ```
pub fn compare_within<D, L>(
    a: &L,
    b: &L,
    budget: &AnalysisBudget,
) -> Result<Decision<Comparison<D::Path>>, AnalysisError>
where
    L: DialectLpe<Dialect = D>,
    D: Dialect<Lpe = L>,
{
    compare_in::<D>(a, b, budget)
}

/// [`compare_within`] on the lazy DFA of both expressions alone: a breadth-first search
/// over its states, one budget step per state. Exponential on `C.*D.{k}L` against
/// `C.*D.{k}[LO]`; kept as the independent oracle the NFA route is tested against and as
/// the baseline of `lpe-check bench --analysis`. It shares with the NFA route the
/// parsed trees, the vertex classes and the letters' order, not the search.
pub fn compare_by_lazy_dfa<D, L>(
    a: &L,
    b: &L,
    budget: &AnalysisBudget,
) -> Result<Decision<Comparison<D::Path>>, AnalysisError>
where
    L: DialectLpe<Dialect = D>,
    D: Dialect<Lpe = L>,
{
    let mut meter = Meter::new(budget);
    by_lazy_dfa::<D>(&both::<D>(a, b), &mut meter)
}

/// The set a comparison compiles: `A`, then `B`.
fn both<D: Dialect>(a: &D::Lpe, b: &D::Lpe) -> [(String, D::Lpe); 2] {
    [("A".to_string(), a.clone()), ("B".to_string(), b.clone())]
}

fn by_lazy_dfa<D: Dialect>(
    aovs: &[(String, D::Lpe)],
    meter: &mut Meter,
) -> Result<Decision<Comparison<D::Path>>, AnalysisError> {
    let set = AovSet::<D>::compile_under(aovs, &D::Registration::default(), &analysis_options())?;
    Ok(decided(differences(|visit| {
        explore_metered(&set, meter, visit)
    })))
}

fn decided<T>(r: Result<T, Undecided>) -> Decision<T> {
    match r {
        Ok(t) => Decision::Decided(t),
        Err(u) => Decision::Undecided(u),
    }
}

/// [`compare_within`] with the dialect named (the expressions' bounds are the dialect's).
fn compare_in<D: Dialect>(
    a: &D::Lpe,
    b: &D::Lpe,
    budget: &AnalysisBudget,
) -> Result<Decision<Comparison<D::Path>>, AnalysisError> {
    let aovs = both::<D>(a, b);
    let mut meter = Meter::new(budget);
    let problem = Problem::<D>::new(&aovs, &analysis_options())?;
    let (fa, fb) = (&problem.formulas[0], &problem.formulas[1]);
    let only = |x: &Algebra<usize>, y: &Algebra<usize>| {
        Algebra::and(x.clone(), Algebra::complement(y.clone()))
    };
    // Half the budget for the NFA route: where its antichains grow as large as the DFA
    // (`C.*D.{k}L` against `(C.*D.{k}L)|(C.*S.{k}L)`, 2^k incomparable subsets), the
    // lazy-DFA route, which compares no subsets, gets the rest.
    let mut nfa_meter = meter.share(meter.left() / 2);
    let witnesses = problem
        .witness(&only(fa, fb), &mut nfa_meter)
        .and_then(|first| Ok((first, problem.witness(&only(fb, fa), &mut nfa_meter)?)));
    meter.absorb(&nfa_meter);
    match witnesses {
        Ok((first_only, second_only)) => Ok(Decision::Decided(Comparison {
            first_only,
            second_only,
        })),
        Err(_) => by_lazy_dfa::<D>(&aovs, &mut meter),
    }
}

/// The first shortest witness each way, from a search over the set of `A` (AOV 0) and
/// `B` (AOV 1).
fn differences<P>(
    run: impl FnOnce(&mut dyn FnMut(AovMask, &dyn Fn() -> P) -> bool) -> Result<(), Undecided>,
) -> Result<Comparison<P>, Undecided> {
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
    use crate::osl;
    use crate::renderman::{parse, Lpe};

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

    fn osl(s: &str) -> osl::Lpe {
        osl::parse(s, &osl::Registered::none()).unwrap()
    }

    fn compare_in_the_osl_dialect(a: &str, b: &str) -> Comparison<osl::Path> {
        compare(&osl(a), &osl(b)).unwrap()
    }

    #[test]
    fn comparisons_in_the_osl_dialect() {
        assert!(compare_in_the_osl_dialect("C<RD>[LO]", "(C<RD>L)|(C<RD>O)").equivalent());
        assert!(compare_in_the_osl_dialect("CD|GL", "C(D|G)L").equivalent());
        assert!(compare_in_the_osl_dialect("C{0}L", "L").equivalent());
        // `|` takes one item each side: this is `C<RD>(L|C)<RD>O`. Witnesses are
        // shortest, built from each class's shortest vertex: NONE comes first, then
        // labels in byte order, so the camera is `C,~`.
        let c = compare_in_the_osl_dialect("C<RD>[LO]", "C<RD>L|C<RD>O");
        assert_eq!(c.first_only.unwrap().to_string(), "C,~ R,D L,~");
        assert_eq!(c.second_only.unwrap().to_string(), "C,~ R,D C,~ R,D O,~");
        // The eater: `R` skips non-basic custom labels only.
        let c = compare_in_the_osl_dialect("C<R.>L", "CRL");
        assert!(c.equivalent());
        let c = compare_in_the_osl_dialect("C<R.'a'>L", "CRL");
        assert_eq!(c.first_only, None);
        assert_eq!(c.second_only.unwrap().to_string(), "C,~ R,~ L,~");
        // `.+L` needs two vertices; `.*L` does not.
        let c = compare_in_the_osl_dialect(".+L", ".*L");
        assert_eq!(c.first_only, None);
        assert_eq!(c.second_only.unwrap().to_string(), "L,~");
    }
}
