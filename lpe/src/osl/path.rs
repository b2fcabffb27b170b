//! OSL paths: vertices of symbols, and their text notation (the notation of OSL's own
//! unit test as docs/language.md's OSL chapter writes it).
//!
//! ```text
//! path   := (vertex (' ' vertex)*)?
//! vertex := symbol (',' symbol)*
//! symbol := '~'                     NONE
//!         | "'" ([^'] | "''")* "'"  a quoted label ('' inside is one quote)
//!         | [^ ,~']+                a bare label (`_` is the label "_")
//! ```
//!
//! A label is printed bare unless it is empty or holds a space, comma, `~` or `'`.

use std::fmt;
use std::str::FromStr;

use super::symbol::Symbol;
use crate::print::write_parts;

/// One vertex: event symbol, scattering symbol, then custom labels, in order. It has at
/// least one symbol; one with fewer than two matches nothing, exactly as in OSL (every
/// event and scattering slot pattern excludes STOP).
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Vertex {
    /// The symbols, event first.
    pub symbols: Vec<Symbol>,
}

impl Vertex {
    /// A vertex of these symbols.
    pub fn new(symbols: Vec<Symbol>) -> Vertex {
        Vertex { symbols }
    }

    /// A vertex of labels only, e.g. `Vertex::labels(&["R", "D", "floor"])`.
    pub fn labels(labels: &[&str]) -> Vertex {
        Vertex::new(labels.iter().map(|l| Symbol::label(*l)).collect())
    }
}

/// A path: its vertices, camera first.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Path {
    /// The vertices, in order.
    pub vertices: Vec<Vertex>,
}

impl Path {
    /// A path of these vertices.
    pub fn new(vertices: Vec<Vertex>) -> Path {
        Path { vertices }
    }

    /// Number of vertices.
    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    /// No vertex.
    pub fn is_empty(&self) -> bool {
        self.vertices.is_empty()
    }
}

/// What is wrong with a path text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PathErrorKind {
    /// A vertex or symbol with no text (two separators in a row, or one at an end).
    EmptySymbol,
    /// A quoted label with no closing `'`.
    UnclosedQuote,
    /// A character that cannot follow a symbol (after a closing quote or `~`).
    Unexpected(char),
}

/// Why a path text did not parse: what, and at which byte.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PathError {
    /// What is wrong.
    pub kind: PathErrorKind,
    /// Byte offset in the text.
    pub pos: usize,
}

impl fmt::Display for PathError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "at byte {}: ", self.pos)?;
        match self.kind {
            PathErrorKind::EmptySymbol => f.write_str(
                "empty symbol (vertices are separated by one space, symbols by one comma; \
                 write an empty label as '')",
            ),
            PathErrorKind::UnclosedQuote => f.write_str("quoted label without its closing `'`"),
            PathErrorKind::Unexpected(c) => {
                write!(f, "unexpected `{c}` (expected `,`, a space or the end)")
            }
        }
    }
}

impl std::error::Error for PathError {}

fn needs_quotes(l: &str) -> bool {
    l.is_empty() || l.contains([' ', ',', '~', '\''])
}

impl fmt::Display for Symbol {
    /// The path-text form: `~`, a bare label or a quoted one.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Symbol::None => f.write_str("~"),
            Symbol::Label(l) if needs_quotes(l) => write!(f, "'{}'", l.replace('\'', "''")),
            Symbol::Label(l) => f.write_str(l),
        }
    }
}

impl fmt::Display for Vertex {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_parts(f, &self.symbols, ",", |_| false)
    }
}

impl fmt::Display for Path {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_parts(f, &self.vertices, " ", |_| false)
    }
}

/// Reads one symbol at `i`; returns it and the offset after it.
fn symbol_at(s: &str, i: usize) -> Result<(Symbol, usize), PathError> {
    let b = s.as_bytes();
    let err = |kind, pos| PathError { kind, pos };
    match b.get(i) {
        Some(b'~') => Ok((Symbol::None, i + 1)),
        Some(b'\'') => {
            let mut label = String::new();
            let mut j = i + 1;
            loop {
                match s[j..].find('\'') {
                    None => return Err(err(PathErrorKind::UnclosedQuote, i)),
                    Some(k) => {
                        label.push_str(&s[j..j + k]);
                        j += k + 1;
                        if b.get(j) == Some(&b'\'') {
                            label.push('\'');
                            j += 1;
                        } else {
                            return Ok((Symbol::Label(label), j));
                        }
                    }
                }
            }
        }
        _ => {
            let end = s[i..]
                .find([' ', ',', '~', '\''])
                .map_or(s.len(), |k| i + k);
            if end == i {
                return Err(err(PathErrorKind::EmptySymbol, i));
            }
            Ok((Symbol::label(&s[i..end]), end))
        }
    }
}

impl FromStr for Vertex {
    type Err = PathError;

    fn from_str(s: &str) -> Result<Vertex, PathError> {
        let p: Path = s.parse()?;
        match <[Vertex; 1]>::try_from(p.vertices) {
            Ok([v]) => Ok(v),
            Err(vs) => {
                // The first space that separates two vertices (or the empty text).
                let pos = if vs.is_empty() {
                    0
                } else {
                    vs[0].to_string().len()
                };
                Err(PathError {
                    kind: PathErrorKind::Unexpected(' '),
                    pos,
                })
            }
        }
    }
}

impl FromStr for Path {
    type Err = PathError;

    /// The empty text is the path of no vertices.
    fn from_str(s: &str) -> Result<Path, PathError> {
        let mut vertices = Vec::new();
        if s.is_empty() {
            return Ok(Path::new(vertices));
        }
        let mut cur = Vec::new();
        let mut i = 0;
        loop {
            let (sym, j) = symbol_at(s, i)?;
            cur.push(sym);
            match s.as_bytes().get(j) {
                None => {
                    vertices.push(Vertex::new(cur));
                    return Ok(Path::new(vertices));
                }
                Some(b',') => i = j + 1,
                Some(b' ') => {
                    vertices.push(Vertex::new(std::mem::take(&mut cur)));
                    i = j + 1;
                }
                Some(_) => {
                    let c = s[j..].chars().next().unwrap_or('?');
                    return Err(PathError {
                        kind: PathErrorKind::Unexpected(c),
                        pos: j,
                    });
                }
            }
            if i == s.len() {
                return Err(PathError {
                    kind: PathErrorKind::EmptySymbol,
                    pos: i,
                });
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lbl(s: &str) -> Symbol {
        Symbol::label(s)
    }

    #[test]
    fn accum_test_notation() {
        let p: Path = "C,_ T,S R,D,1 L,_".parse().unwrap();
        assert_eq!(p.len(), 4);
        assert_eq!(p.vertices[0].symbols, [lbl("C"), lbl("_")]);
        assert_eq!(p.vertices[2].symbols, [lbl("R"), lbl("D"), lbl("1")]);
        assert_eq!(p.to_string(), "C,_ T,S R,D,1 L,_");
        assert!(!p.is_empty());
        assert!(Path::new(Vec::new()).is_empty());
    }

    #[test]
    fn none_and_quoted_labels() {
        let p: Path = "R,~ R,D,'a b','x,y','~','it''s','' L".parse().unwrap();
        assert_eq!(p.vertices[0].symbols, [lbl("R"), Symbol::None]);
        assert_eq!(
            p.vertices[1].symbols,
            [
                lbl("R"),
                lbl("D"),
                lbl("a b"),
                lbl("x,y"),
                lbl("~"),
                lbl("it's"),
                lbl("")
            ]
        );
        assert_eq!(p.vertices[2].symbols, [lbl("L")]);
        // Printing quotes exactly the labels that need it, and parses back.
        let text = p.to_string();
        assert_eq!(text, "R,~ R,D,'a b','x,y','~','it''s','' L");
        assert_eq!(text.parse::<Path>().unwrap(), p);
        // A quote is allowed only at a symbol's start: inside a bare label it is not.
        assert_eq!(Symbol::label("|lightA|").to_string(), "|lightA|");
    }

    #[test]
    fn errors_carry_positions() {
        let e = |s: &str| s.parse::<Path>().unwrap_err();
        assert_eq!(
            e("C,_  L"),
            PathError {
                kind: PathErrorKind::EmptySymbol,
                pos: 4
            }
        );
        assert_eq!(
            e("C,"),
            PathError {
                kind: PathErrorKind::EmptySymbol,
                pos: 2
            }
        );
        assert_eq!(
            e(" C"),
            PathError {
                kind: PathErrorKind::EmptySymbol,
                pos: 0
            }
        );
        assert_eq!(
            e("R,'ab"),
            PathError {
                kind: PathErrorKind::UnclosedQuote,
                pos: 2
            }
        );
        assert_eq!(
            e("R,'a'b"),
            PathError {
                kind: PathErrorKind::Unexpected('b'),
                pos: 5
            }
        );
        assert_eq!(
            e("R,~x"),
            PathError {
                kind: PathErrorKind::Unexpected('x'),
                pos: 3
            }
        );
        assert!(e("C L ").to_string().contains("byte 4"));
    }

    #[test]
    fn empty_text_is_the_empty_path_and_vertices_parse_alone() {
        assert!("".parse::<Path>().unwrap().is_empty());
        let v: Vertex = "R,D,foo".parse().unwrap();
        assert_eq!(v, Vertex::labels(&["R", "D", "foo"]));
        assert_eq!("R,D L".parse::<Vertex>().unwrap_err().pos, 3);
    }
}
