//! The set-algebra tree over whole expressions, generic in the leaf so that every dialect
//! shares it: a leaf is one dialect expression.

use std::fmt;

/// `A & B`, `A - B`, `^A` over whole expressions. Leaves are dialect expressions
/// (`Algebra<crate::Expr>` for RenderMan's); `Algebra<usize>` numbers the leaves.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Algebra<E> {
    /// One expression.
    Leaf(E),
    /// Paths both sides match.
    And(Box<Algebra<E>>, Box<Algebra<E>>),
    /// Paths the left side matches and the right side does not.
    Minus(Box<Algebra<E>>, Box<Algebra<E>>),
    /// Paths of the path model the operand does not match.
    Not(Box<Algebra<E>>),
}

impl<E> Algebra<E> {
    /// `a & b`.
    pub fn and(a: Algebra<E>, b: Algebra<E>) -> Algebra<E> {
        Algebra::And(Box::new(a), Box::new(b))
    }

    /// `a - b`.
    pub fn minus(a: Algebra<E>, b: Algebra<E>) -> Algebra<E> {
        Algebra::Minus(Box::new(a), Box::new(b))
    }

    /// `^a`.
    pub fn complement(a: Algebra<E>) -> Algebra<E> {
        Algebra::Not(Box::new(a))
    }

    /// The leaves, left to right.
    pub fn leaves(&self) -> Vec<&E> {
        let mut out = Vec::new();
        self.visit(&mut |e| out.push(e));
        out
    }

    fn visit<'a>(&'a self, f: &mut impl FnMut(&'a E)) {
        match self {
            Algebra::Leaf(e) => f(e),
            Algebra::And(a, b) | Algebra::Minus(a, b) => {
                a.visit(f);
                b.visit(f);
            }
            Algebra::Not(a) => a.visit(f),
        }
    }

    /// The leaves, mutably, left to right.
    pub fn leaves_mut(&mut self) -> Vec<&mut E> {
        fn go<'a, E>(t: &'a mut Algebra<E>, out: &mut Vec<&'a mut E>) {
            match t {
                Algebra::Leaf(e) => out.push(e),
                Algebra::And(a, b) | Algebra::Minus(a, b) => {
                    go(a, out);
                    go(b, out);
                }
                Algebra::Not(a) => go(a, out),
            }
        }
        let mut out = Vec::new();
        go(self, &mut out);
        out
    }

    /// The same tree with every leaf replaced by a whole subtree (a macro operand that is
    /// itself an algebra expression grafts in here), or the first error.
    pub fn try_graft<F, X>(
        self,
        f: &mut impl FnMut(E) -> Result<Algebra<F>, X>,
    ) -> Result<Algebra<F>, X> {
        Ok(match self {
            Algebra::Leaf(e) => f(e)?,
            Algebra::And(a, b) => Algebra::and(a.try_graft(f)?, b.try_graft(f)?),
            Algebra::Minus(a, b) => Algebra::minus(a.try_graft(f)?, b.try_graft(f)?),
            Algebra::Not(a) => Algebra::complement(a.try_graft(f)?),
        })
    }

    /// The same tree with every leaf mapped.
    pub fn map<'a, F>(&'a self, f: &mut impl FnMut(&'a E) -> F) -> Algebra<F> {
        match self {
            Algebra::Leaf(e) => Algebra::Leaf(f(e)),
            Algebra::And(a, b) => Algebra::and(a.map(f), b.map(f)),
            Algebra::Minus(a, b) => Algebra::minus(a.map(f), b.map(f)),
            Algebra::Not(a) => Algebra::complement(a.map(f)),
        }
    }

    /// The same shape with leaves numbered `first, first + 1, ...` left to right (the
    /// numbering of [`Algebra::leaves`]).
    pub fn numbered(&self, first: usize) -> Algebra<usize> {
        let mut next = first;
        self.map(&mut |_| {
            next += 1;
            next - 1
        })
    }

    /// Whether a path is in the set, given whether it matches each leaf. Every leaf is
    /// asked exactly once, left to right, so a caller may answer from an iterator.
    pub fn eval(&self, leaf: &mut impl FnMut(&E) -> bool) -> bool {
        match self {
            Algebra::Leaf(e) => leaf(e),
            Algebra::And(a, b) => {
                let (x, y) = (a.eval(leaf), b.eval(leaf));
                x && y
            }
            Algebra::Minus(a, b) => {
                let (x, y) = (a.eval(leaf), b.eval(leaf));
                x && !y
            }
            Algebra::Not(a) => !a.eval(leaf),
        }
    }
}

/// A dialect's parsed expression: one expression, or set algebra over several that keeps
/// its first operand as the plain expression (so code that ignores algebra still sees a
/// real expression). Both dialects' `Lpe` implement it; everything below is shared.
pub trait SetExpr {
    /// The dialect's expression: an operand.
    type Operand: Clone;

    /// The plain expression, or the first operand of the set algebra.
    fn first(&self) -> &Self::Operand;

    /// The set algebra, `None` for a plain expression.
    fn algebra(&self) -> Option<&Algebra<Self::Operand>>;

    /// The expressions a matcher must match, left to right: the plain expression alone,
    /// or every operand of the set algebra.
    fn operands(&self) -> Vec<&Self::Operand> {
        match self.algebra() {
            Some(t) => t.leaves(),
            None => vec![self.first()],
        }
    }

    /// The whole expression as a tree (a plain expression is one leaf).
    fn tree(&self) -> Algebra<Self::Operand> {
        self.algebra()
            .cloned()
            .unwrap_or_else(|| Algebra::Leaf(self.first().clone()))
    }

    /// Whether a path is matched, given whether it matches each operand (asked once
    /// each, in [`SetExpr::operands`] order).
    fn eval(&self, operand: &mut impl FnMut(&Self::Operand) -> bool) -> bool {
        match self.algebra() {
            Some(t) => t.eval(operand),
            None => operand(self.first()),
        }
    }
}

/// Per expression, its set algebra over operand numbers, the operands of all of them
/// numbered in one sequence in [`SetExpr::operands`] order (a plain expression is one
/// operand): how a set of expressions maps onto per-operand answers.
pub fn formulas<'a, L: SetExpr + 'a>(lpes: impl IntoIterator<Item = &'a L>) -> Vec<Algebra<usize>> {
    let mut next = 0;
    lpes.into_iter()
        .map(|l| {
            let f = match l.algebra() {
                Some(t) => t.numbered(next),
                None => Algebra::Leaf(next),
            };
            next += l.operands().len();
            f
        })
        .collect()
}

/// Set algebra printed with each operand that is `alternation` in parentheses: in both
/// dialects `A - (b|c)` reads as it parses, where `A - b|c` would suggest `(A - b)|c`.
pub(crate) fn write_operands<E: fmt::Display>(
    f: &mut fmt::Formatter<'_>,
    t: &Algebra<E>,
    alternation: impl Fn(&E) -> bool,
) -> fmt::Result {
    struct Operand<'a, E>(&'a E, bool);
    impl<E: fmt::Display> fmt::Display for Operand<'_, E> {
        fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            if self.1 {
                write!(f, "({})", self.0)
            } else {
                write!(f, "{}", self.0)
            }
        }
    }
    write!(f, "{}", t.map(&mut |e| Operand(e, alternation(e))))
}

impl<E: fmt::Display> fmt::Display for Algebra<E> {
    /// Spelled so that the algebra layer parses it back to the same tree: `&` and `-`
    /// are left-associative, so a binary right operand is parenthesized, and so is a
    /// binary operand of `^`. Leaves print as their dialect prints them.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fn operand<E: fmt::Display>(
            f: &mut fmt::Formatter<'_>,
            t: &Algebra<E>,
            paren_binary: bool,
        ) -> fmt::Result {
            match t {
                Algebra::And(..) | Algebra::Minus(..) if paren_binary => write!(f, "({t})"),
                _ => write!(f, "{t}"),
            }
        }
        match self {
            Algebra::Leaf(e) => write!(f, "{e}"),
            Algebra::And(a, b) | Algebra::Minus(a, b) => {
                let op = if matches!(self, Algebra::And(..)) {
                    "&"
                } else {
                    "-"
                };
                operand(f, a, false)?;
                write!(f, " {op} ")?;
                operand(f, b, true)
            }
            Algebra::Not(a) => {
                f.write_str("^")?;
                operand(f, a, true)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn leaf(s: &str) -> Algebra<String> {
        Algebra::Leaf(s.to_string())
    }

    #[test]
    fn printing_parenthesizes_right_operands_only() {
        let t = Algebra::minus(Algebra::minus(leaf("A"), leaf("B")), leaf("C"));
        assert_eq!(t.to_string(), "A - B - C");
        let t = Algebra::minus(leaf("A"), Algebra::minus(leaf("B"), leaf("C")));
        assert_eq!(t.to_string(), "A - (B - C)");
        let t = Algebra::and(
            Algebra::complement(leaf("A")),
            Algebra::complement(Algebra::and(leaf("B"), leaf("C"))),
        );
        assert_eq!(t.to_string(), "^A & ^(B & C)");
    }

    #[test]
    fn eval_combines_and_asks_each_leaf_once_in_order() {
        // (A - B) & ^C
        let t = Algebra::and(
            Algebra::minus(leaf("A"), leaf("B")),
            Algebra::complement(leaf("C")),
        );
        let table = [
            ([true, false, false], true),
            ([true, true, false], false),
            ([true, false, true], false),
            ([false, false, false], false),
        ];
        for (answers, want) in table {
            let mut asked = Vec::new();
            let got = t.eval(&mut |e: &String| {
                asked.push(e.clone());
                answers[asked.len() - 1]
            });
            assert_eq!(got, want, "{answers:?}");
            assert_eq!(asked, ["A", "B", "C"]);
        }
        assert_eq!(t.numbered(5).leaves(), [&5, &6, &7]);
    }
}
