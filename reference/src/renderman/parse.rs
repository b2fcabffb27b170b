//! The RenderMan reference parser, written from docs/language.md §3–§10 alone:
//! `lpe:`, prefixes, set algebra ([`crate::algebra`]), macro or expression (§6.2) with
//! the light-group suffix (§6.3), and the expression grammar of §5 with the atoms of §4.
//!
//! Every error carries a byte offset into the whole source; nesting is bounded by
//! [`Limits::max_depth`] (checked before each recursion), macro chains by
//! [`Limits::max_macro_depth`], so no input overflows the stack.

use crate::algebra::{self, Algebra};
use crate::error::{Count, ErrorKind, FrontError, Limits};
use crate::scanner::Scanner;

use super::ast::{Atom, Event, Expr, Item, Kind, Lpe, Position, Prefix, Triple, Type};
use super::macros::Registration;

/// Parses a whole RenderMan source under `registration` (user macros, limits).
pub fn parse(src: &str, registration: &Registration) -> Result<Lpe, FrontError> {
    let lpe = parse_source(src, registration, 0)?;
    let positions: u64 = lpe.body.operands().into_iter().map(positions).sum();
    if positions > registration.limits.max_positions {
        return Err(FrontError::new(
            ErrorKind::Limit,
            0,
            format!(
                "{positions} atom positions after unrolling, more than {}",
                registration.limits.max_positions
            ),
        ));
    }
    Ok(lpe)
}

/// Atom positions of §10 after unrolling counted repetition.
fn positions(e: &Expr) -> u64 {
    match e {
        Expr::Atom(_) => 1,
        Expr::Seq(es) | Expr::Alt(es) => es.iter().map(positions).fold(0, u64::saturating_add),
        Expr::Repeat(body, c) => positions(body).saturating_mul(c.unrolled()),
    }
}

fn is_ws(c: char) -> bool {
    c.is_ascii_whitespace()
}

/// `('lpe:')? (prefix ';')* algebra`, macros `macro_depth` deep.
fn parse_source(src: &str, reg: &Registration, macro_depth: usize) -> Result<Lpe, FrontError> {
    let mut pos = src.len() - src.trim_start_matches(is_ws).len();
    if src[pos..]
        .get(..4)
        .is_some_and(|m| m.eq_ignore_ascii_case("lpe:"))
    {
        pos += 4;
    }
    let mut prefixes = Vec::new();
    loop {
        let rest = &src[pos..];
        let start = pos + (rest.len() - rest.trim_start_matches(is_ws).len());
        let name_len = src[start..]
            .find(|c: char| !c.is_ascii_alphabetic())
            .unwrap_or(src.len() - start);
        let after = start + name_len;
        let semi = after + (src[after..].len() - src[after..].trim_start_matches(is_ws).len());
        if !src[semi..].starts_with(';') {
            break;
        }
        let name = &src[start..after];
        if name.is_empty() {
            return Err(FrontError::new(
                ErrorKind::Empty,
                semi,
                "an empty prefix before `;`",
            ));
        }
        let Some(p) = Prefix::ALL
            .iter()
            .find(|p| p.name().eq_ignore_ascii_case(name))
        else {
            return Err(FrontError::new(
                ErrorKind::UnknownPrefix,
                start,
                format!("unknown prefix `{name}`"),
            ));
        };
        prefixes.push(*p);
        pos = semi + 1;
    }
    if src[pos..].trim_matches(is_ws).is_empty() {
        return Err(FrontError::new(
            ErrorKind::Empty,
            src.len(),
            "nothing to match",
        ));
    }
    let mut extra = Vec::new();
    let body = algebra::split(src, pos, src.len(), reg.limits.max_depth, &mut |lo, hi| {
        let (tree, more) = body(src, lo, hi, reg, macro_depth)?;
        extra.extend(more);
        Ok(tree)
    })?;
    prefixes.extend(extra);
    prefixes.sort();
    prefixes.dedup();
    Ok(Lpe { prefixes, body })
}

/// `macro-name ('_' light-group)? | expression` in `src[lo..hi]` (§6.2): the tree and
/// the prefixes a macro brings.
fn body(
    src: &str,
    lo: usize,
    hi: usize,
    reg: &Registration,
    macro_depth: usize,
) -> Result<(Algebra<Expr>, Vec<Prefix>), FrontError> {
    let text = &src[lo..hi];
    let lead = text.len() - text.trim_start_matches(is_ws).len();
    let word = text.trim_matches(is_ws);
    let at = lo + lead;
    if word.is_empty() {
        return Err(FrontError::new(ErrorKind::Empty, hi, "nothing to match"));
    }
    let identifier = word.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        && !word.starts_with(|c: char| c.is_ascii_digit());
    if identifier {
        if let Some(source) = reg.macro_source(word) {
            return expand(source, None, at, word, reg, macro_depth);
        }
        let longest = word
            .char_indices()
            .filter(|&(_, c)| c == '_')
            .map(|(i, _)| i)
            .filter(|&i| reg.macro_source(&word[..i]).is_some())
            .max();
        if let Some(i) = longest {
            let group = &word[i + 1..];
            if group.is_empty() {
                return Err(FrontError::new(
                    ErrorKind::Syntax,
                    at + i,
                    "an empty light group after `_`",
                ));
            }
            let source = reg.macro_source(&word[..i]).unwrap_or_default();
            return expand(source, Some(group), at, word, reg, macro_depth);
        }
        let tokenizes = word
            .chars()
            .all(|c| c.is_ascii_digit() || "CRTLODSU".contains(c.to_ascii_uppercase()));
        if !tokenizes {
            return Err(FrontError::new(
                ErrorKind::UnknownMacro,
                at,
                format!("`{word}` is no macro and no expression"),
            ));
        }
    }
    let mut p = Parser {
        scan: Scanner {
            src,
            pos: lo,
            end: hi,
        },
        limits: reg.limits,
    };
    let e = p.sequence(0)?;
    p.skip_ws();
    if p.pos < p.end {
        return Err(p.error(ErrorKind::Syntax, "unmatched `)`"));
    }
    Ok((Algebra::Operand(e), Vec::new()))
}

/// A macro's tree: its source parsed one chain deeper, the light group written into
/// every `<L.>` triple (§6.3). Errors inside point at the macro name (§9.1).
fn expand(
    source: &str,
    group: Option<&str>,
    at: usize,
    name: &str,
    reg: &Registration,
    macro_depth: usize,
) -> Result<(Algebra<Expr>, Vec<Prefix>), FrontError> {
    if macro_depth + 1 > reg.limits.max_macro_depth {
        return Err(FrontError::new(
            ErrorKind::Limit,
            at,
            format!(
                "macro `{name}` expands more than {} macros deep",
                reg.limits.max_macro_depth
            ),
        ));
    }
    let mut lpe = parse_source(source, reg, macro_depth + 1).map_err(|e| {
        FrontError::new(
            e.kind,
            at,
            format!("macro `{name}` = `{source}` is invalid: {}", e.message),
        )
    })?;
    if let Some(g) = group {
        lpe.body.for_each_mut(&mut |e| set_light_group(e, g));
    }
    Ok((lpe.body, lpe.prefixes))
}

/// Writes `group` into the label position of every triple that is exactly `<L.>`.
fn set_light_group(e: &mut Expr, group: &str) {
    let item = |it: &mut Item| {
        if let Item::Triple(t) = it {
            if t.ty == Position::One(Type::L)
                && t.event == Position::Any
                && t.label == Position::Any
            {
                t.label = Position::One(group.to_string());
            }
        }
    };
    match e {
        Expr::Atom(Atom::Item(it)) => item(it),
        Expr::Atom(Atom::Class { items, .. }) => items.iter_mut().for_each(item),
        Expr::Seq(es) | Expr::Alt(es) => es.iter_mut().for_each(|e| set_light_group(e, group)),
        Expr::Repeat(b, _) => set_light_group(b, group),
    }
}

/// A recursive-descent reader of one expression in `src[pos..end]`.
struct Parser<'s> {
    scan: Scanner<'s>,
    limits: Limits,
}

/// What one entry of a triple or a class is, before its position decides.
enum Entry {
    Dot,
    Type(Type),
    Event(Event),
    Label(String),
}

/// The parser reads through its [`Scanner`] (`self.peek()`, `self.pos`).
impl<'s> std::ops::Deref for Parser<'s> {
    type Target = Scanner<'s>;
    fn deref(&self) -> &Scanner<'s> {
        &self.scan
    }
}

impl<'s> std::ops::DerefMut for Parser<'s> {
    fn deref_mut(&mut self) -> &mut Scanner<'s> {
        &mut self.scan
    }
}

impl Parser<'_> {
    fn skip_ws(&mut self) {
        while self.peek().is_some_and(is_ws) {
            self.pos += 1;
        }
    }

    fn error(&self, kind: ErrorKind, message: impl Into<String>) -> FrontError {
        FrontError::new(kind, self.pos, message)
    }

    fn deeper(&self, depth: usize) -> Result<usize, FrontError> {
        self.scan.deeper(depth, self.limits.max_depth)
    }

    /// `alt alt*`, up to `)` or the end.
    fn sequence(&mut self, depth: usize) -> Result<Expr, FrontError> {
        let mut parts = Vec::new();
        loop {
            self.skip_ws();
            match self.peek() {
                None | Some(')') => break,
                _ => parts.push(self.alt(depth)?),
            }
        }
        match parts.len() {
            0 => Err(self.error(ErrorKind::Empty, "nothing to match")),
            1 => Ok(parts.pop().unwrap_or_else(|| unreachable!())),
            _ => Ok(Expr::Seq(parts)),
        }
    }

    /// `rep ('|' rep)*`.
    fn alt(&mut self, depth: usize) -> Result<Expr, FrontError> {
        let mut choices = vec![self.rep(depth)?];
        loop {
            self.skip_ws();
            if self.peek() != Some('|') {
                break;
            }
            self.bump();
            self.skip_ws();
            if matches!(self.peek(), None | Some(')') | Some('|')) {
                return Err(self.error(ErrorKind::Syntax, "`|` needs something on both sides"));
            }
            choices.push(self.rep(depth)?);
        }
        Ok(if choices.len() == 1 {
            choices.pop().unwrap_or_else(|| unreachable!())
        } else {
            Expr::Alt(choices)
        })
    }

    /// `unit quantifier?`; a second quantifier is an error.
    fn rep(&mut self, depth: usize) -> Result<Expr, FrontError> {
        let unit = self.unit(depth)?;
        self.skip_ws();
        let Some(count) = self.quantifier()? else {
            return Ok(unit);
        };
        self.skip_ws();
        if matches!(self.peek(), Some('*' | '+' | '?' | '{')) {
            return Err(self.error(ErrorKind::Quantifier, "one quantifier per atom"));
        }
        Ok(Expr::Repeat(Box::new(unit), count))
    }

    /// A quantifier at the cursor, if there is one.
    fn quantifier(&mut self) -> Result<Option<Count>, FrontError> {
        let count = match self.peek() {
            Some('*') => Count { min: 0, max: None },
            Some('+') => Count { min: 1, max: None },
            Some('?') => Count {
                min: 0,
                max: Some(1),
            },
            Some('{') => {
                let open = self.pos;
                self.bump();
                let count = self.braces(open)?;
                return Ok(Some(count));
            }
            _ => return Ok(None),
        };
        self.bump();
        Ok(Some(count))
    }

    /// A decimal number at the cursor (after whitespace), if any; over `max_repeat` is a
    /// `Limit` error.
    fn number(&mut self) -> Result<Option<u32>, FrontError> {
        self.skip_ws();
        let start = self.pos;
        while self.peek().is_some_and(|c| c.is_ascii_digit()) {
            self.pos += 1;
        }
        let digits = &self.src[start..self.pos];
        if digits.is_empty() {
            return Ok(None);
        }
        match digits.parse::<u32>() {
            Ok(n) if n <= self.limits.max_repeat => Ok(Some(n)),
            _ => Err(FrontError::new(
                ErrorKind::Limit,
                start,
                format!("count {digits} is over {}", self.limits.max_repeat),
            )),
        }
    }

    /// The rest of `{n}`, `{n,}`, `{n,m}` after `{`.
    fn braces(&mut self, open: usize) -> Result<Count, FrontError> {
        let bad = |p: &Parser<'_>, what: &str| {
            FrontError::new(ErrorKind::Quantifier, p.pos.max(open), what)
        };
        let Some(min) = self.number()? else {
            return Err(bad(self, "a count needs a lower bound"));
        };
        self.skip_ws();
        let max = match self.bump() {
            Some('}') => {
                return Ok(Count {
                    min,
                    max: Some(min),
                })
            }
            Some(',') => {
                let m = self.number()?;
                self.skip_ws();
                if self.bump() != Some('}') {
                    return Err(bad(self, "unclosed `{`"));
                }
                m
            }
            _ => return Err(bad(self, "unclosed `{`")),
        };
        if max.is_some_and(|m| m < min) {
            return Err(FrontError::new(
                ErrorKind::Quantifier,
                open,
                "a count's lower bound is over its upper bound",
            ));
        }
        Ok(Count { min, max })
    }

    /// `'(' sequence ')' | class | triple | letter | label | '.'`.
    fn unit(&mut self, depth: usize) -> Result<Expr, FrontError> {
        self.skip_ws();
        let start = self.pos;
        match self.peek() {
            Some('(') => {
                let depth = self.deeper(depth)?;
                self.bump();
                self.skip_ws();
                if self.peek() == Some(')') {
                    return Err(FrontError::new(ErrorKind::Empty, start, "empty group `()`"));
                }
                let inner = self.sequence(depth)?;
                self.skip_ws();
                if self.bump() != Some(')') {
                    return Err(FrontError::new(ErrorKind::Syntax, start, "unclosed `(`"));
                }
                Ok(inner)
            }
            Some('[') => {
                let depth = self.deeper(depth)?;
                self.class(depth)
            }
            Some('<') => Ok(Expr::Atom(Atom::Item(Item::Triple(self.triple(depth)?)))),
            Some('*' | '+' | '?' | '{') => Err(self.error(
                ErrorKind::Quantifier,
                "a quantifier needs an atom or group before it",
            )),
            Some(_) => {
                let item = self.entry()?;
                Ok(Expr::Atom(Atom::Item(match item {
                    Entry::Dot => Item::Any,
                    Entry::Type(t) => Item::Type(t),
                    Entry::Event(e) => Item::Event(e),
                    Entry::Label(l) => Item::Label(l),
                })))
            }
            None => Err(self.error(ErrorKind::Syntax, "expected an atom")),
        }
    }

    /// `.`, a type or event letter (with its lobe), or a label.
    fn entry(&mut self) -> Result<Entry, FrontError> {
        let start = self.pos;
        let Some(c) = self.bump() else {
            return Err(self.error(ErrorKind::Syntax, "expected an atom"));
        };
        if c == '.' {
            return Ok(Entry::Dot);
        }
        if c == '\'' {
            let rest = &self.src[self.pos..self.end];
            let Some(close) = rest.find('\'') else {
                return Err(FrontError::new(ErrorKind::Syntax, start, "unclosed `'`"));
            };
            let label = rest[..close].to_string();
            self.pos += close + 1;
            return Ok(Entry::Label(label));
        }
        if let Some(t) = Type::from_letter(c) {
            return Ok(Entry::Type(t));
        }
        if let Some(kind) = Kind::from_letter(c) {
            let digits_at = self.pos;
            while self.peek().is_some_and(|c| c.is_ascii_digit()) {
                self.pos += 1;
            }
            let digits = &self.src[digits_at..self.pos];
            if digits.is_empty() {
                return Ok(Entry::Event(Event { kind, lobe: None }));
            }
            return match digits.parse::<u8>() {
                Ok(n) if (1..=kind.max_lobe()).contains(&n) => Ok(Entry::Event(Event {
                    kind,
                    lobe: Some(n),
                })),
                _ => Err(FrontError::new(
                    ErrorKind::Lobe,
                    start,
                    format!(
                        "lobe `{}{digits}` out of range: {} lobes are 1 to {}",
                        kind.letter(),
                        kind.letter(),
                        kind.max_lobe()
                    ),
                )),
            };
        }
        self.pos = start;
        let message = match c {
            '"' => "labels take single quotes",
            ';' => "prefixes go first",
            ')' => "unmatched `)`",
            '|' => "`|` needs something on both sides",
            '0'..='9' => "a stray number",
            _ => "not a letter, label or punctuation of an expression",
        };
        Err(self.error(ErrorKind::Syntax, message))
    }

    /// `[…]` or `[^…]` of items (§4.3).
    fn class(&mut self, depth: usize) -> Result<Expr, FrontError> {
        let open = self.pos;
        self.bump();
        self.skip_ws();
        let negated = self.peek() == Some('^');
        if negated {
            self.bump();
        }
        let mut items = Vec::new();
        loop {
            self.skip_ws();
            match self.peek() {
                None => return Err(FrontError::new(ErrorKind::Syntax, open, "unclosed `[`")),
                Some(']') => {
                    self.bump();
                    break;
                }
                Some('<') => items.push(Item::Triple(self.triple(depth)?)),
                Some('(' | '[' | '|' | ')') => {
                    return Err(self.error(ErrorKind::Syntax, "a class holds single-vertex items"))
                }
                Some('*' | '+' | '?' | '{') => {
                    return Err(self.error(ErrorKind::Quantifier, "no quantifier inside a class"))
                }
                Some(_) => items.push(match self.entry()? {
                    Entry::Dot => Item::Any,
                    Entry::Type(t) => Item::Type(t),
                    Entry::Event(e) => Item::Event(e),
                    Entry::Label(l) => Item::Label(l),
                }),
            }
        }
        if items.is_empty() {
            return Err(FrontError::new(ErrorKind::Empty, open, "empty class"));
        }
        Ok(Expr::Atom(Atom::Class { negated, items }))
    }

    /// `<type event label>` (§4.2).
    fn triple(&mut self, depth: usize) -> Result<Triple, FrontError> {
        let open = self.pos;
        self.bump();
        let mut t = Triple {
            ty: Position::Any,
            event: Position::Any,
            label: Position::Any,
        };
        let mut index = 0usize;
        loop {
            self.skip_ws();
            let at = self.pos;
            let misplaced = |what: &str| FrontError::new(ErrorKind::TriplePosition, at, what);
            match self.peek() {
                None => return Err(FrontError::new(ErrorKind::Syntax, open, "unclosed `<`")),
                Some('>') => {
                    self.bump();
                    break;
                }
                Some('<' | '(' | ')' | '|' | ']') => {
                    return Err(self.error(ErrorKind::Syntax, "a triple is one vertex"))
                }
                Some('*' | '+' | '?' | '{') => {
                    return Err(self.error(ErrorKind::Quantifier, "no quantifier inside a triple"))
                }
                Some('[') => {
                    let depth = self.deeper(depth)?;
                    let _ = depth;
                    self.bump();
                    self.skip_ws();
                    let negated = self.peek() == Some('^');
                    if negated {
                        self.bump();
                    }
                    let mut entries = Vec::new();
                    loop {
                        self.skip_ws();
                        match self.peek() {
                            None => {
                                return Err(FrontError::new(ErrorKind::Syntax, at, "unclosed `[`"))
                            }
                            Some(']') => {
                                self.bump();
                                break;
                            }
                            Some('.' | '[' | '<' | '(' | ')' | '|' | '>') => {
                                return Err(self.error(
                                    ErrorKind::Syntax,
                                    "a position's class holds that position's values",
                                ))
                            }
                            Some('*' | '+' | '?' | '{') => {
                                return Err(self.error(ErrorKind::Quantifier, "no quantifier here"))
                            }
                            Some(_) => entries.push(self.entry()?),
                        }
                    }
                    if entries.is_empty() {
                        return Err(FrontError::new(ErrorKind::Empty, at, "empty class"));
                    }
                    match index {
                        0 => {
                            let mut items = Vec::new();
                            for e in entries {
                                match e {
                                    Entry::Type(ty) => items.push(ty),
                                    _ => {
                                        return Err(misplaced(
                                            "only type letters in the type position",
                                        ))
                                    }
                                }
                            }
                            t.ty = Position::Class { negated, items };
                        }
                        1 => {
                            let mut items = Vec::new();
                            for e in entries {
                                match e {
                                    Entry::Event(ev) => items.push(ev),
                                    _ => {
                                        return Err(misplaced("only events in the event position"))
                                    }
                                }
                            }
                            t.event = Position::Class { negated, items };
                        }
                        2 => {
                            let mut items = Vec::new();
                            for e in entries {
                                match e {
                                    Entry::Label(l) => items.push(l),
                                    _ => {
                                        return Err(misplaced("only labels in the label position"))
                                    }
                                }
                            }
                            t.label = Position::Class { negated, items };
                        }
                        _ => return Err(misplaced("a triple has three positions")),
                    }
                }
                Some(_) => {
                    let e = self.entry()?;
                    match (index, e) {
                        (_, Entry::Dot) if index < 3 => {}
                        (0, Entry::Type(ty)) => t.ty = Position::One(ty),
                        (0, Entry::Event(_)) => {
                            return Err(misplaced("an event in the type position"))
                        }
                        (0 | 1, Entry::Label(_)) => {
                            return Err(misplaced("the label belongs in the third position"))
                        }
                        (1, Entry::Event(ev)) => t.event = Position::One(ev),
                        (1, Entry::Type(_)) => {
                            return Err(misplaced("a type letter in the event position"))
                        }
                        (2, Entry::Label(l)) => t.label = Position::One(l),
                        _ => return Err(misplaced("a letter in the label position")),
                    }
                }
            }
            index += 1;
        }
        if index == 0 {
            return Err(FrontError::new(ErrorKind::Empty, open, "empty triple `<>`"));
        }
        Ok(t)
    }
}
