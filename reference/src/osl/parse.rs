//! The OSL reference parser, written from docs/language.md §18 alone: items outside
//! `<…>` (§18.3), vertex patterns with their slot items, sets, blacklists and `( … )`
//! sub-expressions over symbols (§18.4), postfixes, `|` binding one item on each side and
//! the `{0}` rule (§18.5), set algebra ([`crate::algebra`]), OSL's error messages
//! (§18.6) and the limits (§18.7).
//!
//! Nesting of groups and lists is checked against [`crate::error::Limits::max_depth`]
//! before each recursion, so no input overflows the stack.

use crate::algebra::{self, Algebra};
use crate::error::{Count, ErrorKind, FrontError};
use crate::scanner::Scanner;

use super::ast::{Expr, Lpe, Pattern, Registration, Slot, Sym, Vertex, STOP};

/// The most vertex patterns one `<…>` may stand for (§18.4).
pub const MAX_GROUP_ALTERNATIVES: u64 = 256;

/// Parses a whole OSL source under `registration`, after what a renderer's registration
/// reads before an expression (docs/profiles.md, "What a profile changes"): a leading
/// `name;` whose name the renderer lists is dropped (a prefix changes what accumulates,
/// not what matches); then a source that is exactly one of its built-in AOV names is
/// that AOV's expression. Anything else is an expression.
pub fn parse(src: &str, registration: &Registration) -> Result<Lpe, FrontError> {
    let rest = match src.find(';') {
        Some(i) if registration.prefixes.iter().any(|p| *p == src[..i]) => &src[i + 1..],
        _ => src,
    };
    for (name, expr) in &registration.builtins {
        if name == rest {
            return expression(expr, registration);
        }
    }
    if rest.len() == src.len() {
        return expression(src, registration);
    }
    // Positions count from the source as written.
    let offset = src.len() - rest.len();
    expression(rest, registration).map_err(|mut e| {
        e.pos += offset;
        e
    })
}

/// Parses one OSL expression (set algebra included) under `registration`.
fn expression(src: &str, registration: &Registration) -> Result<Lpe, FrontError> {
    if src.is_empty() {
        return Err(FrontError::new(ErrorKind::Syntax, 0, "Empty expression"));
    }
    let basic = registration.basic();
    let body = algebra::split(
        src,
        0,
        src.len(),
        registration.limits.max_depth,
        &mut |lo, hi| {
            let mut p = Parser {
                scan: Scanner {
                    src,
                    pos: lo,
                    end: hi,
                },
                reg: registration,
                basic: &basic,
            };
            // Outside a group the sequence reads to the operand's end: a stray `)` is an
            // item, and the item's error.
            Ok(Algebra::Operand(p.sequence(0, false)?))
        },
    )
    .map_err(|mut e| {
        if e.kind == ErrorKind::Empty {
            e.kind = ErrorKind::Algebra;
        }
        e
    })?;
    let positions: u64 = body
        .operands()
        .into_iter()
        .map(positions)
        .fold(0, u64::saturating_add);
    if positions > registration.limits.max_positions {
        return Err(FrontError::new(
            ErrorKind::Limit,
            0,
            format!(
                "{positions} vertex positions after unrolling, more than {}",
                registration.limits.max_positions
            ),
        ));
    }
    Ok(Lpe { body })
}

/// How many vertex patterns one slot item stands for, multiplied out.
fn slot_patterns(s: &Slot) -> u64 {
    match s {
        Slot::One(_) => 1,
        Slot::Group(alts) => alts
            .iter()
            .map(|seq| seq.iter().map(slot_patterns).fold(1, u64::saturating_mul))
            .fold(0, u64::saturating_add),
    }
}

/// Vertex positions after unrolling (§10): a vertex pattern counts the patterns it
/// stands for.
fn positions(e: &Expr) -> u64 {
    match e {
        Expr::Vertex(v) => v
            .slots
            .iter()
            .map(slot_patterns)
            .fold(1, u64::saturating_mul),
        Expr::Seq(es) | Expr::Alt(es) => es.iter().map(positions).fold(0, u64::saturating_add),
        Expr::Repeat(b, c) => positions(b).saturating_mul(c.unrolled()),
        Expr::Nothing => 0,
    }
}

struct Parser<'s> {
    scan: Scanner<'s>,
    reg: &'s Registration,
    basic: &'s [Sym],
}

/// An item as read, with whether it is a lone `{0}` item (dropped when leading).
struct Read {
    expr: Expr,
    zero: bool,
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
    fn error(&self, message: impl Into<String>) -> FrontError {
        FrontError::new(ErrorKind::Syntax, self.pos, message)
    }

    fn deeper(&self, depth: usize) -> Result<usize, FrontError> {
        self.scan.deeper(depth, self.reg.limits.max_depth)
    }

    fn zero_here(&self, at: usize) -> FrontError {
        FrontError::new(
            ErrorKind::Syntax,
            at,
            "A {0} item matches nothing here: only leading items of a sequence may be {0}",
        )
    }

    /// Items up to the end (or `)` in a group); leading `{0}` items drop out.
    fn sequence(&mut self, depth: usize, group: bool) -> Result<Expr, FrontError> {
        let start = self.pos;
        let mut parts = Vec::new();
        let mut dropped = false;
        loop {
            match self.peek() {
                None => break,
                Some(')') if group => break,
                _ => {}
            }
            let at = self.pos;
            let item = self.alt(depth)?;
            if item.zero {
                if parts.is_empty() {
                    dropped = true;
                    continue;
                }
                return Err(self.zero_here(at));
            }
            parts.push(item.expr);
        }
        match parts.len() {
            0 if dropped => Err(self.zero_here(start)),
            // Only a group can hold no item: `parse` and the set-algebra split reject a
            // blank operand before its sequence is read.
            0 => Err(FrontError::new(
                ErrorKind::Syntax,
                start.saturating_sub(1),
                "Empty group () not allowed",
            )),
            1 => Ok(parts.pop().unwrap_or(Expr::Nothing)),
            _ => Ok(Expr::Seq(parts)),
        }
    }

    /// `item ('|' item)*`: `|` takes one item, with its postfix, on each side.
    fn alt(&mut self, depth: usize) -> Result<Read, FrontError> {
        let first = self.item(depth)?;
        if self.peek() != Some('|') {
            return Ok(first);
        }
        let mut choices = vec![first];
        while self.peek() == Some('|') {
            self.bump();
            choices.push(self.item(depth)?);
        }
        if let Some(at) = choices.iter().position(|c| c.zero) {
            let _ = at;
            return Err(self.zero_here(self.pos));
        }
        Ok(Read {
            expr: Expr::Alt(choices.into_iter().map(|c| c.expr).collect()),
            zero: false,
        })
    }

    /// One item and its postfix.
    fn item(&mut self, depth: usize) -> Result<Read, FrontError> {
        let unit = self.unit(depth)?;
        let count = match self.peek() {
            Some('*') => {
                self.bump();
                Count { min: 0, max: None }
            }
            Some('+') => {
                self.bump();
                Count { min: 1, max: None }
            }
            Some('{') => self.range()?,
            _ => {
                return Ok(Read {
                    expr: unit,
                    zero: false,
                })
            }
        };
        if count.max == Some(0) {
            return Ok(Read {
                expr: unit,
                zero: true,
            });
        }
        Ok(Read {
            expr: Expr::Repeat(Box::new(unit), count),
            zero: false,
        })
    }

    /// `{n}`, `{n,}`, `{n,m}` at the cursor, through `}`; `{m,n}` with m > n is `{m}`.
    fn range(&mut self) -> Result<Count, FrontError> {
        let open = self.pos;
        self.bump();
        let bad = |p: &Parser<'_>| {
            FrontError::new(
                ErrorKind::Syntax,
                p.pos.max(open),
                "Bad {} range definition",
            )
        };
        let min = self.digits()?.ok_or_else(|| bad(self))?;
        match self.bump() {
            Some('}') => Ok(Count {
                min,
                max: Some(min),
            }),
            Some(',') => {
                let max = self.digits()?;
                if self.bump() != Some('}') {
                    return Err(bad(self));
                }
                Ok(Count {
                    min,
                    max: max.map(|m| m.max(min)),
                })
            }
            _ => Err(bad(self)),
        }
    }

    fn digits(&mut self) -> Result<Option<u32>, FrontError> {
        let start = self.pos;
        while self.peek().is_some_and(|c| c.is_ascii_digit()) {
            self.pos += 1;
        }
        let d = &self.src[start..self.pos];
        if d.is_empty() {
            return Ok(None);
        }
        match d.parse::<u32>() {
            Ok(n) if n <= self.reg.limits.max_repeat => Ok(Some(n)),
            _ => Err(FrontError::new(
                ErrorKind::Limit,
                start,
                format!("count {d} is over {}", self.reg.limits.max_repeat),
            )),
        }
    }

    /// A vertex pattern with the eater unless it has five or more custom items.
    fn vertex(&self, mut slots: Vec<Slot>) -> Expr {
        while slots.len() < 2 {
            slots.push(Slot::One(Pattern::Any));
        }
        let eater = (slots.len() - 2 < 5).then(|| self.basic.to_vec());
        Expr::Vertex(Vertex { slots, eater })
    }

    fn label(s: &str) -> Sym {
        Sym::Label(s.to_string())
    }

    /// A quoted label after its opening quote; `outside`: an unclosed quote gives the
    /// message of an unknown character outside `<…>`.
    fn quoted(&mut self, open: usize, outside: bool) -> Result<String, FrontError> {
        let rest = &self.src[self.pos..self.end];
        let Some(close) = rest.find('\'') else {
            let message = if outside {
                "Unrecognized basic label: "
            } else {
                "Reached end of line looking for ' to end a literal"
            };
            return Err(FrontError::new(ErrorKind::Syntax, open, message));
        };
        let l = rest[..close].to_string();
        self.pos += close + 1;
        if l == STOP {
            return Err(FrontError::new(
                ErrorKind::Syntax,
                open,
                "'__stop__' is not a label: STOP ends every vertex",
            ));
        }
        Ok(l)
    }

    /// One item outside `<…>`, without its postfix.
    fn unit(&mut self, depth: usize) -> Result<Expr, FrontError> {
        let start = self.pos;
        let Some(c) = self.peek() else {
            return Err(self.error("Unrecognized basic label: "));
        };
        match c {
            '(' => {
                let depth = self.deeper(depth)?;
                self.bump();
                let inner = self.sequence(depth, true)?;
                if self.bump() != Some(')') {
                    return Err(FrontError::new(
                        ErrorKind::Syntax,
                        self.end,
                        "Reached end of line looking for )",
                    ));
                }
                Ok(inner)
            }
            '<' => {
                let depth = self.deeper(depth)?;
                self.bump();
                let slots = self.slots(depth)?;
                Ok(self.vertex(slots))
            }
            '[' => {
                let depth = self.deeper(depth)?;
                self.bump();
                if self.peek() == Some('^') {
                    self.bump();
                    return self.blacklist(start, false).map(|(kind, list)| {
                        let p = Slot::One(Pattern::NotIn(list));
                        let any = || Slot::One(Pattern::Any);
                        self.vertex(match kind {
                            Kind::Event => vec![p],
                            Kind::Scattering => vec![any(), p],
                            Kind::Custom => vec![any(), any(), p],
                        })
                    });
                }
                let mut choices = Vec::new();
                loop {
                    match self.peek() {
                        None => {
                            return Err(FrontError::new(
                                ErrorKind::Syntax,
                                self.end,
                                "Reached end of line looking for ] to end an or list",
                            ))
                        }
                        Some(']') => {
                            self.bump();
                            break;
                        }
                        _ => {
                            // Each element is one item with its postfix: `|` is no item
                            // (§18.3), so `[C|D]` is an error at the `|`.
                            let at = self.pos;
                            let r = self.item(depth)?;
                            if r.zero {
                                return Err(self.zero_here(at));
                            }
                            choices.push(r.expr);
                        }
                    }
                }
                Ok(match choices.len() {
                    0 => Expr::Nothing,
                    1 => choices.pop().unwrap_or(Expr::Nothing),
                    _ => Expr::Alt(choices),
                })
            }
            '\'' => {
                self.bump();
                let l = self.quoted(start, true)?;
                let any = || Slot::One(Pattern::Any);
                Ok(self.vertex(vec![any(), any(), Slot::One(Pattern::Is(Sym::Label(l)))]))
            }
            '.' => {
                self.bump();
                Ok(self.vertex(vec![]))
            }
            '|' => Err(self.error("No left expression to or with |")),
            c => {
                let s = c.to_string();
                if c != 'x' && self.reg.is_event(&s) {
                    self.bump();
                    Ok(self.vertex(vec![Slot::One(Pattern::Is(Self::label(&s)))]))
                } else if c != 'x' && self.reg.is_scattering(&s) {
                    self.bump();
                    Ok(self.vertex(vec![
                        Slot::One(Pattern::Any),
                        Slot::One(Pattern::Is(Self::label(&s))),
                    ]))
                } else if c == 'x' {
                    Err(self.error("Unrecognized basic label: "))
                } else {
                    Err(self.error(format!("Unrecognized basic label: {c}")))
                }
            }
        }
    }

    /// The labels of `[^…]` after `^`, through `]`, and the kind of the last one.
    fn blacklist(&mut self, open: usize, inside: bool) -> Result<(Kind, Vec<Sym>), FrontError> {
        let _ = inside;
        let mut list = Vec::new();
        let mut kind = Kind::Custom;
        loop {
            let at = self.pos;
            match self.bump() {
                None => {
                    return Err(FrontError::new(
                        ErrorKind::Syntax,
                        self.end,
                        "Reached end of line looking for ] to end an negative or list'",
                    ))
                }
                Some(']') => break,
                Some('\'') => {
                    list.push(Sym::Label(self.quoted(at, false)?));
                    kind = Kind::Custom;
                }
                Some(c) => {
                    let s = c.to_string();
                    kind = if c == 'x' || c == '.' {
                        return Err(FrontError::new(
                            ErrorKind::Syntax,
                            at,
                            "Unrecognized basic label",
                        ));
                    } else if self.reg.is_event(&s) {
                        Kind::Event
                    } else if self.reg.is_scattering(&s) {
                        Kind::Scattering
                    } else {
                        return Err(FrontError::new(
                            ErrorKind::Syntax,
                            at,
                            "Unrecognized basic label",
                        ));
                    };
                    list.push(Sym::Label(s));
                }
            }
        }
        if list.is_empty() {
            return Err(FrontError::new(
                ErrorKind::Syntax,
                open,
                "Empty or list [^] not allowed",
            ));
        }
        Ok((kind, list))
    }

    /// Slot items inside `<…>`, through the `>`.
    fn slots(&mut self, depth: usize) -> Result<Vec<Slot>, FrontError> {
        let mut slots = Vec::new();
        loop {
            match self.peek() {
                None => {
                    return Err(FrontError::new(
                        ErrorKind::Syntax,
                        self.end,
                        "Reached end of line looking for > to end a group",
                    ))
                }
                Some('>') => {
                    self.bump();
                    break;
                }
                Some(_) => slots.push(self.slot(depth)?),
            }
        }
        let patterns = slots.iter().map(slot_patterns).fold(1, u64::saturating_mul);
        if patterns > MAX_GROUP_ALTERNATIVES {
            return Err(FrontError::new(
                ErrorKind::Limit,
                self.pos,
                format!("one `<…>` stands for {patterns} vertex patterns, more than {MAX_GROUP_ALTERNATIVES}"),
            ));
        }
        Ok(slots)
    }

    /// The items of a `( … )` inside `<…>` after its `(` (at `open`), through `)`: a
    /// sequence in which `|` joins the one item before it and the one after (§18.4),
    /// neither side empty.
    fn group_items(&mut self, depth: usize, open: usize) -> Result<Vec<Slot>, FrontError> {
        let unclosed =
            |end| FrontError::new(ErrorKind::Syntax, end, "Reached end of line looking for )");
        let empty_side = |at| {
            FrontError::new(
                ErrorKind::Syntax,
                at,
                "Empty alternative in a group: `|` needs an expression on both sides",
            )
        };
        let mut items = Vec::new();
        loop {
            match self.peek() {
                None => return Err(unclosed(self.end)),
                Some(')') => {
                    self.bump();
                    break;
                }
                Some('|') => {
                    let Some(before) = items.pop() else {
                        return Err(empty_side(self.pos));
                    };
                    self.bump();
                    match self.peek() {
                        None => return Err(unclosed(self.end)),
                        Some(')' | '|') => return Err(empty_side(self.pos)),
                        Some(_) => {}
                    }
                    let after = self.slot(depth)?;
                    items.push(Slot::Group(vec![vec![before], vec![after]]));
                }
                Some(_) => items.push(self.slot(depth)?),
            }
        }
        if items.is_empty() {
            return Err(FrontError::new(
                ErrorKind::Syntax,
                open,
                "Empty group () not allowed",
            ));
        }
        Ok(items)
    }

    /// One slot item inside `<…>`, and the check after it: a `*`, `+` or `{` that
    /// follows an item is a repetition, refused inside `<…>` (§18.4); one that starts an
    /// item is read as a label by the last arm.
    fn slot(&mut self, depth: usize) -> Result<Slot, FrontError> {
        let at = self.pos;
        let c = self.peek().expect("the caller saw a character");
        let slot = match c {
            '<' => return Err(self.error("No groups allowed inside of groups")),
            '\'' => {
                self.bump();
                Slot::One(Pattern::Is(Sym::Label(self.quoted(at, false)?)))
            }
            '.' => {
                self.bump();
                Slot::One(Pattern::Any)
            }
            'x' => {
                self.bump();
                Slot::One(Pattern::Is(Sym::None))
            }
            '[' => {
                let depth = self.deeper(depth)?;
                self.bump();
                if self.peek() == Some('^') {
                    self.bump();
                    let (_, list) = self.blacklist(at, true)?;
                    Slot::One(Pattern::NotIn(list))
                } else {
                    self.set(depth)?
                }
            }
            '(' => {
                let depth = self.deeper(depth)?;
                self.bump();
                Slot::Group(vec![self.group_items(depth, at)?])
            }
            c => {
                self.bump();
                Slot::One(Pattern::Is(Sym::Label(c.to_string())))
            }
        };
        if matches!(self.peek(), Some('*' | '+' | '{')) {
            return Err(self.error("Repetitions not allowed inside '<...>'"));
        }
        Ok(slot)
    }

    /// A `[…]` inside `<…>` after its `[`, through `]` (§18.4): the alternation of its
    /// slot items. The ways of one symbol make one slot pattern (any of them); each
    /// longer way, through a `( … )` item, stays a way of its own.
    fn set(&mut self, depth: usize) -> Result<Slot, FrontError> {
        let mut one = Vec::new();
        let mut longer = Vec::new();
        loop {
            match self.peek() {
                None => {
                    return Err(FrontError::new(
                        ErrorKind::Syntax,
                        self.end,
                        "Reached end of line looking for ] to end an or list",
                    ))
                }
                Some(']') => {
                    self.bump();
                    break;
                }
                Some(_) => match self.slot(depth)? {
                    Slot::One(p) => one.push(p),
                    Slot::Group(alts) => {
                        for seq in alts {
                            match <[Slot; 1]>::try_from(seq) {
                                Ok([Slot::One(p)]) => one.push(p),
                                Ok([g]) => longer.push(vec![g]),
                                Err(seq) => longer.push(seq),
                            }
                        }
                    }
                },
            }
        }
        if longer.is_empty() {
            return Ok(Slot::One(Pattern::Either(one)));
        }
        let mut alts = Vec::new();
        if !one.is_empty() {
            alts.push(vec![Slot::One(Pattern::Either(one))]);
        }
        alts.extend(longer);
        Ok(Slot::Group(alts))
    }
}

/// Which slot a `[^…]` outside `<…>` negates: that of its last label.
#[derive(Clone, Copy)]
enum Kind {
    Event,
    Scattering,
    Custom,
}
