//! AST -> `regex_syntax::hir::Hir` over the byte encoding of [`super::encode`].
//!
//! Written from the language's semantics (docs/language.md) and the table in
//! `lpe::ast`, as set algebra over the finite vertex universe rather than as per-vertex
//! predicates (the reference matcher's style), so that the two engines share no code and
//! few habits:
//!
//! - `.` = {R, T} × {D*, S*} × every label;
//! - `C` `L` `O` = that type (no event) × every label; `R` `T` = that type ∩ `.`;
//! - `D` `S2` `U` … = {R, T} × those events × every label (user lobes only here, by name);
//! - `'g'` = `.` ∩ label g;
//! - `[a b]` = the union; `[^a b]` = `.` minus the union;
//! - `<t e l>` = T(t) × E(e) × L(l) where each position's `.` is {R, T} / ({D*, S*} ∪
//!   none) / every label including none, and a negated class is that `.` minus the
//!   listed values.
//!
//! Expressions become concatenation, alternation and repetition with the *raw* bounds
//! (`{2,200}` stays `{2,200}`: the fast matcher's `{n,m}` -> `{n,}` rewrite must be
//! tested, not shared).

use lpe::renderman::ast::{Atom, EventPattern, EventPos, Expr, Item, LabelPos, Triple, TypePos};
use lpe::renderman::{Event, EventKind, VertexType};
use regex_syntax::hir::Hir;

use super::encode::{
    all_labels, label_bit, type_byte, LabelMask, Labels, VertexSet, EVENTS, EVENT_NONE, LABEL_NONE,
    TYPES,
};
use crate::regex::hir::{byte_class, repeat};

const RT: [VertexType; 2] = [VertexType::R, VertexType::T];
const NO_EVENT: u32 = 1;

/// The event-index mask of every event matching `p` (kind, and lobe if given).
fn events_of(p: EventPattern) -> u32 {
    Event::all()
        .enumerate()
        .filter(|(_, e)| e.kind() == p.kind && p.lobe.is_none_or(|l| l == e.lobe()))
        .fold(0, |m, (i, _)| m | 1 << (i + 1))
}

/// D and S events, any lobe: what a scattering `.` allows.
fn transport_events() -> u32 {
    events_of(EventPattern {
        kind: EventKind::D,
        lobe: None,
    }) | events_of(EventPattern {
        kind: EventKind::S,
        lobe: None,
    })
}

/// The translation context: the label interning of the whole compiled set.
pub struct Translator<'a> {
    labels: &'a Labels,
}

impl<'a> Translator<'a> {
    /// A translator for expressions whose labels are all in `labels`.
    pub fn new(labels: &'a Labels) -> Translator<'a> {
        Translator { labels }
    }

    fn every_label(&self) -> LabelMask {
        all_labels(self.labels)
    }

    /// Top-level `.`.
    fn dot(&self) -> VertexSet {
        VertexSet::product(&RT, transport_events(), self.every_label())
    }

    fn item(&self, item: &Item) -> VertexSet {
        match item {
            Item::Type(t) if t.is_scattering() => {
                VertexSet::product(&[*t], u32::MAX, self.every_label()).intersect(&self.dot())
            }
            Item::Type(t) => VertexSet::product(&[*t], NO_EVENT, self.every_label()),
            Item::Event(p) => VertexSet::product(&RT, events_of(*p), self.every_label()),
            Item::Any => self.dot(),
            Item::Label(l) => {
                let one = VertexSet::product(&RT, u32::MAX, label_bit(self.labels.byte_of(l)));
                self.dot().intersect(&one)
            }
            Item::Triple(t) => self.triple(t),
        }
    }

    fn triple(&self, t: &Triple) -> VertexSet {
        // Each position is a set of field values; the vertex set is their product.
        let types: Vec<VertexType> = match &t.ty {
            TypePos::Any => RT.to_vec(),
            TypePos::One(ty) => vec![*ty],
            TypePos::Class { negated, types } => {
                if *negated {
                    RT.iter().copied().filter(|x| !types.contains(x)).collect()
                } else {
                    types.clone()
                }
            }
        };
        let event_dot = transport_events() | NO_EVENT;
        let events = match &t.event {
            EventPos::Any => event_dot,
            EventPos::One(p) => events_of(*p),
            EventPos::Class { negated, events } => {
                let listed = events.iter().fold(0, |m, p| m | events_of(*p));
                if *negated {
                    event_dot & !listed
                } else {
                    listed
                }
            }
        };
        let every = self.every_label();
        let labels = match &t.label {
            LabelPos::Any => every,
            LabelPos::One(l) => label_bit(self.labels.byte_of(l)),
            LabelPos::Class { negated, labels } => {
                let listed = labels.iter().fold([0; 4], |m, l| {
                    let b = label_bit(self.labels.byte_of(l));
                    [m[0] | b[0], m[1] | b[1], m[2] | b[2], m[3] | b[3]]
                });
                if *negated {
                    [0, 1, 2, 3].map(|k| every[k] & !listed[k])
                } else {
                    listed
                }
            }
        };
        VertexSet::product(&types, events, labels)
    }

    /// The set of vertices one atom matches.
    pub fn atom_set(&self, a: &Atom) -> VertexSet {
        match a {
            Atom::Item(i) => self.item(i),
            Atom::Class { negated, items } => {
                let union = items
                    .iter()
                    .fold(VertexSet::empty(), |s, i| s.union(&self.item(i)));
                if *negated {
                    self.dot().minus(&union)
                } else {
                    union
                }
            }
        }
    }

    /// The regex for one expression, without anchors.
    pub fn expr(&self, e: &Expr) -> Hir {
        match e {
            Expr::Atom(a) => set_to_hir(&self.atom_set(a)),
            Expr::Concat(es) => Hir::concat(es.iter().map(|e| self.expr(e)).collect()),
            Expr::Alt(es) => Hir::alternation(es.iter().map(|e| self.expr(e)).collect()),
            Expr::Repeat(body, r) => repeat(self.expr(body), *r),
        }
    }
}

/// A vertex set as an alternation of `type-class event-class label-class` triples: the
/// events of one type with the same label mask share one branch, and types with the same
/// events and mask share it too (`.` is one branch, not one per type: each class is a few
/// heap blocks, most of this engine's compile time under AddressSanitizer).
fn set_to_hir(s: &VertexSet) -> Hir {
    // (label mask, event bits, type bits), event bit `ev` for event index `ev`.
    let mut groups: Vec<(LabelMask, u32, u8)> = Vec::new();
    for ty in 0..TYPES {
        let first = groups.len();
        for ev in 0..EVENTS {
            let mask = s.cell(ty, ev);
            if mask == [0; 4] {
                continue;
            }
            match groups[first..].iter_mut().find(|(m, _, _)| *m == mask) {
                Some((_, evs, _)) => *evs |= 1 << ev,
                None => groups.push((mask, 1 << ev, 1 << ty)),
            }
        }
        // This type's branches join an earlier type's with the same events and mask.
        let mut k = first;
        while k < groups.len() {
            let (mask, evs, t) = groups[k];
            match groups[..first]
                .iter_mut()
                .find(|(m, e, _)| *m == mask && *e == evs)
            {
                Some((_, _, types)) => {
                    *types |= t;
                    groups.remove(k);
                }
                None => k += 1,
            }
        }
    }
    let branches: Vec<Hir> = groups
        .iter()
        .map(|&(mask, evs, types)| {
            let types = (0..TYPES)
                .filter(|t| types & (1 << t) != 0)
                .map(|t| type_byte(VertexType::ALL[t]));
            let events = (0..EVENTS)
                .filter(|e| evs & (1 << e) != 0)
                .map(|e| EVENT_NONE + e as u8);
            let labels = (0..256usize)
                .filter(|i| mask[i / 64] & (1 << (i % 64)) != 0)
                .map(|i| LABEL_NONE + i as u8);
            vertex_hir(types, events, labels)
        })
        .collect();
    // An empty alternation never matches: the right meaning for an empty set.
    if branches.is_empty() {
        Hir::fail()
    } else {
        Hir::alternation(branches)
    }
}

/// One vertex: a byte from each field's set, in order. Runs of single-byte fields are one
/// literal (`C` with no event is the literal `00 10`), as `Hir::concat` would make them,
/// but built once instead of as classes that are then rewritten.
fn vertex_hir(
    types: impl Iterator<Item = u8> + Clone,
    events: impl Iterator<Item = u8> + Clone,
    labels: impl Iterator<Item = u8> + Clone,
) -> Hir {
    fn field(bytes: impl Iterator<Item = u8> + Clone, literal: &mut Vec<u8>, parts: &mut Vec<Hir>) {
        let mut two = bytes.clone().take(2);
        match (two.next(), two.next()) {
            (Some(b), None) => literal.push(b),
            _ => {
                if !literal.is_empty() {
                    parts.push(Hir::literal(std::mem::take(literal)));
                }
                parts.push(byte_class(bytes));
            }
        }
    }
    let mut parts = Vec::with_capacity(3);
    let mut literal = Vec::with_capacity(3);
    field(types, &mut literal, &mut parts);
    field(events, &mut literal, &mut parts);
    field(labels, &mut literal, &mut parts);
    if !literal.is_empty() {
        parts.push(Hir::literal(literal));
    }
    if parts.len() == 1 {
        parts.pop().expect("one part")
    } else {
        Hir::concat(parts)
    }
}
