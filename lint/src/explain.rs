//! Which AOVs a path lands in, and how it got there: the path stepped through the
//! compiled set and through each AOV alone, one row per vertex (its class, the set's
//! state, the AOVs still reachable), then the AOVs it lands in or, for a path landing
//! nowhere, the longest live prefix and the closest AOV. `lpe-check explain` prints it;
//! the Python package's `AovSet.explain` returns it.

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
    let opts = lpe::Options::default();
    let set = AovSet::<D>::compile_under(aovs, registration, &opts)?;
    let alone: Vec<AovSet<D>> = aovs
        .iter()
        .map(|a| AovSet::<D>::compile_under(std::slice::from_ref(a), registration, &opts))
        .collect::<Result<_, _>>()?;
    Ok(walk(aovs, &set, &alone, D::vertices(path)))
}

/// The report of one path, `vertices`, through `set` and through each AOV `alone` (the
/// joint state only says whether any AOV is still reachable). States are numbered in the
/// order this path first reaches them, the start `s0`; `dead` once no AOV can match.
fn walk<D: Dialect>(
    aovs: &[(String, D::Lpe)],
    set: &AovSet<D>,
    alone: &[AovSet<D>],
    vertices: &[D::Vertex],
) -> Explanation {
    let mut states: Vec<_> = alone.iter().map(|a| a.start()).collect();
    // How many vertices each AOV stayed reachable through.
    let mut alive_for = vec![0usize; aovs.len()];
    let mut s = set.start();
    let mut seen: Vec<State> = vec![s];
    let mut table = Builder::default();
    table.push_record(["#", "vertex", "class", "state", "still reachable"]);
    for (k, v) in vertices.iter().enumerate() {
        let class = set.classify(v);
        s = set.step_class(s, class);
        let mut reachable = Vec::new();
        for (i, a) in alone.iter().enumerate() {
            states[i] = a.step_class(states[i], a.classify(v));
            if !a.is_dead(states[i]) {
                alive_for[i] = k + 1;
                reachable.push(aovs[i].0.as_str());
            }
        }
        let reach = if reachable.is_empty() {
            "(none: dead)".to_string()
        } else {
            reachable.join(", ")
        };
        let state = if set.is_dead(s) {
            "dead".to_string()
        } else {
            let id = seen.iter().position(|&x| x == s).unwrap_or_else(|| {
                seen.push(s);
                seen.len() - 1
            });
            format!("s{id}")
        };
        table.push_record([
            (k + 1).to_string(),
            v.to_string(),
            class.index().to_string(),
            state,
            reach,
        ]);
    }
    let landed: Vec<usize> = set.matches(s).iter().collect();
    let shown: Vec<String> = vertices.iter().map(ToString::to_string).collect();
    let mut text = format!(
        "path {} against {} AOVs\n{}\n",
        shown.join(" "),
        aovs.len(),
        table.build().with(Style::markdown())
    );
    if landed.is_empty() {
        let longest = alive_for.iter().copied().max().unwrap_or(0);
        text.push_str("lands in no AOV\n");
        if longest == 0 {
            text.push_str("no AOV can match any path starting with its first vertex\n");
        } else {
            let closest = alive_for
                .iter()
                .position(|&n| n == longest)
                .expect("the maximum is in the list");
            let how = if longest == vertices.len() {
                "still reachable after the last vertex: the path ends too early for it".to_string()
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
    } else {
        let names: Vec<&str> = landed.iter().map(|&i| aovs[i].0.as_str()).collect();
        text.push_str(&format!("lands in: {}\n", names.join(", ")));
    }
    Explanation { landed, text }
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
