//! Emptiness: which AOVs of a freshly built NFA can match no path, and why. A
//! breadth-first search over `(NFA position, shape state)` pairs, linear in the NFA and
//! needing neither a determinization nor a finished set.

use std::fmt;

use super::shape::{Shape, ANY, CAMERA_TO_EMITTER, FROM_CAMERA, NONE};
use crate::automata::ir::{PathShape, Place, Regex, VertexClasses};
use crate::automata::nfa::Nfa;
use crate::bits;

/// A compile-time warning: an AOV that can match no path.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Warning {
    /// Index of the AOV in its set.
    pub aov: usize,
    /// Its name.
    pub name: String,
    /// Why it can match no path.
    pub message: String,
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "AOV `{}` can match no path: {}", self.name, self.message)
    }
}

/// Which AOVs match some sequence of `shape`, by breadth-first search over
/// `(position, shape state)`.
pub(crate) fn nonempty_under(nfa: &Nfa, groups: &[u8], shape: &Shape, aovs: usize) -> Vec<bool> {
    let mut found = vec![false; aovs];
    let mut seen = vec![[false; 3]; nfa.positions];
    seen[0][0] = true;
    let mut queue = vec![(0usize, 0u8)];
    while let Some((p, s)) = queue.pop() {
        if shape.accept[s as usize] {
            if let Some(a) = nfa.final_aov(p) {
                found[a] = true;
            }
        }
        for q in bits::ones(nfa.follow_of(p).iter().copied()) {
            let g = groups[nfa.atom_of[q] as usize];
            for group in Place::ALL {
                let t = shape.next[s as usize][group.index()];
                if g >> group.index() & 1 == 1
                    && t != NONE
                    && !std::mem::replace(&mut seen[q][t as usize], true)
                {
                    queue.push((q, t));
                }
            }
        }
    }
    found
}

/// The emptiness warnings of a freshly compiled set whose paths have shape `shape`: an
/// AOV that matches no sequence at all (naming an atom that matches no vertex, if one
/// does), and under [`PathShape::CameraScattersEmitter`] which part of the path shape
/// its sequences miss.
pub(crate) fn empty_aovs<E: Regex>(
    nfa: &Nfa,
    classes: &impl VertexClasses,
    shape: PathShape,
    atoms: &[&E::Atom],
    names: &[String],
    exprs: &[&E],
) -> Vec<Warning> {
    // Per distinct atom: the places (bit per `Place`) of the vertices it accepts.
    let groups: Vec<u8> = (0..atoms.len())
        .map(|a| {
            let mut g = 0u8;
            for c in 0..classes.class_count() {
                if classes.accepts(c, a) {
                    for &place in shape.places() {
                        if classes.occurs_in(c, place) {
                            g |= 1 << place.index();
                        }
                    }
                }
            }
            g
        })
        .collect();
    let n = names.len();
    let on_paths = nonempty_under(nfa, &groups, shape.automaton(), n);
    if on_paths.iter().all(|&b| b) {
        return Vec::new();
    }
    let any = nonempty_under(nfa, &groups, &ANY, n);
    let from_camera = nonempty_under(nfa, &groups, &FROM_CAMERA, n);
    let to_emitter = nonempty_under(nfa, &groups, &CAMERA_TO_EMITTER, n);
    (0..n)
        .filter(|&i| !on_paths[i])
        .map(|i| {
            let message = if !any[i] {
                let dead = dead_atom(exprs[i], atoms, &groups);
                match dead {
                    Some(a) => format!(
                        "it matches no sequence of vertices at all (`{a}` matches no vertex)"
                    ),
                    None => "it matches no sequence of vertices at all".to_string(),
                }
            } else if !from_camera[i] {
                "every sequence it matches starts with a vertex other than the camera `C`"
                    .to_string()
            } else if !to_emitter[i] {
                "it never reaches an emitter: no sequence it matches from the camera `C` \
                 ends with a light `L` or an emissive object `O`"
                    .to_string()
            } else {
                "every sequence it matches from `C` to an emitter has a `C`, `L` or `O` \
                 vertex in the middle (paths have only `R`/`T` vertices there) or \
                 user-lobe vertices where transport is needed"
                    .to_string()
            };
            Warning {
                aov: i,
                name: names[i].clone(),
                message,
            }
        })
        .collect()
}

/// An atom of `e` that accepts no vertex at all, if any, printed.
fn dead_atom<E: Regex>(e: &E, atoms: &[&E::Atom], groups: &[u8]) -> Option<String> {
    let mut out = None;
    e.each_atom(&mut |a| {
        if out.is_none() {
            if let Some(i) = atoms.iter().position(|&x| x == a) {
                if groups[i] == 0 {
                    out = Some(a.to_string());
                }
            }
        }
    });
    out
}
