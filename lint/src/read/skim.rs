//! A streaming pass over `.usda` text that drops the values lint never reads before the
//! USD library parses the layer: a mesh's `points`, normals, primvars and time samples
//! are most of a shot's text and none of its LPE declarations.
//!
//! What is dropped, inside a prim's `{ ... }` body only:
//!
//! - `type name = value` of an attribute `keep` refuses: the value (and the `=`) go, the
//!   declaration and its `( metadata )` stay, so the prim keeps its property names
//!   (lint reads the namespaces of a `RenderSettings` prim's properties);
//! - `type name.timeSamples = { ... }` of such an attribute: the samples go, an empty
//!   `{ }` stays.
//!
//! Everything else is copied byte for byte: layer and prim metadata (composition arcs,
//! variant selections, `active`), relationships, `.connect`, `.spline`, `reorder`,
//! variant sets, comments. Dropped text leaves its newlines behind, so the USD library's
//! line numbers stay the file's. The pass is a usda lexer for what it skips: strings
//! (`"`, `'`, triple-quoted, backslash escapes), asset paths (`@`, `@@@`), path
//! references (`<...>`), comments and nested brackets, so a `]` or `"` inside a string
//! never ends a value early. A string, asset path or bracket left open at the end, or a
//! closing bracket of the wrong kind, is an error at its line and column; a NUL byte or
//! invalid UTF-8 is an error at its byte offset.
//!
//! Memory: the input is read in 64 KiB blocks; only the kept text is held, bounded by
//! the caller's limit.

use std::io::{self, Read};

/// Why a layer could not be skimmed.
#[derive(Debug)]
pub enum SkimError {
    /// Reading failed.
    Io(io::Error),
    /// A NUL byte or invalid UTF-8 at this byte offset.
    NotText {
        /// 0-based byte offset.
        offset: u64,
    },
    /// Text that is no usda: an unterminated string or bracket, a mismatched bracket.
    Syntax {
        /// 1-based line.
        line: usize,
        /// 1-based byte column.
        column: usize,
        /// What is wrong.
        message: String,
    },
    /// The kept text passed the limit.
    TooLarge {
        /// The limit, in bytes of kept text.
        limit: u64,
    },
}

impl std::fmt::Display for SkimError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SkimError::Io(e) => write!(f, "{e}"),
            SkimError::NotText { offset } => write!(f, "byte {offset}: not text"),
            SkimError::Syntax {
                line,
                column,
                message,
            } => write!(f, "{line}:{column}: {message}"),
            SkimError::TooLarge { limit } => {
                write!(f, "more than {limit} bytes of text besides skipped values")
            }
        }
    }
}

impl From<io::Error> for SkimError {
    fn from(e: io::Error) -> Self {
        SkimError::Io(e)
    }
}

type Result<T> = std::result::Result<T, SkimError>;

/// `input` with the values of attributes `keep` refuses dropped (module docs); at most
/// `limit` bytes of text are kept.
pub fn skim(input: impl Read, keep: impl Fn(&str) -> bool, limit: u64) -> Result<String> {
    let mut s = Skim::new(input, limit, None);
    s.run(&keep)?;
    as_str(s.out)
}

/// [`skim`], but the kept text is handed to `sink` in pieces as it is made instead of
/// held whole: a piece ends between tokens, outside any `( )`, `[ ]` or dictionary (in a
/// prim body or at the top level), once [`PIECE_BYTES`] are kept, and the last piece
/// ends the text. `limit` bounds each piece. `sink` returns false to stop the pass (the
/// result is then `Ok(false)`; `Ok(true)` when the whole input was passed).
pub fn skim_pieces(
    input: impl Read,
    keep: impl Fn(&str) -> bool,
    limit: u64,
    sink: &mut dyn FnMut(&str) -> bool,
) -> Result<bool> {
    let mut s = Skim::new(input, limit, Some(sink));
    s.run(&keep)?;
    Ok(!s.stopped && s.hand_over()?)
}

/// How much kept text [`skim_pieces`] gathers before it hands a piece over.
pub const PIECE_BYTES: usize = 64 << 10;

/// Kept text as a string.
fn as_str(out: Vec<u8>) -> Result<String> {
    // Every byte copied came from validated UTF-8 and cuts fall between tokens.
    String::from_utf8(out).map_err(|e| SkimError::NotText {
        offset: e.utf8_error().valid_up_to() as u64,
    })
}

/// A table of the bytes `class` accepts, built at compile time: the scans test one
/// load per byte.
const fn table(class: &[u8]) -> [bool; 256] {
    let mut t = [false; 256];
    let mut i = 0;
    while i < class.len() {
        t[class[i] as usize] = true;
        i += 1;
    }
    t
}

/// Bytes that end a word (a type, a name, a number) in usda.
const DELIMITERS: [bool; 256] = table(b" \t\r\n#\"'@<()[]{}=,;");

/// Bytes a skipped value's scan must stop at: every other byte is passed in bulk.
const SKIP_STOPS: [bool; 256] = table(b"\n#\"'@<()[]{}");

#[inline]
fn delimits(b: u8) -> bool {
    DELIMITERS[b as usize]
}

#[inline]
fn stops_skip(b: u8) -> bool {
    SKIP_STOPS[b as usize]
}

/// The words of the statement being read in a body, as far as its `=` needs them
/// (`custom`, `float3`, `points`: the first, the last, whether one is `rel`), kept in
/// buffers that are reused from statement to statement.
#[derive(Default)]
struct Head {
    /// How many words were read.
    words: usize,
    first: String,
    last: String,
    rel: bool,
}

impl Head {
    fn clear(&mut self) {
        self.words = 0;
        self.rel = false;
    }

    fn push(&mut self, word: &str) {
        if self.words == 0 {
            self.first.clear();
            self.first.push_str(word);
        }
        self.last.clear();
        self.last.push_str(word);
        self.rel |= word == "rel";
        self.words += 1;
    }
}

/// What the innermost open bracket is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Ctx {
    /// A prim's (or variant's) `{ ... }`: property statements.
    Body,
    /// `( ... )`: metadata or a tuple.
    Paren,
    /// `[ ... ]`: an array or list.
    Bracket,
    /// `{ ... }` after an attribute's `=`, or inside metadata: a dictionary or samples.
    Dict,
}

impl Ctx {
    fn closer(self) -> u8 {
        match self {
            Ctx::Body | Ctx::Dict => b'}',
            Ctx::Paren => b')',
            Ctx::Bracket => b']',
        }
    }
}

/// The input, read in blocks, checked as UTF-8 block by block, with the position.
struct Src<R> {
    r: R,
    buf: Vec<u8>,
    /// Next byte to hand out.
    pos: usize,
    /// End of the bytes checked as UTF-8 (a split character waits past it).
    avail: usize,
    /// End of the bytes read.
    len: usize,
    /// Offset in the input of `buf[0]`.
    base: u64,
    line: usize,
    column: usize,
}

impl<R: Read> Src<R> {
    fn new(r: R) -> Self {
        Src {
            r,
            buf: vec![0; 64 << 10],
            pos: 0,
            avail: 0,
            len: 0,
            base: 0,
            line: 1,
            column: 1,
        }
    }

    /// Reads the next block; false at the end of the input.
    fn fill(&mut self) -> Result<bool> {
        // Only an incomplete UTF-8 sequence (at most 3 bytes) is carried over.
        self.buf.copy_within(self.avail..self.len, 0);
        self.base += self.avail as u64;
        self.len -= self.avail;
        self.pos = 0;
        self.avail = 0;
        loop {
            let n = match self.r.read(&mut self.buf[self.len..]) {
                Ok(n) => n,
                Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
                Err(e) => return Err(e.into()),
            };
            if n == 0 {
                return match self.len {
                    0 => Ok(false),
                    _ => Err(SkimError::NotText { offset: self.base }),
                };
            }
            let checked = self.len;
            self.len += n;
            self.avail = match std::str::from_utf8(&self.buf[..self.len]) {
                Ok(_) => self.len,
                Err(e) if e.error_len().is_some() => {
                    let bad = e.valid_up_to();
                    let nul = self.buf[..bad].iter().position(|&b| b == 0).unwrap_or(bad);
                    return Err(SkimError::NotText {
                        offset: self.base + nul as u64,
                    });
                }
                Err(e) => e.valid_up_to(),
            };
            if let Some(i) = self.buf[checked.min(self.avail)..self.avail]
                .iter()
                .position(|&b| b == 0)
            {
                return Err(SkimError::NotText {
                    offset: self.base + (checked.min(self.avail) + i) as u64,
                });
            }
            if self.avail > 0 {
                return Ok(true);
            }
        }
    }

    #[inline]
    fn peek(&mut self) -> Result<Option<u8>> {
        if self.pos == self.avail && !self.fill()? {
            return Ok(None);
        }
        Ok(Some(self.buf[self.pos]))
    }

    /// Takes the byte `peek` returned.
    #[inline]
    fn bump(&mut self) -> u8 {
        let b = self.buf[self.pos];
        self.pos += 1;
        if b == b'\n' {
            self.line += 1;
            self.column = 1;
        } else {
            self.column += 1;
        }
        b
    }

    /// Passes bytes up to the next one `stop` accepts, within the current block. Every
    /// `stop` accepts `\n`, so the bytes passed are on one line: point arrays are long
    /// runs, counted in bulk.
    #[inline]
    fn run_until(&mut self, stop: impl Fn(u8) -> bool, out: Option<&mut Vec<u8>>) {
        debug_assert!(stop(b'\n'));
        let start = self.pos;
        let end = self.buf[start..self.avail]
            .iter()
            .position(|&b| stop(b))
            .map_or(self.avail, |i| start + i);
        let passed = &self.buf[start..end];
        self.column += passed.len();
        if let Some(out) = out {
            out.extend_from_slice(passed);
        }
        self.pos = end;
    }

    fn error(&self, line: usize, column: usize, message: impl Into<String>) -> SkimError {
        SkimError::Syntax {
            line,
            column,
            message: message.into(),
        }
    }
}

struct Skim<'s, R> {
    src: Src<R>,
    out: Vec<u8>,
    stack: Vec<Ctx>,
    /// The words of the statement being read in a body (`custom`, `float3`, `points`).
    head: Head,
    /// An `=` was copied in a body: the next token is its value, not a statement word.
    value_pending: bool,
    /// The `{` after this `=` opens a dictionary or samples, not a body.
    dict_next: bool,
    limit: u64,
    /// Where [`skim_pieces`] hands the kept text; `None`: it is held in `out`.
    sink: Option<&'s mut dyn FnMut(&str) -> bool>,
    /// The sink asked to stop.
    stopped: bool,
}

impl<'s, R: Read> Skim<'s, R> {
    fn new(input: R, limit: u64, sink: Option<&'s mut dyn FnMut(&str) -> bool>) -> Self {
        Skim {
            src: Src::new(input),
            out: Vec::new(),
            stack: Vec::new(),
            head: Head::default(),
            value_pending: false,
            dict_next: false,
            limit,
            sink,
            stopped: false,
        }
    }

    /// Hands the kept text so far to the sink, if there is one; false if it asks to stop.
    fn hand_over(&mut self) -> Result<bool> {
        let Some(sink) = self.sink.as_mut() else {
            return Ok(true);
        };
        let piece = as_str(std::mem::take(&mut self.out))?;
        let go_on = sink(&piece);
        self.out = piece.into_bytes();
        self.out.clear();
        self.stopped = !go_on;
        Ok(go_on)
    }

    /// In a prim body or at the layer's top level, where statements start.
    fn in_body(&self) -> bool {
        matches!(self.stack.last(), None | Some(Ctx::Body))
    }

    /// A token that is no statement word: the statement's head is over.
    fn other_token(&mut self) {
        if self.in_body() {
            self.head.clear();
            self.value_pending = false;
            self.dict_next = false;
        }
    }

    fn run(&mut self, keep: &dyn Fn(&str) -> bool) -> Result<()> {
        while let Some(b) = self.src.peek()? {
            match b {
                b' ' | b'\t' | b'\r' => {
                    let blank = |b| matches!(b, b' ' | b'\t' | b'\r');
                    self.src.run_until(|b| !blank(b), Some(&mut self.out));
                }
                b'\n' => {
                    self.src.bump();
                    self.out.push(b);
                }
                b'#' => self.comment(true)?,
                b'"' | b'\'' | b'@' | b'<' => {
                    self.quoted(true)?;
                    self.other_token();
                }
                b'(' | b'[' | b'{' => self.open(b),
                b')' | b']' | b'}' => self.close()?,
                b'=' => self.equals(keep)?,
                b',' | b';' => {
                    self.src.bump();
                    self.out.push(b);
                    self.other_token();
                }
                _ => self.word()?,
            }
            if self.out.len() as u64 > self.limit {
                return Err(SkimError::TooLarge { limit: self.limit });
            }
            if self.sink.is_some()
                && self.out.len() >= PIECE_BYTES
                && self.in_body()
                && !self.hand_over()?
            {
                return Ok(());
            }
        }
        if let Some(ctx) = self.stack.last() {
            let (line, column) = (self.src.line, self.src.column);
            return Err(self.src.error(
                line,
                column,
                format!("end of file before the closing `{}`", ctx.closer() as char),
            ));
        }
        Ok(())
    }

    fn word(&mut self) -> Result<()> {
        let start = self.out.len();
        while let Some(b) = self.src.peek()? {
            if delimits(b) {
                break;
            }
            self.src.run_until(delimits, Some(&mut self.out));
        }
        if self.in_body() {
            if self.value_pending {
                self.other_token();
            } else {
                // Validated UTF-8, cut at ASCII delimiters.
                let word = std::str::from_utf8(&self.out[start..]).unwrap_or_default();
                self.head.push(word);
            }
        }
        Ok(())
    }

    fn open(&mut self, b: u8) {
        self.src.bump();
        self.out.push(b);
        let ctx = match (b, self.in_body()) {
            (b'(', _) => Ctx::Paren,
            (b'[', _) => Ctx::Bracket,
            (_, true) if !self.dict_next => Ctx::Body,
            _ => Ctx::Dict,
        };
        // `float3[]`: the brackets of an array type are part of the statement's head.
        if ctx != Ctx::Bracket || self.value_pending {
            self.other_token();
        }
        self.stack.push(ctx);
    }

    fn close(&mut self) -> Result<()> {
        let (line, column) = (self.src.line, self.src.column);
        let b = self.src.bump();
        match self.stack.pop() {
            Some(ctx) if ctx.closer() == b => {}
            Some(ctx) => {
                return Err(self.src.error(
                    line,
                    column,
                    format!("`{}` where `{}` closes", b as char, ctx.closer() as char),
                ))
            }
            None => {
                return Err(self
                    .src
                    .error(line, column, format!("`{}` closes nothing", b as char)))
            }
        }
        self.out.push(b);
        if b != b']' {
            self.other_token();
        }
        Ok(())
    }

    /// An `=` in a body ends an attribute's head: its value is copied or dropped.
    fn equals(&mut self, keep: &dyn Fn(&str) -> bool) -> Result<()> {
        self.src.bump();
        if !self.in_body() || self.value_pending {
            self.out.push(b'=');
            return Ok(());
        }
        let head = &self.head;
        let attribute = head.words >= 2
            && !matches!(head.first.as_str(), "variantSet" | "reorder")
            && !head.rel;
        // Read only for an attribute: with fewer than two words, `last` may still be an
        // earlier statement's.
        let (name, suffix) = match head.last.split_once('.') {
            Some((name, suffix)) => (name, Some(suffix)),
            None => (head.last.as_str(), None),
        };
        let kept = !attribute || keep(name);
        let suffix = suffix.map(|s| s == "timeSamples");
        self.head.clear();
        if kept {
            self.out.push(b'=');
            self.value_pending = true;
            self.dict_next = attribute;
            return Ok(());
        }
        match suffix {
            None => {
                // The declaration stays; its `=` and value go.
                self.skip_value()?;
            }
            Some(true) => {
                self.out.push(b'=');
                self.skip_space()?;
                let (line, column) = (self.src.line, self.src.column);
                if self.src.peek()? != Some(b'{') {
                    // Not a block of samples: the USD library's to read or refuse.
                    self.value_pending = true;
                    return Ok(());
                }
                self.src.bump();
                self.out.extend_from_slice(b"{ ");
                self.skip_inside(b'}', line, column)?;
                self.out.push(b'}');
            }
            Some(false) => {
                // `.connect`, `.spline`: small, copied.
                self.out.push(b'=');
                self.value_pending = true;
                self.dict_next = true;
                return Ok(());
            }
        }
        self.other_token();
        Ok(())
    }

    /// Passes white space, keeping its newlines.
    fn skip_space(&mut self) -> Result<()> {
        while let Some(b) = self.src.peek()? {
            match b {
                b' ' | b'\t' | b'\r' => {
                    self.src.bump();
                }
                b'\n' => {
                    self.src.bump();
                    self.out.push(b'\n');
                }
                _ => break,
            }
        }
        Ok(())
    }

    /// Drops one value: a bracketed one, a string, an asset path, a path or a word.
    fn skip_value(&mut self) -> Result<()> {
        self.skip_space()?;
        let (line, column) = (self.src.line, self.src.column);
        match self.src.peek()? {
            None => Err(self.src.error(line, column, "end of file before a value")),
            Some(b @ (b'(' | b'[' | b'{')) => {
                self.src.bump();
                let closer = match b {
                    b'(' => b')',
                    b'[' => b']',
                    _ => b'}',
                };
                self.skip_inside(closer, line, column)
            }
            Some(b'"' | b'\'' | b'@' | b'<') => self.quoted(false),
            Some(b) if delimits(b) => Err(self.src.error(
                line,
                column,
                format!("`{}` where a value starts", b as char),
            )),
            Some(_) => {
                while let Some(b) = self.src.peek()? {
                    if delimits(b) {
                        break;
                    }
                    self.src.run_until(delimits, None);
                }
                Ok(())
            }
        }
    }

    /// Drops everything up to the `closer` matching a bracket opened at `line:column`,
    /// which is taken too; newlines stay.
    fn skip_inside(&mut self, closer: u8, line: usize, column: usize) -> Result<()> {
        let mut closers = vec![closer];
        while let Some(&want) = closers.last() {
            self.src.run_until(stops_skip, None);
            let (l, c) = (self.src.line, self.src.column);
            let Some(b) = self.src.peek()? else {
                return Err(self.src.error(
                    line,
                    column,
                    format!("end of file before the `{}` closing this", want as char),
                ));
            };
            match b {
                b'\n' => {
                    self.src.bump();
                    self.out.push(b'\n');
                }
                b'#' => self.comment(false)?,
                b'"' | b'\'' | b'@' | b'<' => self.quoted(false)?,
                b'(' | b'[' | b'{' => {
                    self.src.bump();
                    closers.push(match b {
                        b'(' => b')',
                        b'[' => b']',
                        _ => b'}',
                    });
                }
                b')' | b']' | b'}' => {
                    self.src.bump();
                    if b != want {
                        return Err(self.src.error(
                            l,
                            c,
                            format!("`{}` where `{}` closes", b as char, want as char),
                        ));
                    }
                    closers.pop();
                }
                // A block ended inside a run of plain bytes: pass on.
                _ => {}
            }
        }
        Ok(())
    }

    /// A comment, to the end of its line (the newline is left).
    fn comment(&mut self, echo: bool) -> Result<()> {
        while let Some(b) = self.src.peek()? {
            if b == b'\n' {
                break;
            }
            let out = echo.then_some(&mut self.out);
            self.src.run_until(|b| b == b'\n', out);
        }
        Ok(())
    }

    /// A string (`"`, `'`, tripled), an asset path (`@`, `@@@`) or a path (`<...>`),
    /// copied when `echo`, dropped (newlines kept) otherwise.
    fn quoted(&mut self, echo: bool) -> Result<()> {
        let (line, column) = (self.src.line, self.src.column);
        let open = self.src.bump();
        let take = |s: &mut Self, b: u8| {
            if echo || b == b'\n' {
                s.out.push(b);
            }
        };
        take(self, open);
        let (close, escapes) = match open {
            b'<' => (b'>', false),
            b'@' => (b'@', false),
            q => (q, true),
        };
        // A doubled quote is an empty string unless a third makes it a triple quote.
        let mut triple = false;
        if open != b'<' && self.src.peek()? == Some(open) {
            let b = self.src.bump();
            take(self, b);
            if self.src.peek()? != Some(open) {
                return Ok(());
            }
            let b = self.src.bump();
            take(self, b);
            triple = true;
        }
        let mut run = 0;
        loop {
            let Some(b) = self.src.peek()? else {
                let what = match open {
                    b'<' => "path",
                    b'@' => "asset path",
                    _ => "string",
                };
                return Err(self.src.error(
                    line,
                    column,
                    format!("end of file inside the {what} starting here"),
                ));
            };
            self.src.bump();
            take(self, b);
            // `\@@@` escapes a triple `@` delimiter; in strings `\` escapes any byte.
            if b == b'\\' && (escapes || triple) {
                if self.src.peek()?.is_some() {
                    let n = self.src.bump();
                    take(self, n);
                }
                run = 0;
                continue;
            }
            if b == close {
                run += 1;
                if !triple || run == 3 {
                    return Ok(());
                }
            } else {
                run = 0;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn keep(name: &str) -> bool {
        name == "sourceName" || name.starts_with("lpe:")
    }

    fn skimmed(text: &str) -> String {
        skim(text.as_bytes(), keep, u64::MAX).unwrap()
    }

    fn error(text: &str) -> String {
        skim(text.as_bytes(), keep, u64::MAX)
            .unwrap_err()
            .to_string()
    }

    #[test]
    fn drops_values_lint_never_reads_and_keeps_declarations() {
        let text = "#usda 1.0\n(\n    defaultPrim = \"W\"\n)\ndef Mesh \"m\" (\n    kind = \"component\"\n)\n{\n    point3f[] points = [(0, 1, 2), (3, 4, 5)] (\n        interpolation = \"vertex\"\n    )\n    int[] faceVertexCounts = [\n        3,\n        4]\n    string sourceName = \"C<RD>L\"\n    custom string lpe:partition = \"a,b\"\n    float3[] extent.timeSamples = {\n        1: [(0, 0, 0)],\n    }\n    rel material:binding = </M>\n}\n";
        let expected = "#usda 1.0\n(\n    defaultPrim = \"W\"\n)\ndef Mesh \"m\" (\n    kind = \"component\"\n)\n{\n    point3f[] points  (\n        interpolation = \"vertex\"\n    )\n    int[] faceVertexCounts \n\n\n    string sourceName = \"C<RD>L\"\n    custom string lpe:partition = \"a,b\"\n    float3[] extent.timeSamples ={ \n\n}\n    rel material:binding = </M>\n}\n";
        assert_eq!(skimmed(text), expected);
    }

    #[test]
    fn brackets_and_quotes_inside_strings_do_not_end_a_value() {
        // A dropped value whose strings hold every delimiter; the next statement is kept.
        let text = "def X \"x\"\n{\n    string[] notes = [\"]}) \\\" '\", '\"]', \"\"\"a\n]\"\"\", @[@, @@@x]\\@@@y@@@, # ]]\n </a{v=x}>]\n    string sourceName = \"L'a]'\"\n}\n";
        assert_eq!(
            skimmed(text),
            "def X \"x\"\n{\n    string[] notes \n\n\n    string sourceName = \"L'a]'\"\n}\n"
        );
    }

    /// Metadata, variant sets, `reorder`, relationships, connections and kept
    /// dictionaries are copied. Planted faults, each seen failing: [`Head`] never seeing
    /// `rel` (the relationship's targets dropped); its first word replaced by every
    /// later one (the `variantSet` statement's `=` read as an attribute's).
    #[test]
    fn statements_outside_attribute_values_are_copied() {
        let text = "def X \"x\" (\n    variants = {\n        string v = \"a\"\n    }\n    prepend variantSets = \"v\"\n)\n{\n    variantSet \"v\" = {\n        \"a\" (doc = \"[\") {\n            float f = 1\n            custom string lpe:dialect = \"osl\"\n        }\n    }\n    reorder properties = [\"f\"]\n    prepend rel r = [</a>, </b>]\n    float g.connect = </a.f>\n    dictionary d = {\n        string k = \"v\"\n    }\n}\n";
        let expected = text.replace("float f = 1", "float f ").replace(
            "dictionary d = {\n        string k = \"v\"\n    }",
            "dictionary d \n\n",
        );
        assert_eq!(skimmed(text), expected);
    }

    #[test]
    fn scalar_values_and_metadata_after_them() {
        // Samples that are no `{ }` block are copied for the USD library to judge.
        let text = "def X \"x\"\n{\n    float a = -1.5e-3 (doc = \"d\")\n    token b = \"t\"\n    custom string lpe:renderer = 'karma'\n    double c = 2\n    double d.timeSamples = None\n}\n";
        let expected = "def X \"x\"\n{\n    float a  (doc = \"d\")\n    token b \n    custom string lpe:renderer = 'karma'\n    double c \n    double d.timeSamples =None\n}\n";
        assert_eq!(skimmed(text), expected);
    }

    #[test]
    fn errors_name_the_line_and_column() {
        assert_eq!(
            error("def X \"x\"\n{\n    float[] a = [1, 2\n}\n"),
            "4:1: `}` where `]` closes"
        );
        assert_eq!(
            error("def X \"x\"\n{\n    string a = \"open\n"),
            "3:16: end of file inside the string starting here"
        );
        assert_eq!(
            error("def X \"x\"\n{\n    float[] a = [1, [2]\n"),
            "3:17: end of file before the `]` closing this"
        );
        assert_eq!(error("#usda 1.0\n)"), "2:1: `)` closes nothing");
        assert_eq!(
            error("#usda 1.0\ndef X \"x\" {"),
            "2:12: end of file before the closing `}`"
        );
    }

    #[test]
    fn binary_and_oversized_input_are_refused() {
        match skim(&b"#usda 1.0\n\"a\xff\""[..], keep, u64::MAX) {
            Err(SkimError::NotText { offset }) => assert_eq!(offset, 12),
            other => panic!("{other:?}"),
        }
        match skim(&b"#usda\0"[..], keep, u64::MAX) {
            Err(SkimError::NotText { offset }) => assert_eq!(offset, 5),
            other => panic!("{other:?}"),
        }
        // 1000 values are dropped: `def X "x"\n{\n    float[] p \n}\n` (29 bytes) is kept.
        let big = format!(
            "def X \"x\"\n{{\n    float[] p = [{}]\n}}\n",
            "1.5, ".repeat(1000)
        );
        assert_eq!(skim(big.as_bytes(), keep, 64).unwrap().len(), 29);
        assert!(matches!(
            skim(big.as_bytes(), |_| true, 64),
            Err(SkimError::TooLarge { limit: 64 })
        ));
    }

    #[test]
    fn blocks_split_anywhere() {
        // One byte per read: tokens, triple quotes and UTF-8 characters cross blocks.
        struct Trickle<'a>(&'a [u8]);
        impl Read for Trickle<'_> {
            fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
                match self.0.split_first() {
                    Some((&b, rest)) if !buf.is_empty() => {
                        buf[0] = b;
                        self.0 = rest;
                        Ok(1)
                    }
                    _ => Ok(0),
                }
            }
        }
        let text = "def X \"é\"\n{\n    string[] s = [\"\"\"ü]\"\"\", \"x\", 'y']\n    float2[] p = [(1.5, 2), (3, 4)]\n    string sourceName = \"\"\"C<.D>L\"\"\"\n}\n";
        assert_eq!(
            skim(Trickle(text.as_bytes()), keep, u64::MAX).unwrap(),
            "def X \"é\"\n{\n    string[] s \n    float2[] p \n    string sourceName = \"\"\"C<.D>L\"\"\"\n}\n"
        );
    }

    /// A reader that hands out its chunks in turn, then an error or the end.
    struct Chunks {
        chunks: Vec<io::Result<Vec<u8>>>,
    }

    impl Read for Chunks {
        fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
            if self.chunks.is_empty() {
                return Ok(0);
            }
            let chunk = self.chunks.remove(0)?;
            buf[..chunk.len()].copy_from_slice(&chunk);
            Ok(chunk.len())
        }
    }

    fn chunks(list: Vec<io::Result<&[u8]>>) -> Chunks {
        Chunks {
            chunks: list.into_iter().map(|c| c.map(<[u8]>::to_vec)).collect(),
        }
    }

    /// An interrupted read is tried again; any other read error is handed on as it is,
    /// with its own message; a byte that is not UTF-8 is reported before anything past it
    /// is read. Planted faults (cargo-mutants), each seen failing: the `Interrupted` guard
    /// as `true`, `false` or `!=` (the interrupted read an error, or a failing reader
    /// asked forever); the invalid-byte test as `false` (the next read's error reported
    /// instead of the byte).
    #[test]
    fn read_errors_are_handed_on_and_interrupted_reads_tried_again() {
        let interrupted = || Err(io::Error::from(io::ErrorKind::Interrupted));
        let text = chunks(vec![
            interrupted(),
            Ok(b"def X \"x\"\n"),
            interrupted(),
            Ok(b"{\n}\n"),
        ]);
        assert_eq!(skim(text, keep, u64::MAX).unwrap(), "def X \"x\"\n{\n}\n");
        let broken = chunks(vec![Ok(b"def X"), Err(io::Error::other("disk gone"))]);
        match skim(broken, keep, u64::MAX) {
            Err(e @ SkimError::Io(_)) => assert_eq!(e.to_string(), "disk gone"),
            other => panic!("{other:?}"),
        }
        let bad_then_broken = chunks(vec![Ok(b"ab\xff"), Err(io::Error::other("disk gone"))]);
        match skim(bad_then_broken, keep, u64::MAX) {
            Err(SkimError::NotText { offset }) => assert_eq!(offset, 2),
            other => panic!("{other:?}"),
        }
    }

    /// Offsets count from the start of the input across blocks: a NUL 70 000 bytes in is
    /// at byte 70 000, in the second 64 KiB block. Planted faults (cargo-mutants), each
    /// seen failing: the block's base advanced by `-=` or `*=`.
    #[test]
    fn offsets_count_across_blocks() {
        let mut text = format!("#{}\n", "x".repeat(69_998)).into_bytes();
        text.push(0);
        assert_eq!(text.len(), 70_001);
        match skim(&text[..], keep, u64::MAX) {
            Err(e @ SkimError::NotText { offset: 70_000 }) => {
                assert_eq!(e.to_string(), "byte 70000: not text")
            }
            other => panic!("{other:?}"),
        }
    }

    /// The limit is on the kept text, exactly: text of `limit` bytes passes, one byte
    /// more does not, and the error says how much. Planted faults (cargo-mutants), each
    /// seen failing: `>` as `>=` or `==`.
    #[test]
    fn the_limit_on_kept_text_is_exact() {
        let text = "def X \"x\"\n{\n}\n";
        assert_eq!(text.len(), 14);
        assert_eq!(skim(text.as_bytes(), keep, 14).unwrap(), text);
        match skim(text.as_bytes(), keep, 13) {
            Err(e @ SkimError::TooLarge { limit: 13 }) => assert_eq!(
                e.to_string(),
                "more than 13 bytes of text besides skipped values"
            ),
            other => panic!("{other:?}"),
        }
    }

    /// A kept attribute's dictionary is copied whole: its entries are not statements
    /// whose values could be dropped. Planted fault (cargo-mutants), seen failing: the
    /// `{` after a kept attribute's `=` opened as a prim body (the entry's value dropped).
    #[test]
    fn a_kept_dictionary_keeps_its_entries() {
        let text = "def X \"x\"\n{\n    custom dictionary lpe:notes = {\n        string a = \"x\"\n    }\n}\n";
        assert_eq!(skimmed(text), text);
    }

    /// A dropped value may start on the next line: the newlines between stay. Planted
    /// fault (cargo-mutants), seen failing: the skip of white space stopping at a newline
    /// (the value then an error).
    #[test]
    fn a_dropped_value_may_start_on_the_next_line() {
        let text = "def X \"x\"\n{\n    float a =\n        1\n    double b.timeSamples =\n    {\n        1: 2,\n    }\n}\n";
        assert_eq!(
            skimmed(text),
            "def X \"x\"\n{\n    float a \n\n    double b.timeSamples =\n{ \n\n}\n}\n"
        );
    }

    /// A closing bracket of the wrong kind in kept text, and a delimiter where a dropped
    /// value starts, are errors at their line and column. Planted faults
    /// (cargo-mutants), each seen failing: any closer accepted; the delimiter read as an
    /// empty value.
    #[test]
    fn a_wrong_closer_and_a_missing_value_are_errors_where_they_are() {
        assert_eq!(error("def X \"x\"\n{\n)\n"), "3:1: `)` where `}` closes");
        assert_eq!(
            error("def X \"x\"\n{\n    float a = ,\n}\n"),
            "3:15: `,` where a value starts"
        );
    }

    /// An unterminated path or asset path is named as what it is. Planted faults
    /// (cargo-mutants), each seen failing: either called a string.
    #[test]
    fn an_unterminated_path_or_asset_path_says_which() {
        assert_eq!(
            error("def X \"x\"\n{\n    rel r = </a\n"),
            "3:13: end of file inside the path starting here"
        );
        assert_eq!(
            error("def X \"x\"\n{\n    asset a = @x\n"),
            "3:15: end of file inside the asset path starting here"
        );
    }

    /// A triple-quoted string ends at three quotes, not one: a single quote inside it,
    /// then a bracket, do not end the dropped value. Planted fault (cargo-mutants), seen
    /// failing: `run == 3` as `!=`.
    #[test]
    fn a_triple_quoted_string_ends_at_three_quotes() {
        let text = "def X \"x\"\n{\n    string[] a = [\"\"\"say \"x]\" here\"\"\", \"y\"]\n    string sourceName = \"L\"\n}\n";
        assert_eq!(
            skimmed(text),
            "def X \"x\"\n{\n    string[] a \n    string sourceName = \"L\"\n}\n"
        );
    }

    /// After a kept value in brackets, the next statement's head is read whole, so its
    /// value is dropped: the brackets of the value end the statement, and an `=` inside
    /// them starts none. Planted faults (cargo-mutants), each seen failing: `open`'s
    /// `ctx != Bracket || value_pending` as `&&`; `equals`' `!in_body() || value_pending`
    /// as `&&` (both keep `float` from the next head, which then keeps its value).
    #[test]
    fn after_a_kept_bracketed_value_the_next_statement_is_read_whole() {
        let text = "def X \"x\"\n{\n    custom string[] lpe:xs = [\"a\"]\n    float a = 1\n    \
                    custom string[] lpe:ys = [(\"k\" = 1)]\n    float b = 2\n}\n";
        let expected = text
            .replace("float a = 1", "float a ")
            .replace("float b = 2", "float b ");
        assert_eq!(skimmed(text), expected);
    }

    /// The pieces of `text` as [`skim_pieces`] hands them over, and its result.
    fn pieces(text: &str, limit: u64, stop_after: usize) -> (Vec<String>, bool) {
        let mut got = Vec::new();
        let mut sink = |piece: &str| {
            got.push(piece.to_string());
            got.len() < stop_after
        };
        let whole = skim_pieces(text.as_bytes(), keep, limit, &mut sink).unwrap();
        (got, whole)
    }

    /// Kept text is handed over once [`PIECE_BYTES`] (64 KiB) are kept, between tokens
    /// where statements start: 200 comment lines of 1 024 bytes come as three pieces of
    /// 64 lines and the last 8 lines. Planted faults (cargo-mutants), each seen
    /// failing: `64 << 10` as `64 >> 10` and the size test `>=` as `<` (a piece per
    /// token); the test's second and third `&&` as `||` (a piece per token in a body,
    /// or wherever the size is short).
    #[test]
    fn kept_text_is_handed_over_every_64_kib_where_statements_start() {
        let text = format!("#{}\n", "x".repeat(1022)).repeat(200);
        let (got, whole) = pieces(&text, u64::MAX, usize::MAX);
        let lengths: Vec<_> = got.iter().map(String::len).collect();
        assert_eq!(lengths, [65_536, 65_536, 65_536, 8_192]);
        assert_eq!(got.concat(), text);
        assert!(whole);
        // The sink asking to stop after the first piece ends the pass there.
        let (got, whole) = pieces(&text, u64::MAX, 1);
        assert_eq!((got.len(), got[0].len(), whole), (1, 65_536, false));
    }

    /// A piece ends only outside brackets: a kept array of 100 KiB is one piece with its
    /// statement, the prim's end the next. The limit bounds each piece, not the text:
    /// the same limit that refuses the text whole passes it in pieces.
    #[test]
    fn a_piece_ends_outside_brackets_and_the_limit_bounds_each_piece() {
        let head = "def X \"x\"\n{\n    custom string[] lpe:xs = [\n";
        let items = format!("\"{}\",\n", "a".repeat(1020)).repeat(100);
        let text = format!("{head}{items}    ]\n}}\n");
        let first = format!("{head}{items}    ]");
        assert_eq!(first.len(), head.len() + 102_400 + 5);
        let limit = first.len() as u64;
        let (got, whole) = pieces(&text, limit, usize::MAX);
        assert_eq!(got, [first, "\n}\n".to_string()]);
        assert!(whole);
        assert!(matches!(
            skim(text.as_bytes(), keep, limit),
            Err(SkimError::TooLarge { .. })
        ));
    }

    /// A statement of one word before its `=` is no attribute (an attribute has a type
    /// and a name): it is copied whole, for the USD library to judge. Planted fault
    /// (cargo-mutants), seen failing: [`Head`]'s word count `+=` as `-=` (one word then
    /// counts as two or more, and the value is dropped).
    #[test]
    fn a_one_word_statement_is_copied_whole() {
        let text = "def X \"x\"\n{\n    a = 1\n}\n";
        assert_eq!(skimmed(text), text);
    }
}
