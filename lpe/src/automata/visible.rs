//! Visible AOV masks from hidden ones. A set with set algebra compiles every operand as a
//! hidden AOV; each visible AOV is a boolean formula over them. The DFA applies the
//! formulas once per state when it is built, so stepping costs nothing more; the NFA
//! stepping mode applies them when asked for matches.

use crate::algebra::Algebra;
use crate::automata::mask::AovMask;

/// Per visible AOV, its formula over hidden AOV indices.
#[derive(Clone, Debug)]
pub(crate) struct Visible {
    formulas: Vec<Algebra<usize>>,
    /// The visible mask when no hidden AOV matches. Once no operand can match any more
    /// (the empty NFA subset), this is what every continuation matches: a complement
    /// `^A` makes it non-empty, and such a state is then not dead.
    none: AovMask,
}

impl Visible {
    pub(crate) fn new(formulas: Vec<Algebra<usize>>) -> Visible {
        let mut v = Visible {
            formulas,
            none: AovMask::EMPTY,
        };
        v.none = v.mask(AovMask::EMPTY);
        v
    }

    /// The visible AOVs matching when exactly the hidden AOVs of `hidden` match.
    pub(crate) fn mask(&self, hidden: AovMask) -> AovMask {
        self.formulas
            .iter()
            .enumerate()
            .filter(|(_, f)| f.eval(&mut |&h| hidden.contains(h)))
            .map(|(i, _)| i)
            .collect()
    }

    /// [`Visible::mask`] of no hidden AOV.
    pub(crate) fn none(&self) -> AovMask {
        self.none
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn masks_follow_the_formulas() {
        let leaf = Algebra::Leaf;
        // Visible 0 = hidden 0 (plain), 1 = h1 - h2, 2 = ^h3 & h1.
        let v = Visible::new(vec![
            leaf(0),
            Algebra::minus(leaf(1), leaf(2)),
            Algebra::and(Algebra::complement(leaf(3)), leaf(1)),
        ]);
        let m = |hs: &[usize]| {
            v.mask(hs.iter().copied().collect())
                .iter()
                .collect::<Vec<_>>()
        };
        assert_eq!(m(&[]), Vec::<usize>::new());
        assert_eq!(m(&[0, 1]), [0, 1, 2]);
        assert_eq!(m(&[1, 2]), [2]);
        assert_eq!(m(&[1, 3]), [1]);
        let only_not = Visible::new(vec![Algebra::complement(leaf(0))]);
        assert_eq!(only_not.none().iter().collect::<Vec<_>>(), [0]);
    }
}
