//! The dialect-independent top layer: finds the set-algebra operators of a source text
//! and hands every operand's text to the dialect's parser.
//!
//! ```text
//! algebra := unary (('&' | '-') unary)*      left-associative, both the same precedence
//! unary   := '^' unary | '(' algebra ')' | operand
//! ```
//!
//! The scanner never looks inside what a dialect treats as one unit: a quoted label
//! (`'a-b'`), a triple or vertex `<...>` (OSL's `<R-D>` has a literal `-` label), a class
//! `[...]` (RenderMan's `[^...]` negation) are skipped whole. Outside them neither
//! dialect gives `&`, `-` or `^` a meaning, so an operator there is always set algebra.
//! A parenthesized group is an algebra group when an operator stands at its top level,
//! else it is part of an operand (`(C|D)` is a dialect group). An operator inside a
//! group that is only part of an operand (`C(A - B)L`) is an error: operands are whole
//! expressions.

use std::fmt;
use std::ops::Range;

use super::tree::Algebra;

/// What is wrong with the set algebra itself (not with an operand).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum AlgebraError {
    /// An operator with no operand on one side: `A -`, `& B`, `^`, `A & & B`, `()`.
    MissingOperand {
        /// The operator, or the empty group.
        at: Range<usize>,
    },
    /// A `(` of an algebra group without its `)`, or a `)` without its `(`.
    Unbalanced {
        /// The parenthesis.
        at: Range<usize>,
    },
    /// An operator inside a group that is only part of an operand: `C(A - B)L`.
    InsideOperand {
        /// The operator.
        at: Range<usize>,
    },
    /// Algebra groups and `^` nested deeper than the dialect's nesting limit.
    TooDeep {
        /// The group or `^` past the limit.
        at: Range<usize>,
        /// The limit.
        max: usize,
    },
    /// More than [`MAX_OPERANDS`] operands.
    TooManyOperands {
        /// The first operand past the limit.
        at: Range<usize>,
    },
}

/// Most operands one expression may have: each is a hidden AOV of the set it compiles
/// into, which holds at most [`crate::MAX_AOVS`] (the same number; written out because
/// the automata sit above this layer), so a larger expression could never compile. Also
/// bounds the depth of the tree (with the nesting limit).
pub const MAX_OPERANDS: usize = 256;

impl AlgebraError {
    /// The byte span the error points at.
    pub fn span(&self) -> Range<usize> {
        match self {
            AlgebraError::MissingOperand { at }
            | AlgebraError::Unbalanced { at }
            | AlgebraError::InsideOperand { at }
            | AlgebraError::TooDeep { at, .. }
            | AlgebraError::TooManyOperands { at } => at.clone(),
        }
    }

    /// How to fix it.
    pub fn help(&self) -> &'static str {
        match self {
            AlgebraError::MissingOperand { .. } => {
                "`&`, `-` take an expression on each side, `^` one after it: `A - B`, `^A`"
            }
            AlgebraError::Unbalanced { .. } => "close every `(` of the set algebra with `)`",
            AlgebraError::InsideOperand { .. } => {
                "set algebra combines whole expressions: write `C.*L - C.*DL`, not `C(.* - .*D)L`"
            }
            AlgebraError::TooDeep { .. } => "remove redundant parentheses or `^^`",
            AlgebraError::TooManyOperands { .. } => "split the expression into several AOVs",
        }
    }
}

impl fmt::Display for AlgebraError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            AlgebraError::MissingOperand { .. } => f.write_str("set algebra operand missing"),
            AlgebraError::Unbalanced { .. } => f.write_str("unbalanced parenthesis in set algebra"),
            AlgebraError::InsideOperand { .. } => {
                f.write_str("set-algebra operator inside an expression")
            }
            AlgebraError::TooDeep { max, .. } => {
                write!(f, "set algebra nests deeper than the limit of {max}")
            }
            AlgebraError::TooManyOperands { .. } => write!(
                f,
                "more than {MAX_OPERANDS} set-algebra operands (each is a hidden AOV)"
            ),
        }
    }
}

impl std::error::Error for AlgebraError {}

/// Why [`parse`] failed: the algebra, or the dialect's parse of an operand.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ParseError<X> {
    /// The operators and groups.
    Algebra(AlgebraError),
    /// The dialect's error for one operand, as its callback returned it.
    Operand(X),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Tok {
    And,
    Minus,
    Not,
    Open,
    Close,
    /// Operand text (quotes, `<...>`, `[...]` and other characters).
    Text,
}

/// The scanner's tokens with byte spans. `^` is an operator only where an operand may
/// start (after the start, an operator or `(`); elsewhere it is operand text for the
/// dialect to judge.
fn scan(src: &str, range: Range<usize>) -> Vec<(Tok, Range<usize>)> {
    let b = src.as_bytes();
    let mut out: Vec<(Tok, Range<usize>)> = Vec::new();
    let mut i = range.start;
    let end = range.end;
    // From a `<` or `[` at `i`: past the closer matching it, or to `end`. Quotes are
    // skipped whole, `<...>` and `[...]` nest in each other (`[<L.>O]`, OSL's
    // `<R[DG]>`), and a closer of the other kind is a plain character there (OSL's
    // `<R]>` has the label `]`).
    let skip = |mut i: usize| -> usize {
        let mut open: Vec<u8> = Vec::new();
        while i < end {
            match b[i] {
                b'\'' => {
                    i = src[i + 1..end].find('\'').map_or(end, |k| i + 1 + k + 1);
                    continue;
                }
                c @ (b'<' | b'[') => open.push(c),
                c @ (b'>' | b']') if open.last() == Some(&if c == b'>' { b'<' } else { b'[' }) => {
                    open.pop();
                    if open.is_empty() {
                        return i + 1;
                    }
                }
                _ => {}
            }
            i += 1;
        }
        end
    };
    while i < end {
        let start = i;
        let tok = match b[i] {
            c if c.is_ascii_whitespace() => {
                i += 1;
                continue;
            }
            b'&' => Tok::And,
            b'-' => Tok::Minus,
            b'^' if matches!(
                out.last(),
                None | Some((Tok::And | Tok::Minus | Tok::Not | Tok::Open, _))
            ) =>
            {
                Tok::Not
            }
            b'(' => Tok::Open,
            b')' => Tok::Close,
            b'\'' => {
                i = src[start + 1..end]
                    .find('\'')
                    .map_or(end, |k| start + 1 + k + 1);
                Tok::Text
            }
            b'<' | b'[' => {
                i = skip(i);
                Tok::Text
            }
            _ => {
                i += src[i..].chars().next().map_or(1, char::len_utf8);
                Tok::Text
            }
        };
        if tok != Tok::Text || i == start {
            i = start + 1;
        }
        out.push((tok, start..i));
    }
    out
}

/// Whether `src[range]` uses set algebra at all: a front end parses plain expressions
/// exactly as before.
pub fn has_algebra(src: &str, range: Range<usize>) -> bool {
    scan(src, range)
        .iter()
        .any(|(t, _)| matches!(t, Tok::And | Tok::Minus | Tok::Not))
}

/// Parses `src[range]` as set algebra, with algebra groups and `^` nested at most
/// `max_depth` deep and at most [`MAX_OPERANDS`] operands. `operand(span)` parses one
/// operand (its span trimmed, in bytes of `src`, so errors point into the whole text)
/// and returns its tree: a leaf, or a whole subtree when the operand is a macro holding
/// algebra.
pub fn parse<E, X>(
    src: &str,
    range: Range<usize>,
    max_depth: usize,
    operand: &mut impl FnMut(Range<usize>) -> Result<Algebra<E>, X>,
) -> Result<Algebra<E>, ParseError<X>> {
    let toks = scan(src, range.clone());
    let mut p = Parser {
        toks: &toks,
        pos: 0,
        end: range.end,
        depth: 0,
        max_depth,
        operands: 0,
    };
    let t = p.algebra(operand)?;
    match p.toks.get(p.pos) {
        Some((_, at)) => Err(ParseError::Algebra(AlgebraError::Unbalanced {
            at: at.clone(),
        })),
        None => Ok(t),
    }
}

struct Parser<'t> {
    toks: &'t [(Tok, Range<usize>)],
    pos: usize,
    end: usize,
    /// Algebra groups and `^` open around the current token.
    depth: usize,
    max_depth: usize,
    operands: usize,
}

impl Parser<'_> {
    fn peek(&self) -> Option<Tok> {
        self.toks.get(self.pos).map(|t| t.0)
    }

    /// Where a missing operand would be: the next token, or the end.
    fn here(&self) -> Range<usize> {
        self.toks
            .get(self.pos)
            .map_or(self.end..self.end, |t| t.1.clone())
    }

    fn algebra<E, X>(
        &mut self,
        operand: &mut impl FnMut(Range<usize>) -> Result<Algebra<E>, X>,
    ) -> Result<Algebra<E>, ParseError<X>> {
        let mut left = self.unary(operand)?;
        while let Some(op @ (Tok::And | Tok::Minus)) = self.peek() {
            self.pos += 1;
            let right = self.unary(operand)?;
            left = if op == Tok::And {
                Algebra::and(left, right)
            } else {
                Algebra::minus(left, right)
            };
        }
        Ok(left)
    }

    fn unary<E, X>(
        &mut self,
        operand: &mut impl FnMut(Range<usize>) -> Result<Algebra<E>, X>,
    ) -> Result<Algebra<E>, ParseError<X>> {
        let missing = |at| Err(ParseError::Algebra(AlgebraError::MissingOperand { at }));
        if matches!(self.peek(), Some(Tok::Not | Tok::Open)) && self.depth >= self.max_depth {
            return Err(ParseError::Algebra(AlgebraError::TooDeep {
                at: self.here(),
                max: self.max_depth,
            }));
        }
        match self.peek() {
            Some(Tok::Not) => {
                let at = self.here();
                self.pos += 1;
                if matches!(self.peek(), None | Some(Tok::And | Tok::Minus | Tok::Close)) {
                    return missing(at);
                }
                self.depth += 1;
                let t = self.unary(operand)?;
                self.depth -= 1;
                Ok(Algebra::complement(t))
            }
            None | Some(Tok::And | Tok::Minus | Tok::Close) => missing(self.here()),
            Some(Tok::Open) if self.is_algebra_group() => {
                let open = self.here();
                self.pos += 1;
                self.depth += 1;
                let t = self.algebra(operand)?;
                self.depth -= 1;
                if self.peek() != Some(Tok::Close) {
                    return Err(ParseError::Algebra(AlgebraError::Unbalanced { at: open }));
                }
                self.pos += 1;
                Ok(t)
            }
            Some(_) => self.operand(operand),
        }
    }

    /// The group opening here is an algebra group: an operator stands at its own top
    /// level, or it only wraps another algebra group (`((A - B))`); and nothing but an
    /// operator, a `)` or the end follows its `)`.
    fn is_algebra_group(&self) -> bool {
        let Some(close) = self.matching_close(self.pos) else {
            return false;
        };
        let after = self.toks.get(close + 1).map(|t| t.0);
        matches!(after, None | Some(Tok::And | Tok::Minus | Tok::Close))
            && self.holds_algebra(self.pos, close)
    }

    /// Whether the group `toks[open..=close]` holds algebra at its top level, or is
    /// nothing but a group that does.
    fn holds_algebra(&self, open: usize, close: usize) -> bool {
        let mut depth = 0usize;
        for (t, _) in &self.toks[open..close] {
            match t {
                Tok::Open => depth += 1,
                Tok::Close => depth -= 1,
                Tok::And | Tok::Minus | Tok::Not if depth == 1 => return true,
                _ => {}
            }
        }
        let inner = open + 1;
        self.toks.get(inner).is_some_and(|t| t.0 == Tok::Open)
            && self.matching_close(inner) == Some(close - 1)
            && self.holds_algebra(inner, close - 1)
    }

    /// The `)` closing the `(` at `open`.
    fn matching_close(&self, open: usize) -> Option<usize> {
        let mut depth = 0usize;
        for (k, (t, _)) in self.toks[open..].iter().enumerate() {
            match t {
                Tok::Open => depth += 1,
                Tok::Close => {
                    depth -= 1;
                    if depth == 0 {
                        return Some(open + k);
                    }
                }
                _ => {}
            }
        }
        None
    }

    /// One operand: tokens up to an operator or `)` at this level. An operator nested in
    /// one of its groups is an error.
    fn operand<E, X>(
        &mut self,
        operand: &mut impl FnMut(Range<usize>) -> Result<Algebra<E>, X>,
    ) -> Result<Algebra<E>, ParseError<X>> {
        let start = self.here().start;
        let mut end = start;
        // Open groups of the operand, innermost last.
        let mut open: Vec<Range<usize>> = Vec::new();
        while let Some((t, span)) = self.toks.get(self.pos) {
            match t {
                Tok::And | Tok::Minus | Tok::Not if !open.is_empty() => {
                    // `(A - B` never closes: say so rather than blame the operator.
                    let closes = self.toks[self.pos..]
                        .iter()
                        .filter(|t| t.0 == Tok::Close)
                        .count();
                    let e = if closes < open.len() {
                        AlgebraError::Unbalanced {
                            at: open[0].clone(),
                        }
                    } else {
                        AlgebraError::InsideOperand { at: span.clone() }
                    };
                    return Err(ParseError::Algebra(e));
                }
                Tok::And | Tok::Minus => break,
                Tok::Close if open.is_empty() => break,
                Tok::Open => open.push(span.clone()),
                Tok::Close => {
                    open.pop();
                }
                _ => {}
            }
            end = span.end;
            self.pos += 1;
        }
        self.operands += 1;
        if self.operands > MAX_OPERANDS {
            return Err(ParseError::Algebra(AlgebraError::TooManyOperands {
                at: start..end,
            }));
        }
        operand(start..end).map_err(ParseError::Operand)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Leaves are the operand texts.
    fn tree(src: &str) -> Result<String, AlgebraError> {
        let t = parse(src, 0..src.len(), 4, &mut |r: Range<usize>| {
            Ok::<_, ()>(Algebra::Leaf(format!("[{}]", &src[r])))
        });
        match t {
            Ok(t) => Ok(t.to_string()),
            Err(ParseError::Algebra(e)) => Err(e),
            Err(ParseError::Operand(())) => unreachable!(),
        }
    }

    #[test]
    fn precedence_and_associativity() {
        assert_eq!(tree("A - B - C").unwrap(), "[A] - [B] - [C]");
        assert_eq!(tree("A - (B - C)").unwrap(), "[A] - ([B] - [C])");
        assert_eq!(tree("^A & B").unwrap(), "^[A] & [B]");
        assert_eq!(tree("^(A & B)").unwrap(), "^([A] & [B])");
        assert_eq!(tree("A & B - C").unwrap(), "[A] & [B] - [C]");
        assert_eq!(tree("(A - B) & ^(C|D)").unwrap(), "[A] - [B] & ^[(C|D)]");
        assert_eq!(tree("^^A").unwrap(), "^^[A]");
        assert_eq!(tree("((A))").unwrap(), "[((A))]");
    }

    #[test]
    fn units_of_the_dialects_are_skipped_whole() {
        assert!(!has_algebra("C<R-D>'a-b'[^'x']L", 0..18));
        assert_eq!(
            tree("C<R-D>L - C['a&b' ^]L").unwrap(),
            "[C<R-D>L] - [C['a&b' ^]L]"
        );
        assert_eq!(
            tree("C[<L.[^'a']>O] - C.*L").unwrap(),
            "[C[<L.[^'a']>O]] - [C.*L]"
        );
        // OSL's `<R]>` has the label `]`: the unit ends at the `>` matching its `<`.
        assert!(!has_algebra("C[<R]-D>]L", 0..10));
        assert_eq!(tree("C<R]>L-C[<]>]L").unwrap(), "[C<R]>L] - [C[<]>]L]");
        // `^` where no operand can start is operand text for the dialect.
        assert!(!has_algebra("C^L", 0..3));
        assert!(has_algebra("^CL", 0..3));
    }

    #[test]
    fn errors_point_at_the_operator() {
        assert_eq!(tree("A -"), Err(AlgebraError::MissingOperand { at: 3..3 }));
        assert_eq!(tree("& B"), Err(AlgebraError::MissingOperand { at: 0..1 }));
        assert_eq!(
            tree("A & ^"),
            Err(AlgebraError::MissingOperand { at: 4..5 })
        );
        assert_eq!(
            tree("C(A - B)L"),
            Err(AlgebraError::InsideOperand { at: 4..5 })
        );
        assert_eq!(tree("(A - B"), Err(AlgebraError::Unbalanced { at: 0..1 }));
        assert_eq!(
            tree("C((A) - B"),
            Err(AlgebraError::Unbalanced { at: 1..2 })
        );
        assert_eq!(tree("A - B)"), Err(AlgebraError::Unbalanced { at: 5..6 }));
        // Nesting and size are bounded: a hostile text gives an error, not a deep tree.
        assert_eq!(tree("^^^^A"), Ok("^^^^[A]".into()));
        assert_eq!(
            tree("^^^^^A"),
            Err(AlgebraError::TooDeep { at: 4..5, max: 4 })
        );
        assert_eq!(tree("((((A - B))))"), Ok("[A] - [B]".into()));
        assert_eq!(
            tree("(((((A - B)))))"),
            Err(AlgebraError::TooDeep { at: 4..5, max: 4 })
        );
        let many = vec!["A"; MAX_OPERANDS + 1].join(" - ");
        let last = many.len() - 1;
        assert_eq!(
            tree(&many),
            Err(AlgebraError::TooManyOperands { at: last..last + 1 })
        );
        assert!(tree(&many[..last - 3]).is_ok());
    }
}
