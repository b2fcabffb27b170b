//! Alphabet compression: every possible vertex, folded into the few classes that the
//! compiled expressions can tell apart.
//!
//! A vertex is a *raw symbol* `(type and event, label)`:
//! - type and event: `C`, `L`, `O` (no event) and `R`/`T` with each of the 24 events
//!   (D1-4, S1-8, U1-12), 51 combinations;
//! - label: none, one of the `k` labels the compiled expressions mention, or OTHER.
//!
//! Expressions only ever compare labels for equality with labels they mention, so every
//! unmentioned label behaves like every other one: mapping them all to one OTHER symbol is
//! exact (OSL does the same with a per-state default transition).
//!
//! Each distinct atom of the compiled set is turned into the set of raw symbols it
//! accepts, per label symbol a bit mask over the 51 `(type, event)` pairs (set algebra
//! written from docs/language.md and the table in [`crate::renderman::ast`]); raw symbols with the
//! same answers from every atom form one [`Class`], found by splitting blocks of raw
//! symbols atom by atom rather than by evaluating every atom on every raw symbol.
//! `Alphabet::classify` is then arithmetic plus one label lookup plus one table load.

use crate::fxhash::FxMap;

use super::ast::{Atom, EventPattern, EventPos, Item, LabelPos, Triple, TypePos};
use super::path::{Event, EventKind, Vertex, VertexType};
use crate::automata::ir::{Place, VertexClasses};
use crate::automata::mask::{Class, LabelId};
use crate::bits;

/// Number of `(type, event)` combinations: C, L, O, then R and T with 24 events each.
pub(crate) const TYPE_EVENTS: usize = 3 + 2 * EVENTS;
const EVENTS: usize = 24;

/// A raw symbol's label part.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum LabelSym {
    None,
    /// Index into the interned labels.
    Known(u32),
    /// Any label the compiled expressions never mention.
    Other,
}

/// One raw symbol, as the predicates see it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Sym {
    pub ty: VertexType,
    pub event: Option<Event>,
    pub label: LabelSym,
}

/// The place a vertex of type `ty` takes in a path.
fn place_of(ty: VertexType) -> Place {
    match ty {
        VertexType::C => Place::Camera,
        VertexType::R | VertexType::T => Place::Scatter,
        VertexType::L | VertexType::O => Place::Emitter,
    }
}

/// Per `VertexType` (C R T L O), where its run of `(type, event)` indices starts.
const TYPE_BASE: [usize; 5] = [0, 3, 3 + EVENTS, 1, 2];

/// Per event kind (D S U), where its lobes start in an R or T run, and how many it has.
const KIND_BASE: [usize; 3] = [0, 4, 12];
const MAX_LOBE: [usize; 3] = [4, 8, 12];

/// `(type, event)` to its index (C 0, L 1, O 2, R 3.., T 27..) tabulated at entry
/// [`type_event_code`] = `type << 6 | kind << 4 | lobe`, `kind` being the event kind's
/// index (D S U), and no event entry 0 of the type's 64 (`kind << 4 | lobe` is how an
/// `Event` is held, and an `Option<Event>` holds none as 0): one load (nested matches
/// mispredict on a realistic mix of vertices, and arithmetic on the event took several
/// dependent steps more). Each alphabet keeps it premultiplied by its label stride.
/// Within the R and T runs the events go D1-4, S1-8, U1-12; C, L and O ignore an event (a
/// `Vertex` carries one exactly when it is R or T; a caller of `classify_interned` may
/// pass one anyway). Codes no `Event` has (kind 3, lobe 0, a lobe past its kind's range)
/// read as no event.
const TYPE_EVENT: [u8; 5 << 6] = {
    let mut t = [0u8; 5 << 6];
    let mut ty = 0;
    while ty < 5 {
        let scattering = ty == VertexType::R as usize || ty == VertexType::T as usize;
        let mut kind = 0;
        while kind < 4 {
            let mut lobe = 0;
            while lobe < 16 {
                let event = if scattering && kind < 3 && lobe >= 1 && lobe <= MAX_LOBE[kind] {
                    KIND_BASE[kind] + lobe - 1
                } else {
                    0
                };
                t[ty << 6 | kind << 4 | lobe] = (TYPE_BASE[ty] + event) as u8;
                lobe += 1;
            }
            kind += 1;
        }
        ty += 1;
    }
    t
};

/// The entry of `(type, event)` in [`TYPE_EVENT`]: `type << 6 | kind << 4 | lobe`, or
/// `type << 6` for no event.
#[inline]
fn type_event_code(ty: VertexType, event: Option<Event>) -> usize {
    // Codes are below 64; the mask tells the compiler so, and the index needs no check.
    (ty as usize) << 6 | usize::from(event.map_or(0, Event::code) & 63)
}

fn type_event(i: usize) -> (VertexType, Option<Event>) {
    // The inverse of `TYPE_EVENT`: D1-4, S1-8, U1-12.
    let event = |j: usize| match j {
        0..4 => Event::new(EventKind::D, j as u8 + 1),
        4..12 => Event::new(EventKind::S, j as u8 - 3),
        _ => Event::new(EventKind::U, j as u8 - 11),
    };
    match i {
        0 => (VertexType::C, None),
        1 => (VertexType::L, None),
        2 => (VertexType::O, None),
        i if i < 3 + EVENTS => (VertexType::R, event(i - 3)),
        i => (VertexType::T, event(i - 3 - EVENTS)),
    }
}

impl VertexClasses for Alphabet {
    type Vertex = Vertex;

    #[inline]
    fn classify(&self, v: &Vertex) -> Class {
        Alphabet::classify(self, v)
    }

    fn class_count(&self) -> usize {
        Alphabet::class_count(self)
    }

    fn accepts(&self, c: usize, a: usize) -> bool {
        Alphabet::accepts(self, c, a)
    }

    fn representative(&self, c: usize, p: Place) -> Option<Vertex> {
        Alphabet::representative(self, c, p)
    }

    fn occurs_in(&self, c: usize, p: Place) -> bool {
        Alphabet::occurs_in(self, c, p)
    }

    fn memory_bytes(&self) -> usize {
        Alphabet::memory_bytes(self)
    }
}

/// The labels the compiled expressions mention, in a small open-addressing hash table.
///
/// The key of a label is its length and two words that, for labels of up to 16 bytes,
/// hold every byte (overlapping reads of the head and tail, the way fast hashers read
/// short strings): [`Alphabet::classify`] of a labelled vertex then costs a few loads,
/// one multiply and one compare, with no string compare and no per-byte loop (whose
/// exit branch mispredicts on labels of mixed lengths). Longer labels compare in full.
#[derive(Clone, Debug)]
struct LabelTable {
    names: Vec<Box<str>>,
    /// Power-of-two length, at most half full.
    slots: Vec<Slot>,
}

#[derive(Clone, Copy, Debug, Default)]
struct Slot {
    key: [u64; 2],
    len: u32,
    /// Label index + 1; 0 = empty.
    index: u32,
}

/// Exact (with the length) for labels up to 16 bytes.
#[inline]
fn label_key(b: &[u8]) -> [u64; 2] {
    let n = b.len();
    let u64_at = |i: usize| {
        let mut w = [0u8; 8];
        w.copy_from_slice(&b[i..i + 8]);
        u64::from_le_bytes(w)
    };
    let u32_at = |i: usize| {
        let mut w = [0u8; 4];
        w.copy_from_slice(&b[i..i + 4]);
        u64::from(u32::from_le_bytes(w))
    };
    if n >= 8 {
        [u64_at(0), u64_at(n - 8)]
    } else if n >= 4 {
        [u32_at(0) | u32_at(n - 4) << 32, 0]
    } else if n > 0 {
        [
            u64::from(b[0]) | u64::from(b[n / 2]) << 8 | u64::from(b[n - 1]) << 16,
            0,
        ]
    } else {
        [0, 0]
    }
}

#[inline]
fn slot_hash(key: [u64; 2], len: usize) -> usize {
    let x = key[0] ^ key[1].rotate_left(29) ^ (len as u64).rotate_left(56);
    (x.wrapping_mul(0x9e37_79b9_7f4a_7c15) >> 32) as usize
}

impl LabelTable {
    fn new(mut names: Vec<String>) -> LabelTable {
        names.sort();
        names.dedup();
        let mut slots = vec![Slot::default(); (names.len() * 2).next_power_of_two().max(2)];
        let mask = slots.len() - 1;
        for (i, n) in names.iter().enumerate() {
            let key = label_key(n.as_bytes());
            let mut s = slot_hash(key, n.len()) & mask;
            while slots[s].index != 0 {
                s = (s + 1) & mask;
            }
            slots[s] = Slot {
                key,
                len: n.len() as u32,
                index: i as u32 + 1,
            };
        }
        LabelTable {
            names: names.into_iter().map(String::into_boxed_str).collect(),
            slots,
        }
    }

    #[inline]
    fn get(&self, name: &str) -> Option<u32> {
        let b = name.as_bytes();
        let key = label_key(b);
        let mask = self.slots.len() - 1;
        let mut s = slot_hash(key, b.len()) & mask;
        loop {
            let slot = self.slots[s];
            if slot.index == 0 {
                return None;
            }
            if slot.key == key
                && slot.len as usize == b.len()
                && (b.len() <= 16 || *self.names[slot.index as usize - 1] == *name)
            {
                return Some(slot.index - 1);
            }
            s = (s + 1) & mask;
        }
    }

    fn len(&self) -> usize {
        self.names.len()
    }
}

/// The compressed alphabet of one compiled set.
#[derive(Clone, Debug)]
pub struct Alphabet {
    labels: LabelTable,
    /// `log2` of the stride of a `(type, event)`'s run in `raw_to_class`: the label
    /// symbols (none, the interned labels, OTHER) rounded up to a power of two, so that
    /// a run's start is a shift of its `(type, event)` index, not a product.
    label_shift: u32,
    /// Raw symbol -> class. Index `type_event << label_shift | label`, where label 0 is
    /// none, `1..=k` the interned labels and `k + 1` OTHER; the slots past OTHER up to
    /// the stride hold OTHER's class (no label id of this set reaches them).
    raw_to_class: Vec<u32>,
    /// Per [`TYPE_EVENT`] entry, where its `(type, event)`'s run starts in
    /// `raw_to_class`: classifying reads this instead of [`TYPE_EVENT`] and so needs no
    /// shift.
    run_start: Box<[u32; 5 << 6]>,
    /// Per class, which of the distinct atoms accept it (bitset over atoms).
    class_atoms: Vec<Vec<u64>>,
    /// Per `(class, group)`, a raw symbol of that class that can occur in that place, for
    /// building witness paths.
    representatives: Vec<[Option<u32>; 3]>,
    /// A label that none of the expressions mention, to stand for OTHER in witnesses.
    other_label: String,
}

impl Alphabet {
    /// Builds the alphabet for `atoms` (the distinct atoms of the compiled set), whose
    /// labels are `labels`.
    pub(crate) fn new(atoms: &[&Atom], labels: Vec<String>) -> Alphabet {
        let labels = LabelTable::new(labels);
        let label_syms = labels.len() + 2;
        let label_shift = label_syms.next_power_of_two().trailing_zeros();
        let stride = 1usize << label_shift;
        let words = atoms.len().div_ceil(64).max(1);
        // Atoms that never look at labels accept the same `(type, event)` pairs whatever
        // the label: their masks are worked out once.
        let blind: Vec<Option<TeMask>> = atoms
            .iter()
            .map(|a| (!mentions_label(a)).then(|| atom_mask(a, ALL_TYPE_EVENTS, &|_| false)))
            .collect();
        // Per label symbol, the 51 `(type, event)` pairs start as one block, and each atom
        // splits every block into the pairs it accepts and the rest. A block is
        // `(pairs, label symbol)`; its signature (the atoms that accept it) is at
        // `sigs[block * words..]`, one flat buffer (every heap block costs a stack trace
        // under the fuzz targets' AddressSanitizer).
        let mut blocks: Vec<(TeMask, usize)> = Vec::new();
        let mut sigs: Vec<u64> = Vec::new();
        for l in 0..label_syms {
            let first = blocks.len();
            blocks.push((ALL_TYPE_EVENTS, l));
            sigs.resize(sigs.len() + words, 0);
            for (a, atom) in atoms.iter().enumerate() {
                let accepted = blind[a].unwrap_or_else(|| {
                    atom_mask(atom, ALL_TYPE_EVENTS, &|name| label_is(name, l, &labels))
                });
                for b in first..blocks.len() {
                    let (pairs, _) = blocks[b];
                    let (inside, outside) = (pairs & accepted, pairs & !accepted);
                    if inside == 0 {
                        continue;
                    }
                    if outside != 0 {
                        blocks[b].0 = inside;
                        blocks.push((outside, l));
                        sigs.extend_from_within(b * words..(b + 1) * words);
                    }
                    bits::set(&mut sigs[b * words..(b + 1) * words], a);
                }
            }
        }
        // Blocks with one signature (across label symbols) are one class. Classes are
        // numbered as raw symbols first show them, in raw-symbol order.
        let mut by_signature: FxMap<&[u64], u32> = FxMap::default();
        // Per signature, a block that has it.
        let mut sig_block = Vec::new();
        let block_sig: Vec<u32> = (0..blocks.len())
            .map(|b| {
                let next = sig_block.len() as u32;
                let sig = *by_signature
                    .entry(&sigs[b * words..(b + 1) * words])
                    .or_insert(next);
                if sig == next {
                    sig_block.push(b);
                }
                sig
            })
            .collect();
        let mut raw_to_class = vec![0u32; TYPE_EVENTS * stride];
        for (&(pairs, l), &sig) in blocks.iter().zip(&block_sig) {
            // OTHER's class also fills the padding past it, up to the stride (no label
            // id of this set reaches it).
            let labels = if l == label_syms - 1 {
                l..stride
            } else {
                l..l + 1
            };
            let mut rest = pairs;
            while rest != 0 {
                let te = rest.trailing_zeros() as usize;
                rest &= rest - 1;
                raw_to_class[te << label_shift..][labels.clone()].fill(sig);
            }
        }
        let mut class_of_sig = vec![u32::MAX; sig_block.len()];
        let mut sig_of_class = Vec::with_capacity(sig_block.len());
        for c in raw_to_class.iter_mut() {
            let class = &mut class_of_sig[*c as usize];
            if *class == u32::MAX {
                *class = sig_of_class.len() as u32;
                sig_of_class.push(*c);
            }
            *c = *class;
        }
        let class_atoms: Vec<Vec<u64>> = sig_of_class
            .iter()
            .map(|&s| sigs[sig_block[s as usize] * words..][..words].to_vec())
            .collect();
        let mut representatives = vec![[None; 3]; class_atoms.len()];
        // Padding reads as OTHER, whose entry comes first: it names no new representative.
        for (raw, &class) in raw_to_class.iter().enumerate() {
            let sym = Self::sym_of(&labels, label_shift, raw);
            // The camera carries no label (path.rs): only `C` with no label is a vertex.
            if sym.ty == VertexType::C && sym.label != LabelSym::None {
                continue;
            }
            let slot = &mut representatives[class as usize][place_of(sym.ty).index()];
            slot.get_or_insert(raw as u32);
        }
        let mut other_label = "other".to_string();
        for n in 1.. {
            if labels.get(&other_label).is_none() {
                break;
            }
            other_label = format!("other{n}");
        }
        let run_start = Box::new(TYPE_EVENT.map(|te| u32::from(te) << label_shift));
        Alphabet {
            labels,
            label_shift,
            raw_to_class,
            run_start,
            class_atoms,
            representatives,
            other_label,
        }
    }

    fn sym_of(labels: &LabelTable, label_shift: u32, raw: usize) -> Sym {
        let (ty, event) = type_event(raw >> label_shift);
        let l = raw & ((1 << label_shift) - 1);
        let label = match l {
            0 => LabelSym::None,
            l if l <= labels.len() => LabelSym::Known(l as u32 - 1),
            _ => LabelSym::Other,
        };
        Sym { ty, event, label }
    }

    /// The class of a vertex.
    #[inline]
    pub(crate) fn classify(&self, v: &Vertex) -> Class {
        self.classify_interned(v.ty(), v.event(), self.label_id(v.label()))
    }

    /// The id of a label for [`Alphabet::classify_interned`]: `0` for no label, then
    /// the interned labels, then OTHER for every label the expressions never mention.
    #[inline]
    pub(crate) fn label_id(&self, name: Option<&str>) -> LabelId {
        LabelId(match name {
            None => 0,
            Some(n) => self
                .labels
                .get(n)
                .map_or(self.labels.len() as u32 + 1, |i| i + 1),
        })
    }

    /// The class of `(type, event, label)` from a label interned beforehand: index
    /// arithmetic and two table loads, no hashing. An event on `C`, `L` or `O` is
    /// ignored; a label id of another set gives some class, never a panic.
    #[inline]
    pub(crate) fn classify_interned(
        &self,
        ty: VertexType,
        event: Option<Event>,
        label: LabelId,
    ) -> Class {
        let raw = self.run_start[type_event_code(ty, event)] as usize + label.0 as usize;
        Class(self.raw_to_class.get(raw).copied().unwrap_or(0))
    }

    pub(crate) fn class_count(&self) -> usize {
        self.class_atoms.len()
    }

    /// Does distinct atom `a` accept class `c`?
    pub(crate) fn accepts(&self, c: usize, a: usize) -> bool {
        bits::get(&self.class_atoms[c], a)
    }

    /// Whether some vertex of class `c` can stand in place `g` of a path: what
    /// [`Alphabet::representative`] answers, without building the vertex (and its label).
    pub(crate) fn occurs_in(&self, c: usize, g: Place) -> bool {
        self.representatives[c][g.index()].is_some()
    }

    /// A vertex of class `c` that can stand in place `g` of a path, if there is one.
    pub(crate) fn representative(&self, c: usize, g: Place) -> Option<Vertex> {
        let raw = self.representatives[c][g.index()]? as usize;
        let sym = Self::sym_of(&self.labels, self.label_shift, raw);
        let label = match sym.label {
            LabelSym::None => None,
            LabelSym::Known(i) => Some(&*self.labels.names[i as usize]),
            LabelSym::Other => Some(self.other_label.as_str()),
        };
        Some(match (sym.ty, sym.event) {
            (VertexType::C, _) => Vertex::camera(),
            (VertexType::L, _) => Vertex::light(label),
            (VertexType::O, _) => Vertex::emissive(label),
            (ty, Some(e)) => Vertex::scatter(ty, e, label),
            // `type_event` gives every R/T slot an event.
            (_, None) => return None,
        })
    }

    /// Bytes held by the tables.
    pub(crate) fn memory_bytes(&self) -> usize {
        self.raw_to_class.len() * 4
            + std::mem::size_of_val(&*self.run_start)
            + self.slots_bytes()
            + self.class_atoms.iter().map(|c| c.len() * 8).sum::<usize>()
            + self.representatives.len() * 24
    }

    fn slots_bytes(&self) -> usize {
        self.labels.slots.len() * std::mem::size_of::<Slot>()
            + self.labels.names.iter().map(|n| n.len()).sum::<usize>()
    }
}

// --- What each atom accepts, as sets (docs/language.md §4.1). ---

/// A set of `(type, event)` pairs, bit `i` for [`type_event`]`(i)`: C 0, L 1, O 2, then
/// R's events from 3 and T's from 27, each run D1-4, S1-8, U1-12.
type TeMask = u64;

const ALL_TYPE_EVENTS: TeMask = (1 << TYPE_EVENTS) - 1;

/// Event bits (D1-4, S1-8, U1-12 as bits 0-23) on both R and T.
const fn on_r_and_t(events: u64) -> TeMask {
    events << TYPE_BASE[VertexType::R as usize] | events << TYPE_BASE[VertexType::T as usize]
}

/// `.` at the top level: R or T with a D or S event.
const TRANSPORT: TeMask = on_r_and_t((1 << (MAX_LOBE[0] + MAX_LOBE[1])) - 1);
/// R or T, any event.
const SCATTERING: TeMask = on_r_and_t((1 << EVENTS) - 1);
/// C, L and O: the pairs without an event.
const NO_EVENT: TeMask = 0b111;

fn type_mask(ty: VertexType) -> TeMask {
    match ty {
        VertexType::R | VertexType::T => ((1 << EVENTS) - 1) << TYPE_BASE[ty as usize],
        VertexType::C | VertexType::L | VertexType::O => 1 << TYPE_BASE[ty as usize],
    }
}

/// The R and T pairs whose event matches `p` (its kind, and its lobe if given).
fn event_mask(p: EventPattern) -> TeMask {
    let kind = p.kind as usize;
    let lobes: u64 = match p.lobe.map(usize::from) {
        None => (1 << MAX_LOBE[kind]) - 1,
        Some(l) if (1..=MAX_LOBE[kind]).contains(&l) => 1 << (l - 1),
        Some(_) => 0,
    };
    on_r_and_t(lobes << KIND_BASE[kind])
}

/// Whether label symbol `l` (0 none, `1..=k` the interned labels, `k + 1` OTHER) is
/// the label `name`.
fn label_is(name: &str, l: usize, labels: &LabelTable) -> bool {
    labels.get(name).is_some_and(|i| i as usize + 1 == l)
}

/// Whether an atom's answer can depend on the vertex label.
fn mentions_label(atom: &Atom) -> bool {
    let item = |i: &Item| match i {
        Item::Label(_) => true,
        Item::Triple(t) => t.label != LabelPos::Any,
        Item::Type(_) | Item::Event(_) | Item::Any => false,
    };
    match atom {
        Atom::Item(i) => item(i),
        Atom::Class { items, .. } => items.iter().any(item),
    }
}

/// Whether `atom` accepts `v`: [`atom_mask`] asked about one vertex, its label compared
/// by name, with no label table: for matching a few paths without building an alphabet
/// ([`crate::DirectSet`]).
pub(crate) fn atom_accepts(atom: &Atom, v: &Vertex) -> bool {
    let te = 1 << TYPE_EVENT[type_event_code(v.ty(), v.event())];
    atom_mask(atom, te, &|name| v.label() == Some(name)) & te != 0
}

/// The `(type, event)` pairs `atom` accepts on a vertex whose label `is_label` tells
/// (`is_label(name)`: the vertex's label is `name`; false for every name when it has
/// none or one the expressions never mention), exact on the pairs of `care` and
/// unspecified on the others: a label is compared only when some pair of `care` could
/// still be accepted, which spares [`atom_accepts`] the string compares of the triples
/// whose type or event already refuse its vertex.
fn atom_mask(atom: &Atom, care: TeMask, is_label: &impl Fn(&str) -> bool) -> TeMask {
    let any = |items: &[Item]| {
        items
            .iter()
            .fold(0, |m, i| m | item_mask(i, care, is_label))
    };
    match atom {
        Atom::Item(item) => item_mask(item, care, is_label),
        Atom::Class {
            negated: false,
            items,
        } => any(items),
        // Negation: what `.` matches, minus the items.
        Atom::Class {
            negated: true,
            items,
        } => TRANSPORT & !any(items),
    }
}

fn item_mask(item: &Item, care: TeMask, is_label: &impl Fn(&str) -> bool) -> TeMask {
    match item {
        // `C`, `L`, `O`: the type, any label. `R`, `T`: the type with a D or S event.
        Item::Type(t) if t.is_scattering() => type_mask(*t) & TRANSPORT,
        Item::Type(t) => type_mask(*t),
        // `D`, `S2`, `U3`: an R/T vertex with that event (user lobes only this way).
        Item::Event(p) => event_mask(*p),
        Item::Any => TRANSPORT,
        Item::Label(name) if TRANSPORT & care != 0 && is_label(name) => TRANSPORT,
        Item::Label(_) => 0,
        Item::Triple(t) => triple_mask(t, care, is_label),
    }
}

/// `<t e l>`: the product of what each position accepts; a negated class in a position
/// is that position's `.` minus its items.
fn triple_mask(t: &Triple, care: TeMask, is_label: &impl Fn(&str) -> bool) -> TeMask {
    let types = match &t.ty {
        TypePos::Any => SCATTERING,
        TypePos::One(ty) => type_mask(*ty),
        TypePos::Class { negated, types } => {
            let listed = types.iter().fold(0, |m, ty| m | type_mask(*ty));
            if *negated {
                SCATTERING & !listed
            } else {
                listed
            }
        }
    };
    // `.` in the event position: D or S on R/T, "no event" on C/L/O.
    let event_dot = NO_EVENT | TRANSPORT;
    let events = match &t.event {
        EventPos::Any => event_dot,
        EventPos::One(p) => event_mask(*p),
        EventPos::Class { negated, events } => {
            let listed = events.iter().fold(0, |m, p| m | event_mask(*p));
            if *negated {
                event_dot & !listed
            } else {
                listed
            }
        }
    };
    let accepted = types & events;
    // The label last: only a pair of `care` still accepted needs it compared.
    if accepted & care == 0 {
        return 0;
    }
    let label_ok = match &t.label {
        // `.` in the label position: any label or none; `[^'a']` includes "no label".
        LabelPos::Any => true,
        LabelPos::One(name) => is_label(name),
        LabelPos::Class {
            negated,
            labels: names,
        } => names.iter().any(|n| is_label(n)) != *negated,
    };
    if label_ok {
        accepted
    } else {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::renderman::ast::Expr;

    /// The atoms' meaning written the other way round: one predicate per atom, asked
    /// of one raw symbol at a time (the construction this module had before it built
    /// sets), to check the sets against.
    mod per_symbol {
        use super::super::*;

        /// `.` at the top level: R or T with a D or S event.
        fn dot(s: &Sym) -> bool {
            s.ty.is_scattering() && s.event.is_some_and(Event::is_transport)
        }

        fn event_is(p: EventPattern, s: &Sym) -> bool {
            s.event
                .is_some_and(|e| e.kind() == p.kind && p.lobe.is_none_or(|l| l == e.lobe()))
        }

        fn label_is(name: &str, s: &Sym, labels: &LabelTable) -> bool {
            // A string compare, not a table lookup: this runs for every raw symbol and atom.
            match s.label {
                LabelSym::Known(i) => *labels.names[i as usize] == *name,
                LabelSym::None | LabelSym::Other => false,
            }
        }

        pub(super) fn atom_accepts(atom: &Atom, s: &Sym, labels: &LabelTable) -> bool {
            match atom {
                Atom::Item(item) => item_accepts(item, s, labels),
                Atom::Class {
                    negated: false,
                    items,
                } => items.iter().any(|i| item_accepts(i, s, labels)),
                // Negation: what `.` matches, minus the items.
                Atom::Class {
                    negated: true,
                    items,
                } => dot(s) && !items.iter().any(|i| item_accepts(i, s, labels)),
            }
        }

        fn item_accepts(item: &Item, s: &Sym, labels: &LabelTable) -> bool {
            match item {
                // `C`, `L`, `O`: the type, any label. `R`, `T`: the type with a D or S event.
                Item::Type(t) if t.is_scattering() => s.ty == *t && dot(s),
                Item::Type(t) => s.ty == *t,
                // `D`, `S2`, `U3`: an R/T vertex with that event (user lobes only this way).
                Item::Event(p) => s.ty.is_scattering() && event_is(*p, s),
                Item::Any => dot(s),
                Item::Label(name) => dot(s) && label_is(name, s, labels),
                Item::Triple(t) => triple_accepts(t, s, labels),
            }
        }

        /// `<t e l>`: every position must accept; a negated class in a position is that
        /// position's `.` minus its items.
        fn triple_accepts(t: &Triple, s: &Sym, labels: &LabelTable) -> bool {
            let ty_dot = s.ty.is_scattering();
            let ty_ok = match &t.ty {
                TypePos::Any => ty_dot,
                TypePos::One(ty) => s.ty == *ty,
                TypePos::Class { negated, types } => {
                    let listed = types.contains(&s.ty);
                    if *negated {
                        ty_dot && !listed
                    } else {
                        listed
                    }
                }
            };
            // `.` in the event position: D or S on R/T, "no event" on C/L/O.
            let ev_dot = s.event.is_none_or(Event::is_transport);
            let ev_ok = match &t.event {
                EventPos::Any => ev_dot,
                EventPos::One(p) => event_is(*p, s),
                EventPos::Class { negated, events } => {
                    let listed = events.iter().any(|p| event_is(*p, s));
                    if *negated {
                        ev_dot && !listed
                    } else {
                        listed
                    }
                }
            };
            // `.` in the label position: any label or none; `[^'a']` includes "no label".
            let label_ok = match &t.label {
                LabelPos::Any => true,
                LabelPos::One(name) => label_is(name, s, labels),
                LabelPos::Class {
                    negated,
                    labels: names,
                } => names.iter().any(|n| label_is(n, s, labels)) != *negated,
            };
            ty_ok && ev_ok && label_ok
        }
    }

    /// Atoms covering every branch of the set construction: types, events with and
    /// without lobes, `.`, labels, triples with each kind of position, classes and
    /// negated classes of each.
    const ATOMS: &[&str] = &[
        "C",
        "R",
        "T",
        "L",
        "O",
        "D",
        "S",
        "U",
        "D2",
        "S8",
        "U12",
        ".",
        "'a'",
        "'b'",
        "<RD>",
        "<T.'a'>",
        "<.S3>",
        "<[RT]D>",
        "<[^R].>",
        "<[CL].>",
        "<L.'b'>",
        "<L.[^'a']>",
        "<O.['a' 'b']>",
        "<.[DS2]>",
        "<.[^D]>",
        "<R[^S].>",
        "<[^T][^D1]['b']>",
        "<.U3>",
        "<C..>",
        "<[^R][^S]'c'>",
        "[DS]",
        "[^D]",
        "[^'a']",
        "[^<RD>]",
        "[<L.'a'>O]",
        "[^R S2]",
        "[C 'b']",
        "[^.]",
        "[^U 'c']",
    ];

    /// The atom of each of [`ATOMS`].
    fn parsed_atoms() -> Vec<Atom> {
        ATOMS
            .iter()
            .map(|src| {
                let mut one = Vec::new();
                parse(src)
                    .unwrap_or_else(|e| panic!("{src}: {e}"))
                    .expr
                    .for_each_atom(&mut |a| one.push(a.clone()));
                assert_eq!(one.len(), 1, "{src}");
                one.remove(0)
            })
            .collect()
    }

    #[test]
    fn classes_are_the_raw_symbols_every_atom_answers_alike() {
        let atoms = parsed_atoms();
        let mut rng = crate::rng::SplitMix64::new(7);
        for case in 0..300 {
            // All atoms, then random subsets in random order, with and without a label
            // that no atom mentions.
            let mut chosen: Vec<&Atom> = if case == 0 {
                atoms.iter().collect()
            } else {
                let n = 1 + rng.below(8);
                (0..n).map(|_| &atoms[rng.below(atoms.len())]).collect()
            };
            chosen.dedup();
            let mut labels: Vec<String> = Vec::new();
            for a in &chosen {
                labels.extend(Expr::Atom((*a).clone()).labels());
            }
            if case % 3 == 0 {
                labels.push("unmentioned".into());
            }
            let al = Alphabet::new(&chosen, labels);
            let stride = 1usize << al.label_shift;
            let label_syms = al.labels.len() + 2;
            let mut class_of: Vec<(Vec<bool>, u32)> = Vec::new();
            let mut next_new_class = 0;
            for (raw, &class) in al.raw_to_class.iter().enumerate() {
                if raw % stride >= label_syms {
                    let other = raw - raw % stride + label_syms - 1;
                    assert_eq!(class, al.raw_to_class[other], "case {case}: padding {raw}");
                    continue;
                }
                let sym = Alphabet::sym_of(&al.labels, al.label_shift, raw);
                let answers: Vec<bool> = chosen
                    .iter()
                    .map(|a| per_symbol::atom_accepts(a, &sym, &al.labels))
                    .collect();
                for (i, &yes) in answers.iter().enumerate() {
                    assert_eq!(
                        al.accepts(class as usize, i),
                        yes,
                        "case {case}: {sym:?} atom {:?}",
                        chosen[i]
                    );
                }
                match class_of.iter().find(|(a, _)| *a == answers) {
                    Some(&(_, c)) => assert_eq!(c, class, "case {case}: {sym:?} split off"),
                    None => {
                        assert!(
                            class_of.iter().all(|&(_, c)| c != class),
                            "case {case}: {sym:?} merged with other answers"
                        );
                        // Classes are numbered as raw symbols first show them.
                        assert_eq!(class, next_new_class, "case {case}: {sym:?}");
                        next_new_class += 1;
                        class_of.push((answers, class));
                    }
                }
            }
            assert_eq!(al.class_count(), class_of.len(), "case {case}");
        }
    }
    /// [`super::atom_accepts`], which decides one vertex with no label table (for
    /// `DirectSet`), against the per-symbol predicates and the alphabet's classes, for
    /// every atom of [`ATOMS`] on a vertex of every raw symbol: every type, event and
    /// label symbol, a label no atom mentions included. Caught when planted: the label
    /// compared as "has a label" rather than by name, the vertex's `(type, event)` bit
    /// read with no event.
    #[test]
    fn one_vertex_is_accepted_as_its_class_is() {
        let atoms = parsed_atoms();
        let chosen: Vec<&Atom> = atoms.iter().collect();
        let mut labels: Vec<String> = Vec::new();
        for a in &chosen {
            labels.extend(Expr::Atom((*a).clone()).labels());
        }
        let al = Alphabet::new(&chosen, labels);
        let stride = 1usize << al.label_shift;
        let label_syms = al.labels.len() + 2;
        let mut checked = 0;
        for raw in (0..al.raw_to_class.len()).filter(|r| r % stride < label_syms) {
            let sym = Alphabet::sym_of(&al.labels, al.label_shift, raw);
            let label = match sym.label {
                LabelSym::None => None,
                LabelSym::Known(i) => Some(&*al.labels.names[i as usize]),
                LabelSym::Other => Some("unmentioned"),
            };
            let v = match (sym.ty, sym.event) {
                (VertexType::C, _) => Vertex::camera(),
                (VertexType::L, _) => Vertex::light(label),
                (VertexType::O, _) => Vertex::emissive(label),
                (ty, Some(e)) => Vertex::scatter(ty, e, label),
                (_, None) => continue,
            };
            let class = al.classify(&v).index();
            for (i, a) in chosen.iter().enumerate() {
                let want = per_symbol::atom_accepts(a, &sym, &al.labels);
                assert_eq!(super::atom_accepts(a, &v), want, "{a:?} on {v}");
                assert_eq!(al.accepts(class, i), want, "{a:?} on {v}");
                checked += 1;
            }
        }
        // Every raw symbol made a vertex: 51 `(type, event)` pairs by every label symbol.
        assert_eq!(checked, 51 * label_syms * ATOMS.len());
    }

    use crate::renderman::parse;

    fn alphabet(src: &str) -> (Alphabet, Vec<Atom>) {
        let e = parse(src).unwrap().expr;
        let mut atoms = Vec::new();
        e.for_each_atom(&mut |a| {
            if !atoms.contains(a) {
                atoms.push(a.clone())
            }
        });
        let refs: Vec<&Atom> = atoms.iter().collect();
        (Alphabet::new(&refs, e.labels()), atoms)
    }

    fn type_event_index(ty: VertexType, event: Option<Event>) -> usize {
        TYPE_EVENT[type_event_code(ty, event)] as usize
    }

    #[test]
    fn type_event_index_round_trips() {
        for i in 0..TYPE_EVENTS {
            let (ty, ev) = type_event(i);
            assert_eq!(type_event_index(ty, ev), i);
        }
    }

    #[test]
    fn an_event_on_a_camera_or_emitter_is_ignored() {
        for kind in [EventKind::D, EventKind::S, EventKind::U] {
            for lobe in 1..=kind.max_lobe() {
                let e = Event::new(kind, lobe);
                assert!(e.is_some());
                for ty in [VertexType::C, VertexType::L, VertexType::O] {
                    assert_eq!(
                        type_event_index(ty, e),
                        type_event_index(ty, None),
                        "{ty:?} {e:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn unmentioned_labels_share_a_class() {
        let (a, _) = alphabet("C<RD'floor'>L");
        let d = |l| Vertex::scatter(VertexType::R, Event::new(EventKind::D, 1).unwrap(), Some(l));
        assert_eq!(a.classify(&d("wall")), a.classify(&d("ceiling")));
        assert_ne!(a.classify(&d("wall")), a.classify(&d("floor")));
    }

    #[test]
    fn label_ids_past_this_sets_read_some_class_and_the_stride_padding_reads_other() {
        // One label: ids 0 (none), 1 ('floor'), 2 (OTHER), and 3, the padding of the
        // stride of 4, which no id of this set reaches: it must read as OTHER.
        let (a, _) = alphabet("C<RD'floor'>L");
        let d1 = Event::new(EventKind::D, 1);
        let other = a.classify(&Vertex::scatter(VertexType::R, d1.unwrap(), Some("x")));
        assert_eq!(a.label_id(Some("x")), LabelId(2));
        assert_eq!(a.classify_interned(VertexType::R, d1, LabelId(3)), other);
        assert_ne!(
            a.classify_interned(VertexType::R, d1, LabelId(1)),
            other,
            "'floor' has its own class"
        );
        for ty in VertexType::ALL {
            for id in 0..40 {
                let c = a.classify_interned(ty, d1, LabelId(id));
                assert!(c.index() < a.class_count(), "{ty:?} {id}");
            }
        }
    }

    #[test]
    fn occurs_in_names_the_places_a_class_can_take() {
        // Classes of `C<RD>L`: the camera, RD, lights, and the rest (O, other
        // scatterings). `O` ends a path; the rest's R/T vertices stand in the middle.
        let (a, _) = alphabet("C<RD>L");
        let d1 = Event::new(EventKind::D, 1).unwrap();
        let places = |v: &Vertex| {
            let c = a.classify(v).0 as usize;
            let places = Place::ALL.map(|g| a.occurs_in(c, g));
            assert_eq!(places, Place::ALL.map(|g| a.representative(c, g).is_some()));
            places
        };
        assert_eq!(places(&Vertex::camera()), [true, false, false]);
        assert_eq!(
            places(&Vertex::scatter(VertexType::R, d1, None)),
            [false, true, false]
        );
        assert_eq!(places(&Vertex::light(None)), [false, false, true]);
        assert_eq!(places(&Vertex::emissive(None)), [false, true, true]);
    }

    #[test]
    fn basic_set_needs_few_classes() {
        // C, <RD>, <TD>, <RS>, <TS>, L/O, and the rest (user lobes).
        let (a, _) = alphabet("C(<RD>|<TD>|<RS>|<TS>).*[<L.>O]");
        assert!(a.class_count() <= 8, "{}", a.class_count());
    }

    #[test]
    fn label_table_finds_every_label_and_nothing_else() {
        let mut names: Vec<String> = (0..40).map(|i| format!("l{i}")).collect();
        // Long labels sharing their first 8 bytes, and the empty label.
        names.extend(
            [
                "a_long_label_1",
                "a_long_label_2",
                "a_much_longer_label_1",
                "a_much_longer_label_2",
                // Past 16 bytes the key holds the first and last 8 only.
                "head_8by_A_tail_8by",
                "",
                "ab",
                "abc",
                "abcdefg",
            ]
            .map(String::from),
        );
        let t = LabelTable::new(names.clone());
        for n in &names {
            assert_eq!(t.names[t.get(n).unwrap() as usize].as_ref(), n.as_str());
        }
        assert_eq!(t.get("nope"), None);
        assert_eq!(t.get("a_long_label_3"), None);
        assert_eq!(t.get("l1\0"), None);
        assert_eq!(t.get("a_much_longer_label_3"), None);
        assert_eq!(t.get("a_much_longer_labex_1"), None);
        assert_eq!(t.get("abcdffg"), None);
        assert_eq!(t.get("head_8by_B_tail_8by"), None);
        assert_eq!(t.get("adc"), None);
        assert_eq!(LabelTable::new(Vec::new()).get("x"), None);
    }

    #[test]
    fn memory_is_the_tables_worked_out_by_hand() {
        // `C<RD'ab'>L`: one label, so 3 label symbols (none, 'ab', OTHER), a stride of
        // 4, per each of the 51 (type, event) pairs: 204 u32 classes = 816 bytes, and a
        // run start per entry of the 320-entry (type, event) table, 1 280 bytes. Label
        // slots: 2 of
        // 24 bytes, plus the 2 bytes of "ab" = 50. Classes: C, <RD'ab'>, L, the rest:
        // 4, each one 8-byte word of atoms (32) and three u32 options of witnesses (96).
        let (a, _) = alphabet("C<RD'ab'>L");
        assert_eq!((a.class_count(), std::mem::size_of::<Slot>()), (4, 24));
        assert_eq!(a.slots_bytes(), 50);
        assert_eq!(a.memory_bytes(), 816 + 1280 + 50 + 32 + 96);
    }
}
