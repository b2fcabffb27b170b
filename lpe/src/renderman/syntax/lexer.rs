//! Tokens of the RenderMan expression body. Whitespace between tokens is skipped; a
//! lobe number must follow its letter directly (`D2`, not `D 2`).

use std::ops::Range;

use super::error::{Error, ErrorKind};
use crate::renderman::path::{EventKind, VertexType};

#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Tok {
    Type(VertexType),
    /// Event letter with its lobe (already range-checked).
    Event(EventKind, Option<u8>),
    Dot,
    LBracket,
    Caret,
    RBracket,
    LAngle,
    RAngle,
    LParen,
    RParen,
    Pipe,
    Star,
    Plus,
    Question,
    LBrace,
    RBrace,
    Comma,
    /// A decimal number, saturated at `u64::MAX`.
    Number(u64),
    Label(String),
}

impl Tok {
    /// How the token reads in an error message.
    pub(crate) fn describe(&self) -> String {
        match self {
            Tok::Type(t) => format!("`{t}`"),
            Tok::Event(k, l) => match l {
                Some(l) => format!("`{}{l}`", k.letter()),
                None => format!("`{}`", k.letter()),
            },
            Tok::Number(n) => format!("number `{n}`"),
            Tok::Label(l) => format!("label `'{l}'`"),
            other => format!("`{}`", other.punct()),
        }
    }

    fn punct(&self) -> &'static str {
        match self {
            Tok::Dot => ".",
            Tok::LBracket => "[",
            Tok::Caret => "^",
            Tok::RBracket => "]",
            Tok::LAngle => "<",
            Tok::RAngle => ">",
            Tok::LParen => "(",
            Tok::RParen => ")",
            Tok::Pipe => "|",
            Tok::Star => "*",
            Tok::Plus => "+",
            Tok::Question => "?",
            Tok::LBrace => "{",
            Tok::RBrace => "}",
            Tok::Comma => ",",
            _ => "",
        }
    }
}

#[derive(Clone, Debug)]
pub(crate) struct Token {
    pub tok: Tok,
    pub span: Range<usize>,
}

/// Tokenizes `source[range]` (one set-algebra operand, or the whole body); spans are
/// byte offsets into `source`.
pub(crate) fn tokenize(source: &str, range: Range<usize>) -> Result<Vec<Token>, Error> {
    let bytes = &source.as_bytes()[..range.end];
    let start = range.start;
    let mut out = Vec::new();
    let mut i = start;
    while i < bytes.len() {
        let b = bytes[i];
        if b.is_ascii_whitespace() {
            i += 1;
            continue;
        }
        let begin = i;
        let simple = match b {
            b'.' => Some(Tok::Dot),
            b'[' => Some(Tok::LBracket),
            b'^' => Some(Tok::Caret),
            b']' => Some(Tok::RBracket),
            b'<' => Some(Tok::LAngle),
            b'>' => Some(Tok::RAngle),
            b'(' => Some(Tok::LParen),
            b')' => Some(Tok::RParen),
            b'|' => Some(Tok::Pipe),
            b'*' => Some(Tok::Star),
            b'+' => Some(Tok::Plus),
            b'?' => Some(Tok::Question),
            b'{' => Some(Tok::LBrace),
            b'}' => Some(Tok::RBrace),
            b',' => Some(Tok::Comma),
            _ => None,
        };
        if let Some(tok) = simple {
            i += 1;
            out.push(Token {
                tok,
                span: begin..i,
            });
            continue;
        }
        if b == b'\'' {
            let Some(close) = source[i + 1..bytes.len()].find('\'') else {
                return Err(Error::new(
                    ErrorKind::Syntax,
                    begin..bytes.len(),
                    "unterminated label: missing closing `'`",
                    source,
                ));
            };
            let label = source[i + 1..i + 1 + close].to_owned();
            i += close + 2;
            out.push(Token {
                tok: Tok::Label(label),
                span: begin..i,
            });
            continue;
        }
        if b.is_ascii_digit() {
            let n = number(bytes, &mut i);
            out.push(Token {
                tok: Tok::Number(n),
                span: begin..i,
            });
            continue;
        }
        let c = source[i..].chars().next().unwrap_or(' ');
        if let Some(t) = VertexType::from_letter(c) {
            i += 1;
            out.push(Token {
                tok: Tok::Type(t),
                span: begin..i,
            });
            continue;
        }
        if let Some(kind) = EventKind::from_letter(c) {
            i += 1;
            let digits = i;
            let n = number(bytes, &mut i);
            let lobe = if i == digits {
                None
            } else if (1..=u64::from(kind.max_lobe())).contains(&n) {
                Some(n as u8)
            } else {
                let k = kind.letter();
                return Err(Error::new(
                    ErrorKind::Lobe,
                    begin..i,
                    format!(
                        "lobe `{}` out of range: {k} lobes are {k}1 to {k}{}",
                        &source[begin..i],
                        kind.max_lobe()
                    ),
                    source,
                ));
            };
            out.push(Token {
                tok: Tok::Event(kind, lobe),
                span: begin..i,
            });
            continue;
        }
        let end = i + c.len_utf8();
        let mut err = Error::new(
            ErrorKind::Syntax,
            begin..end,
            format!("unexpected character `{c}`"),
            source,
        );
        if c == ';' {
            err = err.with_help("prefixes go first, each followed by `;`: `shadows;C.*L`");
        } else if c.is_alphabetic() || c == '_' {
            err = err.with_help(
                "event letters are C R T L O D S U; a macro name must be the whole expression",
            );
        } else if c == '"' {
            err = err.with_help("labels are quoted with single quotes: `'name'`");
        }
        return Err(err);
    }
    Ok(out)
}

/// Reads decimal digits at `*i` (possibly none), saturating at `u64::MAX`.
fn number(bytes: &[u8], i: &mut usize) -> u64 {
    let mut n: u64 = 0;
    while *i < bytes.len() && bytes[*i].is_ascii_digit() {
        n = n
            .saturating_mul(10)
            .saturating_add(u64::from(bytes[*i] - b'0'));
        *i += 1;
    }
    n
}
