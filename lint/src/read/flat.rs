//! A `.usda` layer that composes nothing, read straight from its skimmed text without the
//! USD library: lint's facts are collected prim by prim as the skim
//! ([`super::skim::skim_pieces`]) hands its text over, so neither time nor memory
//! follows the prim count the way composing does (`openusd` spends about 60 µs and
//! 8 KB on every prim it keeps).
//!
//! When a layer has no composition arc, the composed stage is the layer itself: its
//! prims in the order they are written, each with the properties written in its body.
//! This reader takes a layer as flat only when it can see that, and hands it back
//! ([`NotFlat`], with the line and the reason) for [`super::usd`] to compose through
//! `openusd` as soon as it meets anything else:
//!
//! - layer metadata other than [`LAYER_METADATA`] (`subLayers`, `relocates`, ...);
//! - prim metadata other than [`PRIM_METADATA`] (`references`, `payload`, `inherits`,
//!   `specializes`, `variantSets`, `variants`, `instanceable`, `clips`, ...), or an
//!   `active` that is not `true` or `false`;
//! - an `over` or `class` prim, a `variantSet` or `reorder` statement, two sibling prims
//!   of one name, a property after a child prim, a name that is no plain identifier;
//! - an attribute lint reads ([`lint_reads`]) that is not a `string` or `token` holding
//!   one plain quoted string (no escape, not triple-quoted) or `None`, that is authored
//!   twice, with time samples, a connection or a list operation; a RenderProduct's
//!   `orderedVars` that is not one relationship to absolute prim paths;
//! - an attribute type that is no USD value type, a statement of any other shape, a
//!   first line other than `#usda 1.0`.
//!
//! What it collects is a [`PrimFacts`] per prim, handed to the USD reader's own
//! [`DocumentBuilder`] in traversal order (a prim when its first child starts or its
//! body closes), so the conventions (attribute names, `sourceType` spellings, which
//! prims are read) stay defined once, in [`super::usd`]. Inactive prims (`active =
//! false`) and their descendants are skipped, as `openusd`'s default traversal skips
//! them. A read error (a dialect conflict, an unknown renderer) is held until the end of
//! the layer: if the layer turns out not to be flat, the composed reading decides.
//!
//! Text the USD library would refuse is handed back as not flat wherever this reader
//! does not recognise a statement, so the library reports it; the skim's own errors
//! (unterminated strings and brackets, bad bytes) are the same on both paths, with their
//! line and column or byte offset.
//!
//! Memory: the skim's piece ([`super::skim::PIECE_BYTES`], more only for one statement
//! kept whole), the open prims' paths and one 8-byte hash per child name of each open
//! prim (to see a sibling named twice), the current prim's kept properties, and the
//! document (the AOVs, partitions and the distinct group labels). It does not grow with
//! the geometry, nor with the number of prims beyond those hashes.

use std::collections::HashSet;
use std::hash::{DefaultHasher, Hash, Hasher};
use std::path::Path;

use crate::decl::Document;
use crate::error::ReadError;
use crate::read::common::Limits;
use crate::read::skim::skim_pieces;
use crate::read::usd::{
    lint_reads, skim_error, DocumentBuilder, PrimFacts, ORDERED_VARS, READ_PRIM_TYPES,
};

/// The composed reading, which this one must agree with.
#[cfg(test)]
use crate::read::usd::read as read_composed;

/// Layer metadata that changes nothing lint reads.
pub const LAYER_METADATA: [&str; 17] = [
    "colorConfiguration",
    "colorManagementSystem",
    "comment",
    "customLayerData",
    "defaultPrim",
    "doc",
    "documentation",
    "endFrame",
    "endTimeCode",
    "framesPerSecond",
    "kilogramsPerUnit",
    "metersPerUnit",
    "owner",
    "renderSettingsPrimPath",
    "startFrame",
    "startTimeCode",
    "timeCodesPerSecond",
];

/// Prim metadata that changes nothing lint reads (`active` is read; `apiSchemas` adds
/// no authored property).
pub const PRIM_METADATA: [&str; 11] = [
    "active",
    "apiSchemas",
    "assetInfo",
    "comment",
    "customData",
    "displayGroupOrder",
    "displayName",
    "doc",
    "documentation",
    "hidden",
    "kind",
];

/// The value types of USD attributes (`Sdf.ValueTypeNames`), each also as an array.
const VALUE_TYPES: [&str; 56] = [
    "bool",
    "uchar",
    "int",
    "uint",
    "int64",
    "uint64",
    "half",
    "float",
    "double",
    "timecode",
    "string",
    "token",
    "asset",
    "opaque",
    "group",
    "pathExpression",
    "dictionary",
    "int2",
    "int3",
    "int4",
    "half2",
    "half3",
    "half4",
    "float2",
    "float3",
    "float4",
    "double2",
    "double3",
    "double4",
    "point3h",
    "point3f",
    "point3d",
    "vector3h",
    "vector3f",
    "vector3d",
    "normal3h",
    "normal3f",
    "normal3d",
    "color3h",
    "color3f",
    "color3d",
    "color4h",
    "color4f",
    "color4d",
    "quath",
    "quatf",
    "quatd",
    "matrix2d",
    "matrix3d",
    "matrix4d",
    "frame4d",
    "texCoord2h",
    "texCoord2f",
    "texCoord2d",
    "texCoord3h",
    "texCoord3f",
];

/// Why a layer is not read flat: the first thing seen that may compose or that this
/// reader leaves to the USD library.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NotFlat {
    /// The 1-based line where it was seen.
    pub line: usize,
    /// What it is (`a \`references\` prim metadata`).
    pub why: String,
}

/// The document of the `.usda` layer `path` if it composes nothing (module docs), or
/// why it must be composed. Skim errors are errors here as on the composed path.
pub fn read(path: &Path, limits: &Limits) -> Result<Result<Document, NotFlat>, ReadError> {
    let io_err = |source| ReadError::Io {
        path: path.to_path_buf(),
        source,
    };
    let file = std::fs::File::open(path).map_err(io_err)?;
    let mut reader = Reader::new(path);
    let mut sink = |piece: &str| reader.piece(piece).is_ok();
    let whole = skim_pieces(
        std::io::BufReader::new(file),
        lint_reads,
        limits.usd_bytes,
        &mut sink,
    )
    .map_err(|e| skim_error(path, e))?;
    if let Some(not_flat) = reader.not_flat {
        return Ok(Err(not_flat));
    }
    debug_assert!(whole);
    reader.finish()
}

/// Where a token's text is in the reader's text: byte offsets, start and end.
type Span = (usize, usize);

/// One token of skimmed text; its text is a [`Span`] of the text being read, so that
/// reading a token allocates nothing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Tok {
    /// A line end.
    Nl,
    /// A run of bytes up to a delimiter: a keyword, a type, a name, a number.
    Word(Span),
    /// A quoted string: its text between the quotes when plain (`"..."` or `'...'` with
    /// no backslash nor line end), `None` otherwise.
    Str(Option<Span>),
    /// A path, `<...>`: its text.
    Path(Span),
    /// An asset path, `@...@`.
    Asset,
    /// `( ) [ ] { } = , ;`.
    Punct(u8),
}

impl Tok {
    /// The token with its spans `base` bytes earlier: its text moved to the front.
    fn shifted(self, base: usize) -> Tok {
        let back = |(start, end): Span| (start - base, end - base);
        match self {
            Tok::Word(w) => Tok::Word(back(w)),
            Tok::Str(s) => Tok::Str(s.map(back)),
            Tok::Path(p) => Tok::Path(back(p)),
            t => t,
        }
    }
}

/// The text of `span` in `text`.
fn at(text: &str, (start, end): Span) -> &str {
    &text[start..end]
}

/// Bytes that end a word, as the skim has them.
fn delimits(b: u8) -> bool {
    matches!(
        b,
        b' ' | b'\t'
            | b'\r'
            | b'\n'
            | b'#'
            | b'"'
            | b'\''
            | b'@'
            | b'<'
            | b'('
            | b')'
            | b'['
            | b']'
            | b'{'
            | b'}'
            | b'='
            | b','
            | b';'
    )
}

/// The tokens of `text` from byte `from`, each with its offset; the text ends between
/// tokens. `Err(())` for a token cut by the end (which the skim never hands over).
fn tokens(text: &str, from: usize, out: &mut Vec<(usize, Tok)>) -> Result<(), ()> {
    let b = text.as_bytes();
    let mut i = from;
    while i < b.len() {
        let c = b[i];
        match c {
            b'\n' => {
                out.push((i, Tok::Nl));
                i += 1;
            }
            b' ' | b'\t' | b'\r' => i += 1,
            b'#' => {
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
            }
            b'"' | b'\'' | b'@' | b'<' => {
                let triple = c != b'<' && b[i..].starts_with(&[c, c, c]);
                let open = if triple { 3 } else { 1 };
                let (close, escapes): (&[u8], bool) = match (c, triple) {
                    (b'<', _) => (b">", false),
                    (b'@', false) => (b"@", false),
                    (b'@', true) => (b"@@@", true),
                    (_, false) => (std::slice::from_ref(&b[i]), true),
                    (_, true) => (&b[i..i + 3], true),
                };
                let (end, plain) = quoted_end(b, i + open, close, escapes).ok_or(())?;
                let inner = (i + open, end);
                out.push((
                    i,
                    match c {
                        b'<' => Tok::Path(inner),
                        b'@' => Tok::Asset,
                        _ => Tok::Str((plain && !triple).then_some(inner)),
                    },
                ));
                i = end + close.len();
            }
            b'(' | b')' | b'[' | b']' | b'{' | b'}' | b'=' | b',' | b';' => {
                out.push((i, Tok::Punct(c)));
                i += 1;
            }
            _ => {
                let start = i;
                while i < b.len() && !delimits(b[i]) {
                    i += 1;
                }
                out.push((start, Tok::Word((start, i))));
            }
        }
    }
    Ok(())
}

/// Where the quoted text from `start` ends (the offset of its `close`), and whether it
/// is plain: no backslash (when `escapes`) and no line end.
fn quoted_end(b: &[u8], start: usize, close: &[u8], escapes: bool) -> Option<(usize, bool)> {
    let mut j = start;
    let mut plain = true;
    while j < b.len() {
        if escapes && b[j] == b'\\' {
            plain = false;
            j += 2;
            continue;
        }
        if b[j..].starts_with(close) {
            return Some((j, plain));
        }
        plain &= b[j] != b'\n';
        j += 1;
    }
    None
}

/// Whether `name` is a plain identifier: what a prim name is.
fn is_identifier(name: &str) -> bool {
    let mut bytes = name.bytes();
    bytes
        .next()
        .is_some_and(|b| b.is_ascii_alphabetic() || b == b'_')
        && bytes.all(|b| b.is_ascii_alphanumeric() || b == b'_')
}

/// Whether `name` is a property name: identifiers joined by `:`.
fn is_property_name(name: &str) -> bool {
    name.split(':').all(is_identifier)
}

/// An open prim.
struct Frame {
    /// What lint reads of it, so far.
    facts: PrimFacts,
    /// It is traversed: it and its ancestors are active.
    traversed: bool,
    /// Its facts were handed to the builder (its first child started).
    handed: bool,
    /// Whether lint reads it: its type is read, or it holds an attribute lint reads.
    read: bool,
    /// A hash of each child's name.
    children: HashSet<u64>,
}

impl Frame {
    fn new(path: String, name: String, type_name: String, traversed: bool) -> Frame {
        let read = READ_PRIM_TYPES.contains(&type_name.as_str());
        Frame {
            facts: PrimFacts {
                path,
                name,
                type_name,
                ..PrimFacts::default()
            },
            traversed,
            handed: false,
            read,
            children: HashSet::new(),
        }
    }
}

/// What a statement is, from its first token.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// `def ... {`: ends at the `{` outside brackets.
    Prim,
    /// The layer's `( ... )`: ends at its `)`.
    LayerMetadata,
    /// A property: ends at a line end or `;` outside brackets.
    Property,
}

/// The reader's state across pieces.
struct Reader {
    builder: DocumentBuilder,
    /// The pseudo-root, then the open prims.
    frames: Vec<Frame>,
    /// The statement being read, and its bracket depth.
    stmt: Vec<Tok>,
    /// The text the statement's tokens are in, from the statement's start (the rest of
    /// a piece is dropped once read), and where the statement starts in it.
    text: String,
    stmt_start: usize,
    kind: Kind,
    depth: usize,
    /// Line of the token being read.
    line: usize,
    /// The statement's first line.
    stmt_line: usize,
    /// The `#usda 1.0` line was seen.
    started: bool,
    /// A prim or the layer metadata was seen: no layer metadata may follow.
    past_metadata: bool,
    not_flat: Option<NotFlat>,
    /// The first read error, held until the layer is known to be flat.
    error: Option<ReadError>,
    scratch: Vec<(usize, Tok)>,
}

impl Reader {
    fn new(path: &Path) -> Reader {
        Reader {
            builder: DocumentBuilder::new(path),
            frames: vec![Frame::new(
                String::new(),
                String::new(),
                String::new(),
                true,
            )],
            stmt: Vec::new(),
            text: String::new(),
            stmt_start: 0,
            kind: Kind::Property,
            depth: 0,
            line: 1,
            stmt_line: 1,
            started: false,
            past_metadata: false,
            not_flat: None,
            error: None,
            scratch: Vec::new(),
        }
    }

    fn not_flat(&mut self, line: usize, why: impl Into<String>) -> Result<(), ()> {
        self.not_flat = Some(NotFlat {
            line,
            why: why.into(),
        });
        Err(())
    }

    /// Reads a piece of skimmed text; `Err` once the layer is known not to be flat.
    fn piece(&mut self, text: &str) -> Result<(), ()> {
        if !self.started {
            let header = text.strip_prefix("#usda 1.0");
            if !header.is_some_and(|rest| rest.is_empty() || rest.starts_with(['\n', '\r', ' '])) {
                return self.not_flat(1, "a first line other than `#usda 1.0`");
            }
            self.started = true;
        }
        let from = self.text.len();
        self.text.push_str(text);
        let mut toks = std::mem::take(&mut self.scratch);
        toks.clear();
        if tokens(&self.text, from, &mut toks).is_err() {
            return self.not_flat(self.line, "a token the skim cut");
        }
        let result = toks.drain(..).try_for_each(|(at, t)| self.token(at, t));
        self.scratch = toks;
        result?;
        // Only an open statement's text is kept, moved to the front.
        if self.stmt.is_empty() {
            self.text.clear();
        } else {
            let base = self.stmt_start;
            self.text.drain(..base);
            for t in &mut self.stmt {
                *t = t.shifted(base);
            }
            self.stmt_start = 0;
        }
        Ok(())
    }

    /// Reads the token `t`, at byte `offset` of the text.
    fn token(&mut self, offset: usize, t: Tok) -> Result<(), ()> {
        let line = self.line;
        if t == Tok::Nl {
            self.line += 1;
        }
        if self.stmt.is_empty() {
            match &t {
                Tok::Nl | Tok::Punct(b';') => return Ok(()),
                Tok::Punct(b'}') => return self.close(line),
                Tok::Punct(b'(') if self.frames.len() == 1 && !self.past_metadata => {
                    self.kind = Kind::LayerMetadata;
                }
                Tok::Word(w) if matches!(at(&self.text, *w), "def" | "over" | "class") => {
                    self.kind = Kind::Prim;
                }
                Tok::Word(_) if self.frames.len() > 1 => self.kind = Kind::Property,
                _ => return self.not_flat(line, "a statement of another shape"),
            }
            self.stmt_line = line;
            self.stmt_start = offset;
            self.depth = 0;
        }
        match (&t, self.kind) {
            (Tok::Punct(b'{'), Kind::Prim) if self.depth == 0 => return self.open_prim(),
            (Tok::Punct(b'(' | b'[' | b'{'), _) => self.depth += 1,
            (Tok::Punct(b')' | b']' | b'}'), _) if self.depth > 0 => {
                self.depth -= 1;
                if self.depth == 0 && self.kind == Kind::LayerMetadata {
                    self.stmt.push(t);
                    return self.layer_metadata();
                }
            }
            (Tok::Punct(b'}'), Kind::Property) => {
                self.property()?;
                return self.close(line);
            }
            (Tok::Nl | Tok::Punct(b';'), Kind::Property)
                if self.depth == 0 && self.stmt.last() != Some(&Tok::Punct(b'=')) =>
            {
                return self.property();
            }
            _ => {}
        }
        // No statement keeps a line end: inside brackets it separates as a space does
        // (the USD library reads `doc\n= "x"` and `active =\nfalse` in metadata), and
        // outside them it ends a property (above) or is a space.
        if t != Tok::Nl {
            self.stmt.push(t);
        }
        Ok(())
    }

    /// The layer's metadata, whole in `stmt`.
    fn layer_metadata(&mut self) -> Result<(), ()> {
        self.past_metadata = true;
        let stmt = std::mem::take(&mut self.stmt);
        match metadata(&stmt, &self.text, &LAYER_METADATA) {
            Ok(_) => Ok(()),
            Err(why) => self.not_flat(self.stmt_line, why),
        }
    }

    /// `def Type "name" (metadata)`, whole in `stmt`, whose body opens.
    fn open_prim(&mut self) -> Result<(), ()> {
        self.past_metadata = true;
        let mut stmt = std::mem::take(&mut self.stmt);
        let result = self.open_prim_in(&stmt);
        // The statement's buffer serves the next one.
        stmt.clear();
        self.stmt = stmt;
        result
    }

    fn open_prim_in(&mut self, stmt: &[Tok]) -> Result<(), ()> {
        let line = self.stmt_line;
        let text = &self.text;
        let (specifier, type_name, name, rest) = match stmt {
            [Tok::Word(s), Tok::Word(t), Tok::Str(Some(n)), rest @ ..] => {
                (at(text, *s), at(text, *t), at(text, *n), rest)
            }
            [Tok::Word(s), Tok::Str(Some(n)), rest @ ..] => (at(text, *s), "", at(text, *n), rest),
            _ => return self.not_flat(line, "a prim statement of another shape"),
        };
        if specifier != "def" {
            let why = format!("a prim specified `{specifier}`");
            return self.not_flat(line, why);
        }
        let (type_name, name) = (type_name.to_string(), name.to_string());
        if !is_identifier(&name) || !(type_name.is_empty() || is_identifier(&type_name)) {
            return self.not_flat(line, format!("a prim named `{name}` of type `{type_name}`"));
        }
        let active = match rest {
            [] => true,
            [Tok::Punct(b'('), .., Tok::Punct(b')')] => {
                match metadata(rest, text, &PRIM_METADATA) {
                    Ok(active) => active.unwrap_or(true),
                    Err(why) => return self.not_flat(line, why),
                }
            }
            _ => return self.not_flat(line, "a prim statement of another shape"),
        };
        let parent = self.frames.last_mut().expect("the pseudo-root stays");
        let mut hasher = DefaultHasher::new();
        name.hash(&mut hasher);
        if !parent.children.insert(hasher.finish()) {
            return self.not_flat(line, format!("a second prim named `{name}` among siblings"));
        }
        let mut path = String::with_capacity(parent.facts.path.len() + 1 + name.len());
        path.push_str(&parent.facts.path);
        path.push('/');
        path.push_str(&name);
        let traversed = parent.traversed && active;
        self.hand(self.frames.len() - 1);
        if traversed {
            self.builder.prim_type(&type_name);
        }
        let frame = Frame::new(path, name, type_name, traversed);
        self.frames.push(frame);
        Ok(())
    }

    /// Hands the facts of the open prim `frames[i]` to the builder, once, if lint reads it
    /// (never the pseudo-root, which has no type and no property).
    fn hand(&mut self, i: usize) {
        let frame = &mut self.frames[i];
        if frame.handed {
            return;
        }
        frame.handed = true;
        if !(frame.traversed && frame.read) || self.error.is_some() {
            return;
        }
        if let Err(e) = self.builder.prim(&frame.facts) {
            self.error = Some(e);
        }
    }

    /// A prim's `}`.
    fn close(&mut self, line: usize) -> Result<(), ()> {
        if self.frames.len() == 1 {
            return self.not_flat(line, "a `}` outside a prim");
        }
        self.hand(self.frames.len() - 1);
        self.frames.pop();
        Ok(())
    }

    /// A property statement, whole in `stmt`.
    fn property(&mut self) -> Result<(), ()> {
        let mut stmt = std::mem::take(&mut self.stmt);
        let result = self.property_in(&stmt);
        stmt.clear();
        self.stmt = stmt;
        match result {
            Ok(()) => Ok(()),
            Err(why) => self.not_flat(self.stmt_line, why),
        }
    }

    fn property_in(&mut self, stmt: &[Tok]) -> Result<(), String> {
        let frame = self.frames.last_mut().expect("a property is in a prim");
        if frame.handed {
            return Err("a property after a child prim".into());
        }
        let other = || "a statement of another shape".to_string();
        let text = &self.text;
        let word = |i: usize| match stmt.get(i) {
            Some(Tok::Word(w)) => Some(at(text, *w)),
            _ => None,
        };
        let mut i = 0;
        if let Some(w @ ("variantSet" | "reorder")) = word(0) {
            return Err(format!("a `{w}` statement"));
        }
        let list_op = matches!(word(0), Some("prepend" | "append" | "add" | "delete"));
        i += usize::from(list_op);
        i += usize::from(word(i) == Some("custom"));
        i += usize::from(matches!(word(i), Some("uniform" | "varying" | "config")));
        let type_name = word(i).ok_or_else(other)?;
        i += 1;
        let relationship = type_name == "rel";
        let mut array = false;
        if !relationship && stmt.get(i) == Some(&Tok::Punct(b'[')) {
            if stmt.get(i + 1) != Some(&Tok::Punct(b']')) {
                return Err(other());
            }
            array = true;
            i += 2;
        }
        if !relationship && !VALUE_TYPES.contains(&type_name) {
            return Err(format!("an attribute of type `{type_name}`"));
        }
        let full = word(i).ok_or_else(other)?;
        i += 1;
        let (name, suffix) = match full.split_once('.') {
            Some((name, suffix)) => (name, Some(suffix)),
            None => (full, None),
        };
        if !is_property_name(name)
            || !matches!(suffix, None | Some("timeSamples" | "connect" | "spline"))
        {
            return Err(format!("a property named `{full}`"));
        }
        if list_op && !(relationship || suffix == Some("connect")) {
            return Err(other());
        }
        // The value, if any, then metadata, if any.
        let mut value: &[Tok] = &[];
        if stmt.get(i) == Some(&Tok::Punct(b'=')) {
            let end = stmt[i + 1..]
                .iter()
                .position(|t| *t == Tok::Punct(b'('))
                .map_or(stmt.len(), |k| i + 1 + k);
            value = &stmt[i + 1..end];
            i = end;
        }
        match stmt.get(i) {
            None => {}
            Some(Tok::Punct(b'(')) if stmt.last() == Some(&Tok::Punct(b')')) => {}
            Some(_) => return Err(other()),
        }
        let reads = lint_reads(name);
        let ordered = name == ORDERED_VARS && frame.facts.type_name == "RenderProduct";
        let fresh = !frame.facts.properties.iter().any(|p| p == name);
        if (reads || ordered) && !fresh {
            return Err(format!("`{name}` authored twice"));
        }
        if reads {
            if relationship || suffix.is_some() || array || !matches!(type_name, "string" | "token")
            {
                return Err(format!(
                    "`{full}` as {type_name} that lint cannot read flat"
                ));
            }
            let text = match value {
                [] => None,
                [Tok::Word(w)] if at(text, *w) == "None" => None,
                [Tok::Str(Some(s))] => Some(at(text, *s).to_string()),
                _ => return Err(format!("a value of `{name}` that lint cannot read flat")),
            };
            frame.facts.values.push((name.to_string(), text));
            frame.read = true;
        }
        if ordered {
            if !relationship || list_op || suffix.is_some() {
                return Err(format!("`{full}` that is no plain relationship"));
            }
            frame.facts.ordered_vars = targets(value, text)
                .ok_or_else(|| format!("`{name}` targets that lint cannot read flat"))?;
        }
        if fresh && (reads || ordered || frame.facts.type_name == "RenderSettings") {
            frame.facts.properties.push(name.to_string());
        }
        Ok(())
    }

    /// The document, if the layer ended flat.
    fn finish(self) -> Result<Result<Document, NotFlat>, ReadError> {
        // Only a prim statement without its `{` can be open here: the skim refuses text
        // that ends inside brackets or a prim, where every other statement is.
        if !self.stmt.is_empty() {
            return Ok(Err(NotFlat {
                line: self.stmt_line,
                why: "a statement left open".into(),
            }));
        }
        match self.error {
            Some(e) => Err(e),
            None => Ok(Ok(self.builder.finish())),
        }
    }
}

/// Checks metadata `( ... )` (whole, parentheses included): every key must be
/// `allowed`. Returns the `active` value, if there is one.
fn metadata(toks: &[Tok], text: &str, allowed: &[&str]) -> Result<Option<bool>, String> {
    let mut depth = 0;
    let mut active = None;
    for (i, t) in toks.iter().enumerate() {
        match t {
            Tok::Punct(b'(' | b'[' | b'{') => depth += 1,
            Tok::Punct(b')' | b']' | b'}') => depth -= 1,
            Tok::Punct(b'=') if depth == 1 => {
                let key = match i.checked_sub(1).map(|k| &toks[k]) {
                    Some(Tok::Word(k)) => at(text, *k),
                    _ => return Err("metadata of another shape".into()),
                };
                if !allowed.contains(&key) {
                    return Err(format!("`{key}` metadata"));
                }
                if key == "active" {
                    active = match toks.get(i + 1) {
                        Some(Tok::Word(w)) if at(text, *w) == "true" => Some(true),
                        Some(Tok::Word(w)) if at(text, *w) == "false" => Some(false),
                        _ => return Err("an `active` that is neither `true` nor `false`".into()),
                    };
                }
            }
            _ => {}
        }
    }
    Ok(active)
}

/// The prim names of relationship targets `</a/b>` or `[</a/b>, ...]` (or `None`), if
/// every target is an absolute prim path.
fn targets(value: &[Tok], text: &str) -> Option<Vec<String>> {
    let name = |t: &Tok| match t {
        Tok::Path(p) => {
            let p = at(text, *p);
            let rest = p.strip_prefix('/')?;
            rest.split('/')
                .all(is_identifier)
                .then(|| rest.rsplit('/').next().unwrap_or_default().to_string())
        }
        _ => None,
    };
    match value {
        [] => Some(Vec::new()),
        [Tok::Word(w)] if at(text, *w) == "None" => Some(Vec::new()),
        [t @ Tok::Path(_)] => Some(vec![name(t)?]),
        [Tok::Punct(b'['), inner @ .., Tok::Punct(b']')] => {
            let mut names = Vec::new();
            let mut comma = true;
            for t in inner {
                match t {
                    Tok::Punct(b',') if !comma => comma = true,
                    Tok::Path(_) if comma => {
                        names.push(name(t)?);
                        comma = false;
                    }
                    _ => return None,
                }
            }
            Some(names)
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A scratch `.usda` file, removed when dropped.
    struct Scratch(std::path::PathBuf);

    impl std::ops::Deref for Scratch {
        type Target = Path;
        fn deref(&self) -> &Path {
            &self.0
        }
    }

    impl Drop for Scratch {
        fn drop(&mut self) {
            let _ = std::fs::remove_file(&self.0);
        }
    }

    /// A scratch `.usda` file holding `text`, unique to the test `name`.
    fn layer(name: &str, text: &str) -> Scratch {
        let path =
            std::env::temp_dir().join(format!("lpe-flat-{}-{name}.usda", std::process::id()));
        std::fs::write(&path, text).unwrap();
        Scratch(path)
    }

    /// Why `text` is not read flat (panics if it is).
    fn not_flat(name: &str, text: &str) -> NotFlat {
        let path = layer(name, text);
        match read(&path, &Limits::default()) {
            Ok(Err(n)) => n,
            other => panic!("{name}: {other:?}"),
        }
    }

    /// `text` read flat (panics if it is not), after checking that the USD library
    /// reads it the same.
    fn flat_as_composed(name: &str, text: &str) -> Document {
        let path = layer(name, text);
        let flat = read(&path, &Limits::default()).unwrap().unwrap();
        let composed = read_composed(&path, &Limits::default()).unwrap();
        assert_eq!(format!("{flat:?}"), format!("{composed:?}"), "{name}");
        flat
    }

    /// The AOVs of `text` read flat, as `name=source` (panics if it is not read flat).
    fn flat_aovs(name: &str, text: &str) -> Vec<String> {
        let path = layer(name, text);
        match read(&path, &Limits::default()) {
            Ok(Ok(doc)) => doc
                .aovs
                .iter()
                .map(|a| format!("{}={}", a.name, a.source))
                .collect(),
            other => panic!("{name}: {other:?}"),
        }
    }

    /// A stage with every fact lint reads: RenderVars with every `sourceType`
    /// spelling, a raw one and one without `sourceType`, `orderedVars`, the group
    /// attributes of every delegate, partitions, the dialect and renderer, RenderSettings
    /// namespaces, an inactive prim with facts below it, a typeless prim, unread values
    /// dropped by the skim, and a relationship and metadata lint does not read.
    const EVERY_FACT: &str = r#"#usda 1.0
(
    doc = "every fact"
    defaultPrim = "Render"
    metersPerUnit = 0.01
)

def Scope "Render" (
    kind = "group"
)
{
    def RenderSettings "settings" (
        prepend apiSchemas = ["KarmaSettingsAPI"]
    )
    {
        rel products = </Render/product>
        int karma:global:samples = 8
        custom string lpe:partition = "diffuse, specular rest"
        custom string lpe:partition:lights = "diffuse"
        custom token lpe:dialect = "osl"
        custom string lpe:renderer = 'karma'
        uniform token arnold:sampling = "x"
    }

    def RenderProduct "product"
    {
        rel orderedVars = [
            </Render/diffuse>,
            </Render/specular>, </Render/rest>
        ]
        uniform token productName = "beauty.exr"
    }

    def RenderVar "diffuse"
    {
        uniform token sourceType = "lpe"
        uniform string sourceName = "C<RD>[<L.'key'>O]"
    }

    def RenderVar "specular"
    {
        string sourceName = "C<RS>.*<L.'fill'>"
        token sourceType = 'lpe'
        uniform token dataType = "color3f"
    }

    def RenderVar "rest"
    {
        uniform string sourceType = "lpe"
        uniform string sourceName = "C.*<R.'floor'>.*[LO]"
    }

    def RenderVar "beauty"
    {
        uniform string sourceName = "Ci"
        uniform token sourceType = "raw"
    }

    def RenderVar "plain"
    {
        uniform string sourceName = "C<RD>L"
    }

    def Scope "off" (
        active = false
    )
    {
        def RenderVar "hidden"
        {
            uniform token sourceType = "lpe"
            uniform string sourceName = "C<TD>L"
        }
    }
}

def Xform "World"
{
    def RectLight "key"
    {
        string inputs:karma:light:lpetag = "key"
        float inputs:intensity = 2
    }

    def SphereLight "fill"
    {
        string ri:light:lightGroup = "fill"
        string inputs:ri:light:lightGroup = "fill2"
        string primvars:arnold:aov = "fill3"
    }

    def Mesh "floor"
    {
        point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0)]
        int[] faceVertexCounts = [3]
        int[] faceVertexIndices = [0, 1, 2]
        float[] primvars:weights.timeSamples = {
            1: [1, 2, 3],
        }
        string primvars:karma:object:lpetag = "floor"
        rel material:binding = </World/mat>
    }

    def "loose"
    {
        string primvars:ri:attributes:identifier:lpegroup = "loose"
    }

    def Sphere "ball" (
        active = true
    )
    {
        string primvars:karma:object:lpetag = None
    }
}
"#;

    /// The generated stage with every fact kind reads flat and exactly as composed.
    /// Planted faults, each seen failing: `hand` skipping prims of a read type that hold
    /// no read attribute (the RenderProduct's `orderedVars` lost); the RenderSettings'
    /// unread properties not recorded (its `karma` and `arnold` namespaces lost);
    /// `targets` keeping the whole path (the ordered vars `/Render/diffuse`...).
    #[test]
    fn every_fact_kind_reads_as_composed() {
        let flat = flat_as_composed("every_fact", EVERY_FACT);
        // What was read, spelled out, so that both readers dropping a fact fails too.
        assert_eq!(flat.aovs.len(), 3);
        assert_eq!(flat.aovs[1].source, "C<RS>.*<L.'fill'>");
        assert_eq!(
            flat.ordered_vars,
            Some(vec!["diffuse".into(), "specular".into(), "rest".into()])
        );
        let names = |s: &Option<std::collections::BTreeSet<String>>| {
            s.as_ref()
                .unwrap()
                .iter()
                .cloned()
                .collect::<Vec<_>>()
                .join(",")
        };
        assert_eq!(names(&flat.light_groups), "fill,fill2,fill3,key");
        assert_eq!(names(&flat.object_groups), "floor,loose");
        assert_eq!(flat.partitions.len(), 2);
        assert_eq!(flat.partitions[0].members, ["diffuse", "specular", "rest"]);
        assert_eq!(
            flat.settings_namespaces.keys().cloned().collect::<Vec<_>>(),
            ["arnold", "karma", "lpe"]
        );
        assert_eq!(flat.renderer.as_ref().unwrap().0, "karma");
        assert!(flat.dialect.is_some());
    }

    /// A stage of many pieces (the skim hands its text over every 64 KiB, between
    /// tokens, so statements are cut anywhere outside brackets) reads flat as composed:
    /// prim statements over several lines, properties with metadata, groups on every
    /// prim. Planted faults, each seen failing: the open statement's tokens not moved
    /// with its text at a piece's end (`shifted(0)`); the text kept from the piece's
    /// start instead of the statement's.
    #[test]
    fn statements_cut_between_pieces_read_as_composed() {
        let mut text = String::from("#usda 1.0\ndef Xform \"World\"\n{\n");
        for i in 0..1500 {
            text.push_str(&format!(
                "    def Mesh \"m{i}\" (\n        kind = \"component\"\n        active = {}\n    )\n    {{\n        \
                 point3f[] points = [(0, 1, 2), (3, 4, {i})] (\n            interpolation = \"vertex\"\n        )\n        \
                 uniform token primvars:karma:object:lpetag = \"g{}\"\n    }}\n",
                i % 5 != 0,
                i % 37
            ));
        }
        text.push_str("}\n");
        assert!(
            text.len() > 5 * crate::read::skim::PIECE_BYTES,
            "{}",
            text.len()
        );
        let flat = flat_as_composed("pieces", &text);
        assert_eq!(flat.object_groups.unwrap().len(), 37);
    }

    /// Every fixture reads the same flat as composed, and the fixtures without
    /// composition arcs are read flat. Planted faults, each seen failing: the flat
    /// reader dropping `sourceName` values (an AOV's source empty); `open_prim` ignoring
    /// `active = false` (the inactive RenderVar of solaris_karma read); prims of a read
    /// type without a read attribute not handed over (`orderedVars` lost); a
    /// RenderSettings' unread properties not recorded (its namespaces lost);
    /// `orderedVars` targets kept as whole paths.
    #[test]
    fn every_fixture_reads_as_composed() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/testdata");
        let (mut seen, mut flat) = (0, 0);
        for dir in ["usd", "lint"] {
            for entry in std::fs::read_dir(root.join(dir)).unwrap() {
                let path = entry.unwrap().path();
                if !crate::read::usd::is_usda(&path) {
                    continue;
                }
                let limits = Limits::default();
                let composed = format!("{:?}", read_composed(&path, &limits));
                let read = format!("{:?}", crate::read::read_usd(&path, &limits));
                assert_eq!(read, composed, "{}", path.display());
                match super::read(&path, &limits) {
                    Ok(Ok(doc)) => {
                        assert_eq!(format!("{:?}", Ok::<_, ReadError>(doc)), composed);
                        flat += 1;
                    }
                    Err(e) => assert_eq!(format!("{:?}", Err::<Document, _>(e)), composed),
                    Ok(Err(_)) => {}
                }
                seen += 1;
            }
        }
        assert_eq!((seen, flat), (11, 9), "fixtures seen, read flat");
    }

    /// A read error found in a flat layer is the composed reading's error.
    #[test]
    fn a_read_error_is_the_composed_one() {
        let text = "#usda 1.0\ndef Scope \"a\"\n{\n    custom string lpe:dialect = \"osl\"\n}\ndef Scope \"b\"\n{\n    custom string lpe:dialect = \"renderman\"\n}\n";
        let path = layer("conflict", text);
        let flat = read(&path, &Limits::default()).unwrap_err().to_string();
        let composed = read_composed(&path, &Limits::default())
            .unwrap_err()
            .to_string();
        assert_eq!(flat, composed);
        assert!(flat.contains("</b>.lpe:dialect"), "{flat}");
    }

    /// Text the skim refuses is an error at its line and column on the flat path, as on
    /// the composed one; text of a shape the flat reader does not know goes to the USD
    /// library, whose judgement stands.
    #[test]
    fn malformed_text_is_an_error_with_its_position() {
        let path = layer(
            "open_string",
            "#usda 1.0\ndef X \"x\"\n{\n    string a = \"open\n",
        );
        let e = read(&path, &Limits::default()).unwrap_err().to_string();
        assert!(
            e.ends_with("4:16: end of file inside the string starting here"),
            "{e}"
        );
        let garbage = "#usda 1.0\ndef X \"x\"\n{\n    this is not usd\n}\n";
        assert_eq!(not_flat("garbage", garbage).line, 4);
        let path = layer("garbage", garbage);
        assert_eq!(
            format!("{:?}", crate::read::read_usd(&path, &Limits::default())),
            format!("{:?}", read_composed(&path, &Limits::default()))
        );
    }

    /// Quoted text of every kind lint does not read (triple-quoted strings holding a
    /// quote, a `)` and a line end; escaped quotes; asset paths, tripled too; an empty
    /// string) is passed over as one token, in layer and prim metadata, and the layer
    /// reads flat. Mutants, each seen failing: a triple quote not recognised (`c != b'<'`
    /// as `==`); a triple quote's closer taken from `i - 3` or `i * 3`; an escape stepping
    /// back (`j += 2` as `-=`: a loop).
    #[test]
    fn quoted_metadata_of_every_kind_is_passed_over() {
        let text = r#"#usda 1.0
(
    doc = """A "flat" layer: a ) and a ' inside,
over two lines"""
    customLayerData = {
        asset a = @x.usda@
        asset b = @@@odd@name.usda@@@
        string s = "say \"hi\" (twice"
        string t = 'it\'s ) here'
        string u = ""
    }
)

def Scope "Render" (
    doc = """5" tall"""
)
{
    def RenderVar "v"
    {
        uniform token sourceType = "lpe"
        uniform string sourceName = "C<RD>L"
    }
}
"#;
        assert_eq!(flat_aovs("quoted_metadata", text), ["v=C<RD>L"]);
        // The USD library reads the layer the same.
        flat_as_composed("quoted_metadata_composed", text);
    }

    /// A layer may end without a line end, in a comment: it reads flat. Mutant, seen
    /// failing: the comment's scan bounded by `i <= b.len()` (an index past the end).
    #[test]
    fn a_layer_may_end_in_a_comment_without_a_line_end() {
        let text = "#usda 1.0\ndef RenderVar \"v\"\n{\n    token sourceType = \"lpe\"\n    string sourceName = \"CL\"\n}\n# end";
        assert_eq!(flat_aovs("comment_at_end", text), ["v=CL"]);
    }

    /// A layer that ends inside a prim is the skim's error, at the end of the file, on
    /// the flat path as on the composed one: so the reader never finishes with a prim
    /// or a property open, and has no check of its own for one.
    #[test]
    fn a_layer_ending_inside_a_prim_is_an_error_at_its_end() {
        for (name, text, at) in [
            (
                "open_prim",
                "#usda 1.0\ndef RenderVar \"v\"\n{\n    token sourceType = \"lpe\"\n",
                "5:1",
            ),
            (
                "open_property",
                "#usda 1.0\ndef X \"x\"\n{\n    float f = 1",
                "4:16",
            ),
        ] {
            let path = layer(name, text);
            let e = read(&path, &Limits::default()).unwrap_err().to_string();
            assert!(
                e.ends_with(&format!("{at}: end of file before the closing `}}`")),
                "{name}: {e}"
            );
        }
    }

    /// A layer ending in a word (a statement begun and never finished) is handed back
    /// at the statement's line. Mutant, seen failing: the word's scan bounded by
    /// `i <= b.len()` (an index past the end).
    #[test]
    fn a_layer_ending_in_a_word_is_a_statement_left_open() {
        let n = not_flat("word_at_end", "#usda 1.0\ndef X \"x\"\n{\n}\ndef");
        assert_eq!((n.line, n.why.as_str()), (5, "a statement left open"));
    }

    /// Property statements of every shape the flat reader takes: a value followed by
    /// metadata, list operations on a relationship and on a connection, a statement
    /// ended by its prim's `}` on the same line. They read flat, as the USD library reads
    /// them. Mutants, each seen failing: the value's end searched from `i - 1` or `i * 1`
    /// (`stmt[i + 1..]`), or placed at `i - 1 + k`; a list operation's `i +=` as `-=` or
    /// `*=`; the list-operation check's `!` deleted, its `||` as `&&`, its `== connect`
    /// as `!=`; the `}` that ends a property not closing its prim (the arm deleted, or
    /// the closer arm's guard `depth > 0` as `true` or `>=`).
    #[test]
    fn property_statements_of_every_flat_shape_read_as_composed() {
        let text = r#"#usda 1.0
def RenderVar "v"
{
    uniform token sourceType = "lpe" (doc = "the type")
    uniform string sourceName = "C<RD>L" (
        doc = "the expression"
    )
    prepend rel r = </v>
    append float inputs:x.connect = </v.outputs:y>
}
def RenderVar "w"
{
    token sourceType = "lpe"
    string sourceName = "C<TD>L" }
"#;
        assert_eq!(flat_aovs("property_shapes", text), ["v=C<RD>L", "w=C<TD>L"]);
        flat_as_composed("property_shapes_composed", text);
    }

    /// Line ends inside metadata, before or after a `=`, separate as spaces do: the
    /// layer reads flat, with `active =` on one line and `false` on the next making the
    /// prim inactive, as the USD library reads it. Planted fault, seen failing: line ends
    /// kept inside brackets (`t != Tok::Nl || self.depth > 0`: these layers handed back).
    #[test]
    fn line_ends_in_metadata_separate_as_spaces() {
        let text = "#usda 1.0\n(\n    doc\n        = \"x\"\n)\n\
                    def RenderVar \"v\" (\n    doc\n    = \"y\"\n)\n{\n    token sourceType = \"lpe\"\n    string sourceName = \"CL\"\n}\n\
                    def RenderVar \"w\" (\n    active =\n        false\n)\n{\n    token sourceType = \"lpe\"\n    string sourceName = \"CD\"\n}\n";
        assert_eq!(flat_aovs("metadata_lines", text), ["v=CL"]);
        flat_as_composed("metadata_lines_composed", text);
    }

    /// A read attribute declared without a value, or holding `None`, reads flat as no
    /// value: the RenderVars' AOVs have an empty source, as the USD library reads them.
    /// Mutants, each seen failing: the value arm `[]` deleted; the `None` arm's guard as
    /// `true` (an unquoted word read as `None`, `unquoted_values_are_composed`).
    #[test]
    fn a_read_attribute_without_a_value_reads_as_none() {
        let text = "#usda 1.0\ndef RenderVar \"v\"\n{\n    token sourceType = \"lpe\"\n    string sourceName\n}\n\
                    def RenderVar \"w\"\n{\n    token sourceType = \"lpe\"\n    string sourceName = None\n}\n";
        assert_eq!(flat_aovs("no_value", text), ["v=", "w="]);
        flat_as_composed("no_value_composed", text);
    }

    /// `orderedVars` with no value, `None`, one target or a list of them reads flat, and
    /// the first RenderProduct with targets gives the AOV names, as the USD library
    /// reads them. Mutants, each seen failing: the arms `[]` and `[Tok::Path]` of
    /// `targets` deleted; the `None` arm's guard as `false` or its `==` as `!=` (and as
    /// `true`: `word_targets_are_composed`).
    #[test]
    fn ordered_vars_of_every_flat_shape_read_as_composed() {
        let text = "#usda 1.0\ndef Scope \"Render\"\n{\n\
                    def RenderProduct \"a\"\n{\n    rel orderedVars\n}\n\
                    def RenderProduct \"b\"\n{\n    rel orderedVars = None\n}\n\
                    def RenderProduct \"c\"\n{\n    rel orderedVars = </Render/v>\n}\n\
                    def RenderProduct \"d\"\n{\n    rel orderedVars = [</Render/w>, </Render/v>,]\n}\n}\n";
        let flat = flat_as_composed("ordered_vars", text);
        assert_eq!(flat.ordered_vars, Some(vec!["v".to_string()]));
    }

    /// One test per thing that composes or that the flat reader leaves to the USD
    /// library: each is handed back, with its line and what it is (each case is spelled
    /// `fn NAME: ...`, so that a search for the test's `fn` finds it). Planted faults, each
    /// seen failing its test: `references` in [`PRIM_METADATA`]; `subLayers` in
    /// [`LAYER_METADATA`]; the `over` check (`specifier != "def"`) dropped; the
    /// `variantSet` statement check dropped. Mutants, each seen failing its test:
    /// `is_identifier` as `true`, its `&&` as `||`, its `b == b'_'` as `!=`, the prim
    /// name check's `||` as `&&` (`prim_names_are_identifiers`); `is_property_name` as
    /// `true` (`property_names_are_identifiers`); the asset arm of `tokens` deleted
    /// (`asset_values_are_composed`); the layer metadata's guard as `true`, its `&&` as
    /// `||` (`late_layer_metadata_is_composed`); a property's guard `frames.len() > 1`
    /// as `true` or `>=` (`top_level_properties_are_composed`); the guard on text after
    /// a property's metadata as `true` (`text_after_property_metadata_is_composed`);
    /// `(reads || ordered) && !fresh` with `&&` for `||`
    /// (`read_properties_authored_twice_are_composed`); the read attribute's `|| array`
    /// as `&&` (`read_arrays_are_composed`); each `||` of the `orderedVars` shape check
    /// as `&&` (the two `ordered_vars_` tests); `metadata`'s closers not counted (the arm
    /// deleted, `-=` as `+=` or `/=`) and its `depth == 1` as `true`
    /// (`references_after_a_dictionary_compose`); `active`'s `false` guard as `true`
    /// (`other_actives_are_composed`); the `None` guard of `targets` as `true`
    /// (`word_targets_are_composed`), its `!comma` as `true`
    /// (`leading_commas_in_targets_are_composed`).
    macro_rules! composes {
        ($(fn $test:ident: $line:expr, $why:expr, $text:expr;)*) => {$(
            #[test]
            fn $test() {
                let n = not_flat(stringify!($test), $text);
                assert_eq!((n.line, n.why.as_str()), ($line, $why));
            }
        )*};
    }

    composes! {
        fn sublayers_compose: 2, "`subLayers` metadata",
            "#usda 1.0\n(\n    subLayers = [@a.usda@]\n)\n";
        fn references_compose: 2, "`references` metadata",
            "#usda 1.0\ndef X \"x\" (\n    prepend references = @a.usda@</b>\n)\n{\n}\n";
        fn payloads_compose: 2, "`payload` metadata",
            "#usda 1.0\ndef X \"x\" (payload = @a.usda@)\n{\n}\n";
        fn inherits_compose: 3, "`inherits` metadata",
            "#usda 1.0\n\ndef X \"x\" (\n    inherits = </c>\n)\n{\n}\n";
        fn specializes_compose: 2, "`specializes` metadata",
            "#usda 1.0\ndef X \"x\" (specializes = </c>)\n{\n}\n";
        fn variant_sets_compose: 2, "`variantSets` metadata",
            "#usda 1.0\ndef X \"x\" (prepend variantSets = \"v\")\n{\n}\n";
        fn variant_selections_compose: 2, "`variants` metadata",
            "#usda 1.0\ndef X \"x\" (variants = { string v = \"a\" })\n{\n}\n";
        fn variant_set_statements_compose: 4, "a `variantSet` statement",
            "#usda 1.0\ndef X \"x\"\n{\n    variantSet \"v\" = {\n        \"a\" {\n        }\n    }\n}\n";
        fn instancing_composes: 2, "`instanceable` metadata",
            "#usda 1.0\ndef X \"x\" (instanceable = true)\n{\n}\n";
        fn overs_compose: 2, "a prim specified `over`",
            "#usda 1.0\nover \"x\"\n{\n}\n";
        fn classes_compose: 4, "a prim specified `class`",
            "#usda 1.0\ndef X \"x\"\n{\n    class \"c\"\n    {\n    }\n}\n";
        fn relocates_compose: 2, "`relocates` metadata",
            "#usda 1.0\n(\n    relocates = { </a>: </b> }\n)\n";
        fn clips_compose: 2, "`clips` metadata",
            "#usda 1.0\ndef X \"x\" (clips = { dictionary c = {} })\n{\n}\n";
        fn reorders_are_composed: 4, "a `reorder` statement",
            "#usda 1.0\ndef X \"x\"\n{\n    reorder nameChildren = [\"b\", \"a\"]\n}\n";
        fn siblings_of_one_name_are_composed: 5, "a second prim named `a` among siblings",
            "#usda 1.0\ndef X \"a\"\n{\n}\ndef Y \"a\"\n{\n}\n";
        fn properties_after_children_are_composed: 7, "a property after a child prim",
            "#usda 1.0\ndef X \"x\"\n{\n    def Y \"y\"\n    {\n    }\n    float f = 1\n}\n";
        fn escaped_values_are_composed: 4, "a value of `sourceName` that lint cannot read flat",
            "#usda 1.0\ndef RenderVar \"v\"\n{\n    string sourceName = \"C\\\"L\"\n}\n";
        fn timesampled_values_are_composed: 4, "`sourceName.timeSamples` as string that lint cannot read flat",
            "#usda 1.0\ndef RenderVar \"v\"\n{\n    string sourceName.timeSamples = { 1: \"CL\" }\n}\n";
        fn relative_targets_are_composed: 4, "`orderedVars` targets that lint cannot read flat",
            "#usda 1.0\ndef RenderProduct \"p\"\n{\n    rel orderedVars = <../v>\n}\n";
        fn unknown_types_are_composed: 4, "an attribute of type `flaot`",
            "#usda 1.0\ndef X \"x\"\n{\n    flaot f\n}\n";
        fn other_headers_are_composed: 1, "a first line other than `#usda 1.0`",
            "#sdf 1.4.32\ndef X \"x\"\n{\n}\n";
        fn asset_values_are_composed: 4, "a value of `sourceName` that lint cannot read flat",
            "#usda 1.0\ndef RenderVar \"v\"\n{\n    string sourceName = @C<RD>L@\n}\n";
        fn late_layer_metadata_is_composed: 5, "a statement of another shape",
            "#usda 1.0\ndef X \"x\"\n{\n}\n(\n    doc = \"late\"\n)\n";
        fn metadata_inside_a_prim_body_is_composed: 4, "a statement of another shape",
            "#usda 1.0\ndef X \"x\"\n{\n    (\n        doc = \"inside\"\n    )\n}\n";
        fn top_level_properties_are_composed: 2, "a statement of another shape",
            "#usda 1.0\nfloat f = 1\n";
        fn list_operations_on_values_are_composed: 4, "a statement of another shape",
            "#usda 1.0\ndef X \"x\"\n{\n    prepend float f = 1\n}\n";
        fn text_after_property_metadata_is_composed: 4, "a statement of another shape",
            "#usda 1.0\ndef RenderVar \"v\"\n{\n    string sourceName = \"CL\" (doc = \"x\") junk\n}\n";
        fn read_properties_authored_twice_are_composed: 5, "`sourceName` authored twice",
            "#usda 1.0\ndef RenderVar \"v\"\n{\n    string sourceName = \"CL\"\n    string sourceName = \"CD\"\n}\n";
        fn read_arrays_are_composed: 4, "`sourceName` as string that lint cannot read flat",
            "#usda 1.0\ndef RenderVar \"v\"\n{\n    string[] sourceName = [\"CL\"]\n}\n";
        fn unquoted_values_are_composed: 4, "a value of `sourceName` that lint cannot read flat",
            "#usda 1.0\ndef RenderVar \"v\"\n{\n    string sourceName = CL\n}\n";
        fn ordered_vars_as_values_are_composed: 4, "`orderedVars` that is no plain relationship",
            "#usda 1.0\ndef RenderProduct \"p\"\n{\n    token orderedVars = \"v\"\n}\n";
        fn ordered_vars_list_operations_are_composed: 4, "`orderedVars` that is no plain relationship",
            "#usda 1.0\ndef RenderProduct \"p\"\n{\n    prepend rel orderedVars = </v>\n}\n";
        fn references_after_a_dictionary_compose: 2, "`references` metadata",
            "#usda 1.0\ndef X \"x\" (\n    customData = {\n        int a = 1\n    }\n    references = @a.usda@\n)\n{\n}\n";
        fn other_actives_are_composed: 2, "an `active` that is neither `true` nor `false`",
            "#usda 1.0\ndef X \"x\" (active = 0)\n{\n}\n";
        fn word_targets_are_composed: 4, "`orderedVars` targets that lint cannot read flat",
            "#usda 1.0\ndef RenderProduct \"p\"\n{\n    rel orderedVars = foo\n}\n";
        fn leading_commas_in_targets_are_composed: 4, "`orderedVars` targets that lint cannot read flat",
            "#usda 1.0\ndef RenderProduct \"p\"\n{\n    rel orderedVars = [, </v>]\n}\n";
        fn prim_names_are_identifiers: 2, "a prim named `1a` of type `X`",
            "#usda 1.0\ndef X \"1a\"\n{\n}\n";
        fn prim_types_are_identifiers: 2, "a prim named `a` of type `X-1`",
            "#usda 1.0\ndef X-1 \"a\"\n{\n}\n";
        fn property_names_are_identifiers: 4, "a property named `2x`",
            "#usda 1.0\ndef X \"x\"\n{\n    float 2x = 1\n}\n";
    }
}
