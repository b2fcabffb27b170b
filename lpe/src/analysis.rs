//! Formal analysis on the automata: emptiness, equivalence and inclusion, partition
//! checks, each with the shortest witness path.
//!
//! All searches run over *paths* only (DESIGN.md §2: `C`, then `R`/`T` vertices, then one
//! `L` or `O`), as the product of the set's automaton with that path shape:
//! - emptiness ([`AovSet::warnings`]) needs no determinization: a breadth-first search
//!   over `(NFA position, shape state)` pairs, linear in the NFA;
//! - comparisons and partitions need subsets of positions, so they search over
//!   [`crate::aov::State`]s (the DFA's when it was built, else NFA subsets made on the
//!   fly), breadth-first, so the first witness found is a shortest one, bounded by
//!   [`MAX_SEARCH_STATES`].
//!
//! A witness is built from one representative vertex per class (an unmentioned label
//! becomes a fresh name such as `other`). Callers that print witnesses should re-check
//! them with an independent matcher; `lpe-check` does, with the reference matcher.

use crate::fxhash::FxSet;
use std::fmt;

use crate::alphabet::{Alphabet, Group};
use crate::aov::{AovMask, AovSet, CompileError, Options, State};
use crate::ast::{Atom, Expr};
use crate::bits;
use crate::nfa::Nfa;
use crate::path::{Path, Vertex};
use crate::{parse, Lpe};

/// Most `(state, shape)` pairs a comparison or partition search visits before giving up.
pub const MAX_SEARCH_STATES: usize = 2_000_000;

/// The default universe of a partition check: every light-transport path.
pub const DEFAULT_UNIVERSE: &str = "C.*[<L.>O]";

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

// --- Shapes: small DFAs over vertex groups (camera, scatter, emitter). ---

const NONE: u8 = u8::MAX;

/// `next[state][group]` and which states accept; state 0 is the start.
struct Shape {
    next: [[u8; 3]; 3],
    accept: [bool; 3],
}

/// Any non-empty sequence.
const ANY: Shape = Shape {
    next: [[1, 1, 1], [1, 1, 1], [NONE; 3]],
    accept: [false, true, false],
};
/// Starts with the camera.
const FROM_CAMERA: Shape = Shape {
    next: [[1, NONE, NONE], [1, 1, 1], [NONE; 3]],
    accept: [false, true, false],
};
/// Starts with the camera, ends with an emitter, anything between.
const CAMERA_TO_EMITTER: Shape = Shape {
    next: [[1, NONE, NONE], [1, 1, 2], [1, 1, 2]],
    accept: [false, false, true],
};
/// A path: `C`, `R`/`T` vertices, one emitter.
const PATH: Shape = Shape {
    next: [[1, NONE, NONE], [NONE, 1, 2], [NONE; 3]],
    accept: [false, false, true],
};

/// Which AOVs match some sequence of `shape`, by breadth-first search over
/// `(position, shape state)`.
fn nonempty_under(nfa: &Nfa, groups: &[u8], shape: &Shape, aovs: usize) -> Vec<bool> {
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
            for group in Group::ALL {
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

/// The emptiness warnings of a freshly compiled set.
pub(crate) fn empty_aovs(
    nfa: &Nfa,
    alphabet: &Alphabet,
    atoms: &[&Atom],
    names: &[String],
    lpes: &[Lpe],
) -> Vec<Warning> {
    // Per distinct atom: the groups (bit per `Group`) of the vertices it accepts.
    let groups: Vec<u8> = (0..atoms.len())
        .map(|a| {
            let mut g = 0u8;
            for c in 0..alphabet.class_count() {
                if alphabet.accepts(c, a) {
                    for group in Group::ALL {
                        if alphabet.representative(c, group).is_some() {
                            g |= 1 << group.index();
                        }
                    }
                }
            }
            g
        })
        .collect();
    let n = names.len();
    let on_paths = nonempty_under(nfa, &groups, &PATH, n);
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
                let dead = dead_atom(&lpes[i].expr, atoms, &groups);
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

/// An atom of `e` that accepts no vertex at all, if any.
fn dead_atom(e: &Expr, atoms: &[&Atom], groups: &[u8]) -> Option<Atom> {
    let mut out = None;
    e.for_each_atom(&mut |a| {
        if out.is_none() {
            if let Some(i) = atoms.iter().position(|&x| x == a) {
                if groups[i] == 0 {
                    out = Some(a.clone());
                }
            }
        }
    });
    out
}

// --- Searches over complete paths. ---

/// Visits every distinct end state of a complete path, shortest path first, calling
/// `visit(mask, witness)`; `visit` returns `true` to stop. Dead states are pruned, so
/// masks are never empty.
fn explore(
    set: &AovSet,
    mut visit: impl FnMut(AovMask, &dyn Fn() -> Path) -> bool,
) -> Result<(), AnalysisError> {
    let alphabet = set.alphabet();
    // Letters: (class, group) with a representative vertex.
    let letters: Vec<(usize, Group, Vertex)> = (0..alphabet.class_count())
        .flat_map(|c| {
            Group::ALL
                .into_iter()
                .filter_map(move |g| alphabet.representative(c, g).map(|v| (c, g, v)))
        })
        .collect();
    let classes: Vec<_> = letters.iter().map(|(_, _, v)| set.classify(v)).collect();
    // Node: (state, shape state); parent index and letter, for the witness.
    let mut nodes: Vec<(State, u8, usize, usize)> = vec![(set.start(), 0, usize::MAX, 0)];
    let mut seen: FxSet<(State, u8)> = FxSet::default();
    seen.insert((set.start(), 0));
    let mut head = 0;
    while head < nodes.len() {
        let (state, shape, _, _) = nodes[head];
        for (l, (_, group, _)) in letters.iter().enumerate() {
            let t = PATH.next[shape as usize][group.index()];
            if t == NONE {
                continue;
            }
            let next = set.step_class(state, classes[l]);
            if set.is_dead(next) || !seen.insert((next, t)) {
                continue;
            }
            if nodes.len() >= MAX_SEARCH_STATES {
                return Err(AnalysisError::TooLarge(MAX_SEARCH_STATES));
            }
            nodes.push((next, t, head, l));
            if PATH.accept[t as usize] {
                let end = nodes.len() - 1;
                let witness = || {
                    let mut vs = Vec::new();
                    let mut i = end;
                    while nodes[i].2 != usize::MAX {
                        vs.push(letters[nodes[i].3].2.clone());
                        i = nodes[i].2;
                    }
                    vs.reverse();
                    // Built along the PATH shape from constructible vertices: valid.
                    Path::new(vs).expect("witnesses follow the path shape")
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

/// How two expressions relate on paths.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Comparison {
    /// A shortest path matched by the first and not the second.
    pub first_only: Option<Path>,
    /// A shortest path matched by the second and not the first.
    pub second_only: Option<Path>,
}

impl Comparison {
    /// Both match the same paths.
    pub fn equivalent(&self) -> bool {
        self.first_only.is_none() && self.second_only.is_none()
    }
}

/// Compares two expressions on every path: equivalence, inclusion, and shortest
/// witnesses of the differences.
pub fn compare(a: &Lpe, b: &Lpe) -> Result<Comparison, AnalysisError> {
    let set = AovSet::compile_with(
        &[("A".into(), a.clone()), ("B".into(), b.clone())],
        &analysis_options(),
    )?;
    let mut out = Comparison {
        first_only: None,
        second_only: None,
    };
    explore(&set, |m, witness| {
        match (m.contains(0), m.contains(1)) {
            (true, false) if out.first_only.is_none() => out.first_only = Some(witness()),
            (false, true) if out.second_only.is_none() => out.second_only = Some(witness()),
            _ => {}
        }
        out.first_only.is_some() && out.second_only.is_some()
    })?;
    Ok(out)
}

/// The result of a partition check.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Partition {
    /// `(i, j, path)`: a shortest universe path matched by both AOV `i` and AOV `j`
    /// (`i < j`), one entry per overlapping pair.
    pub overlaps: Vec<(usize, usize, Path)>,
    /// A shortest universe path matched by no AOV.
    pub gap: Option<Path>,
    /// `(i, path)`: a shortest path outside the universe that AOV `i` matches.
    pub outside: Vec<(usize, Path)>,
}

impl Partition {
    /// Every universe path matches exactly one AOV and no AOV matches outside.
    pub fn is_clean(&self) -> bool {
        self.overlaps.is_empty() && self.gap.is_none() && self.outside.is_empty()
    }
}

/// Checks whether `aovs` partition `universe` (default [`DEFAULT_UNIVERSE`]): every
/// universe path matched by exactly one AOV, none matching outside it.
pub fn partition(aovs: &[(String, Lpe)], universe: &Lpe) -> Result<Partition, AnalysisError> {
    let mut all = vec![("universe".to_string(), universe.clone())];
    all.extend_from_slice(aovs);
    let set = AovSet::compile_with(&all, &analysis_options())?;
    let mut out = Partition {
        overlaps: Vec::new(),
        gap: None,
        outside: Vec::new(),
    };
    explore(&set, |m, witness| {
        let members: Vec<usize> = m.iter().filter(|&i| i > 0).map(|i| i - 1).collect();
        if m.contains(0) {
            if members.is_empty() && out.gap.is_none() {
                out.gap = Some(witness());
            }
            for (x, &i) in members.iter().enumerate() {
                for &j in &members[x + 1..] {
                    if !out.overlaps.iter().any(|o| (o.0, o.1) == (i, j)) {
                        out.overlaps.push((i, j, witness()));
                    }
                }
            }
        } else {
            for &i in &members {
                if !out.outside.iter().any(|o| o.0 == i) {
                    out.outside.push((i, witness()));
                }
            }
        }
        false
    })?;
    out.overlaps.sort_by_key(|o| (o.0, o.1));
    out.outside.sort_by_key(|o| o.0);
    Ok(out)
}

/// The default universe, parsed.
pub fn default_universe() -> Lpe {
    parse(DEFAULT_UNIVERSE).expect("the default universe parses")
}

/// Analysis sets get a larger DFA budget than renderer sets: a search visits every state
/// anyway, so a DFA built once is cheaper than subsets rebuilt per visit.
fn analysis_options() -> Options {
    Options {
        dfa_budget: 64 << 20,
        ..Options::default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::macros::BASIC;

    fn lpe(s: &str) -> Lpe {
        parse(s).unwrap()
    }

    fn basic() -> Vec<(String, Lpe)> {
        BASIC.iter().map(|(n, s)| (n.to_string(), lpe(s))).collect()
    }

    #[test]
    fn emptiness_warning_for_camera_star() {
        let set = AovSet::compile(&[("c".into(), lpe("C.*")), ("ok".into(), lpe("C.*L"))]).unwrap();
        let w = set.warnings();
        assert_eq!(w.len(), 1, "{w:?}");
        assert_eq!(w[0].aov, 0);
        assert!(
            w[0].message.contains("never reaches an emitter"),
            "{}",
            w[0]
        );
    }

    #[test]
    fn emptiness_reasons() {
        let cases = [
            ("C<CD>L", "matches no vertex"),
            ("RDL", "other than the camera"),
            ("CLRDL", "in the middle"),
        ];
        for (src, needle) in cases {
            let set = AovSet::compile(&[("x".into(), lpe(src))]).unwrap();
            let w = set.warnings();
            assert_eq!(w.len(), 1, "{src}: {w:?}");
            assert!(w[0].message.contains(needle), "{src}: {}", w[0]);
        }
    }

    #[test]
    fn basic_aovs_partition_the_universe() {
        let p = partition(&basic(), &default_universe()).unwrap();
        assert!(p.is_clean(), "{p:?}");
    }

    #[test]
    fn caustics_overlap_with_a_short_witness() {
        let mut aovs = basic();
        aovs.push(("caustics".into(), lpe("CDS+[<L.>O]")));
        let p = partition(&aovs, &default_universe()).unwrap();
        assert!(p.gap.is_none() && p.outside.is_empty(), "{p:?}");
        // `D` is reflected or transmitted diffuse, so caustics lie inside indirectDiffuse
        // (`C RD S L`) and subsurface (`C TD S L`); 4 vertices is the shortest caustic.
        let pairs: Vec<(&str, &str, usize)> = p
            .overlaps
            .iter()
            .map(|(i, j, w)| (aovs[*i].0.as_str(), aovs[*j].0.as_str(), w.len()))
            .collect();
        assert_eq!(
            pairs,
            [
                ("indirectDiffuse", "caustics", 4),
                ("subsurface", "caustics", 4)
            ]
        );
    }

    #[test]
    fn comparisons() {
        let c = compare(&lpe("C.*L"), &lpe("C.*L")).unwrap();
        assert!(c.equivalent());
        let c = compare(&lpe("CD|(SD)L"), &lpe("C(D|(SD))L")).unwrap();
        assert!(c.equivalent());
        // `|` binds only its neighbours: `C(D|SD)L` is `C(D|S)DL`.
        let c = compare(&lpe("CD|(SD)L"), &lpe("C(D|SD)L")).unwrap();
        assert_eq!(c.first_only.unwrap().to_string(), "C RD1 L");
        assert_eq!(c.second_only.unwrap().to_string(), "C RD1 RD1 L");
        let c = compare(&lpe("C.+L"), &lpe("C.*L")).unwrap();
        assert_eq!(c.first_only, None);
        assert_eq!(c.second_only.unwrap().to_string(), "C L");
    }
}
