//! The `paths` view: per AOV, the shortest paths it matches (a few) and its near misses,
//! paths one edit away from its shortest path that it does not match (and where they
//! land instead).
//!
//! The paths are walked breadth-first through the list's automaton, one class at a
//! time, each class written as its representative vertex (the vertex `graph` shows for
//! it); a walk counts as a path only if its text reads back as a path of the dialect
//! (RenderMan's: a camera, scattering vertices, one emitter) and the set and the
//! reference matcher both say the AOV matches it. So every path shown is real; an AOV
//! whose paths need other vertices than the representatives (or are longer than
//! [`MAX_LENGTH`]) shows none.

use lpe::{AovSet, Dialect, State};
use lpe_lint::witness::Checked;
use serde::Serialize;

use crate::automaton::classes;
use crate::list::{ExploreDialect, Parsed};
use crate::request::{ApiError, Request, Setting};

/// Shortest paths shown per AOV.
pub const SHORTEST: usize = 3;
/// Near misses shown per AOV.
pub const NEAR_MISSES: usize = 5;
/// The longest walk searched, in vertices.
pub const MAX_LENGTH: usize = 12;
/// Automaton steps the whole search may take: with the walks kept per state bounded
/// by [`SHORTEST`], a 32-AOV list needs about 10 000.
pub const MAX_STEPS: usize = 1_000_000;

/// The `paths` view's answer.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct Paths {
    /// One entry per AOV, in the list's order.
    pub aovs: Vec<AovPaths>,
    /// Whether the search stopped at [`MAX_STEPS`] before every AOV had its paths.
    pub truncated: bool,
}

/// One AOV's paths.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct AovPaths {
    /// The AOV's name.
    pub name: String,
    /// Its shortest paths, shortest first.
    pub shortest: Vec<String>,
    /// Paths one edit from its first shortest path that it does not match.
    pub near_misses: Vec<NearMiss>,
}

/// A path one edit from an AOV's shortest path, which the AOV does not match.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
pub struct NearMiss {
    /// The path.
    pub path: String,
    /// The edit: `delete vertex 2 (RD1)`, `replace vertex 2 (RD1) by RS1`, `insert RS1
    /// before vertex 3`.
    pub edit: String,
    /// The AOVs of the list it lands in instead.
    pub lands_in: Vec<String>,
}

/// The `paths` view of a request: 422 when the list does not parse or compile.
pub(crate) fn paths_in<D: ExploreDialect>(
    request: &Request,
    setting: &Setting,
) -> Result<Paths, ApiError> {
    let parsed = Parsed::<D>::read(request, setting);
    let set = parsed.compile()?;
    Ok(paths_of(&set))
}

/// The paths of every AOV of a compiled set.
pub fn paths_of<D: Dialect + Checked>(set: &AovSet<D>) -> Paths {
    let reps: Vec<D::Vertex> = (0..set.class_count())
        .filter_map(|c| set.class_vertex(c))
        .collect();
    let (found, truncated) = shortest(set, &reps);
    let aovs = found
        .into_iter()
        .enumerate()
        .map(|(i, walks)| {
            let near_misses = walks
                .first()
                .map_or_else(Vec::new, |w| near_misses(set, &reps, i, w));
            AovPaths {
                name: set.names()[i].clone(),
                shortest: walks
                    .iter()
                    .filter_map(|w| path_of::<D>(w))
                    .map(|p| p.to_string())
                    .collect(),
                near_misses,
            }
        })
        .collect();
    Paths { aovs, truncated }
}

/// The path of `vertices` if its text reads back as a path of the dialect and AOV `i`
/// of `set` matches it, by the set and by the reference matcher.
fn confirmed<D: Dialect + Checked>(set: &AovSet<D>, i: usize, vertices: &[D::Vertex]) -> bool {
    let Some(path) = path_of::<D>(vertices) else {
        return false;
    };
    set.match_path(&path).contains(i) && D::reference_match(&set.lpes()[i], &path)
}

/// The path of `vertices`, if their text reads as one: both dialects write a path as
/// its vertices separated by spaces (`C RD1 L`, `C,_ R,D L,_`), and their path readers
/// refuse what is no path (`Dialect::path` would panic on it instead).
fn path_of<D: Dialect>(vertices: &[D::Vertex]) -> Option<D::Path> {
    let text: Vec<String> = vertices.iter().map(ToString::to_string).collect();
    text.join(" ").parse().ok()
}

/// Up to [`SHORTEST`] shortest confirmed walks per AOV, breadth-first over the
/// automaton with each state keeping at most [`SHORTEST`] walks per length (a walk is
/// its vertices); whether [`MAX_STEPS`] stopped the search.
fn shortest<D: Dialect + Checked>(
    set: &AovSet<D>,
    reps: &[D::Vertex],
) -> (Vec<Vec<Vec<D::Vertex>>>, bool) {
    let classes = classes(set);
    let mut found: Vec<Vec<Vec<D::Vertex>>> = vec![Vec::new(); set.len()];
    let mut frontier: Vec<(State, Vec<D::Vertex>)> = vec![(set.start(), Vec::new())];
    let mut steps = 0usize;
    for _ in 0..MAX_LENGTH {
        let mut next: Vec<(State, Vec<D::Vertex>)> = Vec::new();
        let mut kept: std::collections::HashMap<State, usize> = Default::default();
        for (s, walk) in &frontier {
            for (class, v) in classes.iter().zip(reps) {
                steps += 1;
                if steps > MAX_STEPS {
                    return (found, true);
                }
                let t = set.step_class(*s, *class);
                if set.is_dead(t) {
                    continue;
                }
                let mut longer = walk.clone();
                longer.push(v.clone());
                for i in set.matches(t).iter() {
                    if found[i].len() < SHORTEST && confirmed(set, i, &longer) {
                        found[i].push(longer.clone());
                    }
                }
                let n = kept.entry(t).or_default();
                if *n < SHORTEST {
                    *n += 1;
                    next.push((t, longer));
                }
            }
        }
        if next.is_empty() || found.iter().all(|f| f.len() >= SHORTEST) {
            break;
        }
        frontier = next;
    }
    (found, false)
}

/// The near misses of AOV `i` around its shortest walk `walk`: each vertex deleted,
/// replaced by another class's representative, or another inserted before it, in that
/// order, kept when it reads as a path the AOV does not match.
fn near_misses<D: Dialect + Checked>(
    set: &AovSet<D>,
    reps: &[D::Vertex],
    i: usize,
    walk: &[D::Vertex],
) -> Vec<NearMiss> {
    let mut candidates: Vec<(Vec<D::Vertex>, String)> = Vec::new();
    for (k, v) in walk.iter().enumerate() {
        let mut shorter = walk.to_vec();
        shorter.remove(k);
        candidates.push((shorter, format!("delete vertex {} ({v})", k + 1)));
    }
    for (k, v) in walk.iter().enumerate() {
        for r in reps.iter().filter(|r| *r != v) {
            let mut other = walk.to_vec();
            other[k] = r.clone();
            candidates.push((other, format!("replace vertex {} ({v}) by {r}", k + 1)));
        }
    }
    for k in 0..=walk.len() {
        for r in reps {
            let mut longer = walk.to_vec();
            longer.insert(k, r.clone());
            let at = if k == walk.len() {
                "at the end".to_string()
            } else {
                format!("before vertex {}", k + 1)
            };
            candidates.push((longer, format!("insert {r} {at}")));
        }
    }
    let mut out: Vec<NearMiss> = Vec::new();
    for (vertices, edit) in candidates {
        if out.len() >= NEAR_MISSES {
            break;
        }
        let Some(path) = path_of::<D>(&vertices) else {
            continue;
        };
        let landed = set.match_path(&path);
        let text = path.to_string();
        if landed.contains(i)
            || D::reference_match(&set.lpes()[i], &path)
            || out.iter().any(|m| m.path == text)
        {
            continue;
        }
        out.push(NearMiss {
            path: text,
            edit,
            lands_in: landed
                .iter()
                .filter_map(|j| set.names().get(j).cloned())
                .collect(),
        });
    }
    out
}
