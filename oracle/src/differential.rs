//! The differential harness: every engine on the same expressions and paths.
//!
//! [`check`] (one expression) and [`check_set`] (an AOV set compiled at once) run each
//! engine of [`engine::all`] and compare the answers path by path. Agreement comes back
//! with counts (pairs compared, how many matched, which engines could not build); a
//! disagreement comes back **minimized**: expression subtrees are dropped or simplified,
//! set members dropped, and path vertices dropped or unlabelled, for as long as the
//! engines still disagree, so what is printed is small enough to read.
//!
//! An engine that cannot build the input ([`EngineError::CannotBuild`](crate::engine::EngineError::CannotBuild)) does not take part
//! in that comparison; the skip is recorded in [`Agreement::skipped`] and reported by
//! callers, never hidden.

use std::fmt;

use lpe::ast::{Atom, EventPos, Expr, Item, LabelPos, Repetition, TypePos};
use lpe::{Lpe, Path};

use crate::engine::{self, Engine};

/// What agreeing engines found.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Agreement {
    /// Expression/path pairs compared.
    pub pairs: usize,
    /// Pairs that matched (by the agreed answer).
    pub matched: usize,
    /// Engines that could not build the set, with their reason.
    pub skipped: Vec<(&'static str, String)>,
    /// How many engines answered (built the set).
    pub engines: usize,
}

/// Engines that disagree, on a minimized input.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Counterexample {
    /// The minimized expressions (one for [`check`]).
    pub exprs: Vec<Lpe>,
    /// The minimized path.
    pub path: Path,
    /// Each engine's answer per expression on `path`, or why it could not build.
    pub answers: Vec<(&'static str, Result<Vec<bool>, String>)>,
    /// The input before minimization.
    pub original: (Vec<Lpe>, Path),
}

/// The result of a differential check.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// All engines that could build agree on every path.
    Agree(Agreement),
    /// Two engines differ; minimized.
    Disagree(Box<Counterexample>),
}

impl Outcome {
    /// True for [`Outcome::Agree`].
    pub fn is_agreement(&self) -> bool {
        matches!(self, Outcome::Agree(_))
    }
}

/// Runs every engine on one expression.
pub fn check(expr: &Lpe, paths: &[Path]) -> Outcome {
    check_set(std::slice::from_ref(expr), paths)
}

/// Runs every engine on an AOV set compiled as one.
pub fn check_set(exprs: &[Lpe], paths: &[Path]) -> Outcome {
    check_with(&engine::all(), exprs, paths)
}

/// Runs the given engines on an AOV set compiled as one.
pub fn check_with(engines: &[&dyn Engine], exprs: &[Lpe], paths: &[Path]) -> Outcome {
    let mut built = Vec::new();
    let mut skipped = Vec::new();
    for e in engines {
        match e.compile(exprs) {
            Ok(m) => built.push((e.name(), m)),
            Err(why) => skipped.push((e.name(), why.to_string())),
        }
    }
    let mut agreement = Agreement {
        skipped,
        engines: built.len(),
        ..Agreement::default()
    };
    for path in paths {
        let answers: Vec<Vec<bool>> = built.iter().map(|(_, m)| m.which(path)).collect();
        if answers.windows(2).any(|w| w[0] != w[1]) {
            let original = (exprs.to_vec(), path.clone());
            let (exprs, path) = minimize(engines, exprs.to_vec(), path.clone());
            return Outcome::Disagree(Box::new(Counterexample {
                answers: answers_of(engines, &exprs, &path),
                exprs,
                path,
                original,
            }));
        }
        if let Some(first) = answers.first() {
            agreement.pairs += first.len();
            agreement.matched += first.iter().filter(|&&b| b).count();
        }
    }
    Outcome::Agree(agreement)
}

/// Each engine's answers on one path, or its build error.
pub fn answers_of(
    engines: &[&dyn Engine],
    exprs: &[Lpe],
    path: &Path,
) -> Vec<(&'static str, Result<Vec<bool>, String>)> {
    engines
        .iter()
        .map(|e| {
            let answer = e
                .compile(exprs)
                .map(|m| m.which(path))
                .map_err(|why| why.to_string());
            (e.name(), answer)
        })
        .collect()
}

/// Whether at least two engines that build give different answers on `path`.
fn disagrees(engines: &[&dyn Engine], exprs: &[Lpe], path: &Path) -> bool {
    let answers: Vec<Vec<bool>> = answers_of(engines, exprs, path)
        .into_iter()
        .filter_map(|(_, a)| a.ok())
        .collect();
    answers.windows(2).any(|w| w[0] != w[1])
}

/// Most candidate inputs the minimizer tries (each compiles every engine once).
const MAX_SHRINK_TRIES: usize = 20_000;

/// Greedy minimization: take the first simpler input on which the engines still
/// disagree, and start again from it, until no simpler input disagrees.
pub fn minimize(engines: &[&dyn Engine], mut exprs: Vec<Lpe>, mut path: Path) -> (Vec<Lpe>, Path) {
    let mut tries = 0;
    'outer: loop {
        // Fewer expressions first: a set of one is easiest to read.
        if exprs.len() > 1 {
            for i in 0..exprs.len() {
                let mut fewer = exprs.clone();
                fewer.remove(i);
                tries += 1;
                if disagrees(engines, &fewer, &path) {
                    exprs = fewer;
                    continue 'outer;
                }
            }
        }
        for i in 0..exprs.len() {
            for smaller in shrink_expr(&exprs[i].expr) {
                if tries >= MAX_SHRINK_TRIES {
                    break 'outer;
                }
                tries += 1;
                let mut candidate = exprs.clone();
                candidate[i] = Lpe {
                    prefixes: lpe::Prefixes::NONE,
                    expr: smaller,
                };
                if disagrees(engines, &candidate, &path) {
                    exprs = candidate;
                    continue 'outer;
                }
            }
            // Prefixes never affect matching; drop them for readability.
            if !exprs[i].prefixes.is_empty() {
                let mut candidate = exprs.clone();
                candidate[i].prefixes = lpe::Prefixes::NONE;
                if disagrees(engines, &candidate, &path) {
                    exprs = candidate;
                    continue 'outer;
                }
            }
        }
        let smaller_paths = shrink_path(&path);
        for smaller in &smaller_paths {
            if tries >= MAX_SHRINK_TRIES {
                break 'outer;
            }
            tries += 1;
            if disagrees(engines, &exprs, smaller) {
                path = smaller.clone();
                continue 'outer;
            }
        }
        // Joint steps: dropping an atom often needs the vertex it matched dropped too
        // (`C.'a'L` on `C RD RD'b' L` -> `C'a'L` on `C RD'b' L`).
        for i in 0..exprs.len() {
            for smaller in shrink_expr(&exprs[i].expr) {
                for smaller_path in &smaller_paths {
                    if tries >= MAX_SHRINK_TRIES {
                        break 'outer;
                    }
                    tries += 1;
                    let mut candidate = exprs.clone();
                    candidate[i].expr = smaller.clone();
                    if disagrees(engines, &candidate, smaller_path) {
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

/// Simpler paths: one interior vertex dropped, or one label removed.
pub fn shrink_path(path: &Path) -> Vec<Path> {
    let v = path.vertices();
    let mut out = Vec::new();
    for i in 1..v.len().saturating_sub(1) {
        let mut w = v.to_vec();
        w.remove(i);
        out.extend(Path::new(w).ok());
    }
    for i in 0..v.len() {
        if v[i].label().is_some() {
            let mut w = v.to_vec();
            w[i] = match w[i].event() {
                Some(e) => lpe::Vertex::scatter(w[i].ty(), e, None),
                None if w[i].ty() == lpe::VertexType::L => lpe::Vertex::light(None),
                None => lpe::Vertex::emissive(None),
            };
            out.extend(Path::new(w).ok());
        }
    }
    out
}

/// One-step simplifications of an expression, whole subtrees first. Every candidate
/// is normalized and strictly simpler (fewer nodes, fewer items, looser positions or
/// smaller counts), so repeated shrinking terminates.
pub fn shrink_expr(e: &Expr) -> Vec<Expr> {
    let mut out = Vec::new();
    match e {
        Expr::Atom(a) => {
            out.extend(shrink_atom(a).into_iter().map(Expr::Atom));
        }
        Expr::Concat(es) | Expr::Alt(es) => {
            let rebuild = |parts: Vec<Expr>| match e {
                Expr::Concat(_) => Expr::concat(parts),
                _ => Expr::alt(parts),
            };
            out.extend(es.iter().cloned());
            for i in 0..es.len() {
                let mut fewer = es.clone();
                fewer.remove(i);
                out.push(rebuild(fewer));
            }
            for i in 0..es.len() {
                for smaller in shrink_expr(&es[i]) {
                    let mut parts = es.clone();
                    parts[i] = smaller;
                    out.push(rebuild(parts));
                }
            }
        }
        Expr::Repeat(body, r) => {
            out.push((**body).clone());
            for r2 in shrink_repetition(*r) {
                out.push(Expr::Repeat(body.clone(), r2));
            }
            for smaller in shrink_expr(body) {
                out.push(Expr::Repeat(Box::new(smaller), *r));
            }
        }
    }
    out
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

fn shrink_atom(a: &Atom) -> Vec<Atom> {
    let mut out = Vec::new();
    match a {
        Atom::Item(i) => out.extend(shrink_item(i).into_iter().map(Atom::Item)),
        Atom::Class { negated, items } => {
            if !negated {
                out.extend(items.iter().cloned().map(Atom::Item));
            }
            if items.len() > 1 {
                for i in 0..items.len() {
                    let mut fewer = items.clone();
                    fewer.remove(i);
                    out.push(Atom::Class {
                        negated: *negated,
                        items: fewer,
                    });
                }
            }
            for i in 0..items.len() {
                for smaller in shrink_item(&items[i]) {
                    let mut parts = items.clone();
                    parts[i] = smaller;
                    out.push(Atom::Class {
                        negated: *negated,
                        items: parts,
                    });
                }
            }
        }
    }
    out
}

fn shrink_item(i: &Item) -> Vec<Item> {
    let mut out = Vec::new();
    if let Item::Triple(t) = i {
        if t.ty != TypePos::Any {
            let mut u = t.clone();
            u.ty = TypePos::Any;
            out.push(Item::Triple(u));
        }
        if t.event != EventPos::Any {
            let mut u = t.clone();
            u.event = EventPos::Any;
            out.push(Item::Triple(u));
        }
        if t.label != LabelPos::Any {
            let mut u = t.clone();
            u.label = LabelPos::Any;
            out.push(Item::Triple(u));
        }
    }
    out
}

impl fmt::Display for Counterexample {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "engines disagree (minimized):")?;
        for (i, e) in self.exprs.iter().enumerate() {
            writeln!(f, "  expression {i}: {e}")?;
        }
        writeln!(f, "  path:         {}", self.path)?;
        for (name, answer) in &self.answers {
            match answer {
                Ok(bits) => {
                    let shown: Vec<&str> = bits
                        .iter()
                        .map(|&b| if b { "match" } else { "no-match" })
                        .collect();
                    writeln!(f, "  {name:>12}: {}", shown.join(" "))?;
                }
                Err(why) => writeln!(f, "  {name:>12}: skipped ({why})")?,
            }
        }
        writeln!(f, "  from the original case:")?;
        for (i, e) in self.original.0.iter().enumerate() {
            writeln!(f, "    expression {i}: {e}")?;
        }
        write!(f, "    path:         {}", self.original.1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::{EngineError, Matcher, ReferenceMatcher};

    /// A deliberately wrong engine: it ignores labels in `'g'` items by answering like
    /// the reference on the expression with every label item replaced by `.`.
    struct LabelBlind;

    impl Engine for LabelBlind {
        fn name(&self) -> &'static str {
            "label-blind"
        }
        fn compile(&self, exprs: &[Lpe]) -> Result<Box<dyn Matcher + '_>, EngineError> {
            let mut blind = exprs.to_vec();
            for e in &mut blind {
                e.expr.for_each_atom_mut(&mut |a| {
                    if matches!(a, Atom::Item(Item::Label(_))) {
                        *a = Atom::Item(Item::Any);
                    }
                });
            }
            Ok(Box::new(ReferenceMatcher(blind)))
        }
    }

    #[test]
    fn agreement_counts_pairs_and_matches() {
        let e = lpe::parse("C<RD>[<L.>O]").unwrap();
        let paths: Vec<Path> = ["C RD L", "C RS L", "C RD O'x'"]
            .iter()
            .map(|p| p.parse().unwrap())
            .collect();
        match check(&e, &paths) {
            Outcome::Agree(a) => {
                assert_eq!(a.pairs, 3);
                assert_eq!(a.matched, 2);
                assert!(a.skipped.is_empty());
                assert_eq!(a.engines, engine::all().len());
            }
            Outcome::Disagree(c) => panic!("{c}"),
        }
    }

    #[test]
    fn a_planted_bug_is_found_and_minimized() {
        let engines: Vec<&dyn Engine> = vec![&engine::Reference, &LabelBlind];
        let e = lpe::parse("unoccluded;C(<RD>|<TS>)*'floor'(.|U2)+[<L.>O]").unwrap();
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
    fn sets_shrink_to_the_member_that_disagrees() {
        let engines: Vec<&dyn Engine> = vec![&engine::Reference, &LabelBlind];
        let exprs: Vec<Lpe> = ["C<RD>[<L.>O]", "C'key'L", "CD+L"]
            .iter()
            .map(|s| lpe::parse(s).unwrap())
            .collect();
        let p: Path = "C RD'fill' L".parse().unwrap();
        let Outcome::Disagree(c) = check_with(&engines, &exprs, &[p]) else {
            panic!("the planted bug went unnoticed");
        };
        assert_eq!(c.exprs.len(), 1);
        assert_eq!(c.exprs[0].to_string(), "C'key'L");
        assert_eq!(c.path.to_string(), "C RD1 L");
    }

    /// What every step of [`shrink_expr`] lowers, compared lexicographically: nodes,
    /// then item slots (a class counts one more than its items, so `[x]` -> `x` is a
    /// step), then specific triple positions, then the sum of repetition bounds.
    /// Tuples of naturals under this order have no infinite descending chain, so a
    /// strict decrease on every step proves that shrinking terminates.
    fn measure(e: &Expr) -> (usize, usize, usize, u64) {
        fn item_positions(i: &Item) -> usize {
            match i {
                Item::Triple(t) => {
                    usize::from(t.ty != TypePos::Any)
                        + usize::from(t.event != EventPos::Any)
                        + usize::from(t.label != LabelPos::Any)
                }
                _ => 0,
            }
        }
        match e {
            Expr::Atom(Atom::Item(i)) => (1, 1, item_positions(i), 0),
            Expr::Atom(Atom::Class { items, .. }) => (
                1,
                items.len() + 1,
                items.iter().map(item_positions).sum(),
                0,
            ),
            Expr::Concat(es) | Expr::Alt(es) => es
                .iter()
                .map(measure)
                .fold((1, 0, 0, 0), |(n, i, p, c), (n2, i2, p2, c2)| {
                    (n + n2, i + i2, p + p2, c + c2)
                }),
            Expr::Repeat(body, r) => {
                let (n, i, p, c) = measure(body);
                let bounds = u64::from(r.min) + u64::from(r.max.unwrap_or(0));
                (n + 1, i, p, c + bounds)
            }
        }
    }

    #[test]
    fn shrinking_terminates_and_stays_normalized() {
        let e = lpe::parse("C([^D'a'<T[^D2]['x']>]|(S{2,7})*)+L")
            .unwrap()
            .expr;
        let mut frontier = vec![e];
        let mut seen = 0;
        while let Some(x) = frontier.pop() {
            seen += 1;
            assert!(seen < 200_000, "shrinking does not terminate");
            for y in shrink_expr(&x) {
                assert!(measure(&y) < measure(&x), "{y} is no smaller than {x}");
                let text = y.to_string();
                assert_eq!(lpe::parse(&text).unwrap().expr, y, "{text}");
                if seen < 2000 {
                    frontier.push(y);
                }
            }
        }
    }
}
