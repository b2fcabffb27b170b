//! Which way a translation rounds, and how set algebra passes the rounding to its operands.

use crate::algebra::Algebra;

/// Which way a translation rounds where the target cannot say what the source means.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Bound {
    /// A superset: every path the source matches, and more.
    Upper,
    /// A subset: only paths the source matches.
    Lower,
}

impl Bound {
    fn flip(self) -> Bound {
        match self {
            Bound::Upper => Bound::Lower,
            Bound::Lower => Bound::Upper,
        }
    }
}

/// Maps a set algebra tree leaf by leaf, each leaf rounded the way that keeps the whole
/// rounded by `bound`: the right side of `-` and the operand of `^` the other way.
pub(crate) fn map_algebra<A, B>(
    t: &Algebra<A>,
    bound: Bound,
    f: &mut impl FnMut(&A, Bound) -> B,
) -> Algebra<B> {
    match t {
        Algebra::Leaf(e) => Algebra::Leaf(f(e, bound)),
        Algebra::And(a, b) => Algebra::and(map_algebra(a, bound, f), map_algebra(b, bound, f)),
        Algebra::Minus(a, b) => {
            Algebra::minus(map_algebra(a, bound, f), map_algebra(b, bound.flip(), f))
        }
        Algebra::Not(a) => Algebra::complement(map_algebra(a, bound.flip(), f)),
    }
}
