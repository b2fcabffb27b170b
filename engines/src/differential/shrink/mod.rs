//! One-step simplifications of expressions, AOV sets and paths: what the minimizer
//! ([`super::minimize`](mod@super::minimize)) tries, for as long as the engines still
//! disagree, through each dialect's [`ShrinkDialect`](crate::dialect::ShrinkDialect).
//!
//! Here, the moves every dialect's trees share: set-algebra operands kept alone or
//! shrunk in place, sequence and alternation parts dropped or shrunk, repetition counts
//! lowered. Each dialect's own moves (atoms, vertex patterns, paths) are a sibling:
//! [`renderman`], [`osl`].

use lpe::algebra::{Algebra, SetExpr};
use lpe::automata::ir::Repetition;

pub mod osl;
pub mod renderman;

/// Simpler expressions of a set-algebra expression in any dialect: for set algebra, each
/// operand alone first (a disagreement that survives without the algebra is easier to
/// read), then each operand simplified in place; for a plain expression, its own
/// simplifications. `shrink` simplifies one operand, `build` makes a dialect expression
/// of a tree (a lone leaf is a plain expression).
pub fn shrink_set_expr<L: SetExpr>(
    l: &L,
    shrink: impl Fn(&L::Operand) -> Vec<L::Operand>,
    build: impl Fn(Algebra<L::Operand>) -> L,
) -> Vec<L> {
    let Some(tree) = l.algebra() else {
        return shrink(l.first())
            .into_iter()
            .map(|e| build(Algebra::Leaf(e)))
            .collect();
    };
    let mut out: Vec<L> = l
        .operands()
        .into_iter()
        .map(|e| build(Algebra::Leaf(e.clone())))
        .collect();
    for (k, operand) in l.operands().into_iter().enumerate() {
        for smaller in shrink(operand) {
            let mut t = tree.clone();
            *t.leaves_mut()[k] = smaller;
            out.push(build(t));
        }
    }
    out
}

/// Simpler forms of a sequence or alternation of `parts` (either dialect): each part
/// alone, the node with one part dropped, the node with one part shrunk.
pub fn shrink_parts<E: Clone>(
    parts: &[E],
    rebuild: impl Fn(Vec<E>) -> E,
    shrink: impl Fn(&E) -> Vec<E>,
    out: &mut Vec<E>,
) {
    out.extend(parts.iter().cloned());
    for i in 0..parts.len() {
        let mut fewer = parts.to_vec();
        fewer.remove(i);
        out.push(rebuild(fewer));
    }
    for i in 0..parts.len() {
        for smaller in shrink(&parts[i]) {
            let mut changed = parts.to_vec();
            changed[i] = smaller;
            out.push(rebuild(changed));
        }
    }
}

/// Simpler forms of `body{r}` (either dialect): the body alone, smaller counts, a
/// shrunk body.
pub fn shrink_repeat<E: Clone>(
    body: &E,
    r: Repetition,
    repeat: impl Fn(E, Repetition) -> E,
    shrink: impl Fn(&E) -> Vec<E>,
    out: &mut Vec<E>,
) {
    out.push(body.clone());
    for r2 in shrink_repetition(r) {
        out.push(repeat(body.clone(), r2));
    }
    for smaller in shrink(body) {
        out.push(repeat(smaller, r));
    }
}

fn shrink_repetition(r: Repetition) -> Vec<Repetition> {
    let mut out = Vec::new();
    if r.min > 0 {
        out.push(Repetition { min: 0, max: r.max });
        out.push(Repetition {
            min: r.min - 1,
            max: r.max,
        });
    }
    if let Some(m) = r.max {
        if m > r.min {
            out.push(Repetition {
                min: r.min,
                max: Some(r.min),
            });
            out.push(Repetition {
                min: r.min,
                max: Some(m - 1),
            });
        }
    }
    out.retain(|x| *x != r);
    out
}
