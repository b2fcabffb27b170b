//! Emptiness of set-algebra AOVs. The NFA-only search of the automata layer answers for
//! plain AOVs; whether `A - B` or `A & B` leaves any path needs the two operands'
//! positions together: the antichain search of the NFA route (runs of the operands that
//! must match, a subset of those that must not), or a search of the compiled set's own
//! states for set algebra of many conjuncts.

use super::budget::{AnalysisBudget, Meter, Undecided};
use super::problem::{Problem, Stop};
use super::search::{analysis_options, explore_metered};
use crate::algebra::SetExpr;
use crate::aov::AovSet;
use crate::automata::emptiness::Warning;
use crate::automata::mask::AovMask;
use crate::dialect::Dialect;

/// Search steps [`warnings`] may take; past them no warning is given for the AOVs with
/// set algebra not yet decided (a warning is advice, not a verdict).
const WARNING_STEPS: usize = 200_000;

/// Every AOV of `set` that can match no path, with the reason: [`AovSet::warnings`] for
/// the plain AOVs, and for the AOVs with set algebra a search (none reported for those
/// not decided within 200 000 search steps; [`warnings_within`] says which).
pub fn warnings<D: Dialect>(set: &AovSet<D>) -> Vec<Warning> {
    warnings_within(set, &AnalysisBudget::steps(WARNING_STEPS)).0
}

/// [`warnings`] within `budget`, with [`Undecided`] when the budget ran out before every
/// AOV with set algebra was decided (those not decided get no warning).
pub fn warnings_within<D: Dialect>(
    set: &AovSet<D>,
    budget: &AnalysisBudget,
) -> (Vec<Warning>, Option<Undecided>) {
    let mut out = set.warnings().to_vec();
    let (empty, undecided) = algebra_warnings(set, &mut Meter::new(budget));
    out.extend(empty);
    out.sort_by_key(|w| w.aov);
    (out, undecided)
}

/// Warnings for the AOVs with set algebra that match no path of the path model (for an
/// OSL set: no non-empty sequence of vertices): one NFA search per AOV, or for set
/// algebra with many conjuncts one search of the set's states.
fn algebra_warnings<D: Dialect>(
    set: &AovSet<D>,
    meter: &mut Meter,
) -> (Vec<Warning>, Option<Undecided>) {
    let algebra: Vec<usize> = (0..set.len())
        .filter(|&i| set.lpes()[i].algebra().is_some())
        .collect();
    if algebra.is_empty() {
        return (Vec::new(), None);
    }
    let aovs: Vec<(String, D::Lpe)> = set
        .names()
        .iter()
        .cloned()
        .zip(set.lpes().iter().cloned())
        .collect();
    let mut empty = Vec::new();
    let decided = match Problem::<D>::new(&aovs, &analysis_options()) {
        Ok(problem) => algebra.iter().try_for_each(|&i| {
            if !problem.nonempty(&problem.formulas[i], meter)? {
                empty.push(i);
            }
            Ok(())
        }),
        // It compiled as a set: its operands compile as an NFA.
        Err(_) => Err(Stop::TooManyConjuncts),
    };
    let undecided = match decided {
        Ok(()) => None,
        Err(Stop::Undecided(u)) => Some(u),
        Err(Stop::TooManyConjuncts) => {
            empty.clear();
            let mut seen = AovMask::EMPTY;
            let mut visit = |m: AovMask| {
                seen = m.iter().chain(seen.iter()).collect();
                algebra.iter().all(|&i| seen.contains(i))
            };
            match explore_metered(set, meter, |m, _| visit(m)) {
                Ok(()) => {
                    empty.extend(algebra.iter().filter(|&&i| !seen.contains(i)));
                    None
                }
                Err(u) => Some(u),
            }
        }
    };
    let warnings = empty
        .into_iter()
        .map(|i| Warning {
            aov: i,
            name: set.names()[i].clone(),
            message: "its set algebra leaves no path: every path one operand requires, \
                      another excludes"
                .to_string(),
        })
        .collect();
    (warnings, undecided)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::renderman::parse;

    #[test]
    fn algebra_that_leaves_no_path_is_reported_and_the_rest_is_not() {
        let aovs: Vec<(String, crate::renderman::Lpe)> = [
            ("none", "C.*L - C.*L"),
            ("disjoint", "C<RD>L & C<RS>L"),
            ("some", "C.*L - C.*DL"),
            ("dead", "C<CD>L"),
            ("comp", "^C.*[<L.>O]"),
        ]
        .iter()
        .map(|(n, s)| (n.to_string(), parse(s).unwrap()))
        .collect();
        let set = AovSet::compile(&aovs).unwrap();
        let names = |ws: &[Warning]| ws.iter().map(|w| w.name.clone()).collect::<Vec<_>>();
        assert_eq!(names(set.warnings()), ["dead"]);
        // `^C.*[<L.>O]` still matches paths with a user-lobe vertex.
        assert_eq!(names(&warnings(&set)), ["none", "disjoint", "dead"]);
        assert!(warnings(&set)[0].message.contains("set algebra"));
    }

    #[test]
    fn algebra_that_leaves_no_sequence_is_reported_in_the_osl_dialect() {
        let reg = crate::osl::Registered::none();
        let aovs: Vec<(String, crate::osl::Lpe)> = [
            ("none", "C.*L - C.*L"),
            ("disjoint", "C<RD>L & C<RG>L"),
            ("some", "C.*L - C.*DL"),
            ("comp", "^C.*L"),
            ("dead", "C<R[]>L"),
        ]
        .iter()
        .map(|(n, s)| (n.to_string(), crate::osl::parse(s, &reg).unwrap()))
        .collect();
        let set = AovSet::compile_under(&aovs, &reg, &crate::Options::default()).unwrap();
        let names = |ws: &[Warning]| ws.iter().map(|w| w.name.clone()).collect::<Vec<_>>();
        assert_eq!(names(set.warnings()), ["dead"]);
        assert_eq!(names(&warnings(&set)), ["none", "disjoint", "dead"]);
    }
}
