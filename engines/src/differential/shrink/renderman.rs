//! One-step simplifications of RenderMan expressions and paths, for the minimizer.
//!
//! Every candidate is normalized and strictly simpler than what it came from, so that
//! repeated shrinking terminates and its printed text parses back to it.

use lpe::renderman::ast::{Atom, EventPos, Expr, Item, LabelPos, TypePos};
use lpe::renderman::{Lpe, Path, Prefixes, Vertex, VertexType};

use super::{shrink_parts, shrink_repeat, shrink_set_expr};

/// Simpler expressions, without prefixes ([`shrink_set_expr`] with [`shrink_expr`] on
/// each operand).
pub fn shrink_lpe(l: &Lpe) -> Vec<Lpe> {
    shrink_set_expr(l, shrink_expr, |t| Lpe::from_algebra(Prefixes::NONE, t))
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
                Some(e) => Vertex::scatter(w[i].ty(), e, None),
                None if w[i].ty() == VertexType::L => Vertex::light(None),
                None => Vertex::emissive(None),
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
            shrink_parts(es, rebuild, shrink_expr, &mut out);
        }
        Expr::Repeat(body, r) => shrink_repeat(
            &**body,
            *r,
            |b, r| Expr::Repeat(Box::new(b), r),
            shrink_expr,
            &mut out,
        ),
    }
    out
}

fn shrink_atom(a: &Atom) -> Vec<Atom> {
    let mut out = Vec::new();
    match a {
        Atom::Item(i) => out.extend(shrink_item(i).into_iter().map(Atom::Item)),
        Atom::Class { negated, items } => {
            if *negated {
                // `[^X]` has no member to keep; the wildcard is the simplest atom.
                out.push(Atom::Item(Item::Any));
            } else {
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

#[cfg(test)]
mod tests {
    use super::*;

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
    fn a_label_comes_off_a_light_or_an_emissive_object_and_keeps_its_kind() {
        let shrunk = |p: &str| -> Vec<String> {
            shrink_path(&p.parse().unwrap())
                .iter()
                .map(|q| q.to_string())
                .collect()
        };
        assert_eq!(shrunk("C L'key'"), ["C L"]);
        assert_eq!(shrunk("C O'lamp'"), ["C O"]);
    }

    #[test]
    fn shrinking_terminates_and_stays_normalized() {
        let e = lpe::renderman::parse("C([^D'a'<T[^D2]['x']>]|(S{2,7})*)+L")
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
                assert_eq!(lpe::renderman::parse(&text).unwrap().expr, y, "{text}");
                if seen < 2000 {
                    frontier.push(y);
                }
            }
        }
    }
}
