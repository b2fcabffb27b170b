//! OSL to RenderMan, syntax-directed: the expression keeps its shape and each vertex
//! pattern becomes the RenderMan atom of the vertices whose OSL view it accepts (the
//! preimage under the correspondence).
//!
//! A RenderMan label position cannot say "unlabelled" without also taking every label no
//! list names, nor "labelled with anything" (§4.4: `[^'a']` includes unlabelled
//! vertices), so such label sets are rounded: up ([`Bound::Upper`]) or down
//! ([`Bound::Lower`]). Exactness is decided on the automata ([`super::cross`]).

use std::collections::{BTreeMap, BTreeSet};

use crate::automata::ir::Repetition;
use crate::osl::{self, VertexPattern};
use crate::renderman::ast::{Atom, EventPattern, EventPos, Expr, Item, LabelPos, Triple, TypePos};
use crate::renderman::{self, Event, EventKind, Prefixes, VertexType};
use crate::translate::bound::{map_algebra, Bound};
use crate::translate::correspondence::Correspondence;
use crate::translate::labels;

/// A RenderMan label as the translation tells labels apart.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
enum LabelKey {
    None,
    Named(String),
    Other,
}

/// The translation of `e` to RenderMan, rounded by `bound` where a label position cannot
/// say what a vertex pattern accepts (see the module docs).
pub fn translate(e: &osl::Lpe, corr: &Correspondence, bound: Bound) -> renderman::Lpe {
    let (universe, fresh) = corr.universe(&BTreeSet::new(), &labels::osl(e));
    let vertices: Vec<(renderman::Vertex, Option<osl::Vertex>)> = universe
        .into_iter()
        .map(|v| {
            let w = corr.view(&v);
            (v, w)
        })
        .collect();
    let mut pattern = |p: &VertexPattern, bound: Bound, places: &[VertexType]| -> Atom {
        let accepted: Vec<(&renderman::Vertex, bool)> = vertices
            .iter()
            .filter_map(|(v, w)| {
                let w = w.as_ref()?;
                Some((v, places.contains(&v.ty()) && p.accepts(&w.symbols)))
            })
            .collect();
        atom(&accepted, &fresh, bound)
    };
    let tree = map_algebra(&e.tree(), bound, &mut |op, b| {
        operand(op, b, &mut pattern).unwrap_or_else(|| Expr::Atom(nothing()))
    });
    renderman::Lpe::from_algebra(Prefixes::NONE, tree)
}

/// `[^.]`: matches no vertex.
fn nothing() -> Atom {
    Atom::Class {
        negated: true,
        items: vec![Item::Any],
    }
}

const EVERY_TYPE: [VertexType; 5] = VertexType::ALL;
const SCATTERING: [VertexType; 2] = [VertexType::R, VertexType::T];

/// One operand. A RenderMan path is a camera, scattering vertices, then an emitter: in a
/// sequence whose first and last items each take a vertex, a vertex pattern that is the
/// first item can only meet the camera, one that is the last item only an emitter, and
/// every vertex pattern between them only scattering vertices. Leaving out the other
/// types changes no match and keeps the atoms short (OSL's `.` is any vertex; between a
/// camera and an emitter it is RenderMan's `.`).
fn operand(
    e: &osl::Expr,
    bound: Bound,
    pattern: &mut impl FnMut(&VertexPattern, Bound, &[VertexType]) -> Atom,
) -> Option<Expr> {
    let osl::Expr::Concat(es) = e else {
        return expr(e, bound, &EVERY_TYPE, pattern);
    };
    let ends_take_a_vertex = !nullable(&es[0]) && !nullable(&es[es.len() - 1]);
    let parts: Vec<Expr> = es
        .iter()
        .enumerate()
        .filter_map(|(i, part)| {
            let places: &[VertexType] = match (ends_take_a_vertex, part) {
                (true, osl::Expr::Vertex(_)) if i == 0 => &[VertexType::C],
                (true, osl::Expr::Vertex(_)) if i == es.len() - 1 => {
                    &[VertexType::L, VertexType::O]
                }
                (true, _) if i > 0 && i < es.len() - 1 => &SCATTERING,
                _ => &EVERY_TYPE,
            };
            expr(part, bound, places, pattern)
        })
        .collect();
    (!parts.is_empty()).then(|| Expr::concat(parts))
}

/// Whether `e` matches the empty sequence.
fn nullable(e: &osl::Expr) -> bool {
    match e {
        osl::Expr::Vertex(_) | osl::Expr::Nothing => false,
        osl::Expr::Concat(es) => es.iter().all(nullable),
        osl::Expr::Alt(es) => es.iter().any(nullable),
        osl::Expr::Repeat(e, r) => r.min == 0 || nullable(e),
        osl::Expr::Empty => true,
    }
}

/// `None`: the empty sequence. Vertex patterns meet only vertices of `places`.
fn expr(
    e: &osl::Expr,
    bound: Bound,
    places: &[VertexType],
    pattern: &mut impl FnMut(&VertexPattern, Bound, &[VertexType]) -> Atom,
) -> Option<Expr> {
    match e {
        osl::Expr::Vertex(p) => Some(Expr::Atom(pattern(p, bound, places))),
        osl::Expr::Concat(es) => {
            let parts: Vec<Expr> = es
                .iter()
                .filter_map(|e| expr(e, bound, places, pattern))
                .collect();
            (!parts.is_empty()).then(|| Expr::concat(parts))
        }
        osl::Expr::Alt(es) => {
            let parts: Vec<Option<Expr>> =
                es.iter().map(|e| expr(e, bound, places, pattern)).collect();
            let nonempty: Vec<Expr> = parts.iter().flatten().cloned().collect();
            if nonempty.is_empty() {
                None
            } else if nonempty.len() < parts.len() {
                Some(Expr::Repeat(
                    Box::new(Expr::alt(nonempty)),
                    Repetition::OPTIONAL,
                ))
            } else {
                Some(merge_atoms(nonempty))
            }
        }
        osl::Expr::Repeat(inner, r) => {
            let x = expr(inner, bound, places, pattern)?;
            (r.max != Some(0)).then(|| Expr::Repeat(Box::new(x), *r))
        }
        osl::Expr::Empty => None,
        osl::Expr::Nothing => Some(Expr::Atom(nothing())),
    }
}

/// Alternatives that are all single vertices, as one class (`L|O` is `[LO]`).
fn merge_atoms(alts: Vec<Expr>) -> Expr {
    let mut items = Vec::new();
    for a in &alts {
        match a {
            Expr::Atom(Atom::Item(i)) => items.push(i.clone()),
            Expr::Atom(Atom::Class {
                negated: false,
                items: is,
            }) => items.extend(is.iter().cloned()),
            _ => return Expr::alt(alts),
        }
    }
    Expr::Atom(Atom::Class {
        negated: false,
        items,
    })
}

fn key(v: &renderman::Vertex, fresh: &str) -> LabelKey {
    match v.label() {
        None => LabelKey::None,
        Some(l) if l == fresh => LabelKey::Other,
        Some(l) => LabelKey::Named(l.to_string()),
    }
}

/// The atom of the `accepted` vertices of the universe, rounded by `bound`.
fn atom(accepted: &[(&renderman::Vertex, bool)], fresh: &str, bound: Bound) -> Atom {
    // Per (type, event): every label key, and the accepted ones.
    type Field = (VertexType, Option<Event>);
    let mut all: BTreeMap<Field, BTreeSet<LabelKey>> = BTreeMap::new();
    let mut taken: BTreeMap<Field, BTreeSet<LabelKey>> = BTreeMap::new();
    for (v, a) in accepted {
        let f = (v.ty(), v.event());
        all.entry(f).or_default().insert(key(v, fresh));
        if *a {
            taken.entry(f).or_default().insert(key(v, fresh));
        }
    }
    // Grouped by label position: the fields with that label set.
    let mut groups: Vec<(LabelPos, Vec<Field>)> = Vec::new();
    for (f, keys) in &taken {
        if let Some(label) = label_pos(keys, &all[f], bound) {
            match groups.iter_mut().find(|(l, _)| *l == label) {
                Some((_, fs)) => fs.push(*f),
                None => groups.push((label, vec![*f])),
            }
        }
    }
    let transport: BTreeSet<Event> = Event::all().filter(|e| e.is_transport()).collect();
    let mut items = Vec::new();
    for (label, fields) in groups {
        // Per type: its events (`None`: what `.` means for the type).
        let mut by_type: BTreeMap<VertexType, BTreeSet<Event>> = BTreeMap::new();
        for (ty, ev) in fields {
            let set = by_type.entry(ty).or_default();
            set.extend(ev);
        }
        let mut merged: BTreeMap<Option<BTreeSet<Event>>, Vec<VertexType>> = BTreeMap::new();
        for (ty, evs) in by_type {
            let any = !ty.is_scattering() || evs == transport;
            merged.entry((!any).then_some(evs)).or_default().push(ty);
        }
        for (events, types) in merged {
            items.extend(item(types, events, label.clone()));
        }
    }
    match items.len() {
        0 => nothing(),
        1 => Atom::Item(items.pop().expect("one")),
        _ => Atom::Class {
            negated: false,
            items,
        },
    }
}

/// The label position of the accepted keys among `every`, rounded by `bound`; `None`
/// when rounding down leaves nothing.
fn label_pos(
    keys: &BTreeSet<LabelKey>,
    every: &BTreeSet<LabelKey>,
    bound: Bound,
) -> Option<LabelPos> {
    if keys == every {
        return Some(LabelPos::Any);
    }
    let named: Vec<String> = keys
        .iter()
        .filter_map(|k| match k {
            LabelKey::Named(l) => Some(l.clone()),
            _ => None,
        })
        .collect();
    let excluded: Vec<String> = every
        .iter()
        .filter(|k| !keys.contains(*k))
        .filter_map(|k| match k {
            LabelKey::Named(l) => Some(l.clone()),
            _ => None,
        })
        .collect();
    let (none, other) = (
        keys.contains(&LabelKey::None),
        keys.contains(&LabelKey::Other),
    );
    // Sayable: both "no label" and unnamed labels (a negated list), or neither (a list).
    let both = match (none, other, bound) {
        (true, true, _) => true,
        (false, false, _) => false,
        (_, _, Bound::Upper) => true,
        (_, _, Bound::Lower) => false,
    };
    if both {
        Some(if excluded.is_empty() {
            LabelPos::Any
        } else {
            LabelPos::Class {
                negated: true,
                labels: excluded,
            }
        })
    } else {
        match named.len() {
            0 => None,
            1 => Some(LabelPos::One(named[0].clone())),
            _ => Some(LabelPos::Class {
                negated: false,
                labels: named,
            }),
        }
    }
}

/// The items for `types` (sharing `events`, `None`: `.`) and `label`: letters where they
/// say the same (`[LO]`, not `<[LO].>`), else one triple.
fn item(types: Vec<VertexType>, events: Option<BTreeSet<Event>>, label: LabelPos) -> Vec<Item> {
    if events.is_none() && label == LabelPos::Any {
        let (scattering, others): (Vec<VertexType>, Vec<VertexType>) =
            types.into_iter().partition(|t| t.is_scattering());
        let mut out: Vec<Item> = others.into_iter().map(Item::Type).collect();
        match scattering[..] {
            [] => {}
            [t] => out.push(Item::Type(t)),
            _ => out.push(Item::Any),
        }
        return out;
    }
    vec![single_item(types, events, label)]
}

/// One item for `types`, `events` and `label`, where the events or the label restrict
/// (`item` spells the rest as letters): an event or a label alone where a letter says it,
/// else a triple.
fn single_item(types: Vec<VertexType>, events: Option<BTreeSet<Event>>, label: LabelPos) -> Item {
    let scattering_pair = types == [VertexType::R, VertexType::T];
    let ty = if scattering_pair {
        TypePos::Any
    } else if types.len() == 1 {
        TypePos::One(types[0])
    } else {
        TypePos::Class {
            negated: false,
            types,
        }
    };
    let event = match events {
        None => EventPos::Any,
        Some(evs) => event_pos(&evs),
    };
    match (&ty, &event, &label) {
        (TypePos::Any, EventPos::One(e), LabelPos::Any) => Item::Event(*e),
        (TypePos::Any, EventPos::Any, LabelPos::One(l)) => Item::Label(l.clone()),
        _ => Item::Triple(Triple { ty, event, label }),
    }
}

/// The event position of a set of transport events: whole kinds as `D`/`S`, the rest by
/// lobe.
fn event_pos(evs: &BTreeSet<Event>) -> EventPos {
    let mut items = Vec::new();
    for kind in [EventKind::D, EventKind::S] {
        let of_kind: Vec<Event> = evs.iter().copied().filter(|e| e.kind() == kind).collect();
        if of_kind.len() == usize::from(kind.max_lobe()) {
            items.push(EventPattern { kind, lobe: None });
        } else {
            items.extend(of_kind.iter().map(|e| EventPattern {
                kind,
                lobe: Some(e.lobe()),
            }));
        }
    }
    if items.len() == 1 {
        EventPos::One(items[0])
    } else {
        EventPos::Class {
            negated: false,
            events: items,
        }
    }
}
