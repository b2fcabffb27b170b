//! Set algebra (`&`, `-`, `^`, this toolkit's extension) over any dialect's operands:
//! every dialect's generator draws its set-algebra shapes here, from operands of its
//! own.

use lpe::algebra::Algebra;

use super::choices::Choices;

/// Set algebra over two to four operands drawn by `operand`: `A - B`, `A & B - C`,
/// `A - (B & C)`, `^A & B`, `^(A - B)`.
pub(super) fn algebra_over<C: Choices, E>(
    c: &mut C,
    operand: &mut impl FnMut(&mut C) -> E,
) -> Algebra<E> {
    fn binary<E>(c: &mut impl Choices, a: Algebra<E>, b: Algebra<E>) -> Algebra<E> {
        if c.chance(50) {
            Algebra::and(a, b)
        } else {
            Algebra::minus(a, b)
        }
    }
    let mut leaf = |c: &mut C| {
        let e = Algebra::Leaf(operand(c));
        if c.chance(20) {
            Algebra::complement(e)
        } else {
            e
        }
    };
    let mut t = leaf(c);
    for _ in 0..1 + c.below(2) {
        let mut rhs = leaf(c);
        if c.chance(15) {
            let more = leaf(c);
            rhs = binary(c, rhs, more);
        }
        t = binary(c, t, rhs);
    }
    if c.chance(10) {
        t = Algebra::complement(t);
    }
    t
}
