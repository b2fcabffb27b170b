//! Questions over set algebra as unions of conjunctions: "a path some operands match and
//! others do not". The NFA searches answer one such conjunction at a time (runs for the
//! operands that must match, a subset of positions for those that must not), so a
//! question over set-algebra formulas is put in disjunctive normal form first.

use crate::algebra::Algebra;

/// Operands (hidden AOVs) a path must match and must not match.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(super) struct Conjunct {
    /// Every one of these matches, sorted, without repeats.
    pub must: Vec<usize>,
    /// None of these matches, sorted, without repeats.
    pub must_not: Vec<usize>,
}

/// `f` as a union of conjuncts, contradictory ones (an operand both required and
/// excluded) dropped; `None` when that takes more than `cap` conjuncts at any point.
pub(super) fn dnf(f: &Algebra<usize>, cap: usize) -> Option<Vec<Conjunct>> {
    let mut out = terms(f, true, cap)?;
    out.retain(|c| !c.must.iter().any(|m| c.must_not.binary_search(m).is_ok()));
    out.dedup();
    Some(out)
}

/// The conjuncts of `f` (or of its complement, when `positive` is false).
fn terms(f: &Algebra<usize>, positive: bool, cap: usize) -> Option<Vec<Conjunct>> {
    match (f, positive) {
        (Algebra::Leaf(i), true) => Some(vec![Conjunct {
            must: vec![*i],
            must_not: Vec::new(),
        }]),
        (Algebra::Leaf(i), false) => Some(vec![Conjunct {
            must: Vec::new(),
            must_not: vec![*i],
        }]),
        (Algebra::Not(a), p) => terms(a, !p, cap),
        // a & b, and ^(a - b) = ^a | b: a union.
        (Algebra::And(a, b), true) => product(&terms(a, true, cap)?, &terms(b, true, cap)?, cap),
        (Algebra::Minus(a, b), true) => product(&terms(a, true, cap)?, &terms(b, false, cap)?, cap),
        (Algebra::And(a, b), false) => union(terms(a, false, cap)?, terms(b, false, cap)?, cap),
        (Algebra::Minus(a, b), false) => union(terms(a, false, cap)?, terms(b, true, cap)?, cap),
    }
}

fn union(mut a: Vec<Conjunct>, b: Vec<Conjunct>, cap: usize) -> Option<Vec<Conjunct>> {
    a.extend(b);
    (a.len() <= cap).then_some(a)
}

fn product(a: &[Conjunct], b: &[Conjunct], cap: usize) -> Option<Vec<Conjunct>> {
    if a.len().saturating_mul(b.len()) > cap {
        return None;
    }
    let mut out = Vec::with_capacity(a.len() * b.len());
    for x in a {
        for y in b {
            out.push(Conjunct {
                must: merged(&x.must, &y.must),
                must_not: merged(&x.must_not, &y.must_not),
            });
        }
    }
    Some(out)
}

/// The sorted union of two sorted lists.
fn merged(a: &[usize], b: &[usize]) -> Vec<usize> {
    let mut v: Vec<usize> = a.iter().chain(b).copied().collect();
    v.sort_unstable();
    v.dedup();
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    fn leaf(i: usize) -> Algebra<usize> {
        Algebra::Leaf(i)
    }

    fn c(must: &[usize], must_not: &[usize]) -> Conjunct {
        Conjunct {
            must: must.to_vec(),
            must_not: must_not.to_vec(),
        }
    }

    /// Every conjunct as it is derived: dropping the complement's swap of `And` and
    /// `Minus` (De Morgan) fails the second assert, dropping the contradiction filter
    /// fails the third.
    #[test]
    fn formulas_become_unions_of_conjuncts() {
        let f = Algebra::minus(Algebra::and(leaf(0), leaf(1)), leaf(2));
        assert_eq!(dnf(&f, 8), Some(vec![c(&[0, 1], &[2])]));
        // ^(0 - 1) & 2 = (^0 | 1) & 2.
        let g = Algebra::and(
            Algebra::complement(Algebra::minus(leaf(0), leaf(1))),
            leaf(2),
        );
        assert_eq!(dnf(&g, 8), Some(vec![c(&[2], &[0]), c(&[1, 2], &[])]));
        // 0 - 0 is empty.
        assert_eq!(dnf(&Algebra::minus(leaf(0), leaf(0)), 8), Some(vec![]));
    }

    #[test]
    fn a_formula_past_the_cap_has_no_normal_form() {
        // ^(0 - 1) is the union ^0 | 1: the conjunction of three such unions is
        // 2^3 = 8 conjuncts.
        let d = |a, b| Algebra::complement(Algebra::minus(leaf(a), leaf(b)));
        let f = Algebra::and(Algebra::and(d(0, 1), d(2, 3)), d(4, 5));
        assert_eq!(dnf(&f, 8).map(|v| v.len()), Some(8));
        assert_eq!(dnf(&f, 7), None);
    }
}
