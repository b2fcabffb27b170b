//! The NFA route of the analyses: a list of expressions compiled into one bitset NFA of
//! their operands (no DFA), questions asked as set-algebra formulas over those operands,
//! and each answered by the antichain search of [`super::antichain`] on the formula's
//! disjunctive normal form, with the first shortest witness in letter order over all
//! its conjuncts.

use super::antichain::Graph;
use super::budget::{Meter, Undecided};
use super::dnf::dnf;
use crate::algebra::Algebra;
use crate::aov::{AovSet, CompileError};
use crate::automata::ir::VertexClasses;
use crate::dialect::Dialect;

/// Most conjuncts one question may take in disjunctive normal form; past it the caller
/// takes the lazy-DFA route (a partition of many set-algebra AOVs: the gap excludes
/// every one, and excluding `A - B` is `^A | B`).
const MAX_CONJUNCTS: usize = 64;

/// Why the NFA route gave no answer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Stop {
    /// The budget ran out.
    Undecided(Undecided),
    /// The question has too many conjuncts: ask the lazy-DFA route.
    TooManyConjuncts,
}

impl From<Undecided> for Stop {
    fn from(u: Undecided) -> Self {
        Stop::Undecided(u)
    }
}

/// Expressions compiled for the NFA route.
pub(super) struct Problem<D: Dialect> {
    /// The operands' NFA the searches run on.
    pub(super) graph: Graph,
    /// Per letter of the graph, its representative vertex.
    vertices: Vec<D::Vertex>,
    /// Per expression, its formula over the operands.
    pub(super) formulas: Vec<Algebra<usize>>,
}

impl<D: Dialect> Problem<D> {
    /// The operands of `aovs` in one NFA, with the letters the searches read: every
    /// class at every place of [`Dialect::SHAPE`] that has a representative vertex, in
    /// the order of the lazy-DFA route (class, then place), so both rank witnesses alike.
    pub(super) fn new(
        aovs: &[(String, D::Lpe)],
        opts: &crate::Options,
    ) -> Result<Problem<D>, CompileError> {
        let (classes, nfa, formulas) = AovSet::<D>::operand_nfa(aovs, opts)?;
        let operands = formulas.iter().map(|f| f.leaves().len()).sum();
        let mut letters = Vec::new();
        let mut vertices = Vec::new();
        for c in 0..classes.class_count() {
            for &p in D::SHAPE.places() {
                if let Some(v) = classes.representative(c, p) {
                    letters.push((classes.classify(&v).index(), p));
                    vertices.push(v);
                }
            }
        }
        Ok(Problem {
            graph: Graph::new(nfa, operands, letters, D::SHAPE.automaton()),
            vertices,
            formulas,
        })
    }

    /// The first shortest path (in letter order) on which `f` holds, if any.
    pub(super) fn witness(
        &self,
        f: &Algebra<usize>,
        meter: &mut Meter,
    ) -> Result<Option<D::Path>, Stop> {
        let conjuncts = dnf(f, MAX_CONJUNCTS).ok_or(Stop::TooManyConjuncts)?;
        let mut best: Option<Vec<u32>> = None;
        for c in &conjuncts {
            if let Some(w) = self.graph.shortest(c, meter)? {
                let better = best.as_ref().is_none_or(|b| (w.len(), &w) < (b.len(), b));
                if better {
                    best = Some(w);
                }
            }
        }
        Ok(best.map(|w| {
            D::path(
                w.iter()
                    .map(|&l| self.vertices[l as usize].clone())
                    .collect(),
            )
        }))
    }

    /// Whether `f` holds on some path.
    pub(super) fn nonempty(&self, f: &Algebra<usize>, meter: &mut Meter) -> Result<bool, Stop> {
        Ok(self.witness(f, meter)?.is_some())
    }
}
