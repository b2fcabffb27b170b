//! The regex engine's byte encoding of vertices, and sets of vertices over that encoding.
//!
//! Every vertex is exactly three bytes, one per field, each field in its own byte range
//! so that no byte can be read as another field's value:
//!
//! | field | bytes |
//! |---|---|
//! | type | `0x00..=0x04`: C R T L O |
//! | event | `0x10`: none (C/L/O); `0x11..=0x28`: D1..D4, S1..S8, U1..U12 |
//! | label | `0x40`: unlabelled; `0x41`: any label the expressions never mention; `0x42 + i`: the i-th mentioned label |
//!
//! Label interning is this engine's own: the compiled expressions' labels, sorted, get a
//! byte each. A path label no expression mentions can only ever be told apart from the
//! mentioned ones, never from another unmentioned one, so mapping all of them to one
//! "other" byte is exact.
//!
//! [`VertexSet`] is a set of encoded vertices: for each (type, event) pair a bit mask of
//! label bytes. Complements (negated classes) are computed inside this finite universe
//! by set difference, so the regex never contains `.` or `[^…]`, which would match bytes
//! of the wrong field.

use std::collections::HashMap;

use lpe::renderman::{Event, Path, RenderMan, Vertex, VertexType};

use crate::dialect::Encoder;

/// Bytes per encoded vertex.
pub const WIDTH: usize = 3;
/// First event byte: "no event".
pub const EVENT_NONE: u8 = 0x10;
/// Label byte of an unlabelled vertex.
pub const LABEL_NONE: u8 = 0x40;
/// Label byte shared by every label the expressions do not mention.
pub const LABEL_OTHER: u8 = 0x41;
/// Most distinct labels one compiled set may mention (label bytes run up to 0xff).
pub const MAX_LABELS: usize = 0xff - 0x42 + 1;

/// Number of event values including "none".
pub const EVENTS: usize = 25;
/// Number of vertex types.
pub const TYPES: usize = 5;

/// The type byte.
pub fn type_byte(t: VertexType) -> u8 {
    match t {
        VertexType::C => 0,
        VertexType::R => 1,
        VertexType::T => 2,
        VertexType::L => 3,
        VertexType::O => 4,
    }
}

/// The event byte (`EVENT_NONE` for `None`).
pub fn event_byte(e: Option<Event>) -> u8 {
    match e {
        None => EVENT_NONE,
        Some(e) => {
            let i = Event::all()
                .position(|x| x == e)
                .expect("every Event is in Event::all()");
            EVENT_NONE + 1 + i as u8
        }
    }
}

/// Labels mentioned by the compiled expressions, each with its byte.
#[derive(Clone, Debug, Default)]
pub struct Labels {
    bytes: HashMap<String, u8>,
}

impl Labels {
    /// Interns `labels` (deduplicated, in order); `None` if there are too many.
    pub fn new(labels: &[String]) -> Option<Labels> {
        let mut bytes = HashMap::new();
        for l in labels {
            let next = bytes.len();
            if !bytes.contains_key(l) {
                if next >= MAX_LABELS {
                    return None;
                }
                bytes.insert(l.clone(), 0x42 + next as u8);
            }
        }
        Some(Labels { bytes })
    }

    /// Number of label values: unlabelled, other, and each mentioned label.
    pub fn values(&self) -> usize {
        2 + self.bytes.len()
    }

    /// The byte of a mentioned label.
    pub fn byte_of(&self, label: &str) -> u8 {
        // Translation only asks for labels it interned itself.
        self.bytes[label]
    }

    /// The byte of a path vertex's label.
    pub fn encode(&self, label: Option<&str>) -> u8 {
        match label {
            None => LABEL_NONE,
            Some(l) => self.bytes.get(l).copied().unwrap_or(LABEL_OTHER),
        }
    }
}

/// Appends the three bytes of `v` to `out`.
pub fn encode_vertex(labels: &Labels, v: &Vertex, out: &mut Vec<u8>) {
    out.push(type_byte(v.ty()));
    out.push(event_byte(v.event()));
    out.push(labels.encode(v.label()));
}

/// A set of label bytes, bit `b - LABEL_NONE` for byte `b`.
pub type LabelMask = [u64; 4];

/// The mask with exactly the label byte `b`.
pub fn label_bit(b: u8) -> LabelMask {
    let i = usize::from(b - LABEL_NONE);
    let mut m = [0; 4];
    m[i / 64] |= 1 << (i % 64);
    m
}

/// Every label value of `labels` (unlabelled, other and the mentioned ones).
pub fn all_labels(labels: &Labels) -> LabelMask {
    let mut m = [0; 4];
    for i in 0..labels.values() {
        m[i / 64] |= 1 << (i % 64);
    }
    m
}

/// A set of encoded vertices.
#[derive(Clone, PartialEq, Eq)]
pub struct VertexSet {
    /// Label mask per `(type, event)`, indexed `type * EVENTS + event`. Inline (4 KB):
    /// a translation builds several sets per atom, and a heap block each was most of
    /// the engine's allocations under the fuzzers' AddressSanitizer.
    cells: [LabelMask; TYPES * EVENTS],
}

/// A RenderMan path is its vertices' encodings, one after another.
impl Encoder<RenderMan> for Labels {
    fn encode(&self, path: &Path) -> Vec<u8> {
        let mut bytes = Vec::with_capacity(path.len() * WIDTH);
        for v in path.vertices() {
            encode_vertex(self, v, &mut bytes);
        }
        bytes
    }
}

impl VertexSet {
    /// The empty set.
    pub fn empty() -> VertexSet {
        VertexSet {
            cells: [[0; 4]; TYPES * EVENTS],
        }
    }

    /// Every vertex whose type is in `types`, event in `events` and label in `labels`.
    ///
    /// `events` is a mask over event indices (bit 0 = none, bit `1 + i` = the i-th of
    /// [`Event::all`]). Only combinations a path can contain are included: R/T with an
    /// event, C/L/O without one.
    pub fn product(types: &[VertexType], events: u32, labels: LabelMask) -> VertexSet {
        let mut s = VertexSet::empty();
        for &t in types {
            for e in 0..EVENTS {
                let has_event = e != 0;
                if events & (1 << e) != 0 && has_event == t.is_scattering() {
                    s.cells[usize::from(type_byte(t)) * EVENTS + e] = labels;
                }
            }
        }
        s
    }

    /// `self ∪ other`
    pub fn union(mut self, other: &VertexSet) -> VertexSet {
        for (a, b) in self.cells.iter_mut().zip(&other.cells) {
            for k in 0..4 {
                a[k] |= b[k];
            }
        }
        self
    }

    /// `self ∩ other`
    pub fn intersect(mut self, other: &VertexSet) -> VertexSet {
        for (a, b) in self.cells.iter_mut().zip(&other.cells) {
            for k in 0..4 {
                a[k] &= b[k];
            }
        }
        self
    }

    /// `self \ other`
    pub fn minus(mut self, other: &VertexSet) -> VertexSet {
        for (a, b) in self.cells.iter_mut().zip(&other.cells) {
            for k in 0..4 {
                a[k] &= !b[k];
            }
        }
        self
    }

    /// The label mask of `(type byte, event index)`.
    pub fn cell(&self, ty: usize, event: usize) -> LabelMask {
        self.cells[ty * EVENTS + event]
    }
}
