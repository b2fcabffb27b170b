//! Which AOVs a path lands in, and how it got there: the path stepped through the
//! compiled set and through each AOV alone, one row per vertex (its class, the set's
//! state, the AOVs still reachable), then the AOVs it lands in or, for a path landing
//! nowhere, the longest live prefix and the closest AOV. `lpe-check explain` prints it;
//! the Python package's `AovSet.explain` returns it; the explorer's `explain` view
//! (`lpe-explore`) answers from the same [`Walk`].

use lpe::{AovSet, Dialect, State};
use tabled::builder::Builder;
use tabled::settings::Style;

/// What `explain` found.
pub struct Explanation {
    /// Indices of the AOVs the whole path matches.
    pub landed: Vec<usize>,
    /// The printed report.
    pub text: String,
}

/// Steps `path` through the set of `aovs` (parsed under `registration`) and through each
/// AOV alone.
pub fn explain<D: Dialect>(
    aovs: &[(String, D::Lpe)],
    registration: &D::Registration,
    path: &D::Path,
) -> Result<Explanation, lpe::CompileError> {
    let set = AovSet::<D>::compile_under(aovs, registration, &lpe::Options::default())?;
    let alone = alone(aovs, registration)?;
    let vertices = D::vertices(path);
    Ok(report(aovs, vertices, &walk(&set, &alone, vertices)))
}

/// Each AOV of `aovs` compiled alone, as [`walk`] steps them.
pub fn alone<D: Dialect>(
    aovs: &[(String, D::Lpe)],
    registration: &D::Registration,
) -> Result<Vec<AovSet<D>>, lpe::CompileError> {
    let opts = lpe::Options::default();
    aovs.iter()
        .map(|a| AovSet::<D>::compile_under(std::slice::from_ref(a), registration, &opts))
        .collect()
}

/// One vertex of a [`Walk`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Step {
    /// The vertex's class in the set.
    pub class: usize,
    /// The set's state after the vertex.
    pub state: State,
    /// Whether no AOV can match any continuation from `state`.
    pub dead: bool,
    /// The AOVs (indices) still reachable after the vertex, each stepped alone.
    pub reachable: Vec<usize>,
}

/// A path stepped through a set and through each of its AOVs alone.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Walk {
    /// The set's state before the first vertex.
    pub start: State,
    /// One step per vertex.
    pub steps: Vec<Step>,
    /// Indices of the AOVs the whole path matches.
    pub landed: Vec<usize>,
    /// For each AOV, how many vertices it stayed reachable through.
    pub alive_for: Vec<usize>,
}

impl Walk {
    /// For a path landing nowhere: the AOV that stayed reachable longest (the closest
    /// miss) and for how many vertices; `None` if it landed, or no AOV survived the
    /// first vertex.
    pub fn closest(&self) -> Option<(usize, usize)> {
        if !self.landed.is_empty() {
            return None;
        }
        let longest = self.alive_for.iter().copied().max().unwrap_or(0);
        if longest == 0 {
            return None;
        }
        let aov = self.alive_for.iter().position(|&n| n == longest)?;
        Some((aov, longest))
    }
}

/// Steps `vertices` through `set` and through each AOV `alone` (in the set's order; the
/// joint state only says whether any AOV is still reachable).
pub fn walk<D: Dialect>(set: &AovSet<D>, alone: &[AovSet<D>], vertices: &[D::Vertex]) -> Walk {
    let mut states: Vec<_> = alone.iter().map(|a| a.start()).collect();
    let mut alive_for = vec![0usize; alone.len()];
    let mut s = set.start();
    let mut steps = Vec::with_capacity(vertices.len());
    for (k, v) in vertices.iter().enumerate() {
        let class = set.classify(v);
        s = set.step_class(s, class);
        let mut reachable = Vec::new();
        for (i, a) in alone.iter().enumerate() {
            states[i] = a.step_class(states[i], a.classify(v));
            if !a.is_dead(states[i]) {
                alive_for[i] = k + 1;
                reachable.push(i);
            }
        }
        steps.push(Step {
            class: class.index(),
            state: s,
            dead: set.is_dead(s),
            reachable,
        });
    }
    Walk {
        start: set.start(),
        steps,
        landed: set.matches(s).iter().collect(),
        alive_for,
    }
}

/// The printed report of `walk`, the path `vertices` through the set of `aovs`. States
/// are numbered in the order this path first reaches them, the start `s0`; `dead` once
/// no AOV can match.
fn report<E>(aovs: &[(String, E)], vertices: &[impl ToString], walk: &Walk) -> Explanation {
    let mut seen: Vec<State> = vec![walk.start];
    let mut table = Builder::default();
    table.push_record(["#", "vertex", "class", "state", "still reachable"]);
    for (k, (v, step)) in vertices.iter().zip(&walk.steps).enumerate() {
        let reach = if step.reachable.is_empty() {
            "(none: dead)".to_string()
        } else {
            let names: Vec<&str> = step.reachable.iter().map(|&i| aovs[i].0.as_str()).collect();
            names.join(", ")
        };
        let state = if step.dead {
            "dead".to_string()
        } else {
            let id = seen
                .iter()
                .position(|&x| x == step.state)
                .unwrap_or_else(|| {
                    seen.push(step.state);
                    seen.len() - 1
                });
            format!("s{id}")
        };
        table.push_record([
            (k + 1).to_string(),
            v.to_string(),
            step.class.to_string(),
            state,
            reach,
        ]);
    }
    let shown: Vec<String> = vertices.iter().map(ToString::to_string).collect();
    let mut text = format!(
        "path {} against {} AOVs\n{}\n",
        shown.join(" "),
        aovs.len(),
        table.build().with(Style::markdown())
    );
    if walk.landed.is_empty() {
        text.push_str("lands in no AOV\n");
        match walk.closest() {
            None => text.push_str("no AOV can match any path starting with its first vertex\n"),
            Some((closest, longest)) => {
                let how = if longest == vertices.len() {
                    "still reachable after the last vertex: the path ends too early for it"
                        .to_string()
                } else {
                    format!("dead at vertex {}", longest + 1)
                };
                text.push_str(&format!(
                    "longest live prefix: {} ({longest} of {} vertices)\nclosest AOV: {} ({how})\n",
                    shown[..longest].join(" "),
                    vertices.len(),
                    aovs[closest].0
                ));
            }
        }
    } else {
        let names: Vec<&str> = walk.landed.iter().map(|&i| aovs[i].0.as_str()).collect();
        text.push_str(&format!("lands in: {}\n", names.join(", ")));
    }
    Explanation {
        landed: walk.landed.clone(),
        text,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use lpe::renderman::{Lpe, Parser, RenderMan};

    fn aovs(list: &[(&str, &str)]) -> Vec<(String, Lpe)> {
        list.iter()
            .map(|(n, e)| (n.to_string(), lpe::renderman::parse(e).unwrap()))
            .collect()
    }

    #[test]
    fn a_landing_path_names_its_aovs() {
        let a = aovs(&[
            ("direct", "C<RD>L"),
            ("indirect", "C<RD>.+L"),
            ("any", "C.*L"),
        ]);
        let e =
            explain::<RenderMan>(&a, &Parser::default(), &"C RD RS L".parse().unwrap()).unwrap();
        assert_eq!(e.landed, [1, 2]);
        assert!(e.text.ends_with("lands in: indirect, any\n"), "{}", e.text);
        // After `C RD`, direct is still reachable; after `C RD RS` it is not.
        let reach: Vec<&str> = e
            .text
            .lines()
            .filter(|l| l.starts_with("| "))
            .skip(1)
            .map(|l| l.trim_end_matches('|').rsplit('|').next().unwrap().trim())
            .collect();
        assert_eq!(
            reach,
            [
                "direct, indirect, any",
                "direct, indirect, any",
                "indirect, any",
                "indirect, any"
            ]
        );
    }

    #[test]
    fn a_missing_path_gets_its_closest_aov() {
        let a = aovs(&[("spec", "C<RS>L"), ("diffuse2", "C<RD><RD>L")]);
        let e =
            explain::<RenderMan>(&a, &Parser::default(), &"C RD RS L".parse().unwrap()).unwrap();
        assert!(e.landed.is_empty());
        assert!(
            e.text.contains("longest live prefix: C RD1 (2 of 4 vertices)\nclosest AOV: diffuse2 (dead at vertex 3)\n"),
            "{}",
            e.text
        );
        // Dead states ignore the path shape: an AOV asking for more after the emitter
        // is still reachable when the path ends.
        let a = aovs(&[("spec", "C<RS>L"), ("twice", "C<RD>L<RD>L")]);
        let e = explain::<RenderMan>(&a, &Parser::default(), &"C RD L".parse().unwrap()).unwrap();
        assert!(
            e.text
                .contains("closest AOV: twice (still reachable after the last vertex"),
            "{}",
            e.text
        );
    }
}
