//! Light paths as a renderer records them (docs/language.md §2).
//!
//! A path is `C v1 ... vn E`: a camera vertex, scattering vertices (`R`/`T`) and one
//! emitter at the end (`L` light or `O` emissive object). Scattering vertices carry an
//! [`Event`] (lobe kind and number); every vertex but the camera may carry a label.
//!
//! Text form: vertices separated by whitespace, each its type letter, for `R`/`T` the
//! event with lobe number (bare `D`, `S`, `U` mean lobe 1), then an optional label in
//! single quotes: `C RD2'floor' TS8 RS1 L'key'`.
//!
//! Decisions a renderer could expect either way (documented here so the engines agree):
//! - interior vertices must be `R` or `T` (a renderer never records a camera or an emitter
//!   mid-path), and a path has at least two vertices (`C L`);
//! - the camera vertex carries no label;
//! - labels may hold any character but `'` and may be empty (`''`).

use std::fmt;
use std::num::NonZeroU8;

/// The type of a vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum VertexType {
    /// Camera.
    C,
    /// Reflection.
    R,
    /// Transmission.
    T,
    /// Light (analytic or geometric).
    L,
    /// Emissive object (glow, or a camera-visible light's surface).
    O,
}

impl VertexType {
    /// All vertex types, in canonical order.
    pub const ALL: [VertexType; 5] = [
        VertexType::C,
        VertexType::R,
        VertexType::T,
        VertexType::L,
        VertexType::O,
    ];

    /// The letter used in paths and expressions.
    pub fn letter(self) -> char {
        match self {
            VertexType::C => 'C',
            VertexType::R => 'R',
            VertexType::T => 'T',
            VertexType::L => 'L',
            VertexType::O => 'O',
        }
    }

    /// `R` or `T`: the types that carry a scattering event.
    pub fn is_scattering(self) -> bool {
        matches!(self, VertexType::R | VertexType::T)
    }

    /// Parses an upper- or lower-case type letter.
    pub fn from_letter(c: char) -> Option<VertexType> {
        Some(match c.to_ascii_uppercase() {
            'C' => VertexType::C,
            'R' => VertexType::R,
            'T' => VertexType::T,
            'L' => VertexType::L,
            'O' => VertexType::O,
            _ => return None,
        })
    }
}

impl fmt::Display for VertexType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.letter())
    }
}

/// The kind of a scattering lobe.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum EventKind {
    /// Diffuse, lobes 1..=4.
    D,
    /// Specular or glossy, lobes 1..=8.
    S,
    /// User lobe (a material property, not light transport), lobes 1..=12.
    U,
}

impl EventKind {
    /// All event kinds, in canonical order.
    pub const ALL: [EventKind; 3] = [EventKind::D, EventKind::S, EventKind::U];

    /// The highest lobe number of this kind.
    pub fn max_lobe(self) -> u8 {
        match self {
            EventKind::D => 4,
            EventKind::S => 8,
            EventKind::U => 12,
        }
    }

    /// The letter used in paths and expressions.
    pub fn letter(self) -> char {
        match self {
            EventKind::D => 'D',
            EventKind::S => 'S',
            EventKind::U => 'U',
        }
    }

    /// Parses an upper- or lower-case event letter.
    pub fn from_letter(c: char) -> Option<EventKind> {
        Some(match c.to_ascii_uppercase() {
            'D' => EventKind::D,
            'S' => EventKind::S,
            'U' => EventKind::U,
            _ => return None,
        })
    }
}

/// A concrete scattering event: a lobe kind and its number (`D2`, `S8`, `U6`).
///
/// Held as one byte, `kind << 4 | lobe` (kinds D S U as 0 1 2, lobes from 1), never 0:
/// an `Option<Event>` is that byte with 0 for none, which is what classifying a vertex
/// reads (one load, no test of which variant it is). Ordered by kind, then lobe.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Event {
    code: NonZeroU8,
}

impl Event {
    /// An event, if `lobe` is in range for `kind` (D1-4, S1-8, U1-12).
    pub fn new(kind: EventKind, lobe: u8) -> Option<Event> {
        (1..=kind.max_lobe())
            .contains(&lobe)
            .then(|| Event::in_range(kind, lobe))
    }

    /// `kind` and `lobe`, already known to be in range.
    fn in_range(kind: EventKind, lobe: u8) -> Event {
        Event {
            code: NonZeroU8::new((kind as u8) << 4 | lobe).expect("lobes start at 1"),
        }
    }

    /// Every valid event: D1..D4, S1..S8, U1..U12.
    pub fn all() -> impl Iterator<Item = Event> {
        EventKind::ALL
            .into_iter()
            .flat_map(|kind| (1..=kind.max_lobe()).map(move |lobe| Event::in_range(kind, lobe)))
    }

    /// The lobe kind.
    pub fn kind(self) -> EventKind {
        match self.code.get() >> 4 {
            0 => EventKind::D,
            1 => EventKind::S,
            _ => EventKind::U,
        }
    }

    /// The lobe number, starting at 1.
    pub fn lobe(self) -> u8 {
        self.code.get() & 15
    }

    /// `kind << 4 | lobe` (kinds D S U as 0 1 2): below 64, never 0.
    #[inline]
    pub(crate) fn code(self) -> u8 {
        self.code.get()
    }

    /// D or S: light transport (user lobes are not).
    pub fn is_transport(self) -> bool {
        self.kind() != EventKind::U
    }
}

impl fmt::Debug for Event {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Event")
            .field("kind", &self.kind())
            .field("lobe", &self.lobe())
            .finish()
    }
}

impl fmt::Display for Event {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}{}", self.kind().letter(), self.lobe())
    }
}

/// One vertex of a light path.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Vertex {
    ty: VertexType,
    event: Option<Event>,
    label: Option<String>,
}

impl Vertex {
    /// The camera vertex.
    pub fn camera() -> Vertex {
        Vertex {
            ty: VertexType::C,
            event: None,
            label: None,
        }
    }

    /// A reflection (`R`) or transmission (`T`) vertex.
    ///
    /// # Panics
    /// If `ty` is not `R` or `T` (a programming error, not input).
    pub fn scatter(ty: VertexType, event: Event, label: Option<&str>) -> Vertex {
        assert!(ty.is_scattering(), "Vertex::scatter needs R or T, got {ty}");
        Vertex {
            ty,
            event: Some(event),
            label: label.map(str::to_owned),
        }
    }

    /// A light vertex, with its light group.
    pub fn light(group: Option<&str>) -> Vertex {
        Vertex {
            ty: VertexType::L,
            event: None,
            label: group.map(str::to_owned),
        }
    }

    /// An emissive-object vertex, with its `lpegroup`.
    pub fn emissive(group: Option<&str>) -> Vertex {
        Vertex {
            ty: VertexType::O,
            event: None,
            label: group.map(str::to_owned),
        }
    }

    /// The vertex type.
    pub fn ty(&self) -> VertexType {
        self.ty
    }

    /// The scattering event (`Some` exactly for `R`/`T`).
    pub fn event(&self) -> Option<Event> {
        self.event
    }

    /// The label, if any.
    pub fn label(&self) -> Option<&str> {
        self.label.as_deref()
    }
}

impl fmt::Display for Vertex {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.ty)?;
        if let Some(e) = self.event {
            write!(f, "{e}")?;
        }
        if let Some(l) = &self.label {
            write!(f, "'{l}'")?;
        }
        Ok(())
    }
}

/// A complete light path: `C`, then `R`/`T` vertices, then `L` or `O`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Path {
    vertices: Vec<Vertex>,
}

/// Why a path is malformed: which vertex, where in the text, and what is wrong.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PathError {
    /// Zero-based index of the offending vertex (or the vertex count, for "too short").
    pub vertex: usize,
    /// Byte range of the offending vertex in the text, when parsed from text.
    pub span: Option<std::ops::Range<usize>>,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for PathError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "vertex {}", self.vertex + 1)?;
        if let Some(s) = &self.span {
            write!(f, " (bytes {}..{})", s.start, s.end)?;
        }
        write!(f, ": {}", self.message)
    }
}

impl std::error::Error for PathError {}

impl Path {
    /// Checks the shape rules and builds a path.
    pub fn new(vertices: Vec<Vertex>) -> Result<Path, PathError> {
        Self::check(&vertices, None)?;
        Ok(Path { vertices })
    }

    fn check(
        vertices: &[Vertex],
        spans: Option<&[std::ops::Range<usize>]>,
    ) -> Result<(), PathError> {
        let err = |i: usize, message: String| PathError {
            vertex: i,
            span: spans.and_then(|s| s.get(i).cloned()),
            message,
        };
        let n = vertices.len();
        if n < 2 {
            return Err(err(
                n,
                format!(
                    "a path needs at least a camera and an emitter (`C L`), got {n} vertex{}",
                    if n == 1 { "" } else { "es" }
                ),
            ));
        }
        for (i, v) in vertices.iter().enumerate() {
            if v.ty.is_scattering() != v.event.is_some() {
                return Err(err(
                    i,
                    format!("`{v}`: only R and T vertices carry an event"),
                ));
            }
            let ok = if i == 0 {
                v.ty == VertexType::C
            } else if i == n - 1 {
                matches!(v.ty, VertexType::L | VertexType::O)
            } else {
                v.ty.is_scattering()
            };
            if !ok {
                let want = if i == 0 {
                    "a path must start with the camera `C`"
                } else if i == n - 1 {
                    "a path must end with a light `L` or an emissive object `O`"
                } else {
                    "vertices between the camera and the emitter must be R or T"
                };
                return Err(err(i, format!("`{v}`: {want}")));
            }
            if v.ty == VertexType::C && v.label.is_some() {
                return Err(err(i, format!("`{v}`: the camera vertex has no label")));
            }
        }
        Ok(())
    }

    /// The vertices, camera first.
    pub fn vertices(&self) -> &[Vertex] {
        &self.vertices
    }

    /// Number of vertices.
    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    /// Always false: a path has at least two vertices.
    pub fn is_empty(&self) -> bool {
        self.vertices.is_empty()
    }
}

impl fmt::Display for Path {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        crate::print::write_parts(f, &self.vertices, " ", |_| false)
    }
}

impl std::str::FromStr for Path {
    type Err = PathError;

    /// Parses the text form, e.g. `C RD2'floor' TS8 RS1 L'key'`.
    fn from_str(text: &str) -> Result<Path, PathError> {
        let mut vertices = Vec::new();
        let mut spans = Vec::new();
        let bytes = text.as_bytes();
        let mut i = 0;
        loop {
            while i < bytes.len() && bytes[i].is_ascii_whitespace() {
                i += 1;
            }
            if i >= bytes.len() {
                break;
            }
            let start = i;
            let err = |end: usize, message: String| PathError {
                vertex: vertices.len(),
                span: Some(start..end),
                message,
            };
            // Safe to slice: `start` is at a non-whitespace ASCII boundary or a char start.
            let c = text[start..].chars().next().unwrap_or(' ');
            let Some(ty) = VertexType::from_letter(c) else {
                return Err(err(
                    start + c.len_utf8(),
                    format!("`{c}` is not a vertex type (expected C, R, T, L or O)"),
                ));
            };
            i += 1;
            let mut event = None;
            if ty.is_scattering() {
                let c = text[i..].chars().next();
                let Some(kind) = c.and_then(EventKind::from_letter) else {
                    let found = c.map_or("end of text".to_string(), |c| format!("`{c}`"));
                    return Err(err(
                        i + c.map_or(0, char::len_utf8),
                        format!("{ty} needs an event D, S or U after it, found {found}"),
                    ));
                };
                i += 1;
                let digits_start = i;
                while i < bytes.len() && bytes[i].is_ascii_digit() {
                    i += 1;
                }
                let digits = &text[digits_start..i];
                let lobe: u32 = if digits.is_empty() {
                    1
                } else {
                    digits.parse().unwrap_or(u32::MAX)
                };
                let Some(e) = u8::try_from(lobe).ok().and_then(|l| Event::new(kind, l)) else {
                    return Err(err(
                        i,
                        format!(
                            "lobe {}{digits} out of range ({}1-{})",
                            kind.letter(),
                            kind.letter(),
                            kind.max_lobe()
                        ),
                    ));
                };
                event = Some(e);
            }
            let mut label = None;
            if i < bytes.len() && bytes[i] == b'\'' {
                let Some(close) = text[i + 1..].find('\'') else {
                    return Err(err(text.len(), "unterminated label: missing `'`".into()));
                };
                label = Some(text[i + 1..i + 1 + close].to_owned());
                i += close + 2;
            }
            if i < bytes.len() && !bytes[i].is_ascii_whitespace() {
                let c = text[i..].chars().next().unwrap_or(' ');
                return Err(err(
                    i + c.len_utf8(),
                    format!("unexpected `{c}` after vertex (separate vertices with spaces)"),
                ));
            }
            vertices.push(Vertex { ty, event, label });
            spans.push(start..i);
        }
        Self::check(&vertices, Some(&spans))?;
        Ok(Path { vertices })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_the_design_example() {
        let p: Path = "C RD2'floor' TS8 RS1 L'key'".parse().unwrap();
        let v = p.vertices();
        assert_eq!(v.len(), 5);
        assert_eq!(v[1].ty(), VertexType::R);
        assert_eq!(v[1].event(), Event::new(EventKind::D, 2));
        assert_eq!(v[1].label(), Some("floor"));
        assert_eq!(v[2].event(), Event::new(EventKind::S, 8));
        assert_eq!(v[4].label(), Some("key"));
        assert_eq!(p.to_string(), "C RD2'floor' TS8 RS1 L'key'");
    }

    #[test]
    fn bare_lobe_letter_means_lobe_one_and_case_is_ignored() {
        let p: Path = "c rd ts ru l".parse().unwrap();
        assert_eq!(p.to_string(), "C RD1 TS1 RU1 L");
    }

    #[test]
    fn errors_name_the_vertex() {
        let cases = [
            ("", 0, "at least"),
            ("C", 1, "at least"),
            ("RD L", 0, "start with the camera"),
            ("C RD", 1, "must end"),
            ("C L RD L", 1, "must be R or T"),
            ("C RD5 L", 1, "out of range"),
            ("C RS9 L", 1, "out of range"),
            ("C RU13 L", 1, "out of range"),
            ("C RD99999999999 L", 1, "out of range"),
            ("C R L", 1, "needs an event"),
            ("C RX L", 1, "needs an event"),
            ("C RD'floor L", 1, "unterminated"),
            ("C RD'a'b L", 1, "unexpected"),
            ("C'cam' L", 0, "no label"),
            ("C X L", 1, "not a vertex type"),
            ("C é L", 1, "not a vertex type"),
        ];
        for (text, vertex, needle) in cases {
            let e = text.parse::<Path>().expect_err(text);
            assert_eq!(e.vertex, vertex, "{text}: {e}");
            assert!(e.to_string().contains(needle), "{text}: {e}");
        }
    }

    #[test]
    fn new_checks_the_same_rules() {
        assert!(Path::new(vec![Vertex::camera(), Vertex::light(None)]).is_ok());
        assert!(Path::new(vec![Vertex::camera(), Vertex::camera()]).is_err());
        assert!(Path::new(vec![Vertex::light(None), Vertex::light(None)]).is_err());
    }

    #[test]
    fn an_event_is_its_kind_and_lobe_in_one_byte_ordered_by_kind_then_lobe() {
        assert_eq!(std::mem::size_of::<Option<Event>>(), 1);
        let mut listed = Vec::new();
        for kind in [EventKind::D, EventKind::S, EventKind::U] {
            let max = kind.max_lobe();
            assert_eq!(Event::new(kind, 0), None, "{kind:?}0");
            assert_eq!(Event::new(kind, max + 1), None, "{kind:?}{}", max + 1);
            for lobe in 1..=max {
                let e = Event::new(kind, lobe).unwrap();
                assert_eq!((e.kind(), e.lobe()), (kind, lobe));
                assert_eq!(e.to_string(), format!("{}{lobe}", kind.letter()));
                assert_eq!(
                    format!("{e:?}"),
                    format!("Event {{ kind: {kind:?}, lobe: {lobe} }}")
                );
                listed.push(e);
            }
        }
        // D1-4, S1-8, U1-12: `all` lists them in that order, which is also theirs.
        assert_eq!(Event::all().collect::<Vec<_>>(), listed);
        assert!(listed.windows(2).all(|w| w[0] < w[1]));
        assert_eq!(listed.len(), 24);
    }
}
