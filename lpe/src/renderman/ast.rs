//! The abstract syntax of light path expressions, independent of any dialect's surface
//! syntax (docs/language.md §4–§5).
//!
//! A front end ([`crate::renderman::syntax`] for RenderMan's dialect) produces these values; every
//! engine consumes them. The [`fmt::Display`] impls are the canonical printer: printing
//! an AST and parsing the text with the RenderMan front end gives the same AST back, as
//! long as the AST is *normalized*: [`Expr::Concat`] and [`Expr::Alt`] have at least two
//! children, classes are non-empty and labels contain no `'` (the parser only builds
//! normalized ASTs; [`Expr::concat`] and [`Expr::alt`] build them too).
//!
//! # Vertex semantics of one atom
//!
//! | atom | matches one vertex that is |
//! |---|---|
//! | `C` `L` `O` ([`Item::Type`]) | of that type, any label |
//! | `R` `T` ([`Item::Type`]) | of that type with a D or S event |
//! | `D` `S` `D2`… ([`Item::Event`]) | `R` or `T` with that event kind (any lobe, or exactly that lobe) |
//! | `U` `U3` ([`Item::Event`]) | `R` or `T` with that user lobe; user lobes match only explicitly |
//! | `.` ([`Item::Any`]) | `R` or `T` with a D or S event |
//! | `'g'` ([`Item::Label`]) | `R` or `T` with a D or S event and label `g` |
//! | `<t e l>` ([`Item::Triple`]) | matched by all three positions (see [`Triple`]) |
//! | `[…]` | matched by any item |
//! | `[^…]` | matched by `.` and by no item |
//!
//! **Negation rule** (the same at every level): a negated class means "what `.` matches
//! at this position, minus the items". At the top level `.` is an R/T vertex with a D or
//! S event; in a triple's type position `.` is `[RT]`; in the event position it is "D or
//! S" for R/T and "no event" for C/L/O; in the label position it is "any label or none",
//! so `[^'foo']` there matches unlabelled vertices too. The spec (docs/language.md) fixes the
//! top level and the label position; the type and event positions follow the same rule by
//! choice.

use std::fmt;

use crate::algebra::{write_operands, Algebra, SetExpr};
pub use crate::automata::ir::Repetition;
use crate::print::write_parts;
use crate::renderman::path::{EventKind, VertexType};
use crate::renderman::prefix::Prefixes;

/// A parsed light path expression: prefixes plus the expression proper, which may be
/// set algebra over several expressions ([`crate::algebra`]).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Lpe {
    /// What the renderer accumulates (does not affect matching).
    pub prefixes: Prefixes,
    /// The expression matched against whole paths; for set algebra, its first operand
    /// only (match through [`Lpe::operands`] and [`Lpe::eval`], which see every one).
    pub expr: Expr,
    /// Set algebra (`A - B`, `A & B`, `^A`) over the operands, or `None` for a plain
    /// expression.
    pub algebra: Option<Algebra<Expr>>,
}

impl Lpe {
    /// A plain expression.
    pub fn new(prefixes: Prefixes, expr: Expr) -> Lpe {
        Lpe {
            prefixes,
            expr,
            algebra: None,
        }
    }

    /// Set algebra; a lone leaf is a plain expression.
    pub fn from_algebra(prefixes: Prefixes, algebra: Algebra<Expr>) -> Lpe {
        match algebra {
            Algebra::Leaf(expr) => Lpe::new(prefixes, expr),
            tree => Lpe {
                prefixes,
                expr: tree.leaves()[0].clone(),
                algebra: Some(tree),
            },
        }
    }

    /// The whole expression as a tree (a plain expression is one leaf).
    pub fn tree(&self) -> Algebra<Expr> {
        SetExpr::tree(self)
    }

    /// The expressions a matcher must match, left to right: `expr` alone, or every
    /// operand of the set algebra.
    pub fn operands(&self) -> Vec<&Expr> {
        SetExpr::operands(self)
    }

    /// Rewrites every operand (and `expr` with it).
    pub fn operands_mut(&mut self, f: &mut impl FnMut(&mut Expr)) {
        f(&mut self.expr);
        if let Some(t) = &mut self.algebra {
            t.leaves_mut().into_iter().for_each(&mut *f);
            self.expr = t.leaves()[0].clone();
        }
    }

    /// Per expression, its set algebra over operand numbers ([`crate::algebra::formulas`]).
    pub fn formulas<'a>(lpes: impl IntoIterator<Item = &'a Lpe>) -> Vec<Algebra<usize>> {
        crate::algebra::formulas(lpes)
    }

    /// Whether a path is matched, given whether it matches each operand (asked once
    /// each, in [`Lpe::operands`] order).
    pub fn eval(&self, operand: &mut impl FnMut(&Expr) -> bool) -> bool {
        SetExpr::eval(self, operand)
    }
}

impl SetExpr for Lpe {
    type Operand = Expr;

    fn first(&self) -> &Expr {
        &self.expr
    }

    fn algebra(&self) -> Option<&Algebra<Expr>> {
        self.algebra.as_ref()
    }
}

/// An expression over vertex sequences.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Expr {
    /// One vertex.
    Atom(Atom),
    /// A sequence, at least two parts.
    Concat(Vec<Expr>),
    /// Alternatives, at least two.
    Alt(Vec<Expr>),
    /// A quantified expression.
    Repeat(Box<Expr>, Repetition),
}

impl Expr {
    /// A concatenation, flattening nothing; a single part is returned as is.
    ///
    /// # Panics
    /// If `parts` is empty.
    pub fn concat(mut parts: Vec<Expr>) -> Expr {
        assert!(!parts.is_empty(), "empty concatenation");
        if parts.len() == 1 {
            parts.pop().unwrap()
        } else {
            Expr::Concat(parts)
        }
    }

    /// An alternation; a single alternative is returned as is.
    ///
    /// # Panics
    /// If `alts` is empty.
    pub fn alt(mut alts: Vec<Expr>) -> Expr {
        assert!(!alts.is_empty(), "empty alternation");
        if alts.len() == 1 {
            alts.pop().unwrap()
        } else {
            Expr::Alt(alts)
        }
    }

    /// Visits every atom, mutably (used to rewrite `<L.>` for light groups).
    pub fn for_each_atom_mut(&mut self, f: &mut impl FnMut(&mut Atom)) {
        match self {
            Expr::Atom(a) => f(a),
            Expr::Concat(es) | Expr::Alt(es) => es.iter_mut().for_each(|e| e.for_each_atom_mut(f)),
            Expr::Repeat(e, _) => e.for_each_atom_mut(f),
        }
    }

    /// Visits every atom (borrowed from the expression, so a visitor may keep them).
    pub fn for_each_atom<'a>(&'a self, f: &mut impl FnMut(&'a Atom)) {
        match self {
            Expr::Atom(a) => f(a),
            Expr::Concat(es) | Expr::Alt(es) => es.iter().for_each(|e| e.for_each_atom(f)),
            Expr::Repeat(e, _) => e.for_each_atom(f),
        }
    }

    /// Every label the expression mentions, anywhere (deduplicated, sorted).
    pub fn labels(&self) -> Vec<String> {
        // Borrowed first, so that only the distinct labels are copied.
        let mut out: Vec<&str> = Vec::new();
        self.for_each_atom(&mut |a| {
            let items: &[Item] = match a {
                Atom::Item(i) => std::slice::from_ref(i),
                Atom::Class { items, .. } => items,
            };
            for item in items {
                match item {
                    Item::Label(l) => out.push(l),
                    Item::Triple(t) => match &t.label {
                        LabelPos::Any => {}
                        LabelPos::One(l) => out.push(l),
                        LabelPos::Class { labels, .. } => {
                            out.extend(labels.iter().map(String::as_str))
                        }
                    },
                    _ => {}
                }
            }
        });
        out.sort_unstable();
        out.dedup();
        out.into_iter().map(str::to_string).collect()
    }

    /// Number of atom positions after unrolling counted repetition (`e{n,m}` counts `e`
    /// `max(n, m)` times, `e{n,}` counts it `n + 1` times), saturating.
    pub fn positions(&self) -> u64 {
        self.positions_with(None)
    }

    /// [`Expr::positions`] of the automaton built for paths of at most `max_path_len`
    /// vertices, whose repetitions are [`Repetition::bounded`]: checked against the
    /// budget before anything is built.
    pub(crate) fn positions_with(&self, max_path_len: Option<u32>) -> u64 {
        match self {
            Expr::Atom(_) => 1,
            Expr::Concat(es) | Expr::Alt(es) => es.iter().fold(0u64, |acc, e| {
                acc.saturating_add(e.positions_with(max_path_len))
            }),
            Expr::Repeat(e, r) => e
                .positions_with(max_path_len)
                .saturating_mul(r.bounded(max_path_len).copies()),
        }
    }
}

/// One vertex: a single item or a class of items.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Atom {
    /// A single item.
    Item(Item),
    /// `[a b …]` or, negated, `[^a b …]` (non-empty).
    Class {
        /// `[^…]`
        negated: bool,
        /// The items; at least one.
        items: Vec<Item>,
    },
}

/// Something that matches one vertex, usable alone or inside a class.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Item {
    /// A type letter `C R T L O`.
    Type(VertexType),
    /// An event letter `D S U`, with an optional lobe number.
    Event(EventPattern),
    /// `.`
    Any,
    /// `'name'`
    Label(String),
    /// `<type event label>`
    Triple(Triple),
}

/// An event letter with an optional lobe: `D` (any diffuse lobe), `S4`, `U2`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct EventPattern {
    /// D, S or U.
    pub kind: EventKind,
    /// A specific lobe (in range for the kind), or any lobe of the kind.
    pub lobe: Option<u8>,
}

/// `<t e l>`: a vertex whose type, event and label each match their position.
///
/// Omitted event and label positions are `.`: `<L>` is `<L.>` and prints as `<L.>`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Triple {
    /// Type position.
    pub ty: TypePos,
    /// Event position.
    pub event: EventPos,
    /// Label position.
    pub label: LabelPos,
}

/// A triple's type position.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum TypePos {
    /// `.`: R or T.
    Any,
    /// One type letter.
    One(VertexType),
    /// `[RT]`, or negated `[^R]` (= `.` minus the items).
    Class {
        /// `[^…]`
        negated: bool,
        /// At least one.
        types: Vec<VertexType>,
    },
}

/// A triple's event position.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum EventPos {
    /// `.` (or omitted): D or S for R/T vertices, no event for C/L/O.
    Any,
    /// One event letter, optionally with a lobe.
    One(EventPattern),
    /// `[DS]`, or negated `[^D2]` (= `.` minus the items).
    Class {
        /// `[^…]`
        negated: bool,
        /// At least one.
        events: Vec<EventPattern>,
    },
}

/// A triple's label position.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum LabelPos {
    /// `.` (or omitted): any label, or none.
    Any,
    /// `'name'`: exactly this label.
    One(String),
    /// `['a' 'b']`, or negated `[^'a']`: any label but these, *including no label*.
    Class {
        /// `[^…]`
        negated: bool,
        /// At least one.
        labels: Vec<String>,
    },
}

impl fmt::Display for Lpe {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for p in self.prefixes.iter() {
            write!(f, "{p};")?;
        }
        match &self.algebra {
            Some(t) => write_operands(f, t, |e| matches!(e, Expr::Alt(_))),
            None => write!(f, "{}", self.expr),
        }
    }
}

impl fmt::Display for Expr {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // Parenthesize exactly where the parser would otherwise build a different tree:
        // `|` binds tighter than concatenation and a quantifier binds tighter than `|`.
        match self {
            Expr::Atom(a) => write!(f, "{a}"),
            Expr::Concat(es) => write_parts(f, es, "", |e| matches!(e, Expr::Concat(_))),
            Expr::Alt(es) => {
                write_parts(f, es, "|", |e| matches!(e, Expr::Concat(_) | Expr::Alt(_)))
            }
            Expr::Repeat(e, r) => {
                write_parts(f, std::slice::from_ref(&**e), "", |e| {
                    !matches!(e, Expr::Atom(_))
                })?;
                write!(f, "{r}")
            }
        }
    }
}

impl fmt::Display for Atom {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Atom::Item(i) => write!(f, "{i}"),
            Atom::Class { negated, items } => write_class(f, *negated, items, |i| i.to_string()),
        }
    }
}

impl fmt::Display for Item {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Item::Type(t) => write!(f, "{t}"),
            Item::Event(e) => write!(f, "{e}"),
            Item::Any => f.write_str("."),
            Item::Label(l) => write!(f, "'{l}'"),
            Item::Triple(t) => write!(f, "{t}"),
        }
    }
}

impl fmt::Display for EventPattern {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.kind.letter())?;
        if let Some(l) = self.lobe {
            write!(f, "{l}")?;
        }
        Ok(())
    }
}

impl fmt::Display for Triple {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("<")?;
        match &self.ty {
            TypePos::Any => f.write_str(".")?,
            TypePos::One(t) => write!(f, "{t}")?,
            TypePos::Class { negated, types } => {
                write_class(f, *negated, types, |t| t.to_string())?
            }
        }
        match &self.event {
            EventPos::Any => f.write_str(".")?,
            EventPos::One(e) => write!(f, "{e}")?,
            EventPos::Class { negated, events } => {
                write_class(f, *negated, events, |e| e.to_string())?
            }
        }
        match &self.label {
            LabelPos::Any => {}
            LabelPos::One(l) => write!(f, "'{l}'")?,
            LabelPos::Class { negated, labels } => {
                write_class(f, *negated, labels, |l| format!("'{l}'"))?
            }
        }
        f.write_str(">")
    }
}

/// `[a b]` or `[^a b]`, items printed without separators (no item text can run into
/// the next: none starts with a digit).
fn write_class<T>(
    f: &mut fmt::Formatter<'_>,
    negated: bool,
    items: &[T],
    show: impl Fn(&T) -> String,
) -> fmt::Result {
    f.write_str(if negated { "[^" } else { "[" })?;
    items.iter().try_for_each(|i| f.write_str(&show(i)))?;
    f.write_str("]")
}
