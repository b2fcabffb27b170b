//! Greedy minimization of a disagreement: simpler expressions, fewer set members,
//! shorter and less labelled paths ([`super::shrink`]), for as long as the engines still
//! disagree.

use super::answers::answers_in;
use lpe::Dialect;

use crate::dialect::ShrinkDialect;
use crate::engine::Engine;

/// Whether at least two engines that build give different answers on `path`.
fn disagrees<D: Dialect>(
    engines: &[&dyn Engine<D>],
    registration: &D::Registration,
    exprs: &[D::Lpe],
    path: &D::Path,
) -> bool {
    let answers: Vec<Vec<bool>> = answers_in(engines, registration, exprs, path)
        .into_iter()
        .filter_map(|(_, a)| a.ok())
        .collect();
    answers.windows(2).any(|w| w[0] != w[1])
}

/// Most candidate inputs the minimizer tries (each compiles every engine once).
const MAX_SHRINK_TRIES: usize = 20_000;

/// Greedy minimization: take the first simpler input on which the engines still
/// disagree, and start again from it, until no simpler input disagrees.
pub fn minimize_in<D: ShrinkDialect>(
    engines: &[&dyn Engine<D>],
    registration: &D::Registration,
    exprs: Vec<D::Lpe>,
    path: D::Path,
) -> (Vec<D::Lpe>, D::Path) {
    minimize_by::<D>(registration, exprs, path, |exprs, path| {
        disagrees(engines, registration, exprs, path)
    })
}

/// Greedy minimization against any failure test: take the first simpler input (fewer
/// expressions, a simpler expression, a shorter or less labelled path, or an expression
/// and a path step together) on which `fails` still holds, and start again from it,
/// until no simpler input fails. `lpe-check diff --external` passes a test that re-asks
/// the external process.
pub fn minimize_by<D: ShrinkDialect>(
    registration: &D::Registration,
    mut exprs: Vec<D::Lpe>,
    mut path: D::Path,
    mut fails: impl FnMut(&[D::Lpe], &D::Path) -> bool,
) -> (Vec<D::Lpe>, D::Path) {
    let mut tries = 0;
    'outer: loop {
        // Fewer expressions first: a set of one is easiest to read.
        if exprs.len() > 1 {
            for i in 0..exprs.len() {
                let mut fewer = exprs.clone();
                fewer.remove(i);
                tries += 1;
                if fails(&fewer, &path) {
                    exprs = fewer;
                    continue 'outer;
                }
            }
        }
        for i in 0..exprs.len() {
            for smaller in D::shrink_expr(&exprs[i], registration) {
                if tries >= MAX_SHRINK_TRIES {
                    break 'outer;
                }
                tries += 1;
                let mut candidate = exprs.clone();
                candidate[i] = smaller;
                if fails(&candidate, &path) {
                    exprs = candidate;
                    continue 'outer;
                }
            }
        }
        let smaller_paths = D::shrink_path(&path);
        for smaller in &smaller_paths {
            if tries >= MAX_SHRINK_TRIES {
                break 'outer;
            }
            tries += 1;
            if fails(&exprs, smaller) {
                path = smaller.clone();
                continue 'outer;
            }
        }
        // Joint steps: dropping an atom often needs the vertex it matched dropped too
        // (`C.'a'L` on `C RD RD'b' L` -> `C'a'L` on `C RD'b' L`).
        for i in 0..exprs.len() {
            for smaller in D::shrink_expr(&exprs[i], registration) {
                for smaller_path in &smaller_paths {
                    if tries >= MAX_SHRINK_TRIES {
                        break 'outer;
                    }
                    tries += 1;
                    let mut candidate = exprs.clone();
                    candidate[i] = smaller.clone();
                    if fails(&candidate, smaller_path) {
                        exprs = candidate;
                        path = smaller_path.clone();
                        continue 'outer;
                    }
                }
            }
        }
        break;
    }
    (exprs, path)
}

#[cfg(test)]
mod tests {
    use super::*;
    use lpe::renderman::{Lpe, Path, RenderMan};

    use crate::adapters::Reference;
    use crate::differential::tests::LabelBlind;
    use crate::differential::{check_with, Outcome};

    #[test]
    fn a_planted_bug_is_found_and_minimized() {
        let engines: Vec<&dyn Engine<RenderMan>> = vec![&Reference, &LabelBlind];
        let e = lpe::renderman::parse("unoccluded;C(<RD>|<TS>)*'floor'(.|U2)+[<L.>O]").unwrap();
        let p: Path = "C RD TS RD'wall' RS1 TS2 L".parse().unwrap();
        let Outcome::Disagree(c) = check_with(&engines, std::slice::from_ref(&e), &[p]) else {
            panic!("the planted bug went unnoticed");
        };
        // Down to a label item against a vertex with another label, between the
        // camera and the emitter (the joint expression+path steps drop the `.`s).
        assert_eq!(c.exprs.len(), 1);
        assert_eq!(c.exprs[0].to_string(), "C'floor'<L.>");
        assert_eq!(c.path.len(), 3, "{}", c.path);
        assert_ne!(c.path.vertices()[1].label(), Some("floor"));
        let text = c.to_string();
        assert!(text.contains("reference: no-match"), "{text}");
        assert!(text.contains("label-blind: match"), "{text}");
    }

    #[test]
    fn the_failure_test_is_asked_at_most_the_try_budget() {
        // A failure test that never holds: each candidate is asked once, until the budget
        // runs out, and the input comes back unchanged.
        let exprs: Vec<Lpe> = ["C(<RD>'a')*.'b'.'c'.'d'[<L.>O]", "C.{2,5}'e'+L"]
            .iter()
            .map(|s| lpe::renderman::parse(s).unwrap())
            .collect();
        let path: Path = format!("C {}L'key'", "RD1'w' ".repeat(300))
            .parse()
            .unwrap();
        // The premise: more candidates than the budget, counting the first loop's two
        // (set members dropped) that are asked before the budget is first checked.
        let reg = Default::default();
        let paths = RenderMan::shrink_path(&path).len();
        let expr_steps: usize = exprs
            .iter()
            .map(|e| RenderMan::shrink_expr(e, &reg).len())
            .sum();
        assert!(
            2 + expr_steps + paths + expr_steps * paths > MAX_SHRINK_TRIES + 2,
            "{expr_steps} {paths}"
        );
        let mut asked = 0;
        let (e, p) = minimize_by::<RenderMan>(&reg, exprs.clone(), path.clone(), |_, _| {
            asked += 1;
            false
        });
        assert_eq!(asked, MAX_SHRINK_TRIES);
        assert_eq!((e, p), (exprs, path));
    }

    #[test]
    fn sets_shrink_to_the_member_that_disagrees() {
        let engines: Vec<&dyn Engine<RenderMan>> = vec![&Reference, &LabelBlind];
        let exprs: Vec<Lpe> = ["C<RD>[<L.>O]", "C'key'L", "CD+L"]
            .iter()
            .map(|s| lpe::renderman::parse(s).unwrap())
            .collect();
        let p: Path = "C RD'fill' L".parse().unwrap();
        let Outcome::Disagree(c) = check_with(&engines, &exprs, &[p]) else {
            panic!("the planted bug went unnoticed");
        };
        assert_eq!(c.exprs.len(), 1);
        assert_eq!(c.exprs[0].to_string(), "C'key'L");
        assert_eq!(c.path.to_string(), "C RD1 L");
    }
}
