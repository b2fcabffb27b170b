//! RenderMan to OSL, syntax-directed: the expression keeps its shape (sequence,
//! alternation, repetition, set algebra) and each atom becomes the OSL vertex patterns of
//! the OSL views of the vertices it matches.
//!
//! A vertex pattern cannot say "no custom label" (with no custom slot the eater takes any
//! label; a custom slot needs one), so an atom whose views include unlabelled vertices but
//! not every label is rounded: up to any label ([`Bound::Upper`]) or down to the labelled
//! ones ([`Bound::Lower`]). The upper translation is the image of the expression under the
//! correspondence wherever no rounding happened; whether it is exact is decided on the
//! automata ([`super::cross`]), not here.

use std::collections::{BTreeMap, BTreeSet};

use crate::automata::ir::Repetition;
use crate::dialect::Dialect;
use crate::osl::{self, Registered, Symbol, SymbolPattern, VertexPattern};
use crate::renderman::ast::{Atom, Expr};
use crate::renderman::{self, RenderMan, VertexType};
use crate::translate::bound::{map_algebra, Bound};
use crate::translate::correspondence::Correspondence;
use crate::translate::labels;

/// A custom label as the translation tells labels apart.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
enum LabelKey {
    /// No custom label.
    None,
    /// A label some expression names.
    Named(String),
    /// Any label no expression names.
    Other,
}

/// An OSL view: event, scattering (`None`: NONE), custom label.
type View = (&'static str, Option<&'static str>, LabelKey);

/// The translation of `e` to OSL, rounded by `bound` where OSL cannot say what an atom
/// matches (see the module docs). Prefixes are not carried (OSL has none).
pub fn translate(e: &renderman::Lpe, corr: &Correspondence, bound: Bound) -> osl::Lpe {
    let (universe, fresh) = corr.universe(&labels::renderman(e), &BTreeSet::new());
    let views: Vec<Option<View>> = universe.iter().map(|v| view(corr, v, &fresh)).collect();
    let mut atoms: Vec<&Atom> = Vec::new();
    for op in e.operands() {
        op.for_each_atom(&mut |a| {
            if !atoms.contains(&a) {
                atoms.push(a);
            }
        });
    }
    let classes = RenderMan::classes(&atoms, &e.operands()).expect("a parsed set's atoms");
    let vertex_classes: Vec<usize> = universe
        .iter()
        .map(|v| classes.classify(v).index())
        .collect();
    let mut atom = |a: &Atom, bound: Bound| -> osl::Expr {
        let i = atoms.iter().position(|x| *x == a).expect("collected above");
        let accepted: Vec<bool> = vertex_classes
            .iter()
            .map(|&c| classes.accepts(c, i))
            .collect();
        patterns(&views, &accepted, bound)
    };
    let tree = map_algebra(&e.tree(), bound, &mut |op, b| {
        let x = expr(op, b, &mut atom);
        // No path is empty: an operand left matching only the empty sequence matches none.
        if x == osl::Expr::Empty {
            osl::Expr::Nothing
        } else {
            x
        }
    });
    osl::Lpe::from_algebra(tree)
}

/// The OSL view of a universe vertex, `None` outside the correspondence.
fn view(corr: &Correspondence, v: &renderman::Vertex, fresh: &str) -> Option<View> {
    let w = corr.view(v)?;
    let event = match v.ty() {
        VertexType::C => "C",
        VertexType::R => "R",
        VertexType::T => "T",
        VertexType::L => "L",
        VertexType::O => "O",
    };
    let scattering = v
        .event()
        .and_then(|e| corr.scattering(e))
        .map(|s| s.label());
    let label = match w.symbols.get(2) {
        None => LabelKey::None,
        Some(Symbol::Label(l)) if l == fresh => LabelKey::Other,
        Some(Symbol::Label(l)) => LabelKey::Named(l.clone()),
        Some(Symbol::None) => unreachable!("custom labels are labels"),
    };
    Some((event, scattering, label))
}

fn expr(e: &Expr, bound: Bound, atom: &mut impl FnMut(&Atom, Bound) -> osl::Expr) -> osl::Expr {
    match e {
        Expr::Atom(a) => atom(a, bound),
        Expr::Concat(es) => {
            let parts: Vec<osl::Expr> = es
                .iter()
                .map(|e| expr(e, bound, atom))
                .filter(|x| *x != osl::Expr::Empty)
                .collect();
            match parts.len() {
                0 => osl::Expr::Empty,
                1 => parts.into_iter().next().expect("one part"),
                _ => osl::Expr::Concat(parts),
            }
        }
        Expr::Alt(es) => {
            let parts: Vec<osl::Expr> = es.iter().map(|e| expr(e, bound, atom)).collect();
            let nonempty: Vec<osl::Expr> = parts
                .iter()
                .filter(|x| **x != osl::Expr::Empty)
                .cloned()
                .collect();
            if nonempty.is_empty() {
                osl::Expr::Empty
            } else if nonempty.len() < parts.len() {
                // OSL has no empty alternative: `(a|{0})` is `a{0,1}`.
                osl::Expr::Repeat(Box::new(osl::Expr::alt(nonempty)), Repetition::OPTIONAL)
            } else {
                osl::Expr::alt(nonempty)
            }
        }
        Expr::Repeat(inner, r) => {
            let x = expr(inner, bound, atom);
            if x == osl::Expr::Empty || r.max == Some(0) {
                osl::Expr::Empty
            } else {
                osl::Expr::Repeat(Box::new(x), *r)
            }
        }
    }
}

/// The vertex patterns of the views of the `accepted` universe vertices, rounded by
/// `bound`.
fn patterns(views: &[Option<View>], accepted: &[bool], bound: Bound) -> osl::Expr {
    // Per (event, scattering): the label keys every view has, and those accepted. A view
    // is accepted by the upper bound when some vertex of it is, by the lower bound when
    // every vertex of it is.
    let mut all: BTreeMap<(&str, Option<&str>), BTreeSet<LabelKey>> = BTreeMap::new();
    let mut some: BTreeSet<&View> = BTreeSet::new();
    let mut not_all: BTreeSet<&View> = BTreeSet::new();
    for (w, &a) in views.iter().zip(accepted) {
        let Some(w) = w else { continue };
        all.entry((w.0, w.1)).or_default().insert(w.2.clone());
        if a {
            some.insert(w);
        } else {
            not_all.insert(w);
        }
    }
    // Grouped by the label keys they accept: (event, scattering) pairs.
    let mut groups: BTreeMap<BTreeSet<LabelKey>, BTreeSet<(&str, Option<&str>)>> = BTreeMap::new();
    for (&(ev, sc), keys) in &all {
        let mut taken: BTreeSet<LabelKey> = keys
            .iter()
            .filter(|k| {
                let w = (ev, sc, (*k).clone());
                match bound {
                    Bound::Upper => some.contains(&w),
                    Bound::Lower => some.contains(&w) && !not_all.contains(&w),
                }
            })
            .cloned()
            .collect();
        // "No label" alone is unsayable: round to every label, or to the labelled ones.
        if taken.contains(&LabelKey::None) && taken != *keys {
            match bound {
                Bound::Upper => taken = keys.clone(),
                Bound::Lower => {
                    taken.remove(&LabelKey::None);
                }
            }
        }
        if !taken.is_empty() {
            let all_keys = taken == *keys;
            let key = if all_keys { BTreeSet::new() } else { taken };
            groups.entry(key).or_default().insert((ev, sc));
        }
    }
    let eater = Some(Registered::none().basic_labels());
    let scatterings_of = |ev: &str| -> BTreeSet<Option<&str>> {
        all.keys()
            .filter(|(e, _)| *e == ev)
            .map(|(_, s)| *s)
            .collect()
    };
    let mut out = Vec::new();
    for (keys, pairs) in &groups {
        let custom = custom_slot(keys, all.values().flatten());
        // Events with the same scatterings share one pattern.
        let mut by_event: BTreeMap<&str, BTreeSet<Option<&str>>> = BTreeMap::new();
        for &(ev, sc) in pairs {
            by_event.entry(ev).or_default().insert(sc);
        }
        let mut merged: BTreeMap<BTreeSet<Option<&str>>, Vec<&str>> = BTreeMap::new();
        for (ev, scs) in by_event {
            merged.entry(scs).or_default().push(ev);
        }
        for (scs, events) in merged {
            let whole = events.iter().all(|ev| scatterings_of(ev) == scs);
            let scattering = if whole {
                SymbolPattern::Any
            } else {
                slot(
                    scs.iter()
                        .map(|s| s.map_or(Symbol::None, Symbol::label))
                        .collect(),
                )
            };
            let mut symbols = vec![
                slot(events.iter().map(|e| Symbol::label(*e)).collect()),
                scattering,
            ];
            symbols.extend(custom.clone());
            out.push(osl::Expr::Vertex(VertexPattern {
                symbols,
                eater: eater.clone(),
            }));
        }
    }
    if out.is_empty() {
        osl::Expr::Nothing
    } else {
        osl::Expr::alt(out)
    }
}

/// One slot accepting exactly `symbols` (at least one).
fn slot(mut symbols: Vec<Symbol>) -> SymbolPattern {
    if symbols.len() == 1 {
        SymbolPattern::One(symbols.pop().expect("one"))
    } else {
        SymbolPattern::Set(symbols)
    }
}

/// The custom slot for accepted label keys without [`LabelKey::None`] (empty: every
/// label and none, so no custom slot).
fn custom_slot<'a>(
    keys: &BTreeSet<LabelKey>,
    every: impl Iterator<Item = &'a LabelKey>,
) -> Option<SymbolPattern> {
    if keys.is_empty() {
        return None;
    }
    let named = |k: &LabelKey| match k {
        LabelKey::Named(l) => Some(Symbol::label(l.clone())),
        _ => None,
    };
    Some(if keys.contains(&LabelKey::Other) {
        let every: BTreeSet<&LabelKey> = every.collect();
        let excluded: Vec<Symbol> = every
            .into_iter()
            .filter(|k| !keys.contains(*k))
            .filter_map(named)
            .collect();
        if excluded.is_empty() {
            SymbolPattern::Any
        } else {
            SymbolPattern::NotIn(excluded)
        }
    } else {
        slot(keys.iter().filter_map(named).collect())
    })
}
