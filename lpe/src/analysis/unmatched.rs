//! Emptiness of set-algebra AOVs. The NFA-only search of the automata layer answers for
//! plain AOVs; whether `A - B` or `A & B` leaves any path needs the two operands' states
//! together, so it searches the compiled set's own states.

use super::search::explore_within;
use crate::algebra::SetExpr;
use crate::aov::AovSet;
use crate::automata::emptiness::Warning;
use crate::automata::mask::AovMask;
use crate::dialect::Dialect;

/// Most states the search visits; past it no warning is given (a warning is advice, not
/// a verdict).
const MAX_STATES: usize = 200_000;

/// Every AOV of `set` that can match no path, with the reason: [`AovSet::warnings`] for
/// the plain AOVs, and for the AOVs with set algebra a search of the set's states (none
/// reported for them if it passes 200 000 states).
pub fn warnings<D: Dialect>(set: &AovSet<D>) -> Vec<Warning> {
    let mut out = set.warnings().to_vec();
    out.extend(algebra_warnings(set));
    out.sort_by_key(|w| w.aov);
    out
}

/// Warnings for the AOVs with set algebra that match no path of the path model (for an
/// OSL set: no non-empty sequence of vertices).
fn algebra_warnings<D: Dialect>(set: &AovSet<D>) -> Vec<Warning> {
    let algebra: Vec<usize> = (0..set.len())
        .filter(|&i| set.lpes()[i].algebra().is_some())
        .collect();
    if algebra.is_empty() {
        return Vec::new();
    }
    let mut seen = AovMask::EMPTY;
    let mut visit = |m: AovMask| {
        seen = m.iter().chain(seen.iter()).collect();
        algebra.iter().all(|&i| seen.contains(i))
    };
    let searched = explore_within(set, MAX_STATES, |m, _| visit(m));
    if searched.is_err() {
        return Vec::new();
    }
    algebra
        .into_iter()
        .filter(|&i| !seen.contains(i))
        .map(|i| Warning {
            aov: i,
            name: set.names()[i].clone(),
            message: "its set algebra leaves no path: every path one operand requires, \
                      another excludes"
                .to_string(),
        })
        .collect()
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
