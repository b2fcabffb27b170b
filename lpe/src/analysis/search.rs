//! The breadth-first search over complete paths that comparisons and partitions share,
//! with the witness it rebuilds and the error it gives up with.

use std::fmt;

use super::budget::{Meter, Undecided};
use crate::aov::{AovSet, CompileError, Options};
use crate::automata::ir::{Place, VertexClasses};
use crate::automata::mask::{AovMask, Class, State};
use crate::automata::shape::{Shape, NONE};
use crate::dialect::Dialect;
use crate::fxhash::FxSet;

/// Most `(state, shape)` pairs a comparison or partition search visits before giving up.
pub const MAX_SEARCH_STATES: usize = 2_000_000;

/// Why an analysis gave no answer.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum AnalysisError {
    /// The expressions did not compile into one set.
    Compile(CompileError),
    /// The search passed [`MAX_SEARCH_STATES`].
    TooLarge(usize),
}

impl fmt::Display for AnalysisError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            AnalysisError::Compile(e) => write!(f, "{e}"),
            AnalysisError::TooLarge(n) => write!(
                f,
                "the search visited more than {n} automaton states without finishing"
            ),
        }
    }
}

impl std::error::Error for AnalysisError {}

impl From<CompileError> for AnalysisError {
    fn from(e: CompileError) -> Self {
        AnalysisError::Compile(e)
    }
}

/// Visits every distinct end state of a complete path on the set's DFA or lazy DFA,
/// shortest path first, calling `visit(mask, witness)`; `visit` returns `true` to stop.
/// Dead states are pruned, so masks are never empty. Paths are the sequences of the
/// dialect's [`Dialect::SHAPE`] (RenderMan's: `C`, scattering vertices, one emitter;
/// OSL's: any sequence). One step of `meter` per state visited. The route of the
/// analyses for questions the NFA route does not take, and the oracle its tests compare
/// it with.
pub(super) fn explore_metered<D: Dialect>(
    set: &AovSet<D>,
    meter: &mut Meter,
    mut visit: impl FnMut(AovMask, &dyn Fn() -> D::Path) -> bool,
) -> Result<(), Undecided> {
    let classes = set.classes();
    // Letters: (class, place) with a representative vertex.
    let letters: Vec<(Class, Place, D::Vertex)> = (0..classes.class_count())
        .flat_map(|c| {
            D::SHAPE.places().iter().filter_map(move |&p| {
                classes
                    .representative(c, p)
                    .map(|v| (set.classify(&v), p, v))
            })
        })
        .collect();
    walk(set, &letters, D::SHAPE.automaton(), meter, |m, witness| {
        visit(m, &|| D::path(witness()))
    })
}

/// Breadth-first search over `(state, shape state)` of the product of `set` with
/// `shape`, reading `letters`; calls `visit` on every newly reached accepting node, with
/// the letters' values along a shortest way there.
fn walk<D: Dialect, V: Clone>(
    set: &AovSet<D>,
    letters: &[(Class, Place, V)],
    shape: &Shape,
    meter: &mut Meter,
    mut visit: impl FnMut(AovMask, &dyn Fn() -> Vec<V>) -> bool,
) -> Result<(), Undecided> {
    // Node: (state, shape state); parent index and letter, for the witness.
    let mut nodes: Vec<(State, u8, usize, usize)> = vec![(set.start(), 0, usize::MAX, 0)];
    let mut seen: FxSet<(State, u8)> = FxSet::default();
    seen.insert((set.start(), 0));
    let mut head = 0;
    while head < nodes.len() {
        let (state, at, _, _) = nodes[head];
        for (l, (class, group, _)) in letters.iter().enumerate() {
            let t = shape.next[at as usize][group.index()];
            if t == NONE {
                continue;
            }
            let next = set.step_class(state, *class);
            if set.is_dead(next) || !seen.insert((next, t)) {
                continue;
            }
            meter.spend(1)?;
            nodes.push((next, t, head, l));
            if shape.accept[t as usize] {
                let end = nodes.len() - 1;
                let witness = || {
                    let mut vs = Vec::new();
                    let mut i = end;
                    while nodes[i].2 != usize::MAX {
                        vs.push(letters[nodes[i].3].2.clone());
                        i = nodes[i].2;
                    }
                    vs.reverse();
                    vs
                };
                if visit(set.matches(next), &witness) {
                    return Ok(());
                }
            }
        }
        head += 1;
    }
    Ok(())
}

/// Analysis sets get a larger DFA budget than renderer sets: a search visits every state
/// anyway, so a DFA built once is cheaper than subsets rebuilt per visit.
pub(crate) fn analysis_options() -> Options {
    Options {
        dfa_budget: 64 << 20,
        ..Options::default()
    }
}
