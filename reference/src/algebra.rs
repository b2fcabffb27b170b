//! Set algebra over whole expressions (docs/language.md §5.5, §18.5), written once for
//! both reference front ends: `A & B`, `A - B`, `^A` and algebra groups, found by a scan
//! that skips `'…'`, `<…>` and `[…]` whole.
//!
//! [`split`] finds the operators in a source range and hands each operand's byte range
//! to the dialect's operand parser; the tree it returns is [`Algebra`], whose
//! [`Algebra::eval`] is the definition of §5.5: each operand matched on its own, the
//! answers combined.

use crate::error::{ErrorKind, FrontError};

/// Set algebra over operands of type `T`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Algebra<T> {
    /// A whole expression.
    Operand(T),
    /// Both match.
    And(Box<Algebra<T>>, Box<Algebra<T>>),
    /// The left matches and the right does not.
    Minus(Box<Algebra<T>>, Box<Algebra<T>>),
    /// The operand does not match.
    Not(Box<Algebra<T>>),
}

impl<T> Algebra<T> {
    /// The answer for a path, given each operand's answer.
    pub fn eval(&self, f: &mut dyn FnMut(&T) -> bool) -> bool {
        match self {
            Algebra::Operand(t) => f(t),
            Algebra::And(a, b) => a.eval(f) && b.eval(f),
            Algebra::Minus(a, b) => a.eval(f) && !b.eval(f),
            Algebra::Not(a) => !a.eval(f),
        }
    }

    /// Every operand, left to right.
    pub fn operands(&self) -> Vec<&T> {
        let mut out = Vec::new();
        self.visit(&mut |t| out.push(t));
        out
    }

    fn visit<'a>(&'a self, f: &mut dyn FnMut(&'a T)) {
        match self {
            Algebra::Operand(t) => f(t),
            Algebra::And(a, b) | Algebra::Minus(a, b) => {
                a.visit(f);
                b.visit(f);
            }
            Algebra::Not(a) => a.visit(f),
        }
    }

    /// Every operand changed in place.
    pub fn for_each_mut(&mut self, f: &mut dyn FnMut(&mut T)) {
        match self {
            Algebra::Operand(t) => f(t),
            Algebra::And(a, b) | Algebra::Minus(a, b) => {
                a.for_each_mut(f);
                b.for_each_mut(f);
            }
            Algebra::Not(a) => a.for_each_mut(f),
        }
    }

    /// Prints the algebra with ` & `, ` - ` and `^`, every compound operand in
    /// parentheses, each operand by `operand`.
    pub fn print(&self, operand: &dyn Fn(&T) -> String) -> String {
        let sub = |a: &Algebra<T>| match a {
            Algebra::Operand(t) => operand(t),
            other => format!("({})", other.print(operand)),
        };
        match self {
            Algebra::Operand(t) => operand(t),
            Algebra::And(a, b) => format!("{} & {}", sub(a), sub(b)),
            Algebra::Minus(a, b) => format!("{} - {}", sub(a), sub(b)),
            Algebra::Not(a) => format!("^{}", sub(a)),
        }
    }
}

/// One token of the operator scan.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Tok {
    Open,
    Close,
    And,
    Minus,
    Not,
}

/// The operator tokens of `src[lo..hi]` with their byte offsets: parentheses, `&`, `-`
/// outside `'…'`, `<…>`, `[…]`, and `^` where an operand may start.
fn scan(src: &str, lo: usize, hi: usize) -> Vec<(Tok, usize)> {
    let mut out = Vec::new();
    let mut regions: Vec<char> = Vec::new();
    let mut quoted = false;
    let mut operand_start = true;
    for (i, c) in src[lo..hi].char_indices() {
        let at = lo + i;
        if quoted {
            quoted = c != '\'';
            continue;
        }
        if c == '\'' {
            quoted = true;
            operand_start = false;
            continue;
        }
        if let Some(&closer) = regions.last() {
            match c {
                '<' => regions.push('>'),
                '[' => regions.push(']'),
                c if c == closer => {
                    regions.pop();
                }
                _ => {}
            }
            continue;
        }
        match c {
            '<' => regions.push('>'),
            '[' => regions.push(']'),
            '(' => out.push((Tok::Open, at)),
            ')' => out.push((Tok::Close, at)),
            '&' => out.push((Tok::And, at)),
            '-' => out.push((Tok::Minus, at)),
            '^' if operand_start => out.push((Tok::Not, at)),
            _ => {}
        }
        operand_start = match c {
            '&' | '-' | '^' | '(' => true,
            c if c.is_ascii_whitespace() => operand_start,
            _ => false,
        };
    }
    out
}

/// Parses `src[lo..hi]` as set algebra over operands read by `operand` (given a
/// trimmed byte range, it returns the operand's own tree, itself possibly algebra: a
/// macro). Without any operator the whole range, untrimmed, is the one operand.
/// Algebra groups nest at most `max_depth` deep.
pub fn split<T>(
    src: &str,
    lo: usize,
    hi: usize,
    max_depth: usize,
    operand: &mut dyn FnMut(usize, usize) -> Result<Algebra<T>, FrontError>,
) -> Result<Algebra<T>, FrontError> {
    let toks = scan(src, lo, hi);
    if !toks
        .iter()
        .any(|(t, _)| matches!(t, Tok::And | Tok::Minus | Tok::Not))
    {
        return operand(lo, hi);
    }
    let mut p = Splitter {
        src,
        hi,
        toks,
        i: 0,
        cursor: lo,
        max_depth,
        operand,
    };
    let tree = p.algebra(0)?;
    if p.i < p.toks.len() {
        let at = p.toks[p.i].1;
        return Err(FrontError::new(
            ErrorKind::Algebra,
            at,
            "unbalanced `)` in set algebra",
        ));
    }
    Ok(tree)
}

struct Splitter<'s, 'f, T> {
    src: &'s str,
    hi: usize,
    toks: Vec<(Tok, usize)>,
    i: usize,
    /// The first byte not yet consumed.
    cursor: usize,
    max_depth: usize,
    operand: &'f mut dyn FnMut(usize, usize) -> Result<Algebra<T>, FrontError>,
}

impl<T> Splitter<'_, '_, T> {
    fn peek(&self) -> Option<(Tok, usize)> {
        self.toks.get(self.i).copied()
    }

    /// `unary (('&' | '-') unary)*`, up to an unmatched `)` or the end.
    fn algebra(&mut self, depth: usize) -> Result<Algebra<T>, FrontError> {
        let mut lhs = self.unary(depth)?;
        while let Some((t @ (Tok::And | Tok::Minus), at)) = self.peek() {
            self.i += 1;
            self.cursor = at + 1;
            let rhs = self.unary(depth)?;
            lhs = if t == Tok::And {
                Algebra::And(Box::new(lhs), Box::new(rhs))
            } else {
                Algebra::Minus(Box::new(lhs), Box::new(rhs))
            };
        }
        Ok(lhs)
    }

    /// The token index of the `)` matching the `(` at `open`, if any.
    fn matching(&self, open: usize) -> Option<usize> {
        let mut depth = 0usize;
        for (k, (t, _)) in self.toks.iter().enumerate().skip(open) {
            match t {
                Tok::Open => depth += 1,
                Tok::Close => {
                    depth -= 1;
                    if depth == 0 {
                        return Some(k);
                    }
                }
                _ => {}
            }
        }
        None
    }

    fn is_blank(&self, lo: usize, hi: usize) -> bool {
        self.src[lo..hi]
            .trim_matches(|c: char| c.is_ascii_whitespace())
            .is_empty()
    }

    /// `'^' unary | '(' algebra ')' | operand`.
    fn unary(&mut self, depth: usize) -> Result<Algebra<T>, FrontError> {
        if depth > self.max_depth {
            return Err(FrontError::new(
                ErrorKind::Limit,
                self.cursor,
                format!("set algebra nested deeper than {}", self.max_depth),
            ));
        }
        let first = self.peek();
        if let Some((Tok::Not, at)) = first {
            if self.is_blank(self.cursor, at) {
                self.i += 1;
                self.cursor = at + 1;
                let inner = self.unary(depth + 1)?;
                return Ok(Algebra::Not(Box::new(inner)));
            }
        }
        if let Some((Tok::Open, at)) = first {
            if self.is_blank(self.cursor, at) {
                if let Some(close) = self.matching(self.i) {
                    let holds_operator = self.toks[self.i..close]
                        .iter()
                        .any(|(t, _)| matches!(t, Tok::And | Tok::Minus | Tok::Not));
                    let close_at = self.toks[close].1;
                    let next_at = self.toks.get(close + 1).map_or(self.hi, |t| t.1);
                    let whole = self.is_blank(close_at + 1, next_at)
                        && !matches!(self.toks.get(close + 1), Some((Tok::Open | Tok::Not, _)));
                    if holds_operator && whole {
                        self.i += 1;
                        self.cursor = at + 1;
                        let inner = self.algebra(depth + 1)?;
                        if self.i != close {
                            let at = self.toks[self.i].1;
                            return Err(FrontError::new(
                                ErrorKind::Algebra,
                                at,
                                "unbalanced set-algebra group",
                            ));
                        }
                        self.i += 1;
                        self.cursor = close_at + 1;
                        return Ok(inner);
                    }
                } else {
                    return Err(FrontError::new(
                        ErrorKind::Algebra,
                        at,
                        "unclosed `(` in set algebra",
                    ));
                }
            }
        }
        // An operand: up to the next `&`/`-` at this level, an unmatched `)` or the end.
        let start = self.cursor;
        let mut depth_here = 0usize;
        let mut inner_operator = None;
        let mut end = self.hi;
        while let Some((t, at)) = self.peek() {
            match t {
                Tok::Open => depth_here += 1,
                Tok::Close if depth_here == 0 => {
                    end = at;
                    break;
                }
                Tok::Close => depth_here -= 1,
                Tok::And | Tok::Minus if depth_here == 0 => {
                    end = at;
                    break;
                }
                _ => {
                    inner_operator.get_or_insert(at);
                }
            }
            self.i += 1;
        }
        if let Some(at) = inner_operator {
            return Err(FrontError::new(
                ErrorKind::Algebra,
                at,
                "a set-algebra operator inside a group that is only part of an expression",
            ));
        }
        let trimmed = |c: char| c.is_ascii_whitespace();
        let text = &self.src[start..end];
        let lo = start + (text.len() - text.trim_start_matches(trimmed).len());
        let hi = end - (text.len() - text.trim_end_matches(trimmed).len());
        if lo >= hi {
            return Err(FrontError::new(
                ErrorKind::Empty,
                end.min(self.hi),
                "a set-algebra operator is missing an operand",
            ));
        }
        self.cursor = end;
        (self.operand)(lo, hi)
    }
}
