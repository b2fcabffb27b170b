//! Recursive descent over the tokens of one expression body:
//!
//! ```text
//! seq  := alt+
//! alt  := rep ('|' rep)*
//! rep  := atom quant?
//! atom := '(' seq ')' | class | triple | type | event | label | '.'
//! ```

use std::ops::Range;

use super::error::{Error, ErrorKind};
use super::lexer::{Tok, Token};
use super::Limits;
use crate::renderman::ast::{
    Atom, EventPattern, EventPos, Expr, Item, LabelPos, Repetition, Triple, TypePos,
};

pub(crate) struct ExprParser<'a> {
    source: &'a str,
    tokens: Vec<Token>,
    pos: usize,
    limits: &'a Limits,
    depth: usize,
    /// End of the body being parsed: where "unexpected end" errors point.
    end: usize,
}

type Result<T> = std::result::Result<T, Error>;

impl<'a> ExprParser<'a> {
    pub(crate) fn new(source: &'a str, tokens: Vec<Token>, limits: &'a Limits) -> Self {
        ExprParser {
            source,
            tokens,
            pos: 0,
            limits,
            depth: 0,
            end: source.len(),
        }
    }

    /// Parses the whole token stream as one expression.
    pub(crate) fn parse(mut self, body: Range<usize>) -> Result<Expr> {
        self.end = body.end;
        if self.tokens.is_empty() {
            return Err(self.err(ErrorKind::Empty, body, "empty expression"));
        }
        let e = self.seq()?;
        if let Some(t) = self.peek_token() {
            let span = t.span.clone();
            let msg = if t.tok == Tok::RParen {
                "unmatched `)`".to_string()
            } else {
                format!("unexpected {}", t.tok.describe())
            };
            return Err(self.err(ErrorKind::Syntax, span, msg));
        }
        self.check_positions(&e, body)?;
        Ok(e)
    }

    fn err(&self, kind: ErrorKind, span: Range<usize>, msg: impl Into<String>) -> Error {
        Error::new(kind, span, msg, self.source)
    }

    fn peek(&self) -> Option<&Tok> {
        self.tokens.get(self.pos).map(|t| &t.tok)
    }

    fn peek_token(&self) -> Option<&Token> {
        self.tokens.get(self.pos)
    }

    fn bump(&mut self) -> Token {
        let t = self.tokens[self.pos].clone();
        self.pos += 1;
        t
    }

    /// Span of the current token, or an empty span at the end of the source.
    fn here(&self) -> Range<usize> {
        self.peek_token()
            .map_or(self.end..self.end, |t| t.span.clone())
    }

    fn expect(&mut self, want: Tok, what: &str) -> Result<Token> {
        match self.peek() {
            Some(t) if *t == want => Ok(self.bump()),
            Some(t) => {
                let msg = format!("expected {what}, found {}", t.describe());
                Err(self.err(ErrorKind::Syntax, self.here(), msg))
            }
            None => Err(self.err(
                ErrorKind::Syntax,
                self.here(),
                format!("expected {what}, found end of expression"),
            )),
        }
    }

    fn enter(&mut self, span: Range<usize>) -> Result<()> {
        self.depth += 1;
        if self.depth > self.limits.max_depth {
            return Err(self.err(
                ErrorKind::Limit,
                span,
                format!("nesting deeper than the limit of {}", self.limits.max_depth),
            ));
        }
        Ok(())
    }

    fn check_positions(&self, e: &Expr, span: Range<usize>) -> Result<()> {
        let n = e.positions();
        if n > self.limits.max_positions as u64 {
            return Err(self.err(
                ErrorKind::Limit,
                span,
                format!(
                    "expression unrolls to {n} positions, over the limit of {}",
                    self.limits.max_positions
                ),
            ));
        }
        Ok(())
    }

    fn at_seq_end(&self) -> bool {
        matches!(self.peek(), None | Some(Tok::RParen))
    }

    fn seq(&mut self) -> Result<Expr> {
        let mut parts = vec![self.alt()?];
        while !self.at_seq_end() {
            parts.push(self.alt()?);
        }
        Ok(Expr::concat(parts))
    }

    fn alt(&mut self) -> Result<Expr> {
        let mut alts = vec![self.rep()?];
        while self.peek() == Some(&Tok::Pipe) {
            let bar = self.bump();
            if matches!(self.peek(), None | Some(Tok::RParen) | Some(Tok::Pipe)) {
                return Err(self.err(
                    ErrorKind::Syntax,
                    bar.span,
                    "`|` needs an alternative on both sides",
                ));
            }
            alts.push(self.rep()?);
        }
        Ok(Expr::alt(alts))
    }

    fn rep(&mut self) -> Result<Expr> {
        let atom_start = self.here().start;
        let e = self.atom()?;
        let Some((r, span)) = self.quantifier()? else {
            return Ok(e);
        };
        if let Some((_, second)) = self.quantifier()? {
            let shown = &self.source[atom_start..second.end];
            return Err(self
                .err(
                    ErrorKind::Quantifier,
                    second,
                    format!("a second quantifier on `{shown}`: one quantifier per atom"),
                )
                .with_help("group to repeat a repetition: `(x*)+`"));
        }
        let e = Expr::Repeat(Box::new(e), r);
        self.check_positions(&e, atom_start..span.end)?;
        Ok(e)
    }

    /// Parses `* + ? {n} {n,} {n,m}` if one is next.
    fn quantifier(&mut self) -> Result<Option<(Repetition, Range<usize>)>> {
        let t = match self.peek() {
            Some(Tok::Star | Tok::Plus | Tok::Question | Tok::LBrace) => self.bump(),
            _ => return Ok(None),
        };
        let r = match t.tok {
            Tok::Star => Repetition::STAR,
            Tok::Plus => Repetition::PLUS,
            Tok::Question => Repetition::OPTIONAL,
            _ => return self.braces(t.span).map(Some),
        };
        Ok(Some((r, t.span)))
    }

    fn braces(&mut self, open: Range<usize>) -> Result<(Repetition, Range<usize>)> {
        let start = open.start;
        let min = match self.peek() {
            Some(Tok::Number(_)) => Some(self.count()?),
            _ => None,
        };
        let mut max = min.map(Some);
        if self.peek() == Some(&Tok::Comma) {
            self.bump();
            max = match self.peek() {
                Some(Tok::Number(_)) => Some(Some(self.count()?)),
                _ => Some(None),
            };
        }
        let close = match self.peek() {
            Some(Tok::RBrace) => self.bump().span,
            _ => {
                let (found, at) = match self.peek_token() {
                    Some(t) => (t.tok.describe(), t.span.clone()),
                    None => ("end of expression".into(), self.here()),
                };
                return Err(self.err(
                    ErrorKind::Quantifier,
                    at,
                    format!("expected a number, `,` or `}}` in `{{n,m}}`, found {found}"),
                ));
            }
        };
        let span = start..close.end;
        let Some(min) = min else {
            let help = match max {
                Some(Some(m)) => format!("write `{{0,{m}}}`"),
                _ => "write `{n}`, `{n,}` or `{n,m}`".into(),
            };
            let msg = if max.is_some() {
                "a repetition needs a lower bound"
            } else {
                "empty repetition `{}`"
            };
            return Err(self.err(ErrorKind::Quantifier, span, msg).with_help(help));
        };
        // `{n}` (no comma) is `{n,n}`.
        let max = max.unwrap_or(Some(min));
        if let Some(m) = max {
            if min > m {
                return Err(self.err(
                    ErrorKind::Quantifier,
                    span,
                    format!("`{{{min},{m}}}`: the lower bound is above the upper bound"),
                ));
            }
        }
        Ok((Repetition { min, max }, span))
    }

    /// A repetition count, checked against the limit.
    fn count(&mut self) -> Result<u32> {
        let t = self.bump();
        let Tok::Number(n) = t.tok else {
            unreachable!("count() is called on a number token")
        };
        if n > u64::from(self.limits.max_repeat) {
            let shown = &self.source[t.span.clone()];
            return Err(self.err(
                ErrorKind::Limit,
                t.span,
                format!(
                    "repetition count {shown} is over the limit of {}",
                    self.limits.max_repeat
                ),
            ));
        }
        Ok(n as u32)
    }

    fn atom(&mut self) -> Result<Expr> {
        let Some(t) = self.peek_token().cloned() else {
            return Err(self.err(
                ErrorKind::Syntax,
                self.here(),
                "expected an event, found end of expression",
            ));
        };
        match t.tok {
            Tok::LParen => {
                self.bump();
                self.enter(t.span.clone())?;
                if self.peek() == Some(&Tok::RParen) {
                    let close = self.bump().span;
                    return Err(self.err(
                        ErrorKind::Empty,
                        t.span.start..close.end,
                        "empty group `()`",
                    ));
                }
                let e = self.seq()?;
                if self.peek() != Some(&Tok::RParen) {
                    return Err(self.err(ErrorKind::Syntax, t.span, "unclosed `(`"));
                }
                self.bump();
                self.depth -= 1;
                Ok(e)
            }
            Tok::LBracket => {
                self.bump();
                self.enter(t.span.clone())?;
                let negated = self.eat(Tok::Caret);
                let mut items = Vec::new();
                while !matches!(self.peek(), Some(Tok::RBracket) | None) {
                    items.push(self.class_item()?);
                }
                let close = self.expect(Tok::RBracket, "`]`")?;
                self.depth -= 1;
                if items.is_empty() {
                    return Err(self.err(
                        ErrorKind::Empty,
                        t.span.start..close.span.end,
                        "empty class: `[]` matches nothing",
                    ));
                }
                Ok(Expr::Atom(Atom::Class { negated, items }))
            }
            Tok::Star | Tok::Plus | Tok::Question | Tok::LBrace => Err(self.err(
                ErrorKind::Quantifier,
                t.span,
                format!("quantifier {} has nothing to repeat", t.tok.describe()),
            )),
            Tok::Pipe => Err(self.err(
                ErrorKind::Syntax,
                t.span,
                "`|` needs an alternative on both sides",
            )),
            Tok::RParen => Err(self.err(ErrorKind::Syntax, t.span, "unmatched `)`")),
            _ => Ok(Expr::Atom(Atom::Item(self.item()?))),
        }
    }

    fn eat(&mut self, want: Tok) -> bool {
        if self.peek() == Some(&want) {
            self.bump();
            true
        } else {
            false
        }
    }

    fn class_item(&mut self) -> Result<Item> {
        let t = self.peek_token().cloned().expect("caller checked");
        match t.tok {
            Tok::LParen | Tok::LBracket => Err(self.err(
                ErrorKind::Syntax,
                t.span,
                format!(
                    "{} inside `[...]`: a class holds events, labels, triples and `.`",
                    t.tok.describe()
                ),
            )),
            Tok::Star | Tok::Plus | Tok::Question | Tok::LBrace => Err(self.err(
                ErrorKind::Quantifier,
                t.span,
                "quantifier inside `[...]`: put it after the `]`",
            )),
            _ => self.item(),
        }
    }

    /// One item: a type or event letter, `.`, a label or a triple.
    fn item(&mut self) -> Result<Item> {
        let t = self.bump();
        Ok(match t.tok {
            Tok::Type(ty) => Item::Type(ty),
            Tok::Event(kind, lobe) => Item::Event(EventPattern { kind, lobe }),
            Tok::Dot => Item::Any,
            Tok::Label(l) => Item::Label(l),
            Tok::LAngle => Item::Triple(self.triple(t.span)?),
            other => {
                return Err(self.err(
                    ErrorKind::Syntax,
                    t.span,
                    format!("unexpected {}", other.describe()),
                ))
            }
        })
    }

    fn triple(&mut self, open: Range<usize>) -> Result<Triple> {
        let ty = self.type_pos(&open)?;
        let event = self.event_pos(&open)?;
        let label = self.label_pos(&open)?;
        match self.peek_token().cloned() {
            Some(Token {
                tok: Tok::RAngle, ..
            }) => {
                self.bump();
                Ok(Triple { ty, event, label })
            }
            Some(t) => Err(self.triple_stray(&open, t)),
            None => Err(self.err(ErrorKind::Syntax, open, "unclosed `<`")),
        }
    }

    /// An error for a token that cannot stand where it is inside `<...>`.
    fn triple_stray(&self, open: &Range<usize>, t: Token) -> Error {
        match t.tok {
            Tok::Star | Tok::Plus | Tok::Question | Tok::LBrace => self
                .err(
                    ErrorKind::Quantifier,
                    t.span,
                    "quantifier inside `<...>`: a triple is one vertex",
                )
                .with_help("put the quantifier after the `>`"),
            Tok::Type(ty) => self.err(
                ErrorKind::TriplePosition,
                t.span,
                format!("`{ty}` is a vertex type; in `<type event label>` the type comes first"),
            ),
            Tok::Event(..) => self.err(
                ErrorKind::TriplePosition,
                t.span,
                format!(
                    "{} in the label position of `<type event label>`",
                    t.tok.describe()
                ),
            ),
            _ => self.err(
                ErrorKind::Syntax,
                open.start..t.span.end,
                format!(
                    "expected `>` to close the triple, found {}",
                    t.tok.describe()
                ),
            ),
        }
    }

    /// A class inside a triple position, at its `[`: `^`? then items accepted by `take`
    /// up to `]`. `what` names the position and `holds` what it may hold, for errors.
    fn position_class<T>(
        &mut self,
        open: Range<usize>,
        what: &str,
        holds: &str,
        take: impl Fn(&Tok) -> Option<T>,
    ) -> Result<(bool, Vec<T>)> {
        self.bump();
        let negated = self.eat(Tok::Caret);
        let mut items = Vec::new();
        loop {
            let Some(t) = self.peek_token().cloned() else {
                return Err(self.err(ErrorKind::Syntax, open, "unclosed `[`"));
            };
            if t.tok == Tok::RBracket {
                let close = self.bump().span;
                if items.is_empty() {
                    return Err(self.err(
                        ErrorKind::Empty,
                        open.start..close.end,
                        format!("empty {what} class `[]`"),
                    ));
                }
                return Ok((negated, items));
            }
            let Some(item) = take(&t.tok) else {
                let e = self.err(
                    ErrorKind::TriplePosition,
                    t.span,
                    format!(
                        "{} in {} {what} class: the {what} position holds {holds}",
                        t.tok.describe(),
                        if what.starts_with('e') { "an" } else { "a" },
                    ),
                );
                return Err(if matches!(t.tok, Tok::Label(_)) {
                    e.with_help("labels go in the third position: `<R.['a' 'b']>`")
                } else {
                    e
                });
            };
            self.bump();
            items.push(item);
        }
    }

    /// Text of the triple from `<` to the next `>` (or the end), for suggestions.
    fn triple_text(&self, open: &Range<usize>) -> &str {
        let rest = &self.source[open.start..];
        rest.find('>').map_or(rest, |i| &rest[..=i])
    }

    fn type_pos(&mut self, open: &Range<usize>) -> Result<TypePos> {
        let Some(t) = self.peek_token().cloned() else {
            return Err(self.err(ErrorKind::Syntax, open.clone(), "unclosed `<`"));
        };
        match t.tok {
            Tok::Type(ty) => {
                self.bump();
                Ok(TypePos::One(ty))
            }
            Tok::Dot => {
                self.bump();
                Ok(TypePos::Any)
            }
            Tok::LBracket => {
                let (negated, types) =
                    self.position_class(t.span, "type", "C R T L O", |t| match t {
                        Tok::Type(ty) => Some(*ty),
                        _ => None,
                    })?;
                Ok(TypePos::Class { negated, types })
            }
            Tok::RAngle => Err(self.err(
                ErrorKind::Empty,
                open.start..t.span.end,
                "empty triple `<>`",
            )),
            Tok::Event(kind, _) => {
                let mut e = self.err(
                    ErrorKind::TriplePosition,
                    t.span.clone(),
                    format!(
                        "{} is an event, but the first position of `<type event label>` is the vertex type",
                        t.tok.describe()
                    ),
                );
                // `<DR>` -> `<RD>`; `<D>` -> `<.D>`.
                let ev = &self.source[t.span.clone()];
                e = match self.tokens.get(self.pos + 1).map(|n| &n.tok) {
                    Some(Tok::Type(ty)) => e.with_help(format!("write `<{ty}{ev}>`")),
                    _ => e.with_help(format!(
                        "write `<.{ev}>` for any R/T vertex with a {} event",
                        kind.letter()
                    )),
                };
                Err(e)
            }
            Tok::Label(l) => Err(self
                .err(
                    ErrorKind::TriplePosition,
                    t.span,
                    "a label in the type position of `<type event label>`",
                )
                .with_help(format!("write `<..'{l}'>`"))),
            _ => Err(self.triple_stray(open, t)),
        }
    }

    fn event_pos(&mut self, open: &Range<usize>) -> Result<EventPos> {
        let Some(t) = self.peek_token().cloned() else {
            return Err(self.err(ErrorKind::Syntax, open.clone(), "unclosed `<`"));
        };
        match t.tok {
            Tok::Event(kind, lobe) => {
                self.bump();
                Ok(EventPos::One(EventPattern { kind, lobe }))
            }
            Tok::Dot => {
                self.bump();
                Ok(EventPos::Any)
            }
            Tok::LBracket => {
                let (negated, events) =
                    self.position_class(t.span, "event", "D S U", |t| match t {
                        Tok::Event(kind, lobe) => Some(EventPattern {
                            kind: *kind,
                            lobe: *lobe,
                        }),
                        _ => None,
                    })?;
                Ok(EventPos::Class { negated, events })
            }
            Tok::Label(_) => {
                let text = self.triple_text(open);
                let fixed = match text.find('\'') {
                    Some(q) => format!("{}.{}", &text[..q], &text[q..]),
                    None => text.to_string(),
                };
                Err(self
                    .err(
                        ErrorKind::TriplePosition,
                        t.span,
                        "the label belongs in the third position of `<type event label>`",
                    )
                    .with_help(format!("write `{fixed}`")))
            }
            Tok::RAngle => Ok(EventPos::Any),
            _ => Err(self.triple_stray(open, t)),
        }
    }

    fn label_pos(&mut self, open: &Range<usize>) -> Result<LabelPos> {
        let Some(t) = self.peek_token().cloned() else {
            return Err(self.err(ErrorKind::Syntax, open.clone(), "unclosed `<`"));
        };
        match t.tok {
            Tok::Label(l) => {
                self.bump();
                Ok(LabelPos::One(l))
            }
            Tok::Dot => {
                self.bump();
                Ok(LabelPos::Any)
            }
            Tok::LBracket => {
                let (negated, labels) =
                    self.position_class(t.span, "label", "quoted names", |t| match t {
                        Tok::Label(l) => Some(l.clone()),
                        _ => None,
                    })?;
                Ok(LabelPos::Class { negated, labels })
            }
            _ => Ok(LabelPos::Any),
        }
    }
}
