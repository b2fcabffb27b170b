//! Cross-dialect questions decided on the automata: does a RenderMan expression match
//! exactly the paths whose OSL view an OSL expression matches, and does a RenderMan
//! expression tell apart two paths the correspondence sees as one?
//!
//! Both are breadth-first searches over RenderMan paths built from the correspondence's
//! [universe](Correspondence::universe) (so the first witness is a shortest one), each
//! vertex stepping the compiled sets of both sides.

use std::collections::BTreeSet;

use crate::analysis::{analysis_options, AnalysisError, MAX_SEARCH_STATES};
use crate::aov::AovSet;
use crate::automata::mask::{Class, State};
use crate::dialect::Dialect;
use crate::fxhash::{FxMap, FxSet};
use crate::osl::{self, Osl};
use crate::renderman::{self, RenderMan, VertexType};
use crate::translate::correspondence::Correspondence;
use crate::translate::labels;

/// A RenderMan path with its OSL view (`None`: it has none).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Witness {
    /// The RenderMan path.
    pub renderman: renderman::Path,
    /// Its OSL view under the correspondence.
    pub osl: Option<osl::Path>,
}

/// How a RenderMan and an OSL expression relate under a correspondence.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CrossComparison {
    /// A shortest path the RenderMan expression matches and whose OSL view the OSL
    /// expression does not.
    pub renderman_only: Option<Witness>,
    /// A shortest path the RenderMan expression does not match and whose OSL view the
    /// OSL expression does.
    pub osl_only: Option<Witness>,
    /// A shortest path the RenderMan expression matches that has no OSL view (a user
    /// lobe): OSL's AOV can never receive it.
    pub outside: Option<renderman::Path>,
}

impl CrossComparison {
    /// Both mean the same on every RenderMan path.
    pub fn equivalent(&self) -> bool {
        self.renderman_only.is_none() && self.osl_only.is_none() && self.outside.is_none()
    }
}

/// Two RenderMan paths with one OSL view, one matched and one not.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Collision {
    /// The path the expression matches.
    pub matched: renderman::Path,
    /// The path it does not match.
    pub unmatched: renderman::Path,
    /// The OSL view of both.
    pub osl: osl::Path,
}

/// Where a letter may stand in a RenderMan path: shape states 0 (start), 1 (after the
/// camera and any scattering), 2 (after the emitter: accepting).
fn next_shape(at: u8, ty: VertexType) -> Option<u8> {
    match (at, ty) {
        (0, VertexType::C) => Some(1),
        (1, VertexType::R | VertexType::T) => Some(1),
        (1, VertexType::L | VertexType::O) => Some(2),
        _ => None,
    }
}

/// The one-AOV analysis set of `e` (nothing registered).
fn compile<D: Dialect>(e: &D::Lpe) -> Result<AovSet<D>, AnalysisError> {
    let aovs = [("A".to_string(), e.clone())];
    Ok(AovSet::compile_under(
        &aovs,
        &D::Registration::default(),
        &analysis_options(),
    )?)
}

/// A breadth-first search node: both sides' states, the shape state, and how it was
/// reached (parent node, letter).
struct Node<S> {
    state: S,
    shape: u8,
    parent: usize,
    letter: usize,
}

/// Breadth-first search over `(state, shape)` from `start`, reading `letters` (each a
/// vertex type and what it does to the state); calls `visit` on each newly reached
/// complete path with its letters, shortest first, until `visit` returns `true`.
fn search<S: Copy + Eq + std::hash::Hash>(
    start: S,
    letters: &[(VertexType, usize)],
    step: impl Fn(S, usize) -> Option<S>,
    mut visit: impl FnMut(S, &dyn Fn() -> Vec<usize>) -> bool,
) -> Result<(), AnalysisError> {
    let mut nodes = vec![Node {
        state: start,
        shape: 0,
        parent: usize::MAX,
        letter: 0,
    }];
    let mut seen: FxSet<(S, u8)> = FxSet::default();
    seen.insert((start, 0));
    let mut head = 0;
    while head < nodes.len() {
        let (state, at) = (nodes[head].state, nodes[head].shape);
        for (l, &(ty, _)) in letters.iter().enumerate() {
            let Some(shape) = next_shape(at, ty) else {
                continue;
            };
            let Some(next) = step(state, l) else {
                continue;
            };
            if !seen.insert((next, shape)) {
                continue;
            }
            if nodes.len() >= MAX_SEARCH_STATES {
                return Err(AnalysisError::TooLarge(MAX_SEARCH_STATES));
            }
            nodes.push(Node {
                state: next,
                shape,
                parent: head,
                letter: l,
            });
            if shape == 2 {
                let end = nodes.len() - 1;
                let path = || {
                    let mut ls = Vec::new();
                    let mut i = end;
                    while nodes[i].parent != usize::MAX {
                        ls.push(nodes[i].letter);
                        i = nodes[i].parent;
                    }
                    ls.reverse();
                    ls
                };
                if visit(next, &path) {
                    return Ok(());
                }
            }
        }
        head += 1;
    }
    Ok(())
}

fn path_of(vertices: Vec<renderman::Vertex>) -> renderman::Path {
    renderman::Path::new(vertices).expect("the search follows the path shape")
}

/// Compares a RenderMan and an OSL expression on every RenderMan path: the RenderMan
/// expression against the path, the OSL expression against its OSL view.
pub fn compare(
    rm: &renderman::Lpe,
    osl: &osl::Lpe,
    corr: &Correspondence,
) -> Result<CrossComparison, AnalysisError> {
    let (a, b) = (compile::<RenderMan>(rm)?, compile::<Osl>(osl)?);
    let (universe, _) = corr.universe(&labels::renderman(rm), &labels::osl(osl));
    // Letters: one per distinct (type, RenderMan class, OSL class or none).
    let mut distinct: FxSet<(VertexType, Class, Option<Class>)> = FxSet::default();
    let mut letters = Vec::new();
    let mut steps: Vec<(Class, Option<Class>)> = Vec::new();
    let mut vertices = Vec::new();
    for v in universe {
        let ca = a.classify(&v);
        let cb = corr.view(&v).map(|w| b.classify(&w));
        if distinct.insert((v.ty(), ca, cb)) {
            letters.push((v.ty(), letters.len()));
            steps.push((ca, cb));
            vertices.push(v);
        }
    }
    // `None` on the OSL side: the path left the correspondence (no OSL view).
    let start: (State, Option<State>) = (a.start(), Some(b.start()));
    let mut out = CrossComparison {
        renderman_only: None,
        osl_only: None,
        outside: None,
    };
    let witness = |ls: Vec<usize>| {
        let p = path_of(ls.into_iter().map(|l| vertices[l].clone()).collect());
        let osl = corr.view_path(&p);
        Witness { renderman: p, osl }
    };
    search(
        start,
        &letters,
        |(sa, sb), l| {
            let (ca, cb) = steps[l];
            let na = a.step_class(sa, ca);
            let nb = match (sb, cb) {
                (Some(sb), Some(cb)) => Some(b.step_class(sb, cb)),
                _ => None,
            };
            (!a.is_dead(na) || nb.is_some_and(|s| !b.is_dead(s))).then_some((na, nb))
        },
        |(sa, sb), ls| {
            let in_a = a.matches(sa).contains(0);
            match sb {
                None if in_a && out.outside.is_none() => {
                    out.outside = Some(witness(ls()).renderman);
                }
                Some(sb) => match (in_a, b.matches(sb).contains(0)) {
                    (true, false) if out.renderman_only.is_none() => {
                        out.renderman_only = Some(witness(ls()))
                    }
                    (false, true) if out.osl_only.is_none() => out.osl_only = Some(witness(ls())),
                    _ => {}
                },
                None => {}
            }
            out.renderman_only.is_some() && out.osl_only.is_some() && out.outside.is_some()
        },
    )?;
    Ok(out)
}

/// A shortest pair of RenderMan paths with the same OSL view, one matched by `rm` and
/// one not: the reason no OSL expression can mean what `rm` means. `None` when `rm`
/// never tells such paths apart.
pub fn collision(
    rm: &renderman::Lpe,
    corr: &Correspondence,
) -> Result<Option<Collision>, AnalysisError> {
    let a = compile::<RenderMan>(rm)?;
    let (universe, _) = corr.universe(&labels::renderman(rm), &BTreeSet::new());
    // Group the universe by OSL view; a letter is a pair of vertices of one view.
    let mut by_view: FxMap<String, Vec<renderman::Vertex>> = FxMap::default();
    let mut views: Vec<String> = Vec::new();
    for v in universe {
        if let Some(w) = corr.view(&v) {
            let key = w.to_string();
            if !by_view.contains_key(&key) {
                views.push(key.clone());
            }
            by_view.entry(key).or_default().push(v);
        }
    }
    let mut distinct: FxSet<(VertexType, Class, Class)> = FxSet::default();
    let mut letters = Vec::new();
    let mut pairs: Vec<(renderman::Vertex, renderman::Vertex, Class, Class)> = Vec::new();
    for key in &views {
        let group = &by_view[key];
        for x in group {
            for y in group {
                let (cx, cy) = (a.classify(x), a.classify(y));
                if distinct.insert((x.ty(), cx, cy)) {
                    letters.push((x.ty(), pairs.len()));
                    pairs.push((x.clone(), y.clone(), cx, cy));
                }
            }
        }
    }
    let mut found = None;
    search(
        (a.start(), a.start()),
        &letters,
        |(s, t), l| {
            let (_, _, cx, cy) = pairs[l];
            let (s, t) = (a.step_class(s, cx), a.step_class(t, cy));
            (!a.is_dead(s)).then_some((s, t))
        },
        |(s, t), ls| {
            if a.matches(s).contains(0) && !a.matches(t).contains(0) {
                let ls = ls();
                let matched = path_of(ls.iter().map(|&l| pairs[l].0.clone()).collect());
                let unmatched = path_of(ls.iter().map(|&l| pairs[l].1.clone()).collect());
                let osl = corr.view_path(&matched).expect("pairs share one OSL view");
                found = Some(Collision {
                    matched,
                    unmatched,
                    osl,
                });
                return true;
            }
            false
        },
    )?;
    Ok(found)
}
