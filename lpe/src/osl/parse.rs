//! The OSL parser: text to the expanded [`Expr`], following OSL's `lpeparse` grammar
//! (docs/language.md, OSL chapter) with a clean error where OSL crashes or truncates.
//!
//! ```text
//! seq    := (item | '|' item)*          `|` ORs the next item with the previous one
//! item   := atom postfix?               one postfix at most
//! atom   := '.' | letter | "'" label "'" | '(' seq ')' | '[' item* ']'
//!         | '[^' label+ ']' | '<' slot* '>'
//! postfix:= '*' | '+' | '{' n '}' | '{' n ',' '}' | '{' n ',' m '}'
//! slot   := '.' | 'x' | char | "'" label "'" | '[' slot* ']' | '[^' label+ ']'
//!         | '(' (slot | '|' slot)+ ')'     `|` ORs the next slot with the previous one
//! ```
//!
//! Inside `<>` no slot takes a postfix: a `*`, `+` or `{` after a slot is an error, one
//! starting a slot is its label (`<*D>`), as OSL reads them.
//!
//! Every vertex-level atom expands to a whole [`VertexPattern`] with the eater (when it
//! has fewer than five custom items). No whitespace is skipped.

use super::ast::{Expr, Lpe, SymbolPattern, VertexPattern, Warning, WarningKind};
use super::error::{Error, ErrorKind};
use super::symbol::{LabelKind, Registered, Symbol, STOP_LABEL};
use crate::algebra::{self, Algebra, ParseError};
use crate::automata::ir::Repetition;
use crate::limits::Limits;

/// Custom items from which on a vertex pattern gets no eater.
const EATER_MAX_CUSTOM: usize = 5;

/// Most vertex patterns one `<…>` may stand for once the `|` of its groups are spelled
/// out (`<(R|T)(D|G)>` stands for four): a bound on the product, so that a few short
/// groups cannot multiply into a huge alternation.
pub const MAX_GROUP_ALTERNATIVES: usize = 256;

/// Parses `src` with `registered` labels and default [`Limits`].
///
/// ```
/// use lpe::osl::{parse, Registered};
///
/// let lpe = parse("C<RD>[LO]", &Registered::none()).unwrap();
/// assert_eq!(lpe.expr.to_string(), "<C.><RD><L.>|<O.>");
/// let err = parse("C<RD", &Registered::none()).unwrap_err();
/// assert_eq!(err.to_string(), "Reached end of line looking for > to end a group at char 4");
/// ```
pub fn parse(src: &str, registered: &Registered) -> std::result::Result<Lpe, Error> {
    parse_with(src, registered, &Limits::default())
}

/// The mark display files and RenderVars put before an LPE source (`lpe:C<RD>L`). It is
/// the pipeline's, not OSL's: OSL's parser would read `l`, `p`, `e` as custom labels.
pub const SOURCE_MARK: &str = "lpe:";

/// Parses an AOV source as pipelines write it: a leading [`SOURCE_MARK`] is skipped, then
/// it parses as [`parse`] does, error and warning positions counting from `src` as
/// written.
///
/// ```
/// use lpe::osl::{parse, parse_source, Registered};
///
/// let none = Registered::none();
/// assert_eq!(parse_source("lpe:C<RD>L", &none).unwrap(), parse("C<RD>L", &none).unwrap());
/// assert_eq!(parse_source("lpe:C<RD", &none).unwrap_err().pos, 8);
/// ```
pub fn parse_source(src: &str, registered: &Registered) -> std::result::Result<Lpe, Error> {
    let Some(body) = src.strip_prefix(SOURCE_MARK) else {
        return parse(src, registered);
    };
    shifted(parse(body, registered), SOURCE_MARK.len())
}

/// The parse of a text that starts `by` bytes into the source: its error and warning
/// positions moved to count from the source's start.
fn shifted(parsed: std::result::Result<Lpe, Error>, by: usize) -> std::result::Result<Lpe, Error> {
    match parsed {
        Ok(mut lpe) => {
            lpe.shift_warnings(by);
            Ok(lpe)
        }
        Err(e) => Err(Error {
            pos: e.pos + by,
            ..e
        }),
    }
}

/// What a renderer's registration reads before an expression: a prefix it accepts
/// (`unoccluded;`, [`Registered::prefixes`]), taken off and kept in [`Lpe::prefix`], then
/// one of its built-in AOV names ([`Registered::builtins`]), read as that AOV's
/// expression; a `name;` prefix it does not read, or a name that is none of its
/// built-ins, is an error naming what it reads. Plain OSL (no prefixes, no built-ins)
/// reads neither.
///
/// ```
/// use lpe::osl::{parse, Registered};
///
/// let karma = Registered {
///     prefixes: Some(vec!["unoccluded".into()]),
///     builtins: vec![("diffuse_direct".into(), "C<RD>L".into())],
///     ..Registered::none()
/// };
/// assert_eq!(parse("unoccluded;C<RD>L", &karma).unwrap().prefix.as_deref(), Some("unoccluded"));
/// assert_eq!(parse("shadow;C<RD>L", &karma).unwrap_err().pos, 0);
/// assert_eq!(parse("diffuse_direct", &karma).unwrap().expr, parse("C<RD>L", &karma).unwrap().expr);
/// ```
fn parse_renderer(
    src: &str,
    registered: &Registered,
    limits: &Limits,
) -> std::result::Result<Lpe, Error> {
    let mut start = 0;
    let mut prefix = None;
    if let Some(accepted) = &registered.prefixes {
        if let Some(name) = written_prefix(src) {
            if !accepted.iter().any(|a| a == name) {
                return Err(Error {
                    kind: ErrorKind::UnacceptedPrefix {
                        prefix: name.to_string(),
                        accepted: accepted.clone(),
                    },
                    pos: 0,
                });
            }
            prefix = Some(name.to_string());
            start = name.len() + 1;
        }
    }
    let body = &src[start..];
    let mut lpe = match builtin(body, registered) {
        // A built-in's expression is the renderer's: its errors point at the name.
        Builtin::Expression(expr) => {
            parse_expression(expr, registered, limits).map_err(|e| Error { pos: start, ..e })?
        }
        Builtin::Unknown(nearest) => {
            return Err(Error {
                kind: ErrorKind::UnknownBuiltin {
                    name: body.to_string(),
                    nearest,
                },
                pos: start,
            })
        }
        Builtin::NotAName => shifted(parse_expression(body, registered, limits), start)?,
    };
    lpe.prefix = prefix;
    Ok(lpe)
}

/// The name of a leading `name;` (letters and `_`, then `;`).
fn written_prefix(s: &str) -> Option<&str> {
    let (name, _) = s.split_once(';')?;
    let word = !name.is_empty() && name.bytes().all(|b| b.is_ascii_alphabetic() || b == b'_');
    word.then_some(name)
}

/// What a whole source is with respect to the registration's built-in AOVs.
enum Builtin<'a> {
    /// One of them: its expression.
    Expression(&'a str),
    /// A name that is none of them (the nearest ones given).
    Unknown(Vec<String>),
    /// Not a name: an expression to parse.
    NotAName,
}

/// A source is a name when it is a lowercase word (`a`–`z`, digits, `_`) that OSL could
/// not read: it holds a character other than the lowercase items `s` (straight) and `x`
/// (NONE), so `ss` stays an expression. Only a registration with built-ins reads names.
fn builtin<'a>(body: &str, registered: &'a Registered) -> Builtin<'a> {
    if let Some((_, expr)) = registered.builtins.iter().find(|(n, _)| n == body) {
        return Builtin::Expression(expr);
    }
    let word = body.starts_with(|c: char| c.is_ascii_lowercase())
        && body
            .bytes()
            .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_');
    let osl_could_read = body.bytes().all(|b| b == b's' || b == b'x');
    if registered.builtins.is_empty() || !word || osl_could_read {
        return Builtin::NotAName;
    }
    let names = registered.builtins.iter().map(|(n, _)| n.as_str());
    // Three edits: a typo of a built-in (`diffuse_dirct`), not an unrelated word.
    Builtin::Unknown(
        crate::suggest::close(body, names, 3)
            .map(str::to_string)
            .into_iter()
            .collect(),
    )
}

/// Parses with explicit limits (`max_repeat`, `max_depth`, `max_positions` apply),
/// after what the registration's renderer reads before an expression (a prefix, a
/// built-in AOV name: [`Registered::prefixes`], [`Registered::builtins`]).
/// Set algebra over whole expressions (`A - B`, `A & B`, `^A`) is found first by the
/// dialect-independent [`crate::algebra`] layer; each operand is then an OSL expression,
/// its errors and warnings at their bytes in the whole text.
pub fn parse_with(
    src: &str,
    registered: &Registered,
    limits: &Limits,
) -> std::result::Result<Lpe, Error> {
    parse_renderer(src, registered, limits)
}

/// An expression (set algebra included), after any prefix or built-in name.
fn parse_expression(
    src: &str,
    registered: &Registered,
    limits: &Limits,
) -> std::result::Result<Lpe, Error> {
    if src.is_empty() {
        return Err(Error {
            kind: ErrorKind::Empty,
            pos: 0,
        });
    }
    let whole = 0..src.len();
    let mut warnings = Vec::new();
    let tree = if algebra::has_algebra(src, whole.clone()) {
        algebra::parse(src, whole, limits.max_depth, &mut |span| {
            parse_operand(src, span, registered, limits, &mut warnings).map(Algebra::Leaf)
        })
        .map_err(|e| match e {
            ParseError::Operand(e) => e,
            ParseError::Algebra(e) => Error {
                pos: e.span().start,
                kind: ErrorKind::Algebra(e),
            },
        })?
    } else {
        Algebra::Leaf(parse_operand(
            src,
            whole,
            registered,
            limits,
            &mut warnings,
        )?)
    };
    let lpe = Lpe {
        warnings,
        ..Lpe::from_algebra(tree)
    };
    let positions = lpe.positions();
    if positions > limits.max_positions as u64 {
        return Err(Error {
            kind: ErrorKind::TooManyPositions {
                positions,
                max: limits.max_positions,
            },
            pos: 0,
        });
    }
    Ok(lpe)
}

/// One expression, `src[span]`: the parser reads the text up to the span's end from its
/// start, so positions (and "end of line") are those of the whole text.
fn parse_operand(
    src: &str,
    span: std::ops::Range<usize>,
    registered: &Registered,
    limits: &Limits,
    warnings: &mut Vec<Warning>,
) -> std::result::Result<Expr, Error> {
    let mut p = Parser {
        src: &src[..span.end],
        pos: span.start,
        reg: registered,
        eater: registered.basic_labels(),
        limits,
        depth: 0,
        warnings: Vec::new(),
    };
    let expr = match p.seq(false)? {
        // A whole expression of `{0}` items: OSL builds a rule with no states.
        Expr::Empty => return Err(p.err(ErrorKind::ZeroRepeat, span.start)),
        e => e,
    };
    warnings.append(&mut p.warnings);
    Ok(expr)
}

/// Adds an alternative, flattening nested alternations (`(a|b)|c`, `[[ab]c]`): the
/// same language, and one tree per language for printing to reproduce.
fn push_alt(alts: &mut Vec<Expr>, e: Expr) {
    match e {
        Expr::Alt(es) => alts.extend(es),
        e => alts.push(e),
    }
}

struct Parser<'a> {
    src: &'a str,
    pos: usize,
    reg: &'a Registered,
    eater: Vec<Symbol>,
    limits: &'a Limits,
    depth: usize,
    warnings: Vec<Warning>,
}

type Result<T> = std::result::Result<T, Error>;

/// What a label in a `[^...]` list is, for choosing the negated slot.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    Event,
    Scattering,
    Quoted,
}

impl<'a> Parser<'a> {
    fn err(&self, kind: ErrorKind, pos: usize) -> Error {
        Error { kind, pos }
    }

    fn head(&self) -> Option<char> {
        self.src[self.pos..].chars().next()
    }

    fn bump(&mut self) -> Option<char> {
        let c = self.head()?;
        self.pos += c.len_utf8();
        Some(c)
    }

    fn enter(&mut self) -> Result<()> {
        self.depth += 1;
        if self.depth > self.limits.max_depth {
            return Err(self.err(
                ErrorKind::TooDeep {
                    max: self.limits.max_depth,
                },
                self.pos,
            ));
        }
        Ok(())
    }

    fn vertex(&self, symbols: Vec<SymbolPattern>, customs: usize) -> Expr {
        Expr::Vertex(VertexPattern {
            symbols,
            eater: (customs < EATER_MAX_CUSTOM).then(|| self.eater.clone()),
        })
    }

    /// A sequence, up to the end of the text or (inside a group) its `)`.
    fn seq(&mut self, in_paren: bool) -> Result<Expr> {
        let open = self.pos.saturating_sub(1);
        let mut items: Vec<(Expr, usize)> = Vec::new();
        loop {
            let start = self.pos;
            match self.head() {
                None if in_paren => return Err(self.err(ErrorKind::UnclosedParen, self.src.len())),
                None => break,
                Some(')') if in_paren => {
                    self.pos += 1;
                    break;
                }
                Some('|') => {
                    let Some((prev, prev_start)) = items.pop() else {
                        return Err(self.err(ErrorKind::NoLeftExpression, start));
                    };
                    self.pos += 1;
                    let next_start = self.pos;
                    let next = self.item()?;
                    for (e, at) in [(&prev, prev_start), (&next, next_start)] {
                        if *e == Expr::Empty {
                            return Err(self.err(ErrorKind::ZeroRepeat, at));
                        }
                    }
                    let mut alts = Vec::new();
                    push_alt(&mut alts, prev);
                    push_alt(&mut alts, next);
                    items.push((Expr::Alt(alts), prev_start));
                }
                Some(_) => {
                    let e = self.item()?;
                    items.push((e, start));
                }
            }
        }
        if items.is_empty() {
            return Err(self.err(ErrorKind::EmptyGroup, open));
        }
        // OSL chains fragments from the first non-empty one: leading `{0}` items drop
        // out; a later one would be chained to as a null state.
        let lead = items.iter().take_while(|(e, _)| *e == Expr::Empty).count();
        if lead == items.len() {
            return Ok(Expr::Empty);
        }
        let mut parts = Vec::with_capacity(items.len() - lead);
        for (e, at) in items.into_iter().skip(lead) {
            if e == Expr::Empty {
                return Err(self.err(ErrorKind::ZeroRepeat, at));
            }
            parts.push(e);
        }
        Ok(if parts.len() == 1 {
            parts.pop().expect("one part")
        } else {
            Expr::Concat(parts)
        })
    }

    /// One atom and its postfix. A `{0}` item is returned as [`Expr::Empty`].
    fn item(&mut self) -> Result<Expr> {
        let start = self.pos;
        let atom = match self.head() {
            None => return Err(self.err(ErrorKind::UnrecognizedBasicLabel(String::new()), start)),
            Some('.') => {
                self.pos += 1;
                self.vertex(vec![SymbolPattern::Any, SymbolPattern::Any], 0)
            }
            Some('(') => {
                self.enter()?;
                self.pos += 1;
                let e = self.seq(true)?;
                self.depth -= 1;
                e
            }
            Some('[') => {
                self.enter()?;
                self.pos += 1;
                let e = if self.head() == Some('^') {
                    self.pos += 1;
                    self.negation_item(start)?
                } else {
                    self.or_list()?
                };
                self.depth -= 1;
                e
            }
            Some('<') => {
                self.enter()?;
                let e = self.group()?;
                self.depth -= 1;
                e
            }
            Some('\'') => {
                // OSL overwrites the unclosed-quote message here with an empty label.
                let l = self.literal().map_err(|e| match e.kind {
                    ErrorKind::UnclosedLiteral => {
                        self.err(ErrorKind::UnrecognizedBasicLabel(String::new()), e.pos)
                    }
                    _ => e,
                })?;
                self.vertex(
                    vec![
                        SymbolPattern::Any,
                        SymbolPattern::Any,
                        SymbolPattern::One(l),
                    ],
                    1,
                )
            }
            Some(c) => {
                let slots = match self.reg.kind_of(c.encode_utf8(&mut [0; 4])) {
                    Some(LabelKind::Event) => {
                        vec![SymbolPattern::One(Symbol::label(c)), SymbolPattern::Any]
                    }
                    Some(LabelKind::Scattering) => {
                        vec![SymbolPattern::Any, SymbolPattern::One(Symbol::label(c))]
                    }
                    None => {
                        // `x` is NONE, whose name is empty.
                        let shown = if c == 'x' {
                            String::new()
                        } else {
                            c.to_string()
                        };
                        return Err(self.err(ErrorKind::UnrecognizedBasicLabel(shown), start));
                    }
                };
                self.pos += c.len_utf8();
                self.vertex(slots, 0)
            }
        };
        self.postfix(atom)
    }

    fn postfix(&mut self, atom: Expr) -> Result<Expr> {
        let start = self.pos;
        let rep = match self.head() {
            Some('*') => {
                self.pos += 1;
                Repetition::STAR
            }
            Some('+') => {
                self.pos += 1;
                Repetition::PLUS
            }
            Some('{') => self.range()?,
            _ => return Ok(atom),
        };
        if rep.max == Some(0) {
            return Ok(Expr::Empty);
        }
        if atom == Expr::Empty {
            return Err(self.err(ErrorKind::ZeroRepeat, start));
        }
        Ok(Expr::Repeat(Box::new(atom), rep))
    }

    /// `{n}`, `{n,}`, `{n,m}`; `{m,n}` with `m > n` is `{m}` plus a warning.
    fn range(&mut self) -> Result<Repetition> {
        let open = self.pos;
        self.pos += 1;
        let min = self
            .number()?
            .ok_or_else(|| self.err(ErrorKind::BadRange, self.pos))?;
        let max = if self.head() == Some(',') {
            self.pos += 1;
            self.number()?
        } else {
            Some(min)
        };
        if self.head() != Some('}') {
            return Err(self.err(ErrorKind::BadRange, self.pos));
        }
        self.pos += 1;
        Ok(match max {
            Some(m) if m < min => {
                self.warnings.push(Warning {
                    kind: WarningKind::ReversedRange { min, max: m },
                    pos: open,
                });
                Repetition {
                    min,
                    max: Some(min),
                }
            }
            max => Repetition { min, max },
        })
    }

    fn number(&mut self) -> Result<Option<u32>> {
        let start = self.pos;
        let digits = self.src[start..]
            .bytes()
            .take_while(u8::is_ascii_digit)
            .count();
        if digits == 0 {
            return Ok(None);
        }
        self.pos += digits;
        let max = self.limits.max_repeat;
        match self.src[start..self.pos].parse::<u32>() {
            Ok(n) if n <= max => Ok(Some(n)),
            _ => Err(self.err(ErrorKind::RepeatTooLarge { max }, start)),
        }
    }

    /// `[...]` outside `<>`: an alternation of items; `[]` matches nothing.
    fn or_list(&mut self) -> Result<Expr> {
        let mut alts = Vec::new();
        loop {
            match self.head() {
                None => return Err(self.err(ErrorKind::UnclosedOrList, self.src.len())),
                Some(']') => {
                    self.pos += 1;
                    break;
                }
                Some(_) => {
                    let at = self.pos;
                    let e = self.item()?;
                    if e == Expr::Empty {
                        return Err(self.err(ErrorKind::ZeroRepeat, at));
                    }
                    push_alt(&mut alts, e);
                }
            }
        }
        Ok(match alts.len() {
            0 => Expr::Nothing,
            1 => alts.pop().expect("one alternative"),
            _ => Expr::Alt(alts),
        })
    }

    /// The labels of a `[^...]` (after the `^`) and the kind of each.
    fn negated_labels(&mut self) -> Result<Vec<(Symbol, Kind)>> {
        let mut out = Vec::new();
        loop {
            match self.head() {
                None => return Err(self.err(ErrorKind::UnclosedNegativeOrList, self.src.len())),
                Some(']') => {
                    if out.is_empty() {
                        return Err(self.err(ErrorKind::EmptyNegation, self.pos));
                    }
                    self.pos += 1;
                    return Ok(out);
                }
                Some('\'') => out.push((self.literal()?, Kind::Quoted)),
                Some(c) => {
                    let kind = match self.reg.kind_of(c.encode_utf8(&mut [0; 4])) {
                        Some(LabelKind::Event) => Kind::Event,
                        Some(LabelKind::Scattering) => Kind::Scattering,
                        None => return Err(self.err(ErrorKind::UnrecognizedLabel, self.pos)),
                    };
                    self.pos += c.len_utf8();
                    out.push((Symbol::label(c), kind));
                }
            }
        }
    }

    /// `[^...]` outside `<>`: one negated slot, the slot of the last label listed.
    fn negation_item(&mut self, open: usize) -> Result<Expr> {
        let labels = self.negated_labels()?;
        let last = labels.last().expect("non-empty").1;
        if labels.iter().any(|(_, k)| *k != last) {
            self.warnings.push(Warning {
                kind: WarningKind::MixedNegation,
                pos: open,
            });
        }
        let not_in = SymbolPattern::NotIn(labels.into_iter().map(|(s, _)| s).collect());
        Ok(match last {
            Kind::Event => self.vertex(vec![not_in, SymbolPattern::Any], 0),
            Kind::Scattering => self.vertex(vec![SymbolPattern::Any, not_in], 0),
            Kind::Quoted => self.vertex(vec![SymbolPattern::Any, SymbolPattern::Any, not_in], 1),
        })
    }

    /// `'...'` at the quote: any characters but `'`, no escapes.
    fn literal(&mut self) -> Result<Symbol> {
        let start = self.pos + 1;
        let Some(len) = self.src[start..].find('\'') else {
            return Err(self.err(ErrorKind::UnclosedLiteral, self.src.len()));
        };
        let label = &self.src[start..start + len];
        if label == STOP_LABEL {
            return Err(self.err(ErrorKind::StopLabel, self.pos));
        }
        self.pos = start + len + 1;
        Ok(Symbol::label(label))
    }

    /// `<...>` at the `<`: items fill the event slot, the scattering slot, then custom
    /// slots; missing slots are `.`. A `( … )` item is a sub-expression over the symbols
    /// (OSL parses it as one): with `|` in it, the `<…>` stands for one vertex pattern per
    /// way through its items, an alternation.
    fn group(&mut self) -> Result<Expr> {
        let at = self.pos;
        self.pos += 1;
        // Per item, its alternative symbol sequences (one for a plain slot); a count past
        // the limit is reported at the group's `<`.
        let mut items: Vec<(usize, Vec<Vec<SymbolPattern>>)> = Vec::new();
        loop {
            match self.head() {
                None => return Err(self.err(ErrorKind::UnclosedGroup, self.src.len())),
                Some('>') => {
                    self.pos += 1;
                    break;
                }
                Some(_) => items.push((at, self.slot_item()?)),
            }
        }
        let customs = items.len().saturating_sub(2);
        while items.len() < 2 {
            items.push((at, vec![vec![SymbolPattern::Any]]));
        }
        let ways = self.product(&items)?;
        let mut vertices: Vec<Expr> = ways.into_iter().map(|w| self.vertex(w, customs)).collect();
        Ok(if vertices.len() == 1 {
            vertices.pop().expect("one")
        } else {
            Expr::Alt(vertices)
        })
    }

    /// Every sequence made of one alternative of each item, in order (the items'
    /// product, the last item's alternative varying fastest), within
    /// [`MAX_GROUP_ALTERNATIVES`]: past it, an error at the position paired with the item
    /// that took the count past it. Each sequence is built once, so the time is the size
    /// of the product (at most the limit times the items' text), where extending every
    /// partial sequence item by item took that size times the number of items.
    fn product(
        &self,
        items: &[(usize, Vec<Vec<SymbolPattern>>)],
    ) -> Result<Vec<Vec<SymbolPattern>>> {
        let mut count = 1usize;
        for (at, alts) in items {
            count = count.saturating_mul(alts.len());
            if count > MAX_GROUP_ALTERNATIVES {
                return Err(self.err(
                    ErrorKind::TooManyAlternatives {
                        max: MAX_GROUP_ALTERNATIVES,
                    },
                    *at,
                ));
            }
        }
        let mut ways = Vec::with_capacity(count);
        if count == 0 {
            // An item with no alternatives leaves none. The parser's items all have one
            // at least (`[]` is one pattern, the empty set), so this only keeps the
            // indexing below from reading an empty item.
            return Ok(ways);
        }
        let longest: usize = items
            .iter()
            .map(|(_, alts)| alts.iter().map(Vec::len).max().unwrap_or(0))
            .sum();
        // Which alternative of each item the next sequence takes.
        let mut choice = vec![0usize; items.len()];
        loop {
            let mut way = Vec::with_capacity(longest);
            for ((_, alts), &c) in items.iter().zip(&choice) {
                way.extend_from_slice(&alts[c]);
            }
            ways.push(way);
            let Some(k) = (0..items.len())
                .rev()
                .find(|&k| choice[k] + 1 < items[k].1.len())
            else {
                return Ok(ways);
            };
            choice[k] += 1;
            choice[k + 1..].fill(0);
        }
    }

    /// `( ... )` inside `<>`, after the `(`, through its `)`: a sequence of slot items,
    /// its alternative symbol sequences. `|` binds tighter than the sequence, as
    /// everywhere in OSL: it takes the one item before it and the one after
    /// (`(RD|T)` is `R` then `D` or `T`). An empty side is an error.
    fn slot_alternatives(&mut self, open: usize) -> Result<Vec<Vec<SymbolPattern>>> {
        // Per item, with its start, its alternative symbol sequences.
        let mut items: Vec<(usize, Vec<Vec<SymbolPattern>>)> = Vec::new();
        loop {
            let at = self.pos;
            match self.head() {
                None => return Err(self.err(ErrorKind::UnclosedParen, self.src.len())),
                Some(')') => {
                    if items.is_empty() {
                        return Err(self.err(ErrorKind::EmptyGroup, open));
                    }
                    self.pos += 1;
                    break;
                }
                Some('|') => {
                    let Some((prev_at, mut alts)) = items.pop() else {
                        return Err(self.err(ErrorKind::EmptyAlternative, at));
                    };
                    self.pos += 1;
                    match self.head() {
                        None => return Err(self.err(ErrorKind::UnclosedParen, self.src.len())),
                        Some(')' | '|') => {
                            return Err(self.err(ErrorKind::EmptyAlternative, self.pos));
                        }
                        Some(_) => {}
                    }
                    alts.extend(self.slot_item()?);
                    items.push((prev_at, alts));
                }
                Some(_) => {
                    let alts = self.slot_item()?;
                    items.push((at, alts));
                }
            }
        }
        self.product(&items)
    }

    /// One item inside `<>` (a slot, or an item of a `( … )` or `[ … ]` there): its
    /// alternative symbol sequences (one sequence of one pattern for a plain slot). As in
    /// OSL, which reads a postfix after every item and refuses it inside `<>`, a `*`, `+`
    /// or `{` right after an item is an error, while at an item's start it is a label.
    fn slot_item(&mut self) -> Result<Vec<Vec<SymbolPattern>>> {
        let open = self.pos;
        let alts = match (self.head(), self.src[open..].chars().nth(1)) {
            (Some('('), _) => {
                self.enter()?;
                self.pos += 1;
                let alts = self.slot_alternatives(open)?;
                self.depth -= 1;
                alts
            }
            (Some('['), next) if next != Some('^') => {
                self.enter()?;
                self.pos += 1;
                let alts = self.set_alternatives()?;
                self.depth -= 1;
                alts
            }
            _ => vec![vec![self.slot()?]],
        };
        if let Some('*' | '+' | '{') = self.head() {
            return Err(self.err(ErrorKind::RepetitionInGroup, self.pos));
        }
        Ok(alts)
    }

    /// One slot pattern inside `<>`: `.`, `x`, a quoted or plain label, a `[^…]`.
    fn slot(&mut self) -> Result<SymbolPattern> {
        let at = self.pos;
        match self.head() {
            Some('<') => Err(self.err(ErrorKind::NestedGroup, at)),
            Some('.') => {
                self.pos += 1;
                Ok(SymbolPattern::Any)
            }
            Some('x') => {
                self.pos += 1;
                Ok(SymbolPattern::One(Symbol::None))
            }
            Some('\'') => Ok(SymbolPattern::One(self.literal()?)),
            Some('[') => {
                // `slot_item` reads a plain `[…]`: here it is `[^…]`.
                self.pos += 2;
                let labels = self.negated_labels()?;
                Ok(SymbolPattern::NotIn(
                    labels.into_iter().map(|(s, _)| s).collect(),
                ))
            }
            _ => {
                let c = self.bump().expect("not at the end");
                Ok(SymbolPattern::One(Symbol::label(c)))
            }
        }
    }

    /// `[...]` inside `<>`, after the `[`: the alternation of its items, each read as a
    /// slot item (OSL's or-list parses items there as everywhere: `x` is NONE, `.` any
    /// symbol, `( … )` a sequence, `[ … ]` a nested list). Its one-symbol alternatives
    /// join into one pattern (so `[RT]` stays one vertex pattern); `[]` is the empty set.
    fn set_alternatives(&mut self) -> Result<Vec<Vec<SymbolPattern>>> {
        let mut one = Vec::new();
        let mut longer = Vec::new();
        loop {
            match self.head() {
                None => return Err(self.err(ErrorKind::UnclosedOrList, self.src.len())),
                Some(']') => {
                    self.pos += 1;
                    break;
                }
                Some(_) => {
                    for mut alt in self.slot_item()? {
                        if alt.len() == 1 {
                            one.push(alt.pop().expect("one pattern"));
                        } else {
                            longer.push(alt);
                        }
                    }
                }
            }
        }
        let mut alts = Vec::with_capacity(longer.len() + 1);
        if !one.is_empty() || longer.is_empty() {
            alts.push(vec![SymbolPattern::any_of(one)]);
        }
        alts.extend(longer);
        Ok(alts)
    }
}
