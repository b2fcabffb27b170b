//! The parsed OSL expression, fully expanded: shorthand is already turned into whole
//! vertex patterns and registration already applied, so a matcher needs nothing but this
//! tree.
//!
//! A vertex pattern reads one vertex's symbols: `symbols[0]` the event, `symbols[1]` the
//! scattering, the rest the custom labels in order; then, when it has an eater, any
//! further symbols outside the eater's exclusion list; then the vertex must end. The
//! [`fmt::Display`] impls print OSL syntax that means the same tree when every vertex
//! pattern keeps OSL's own eater rule (an eater exactly when it has fewer than five custom
//! items and is the basic set); a hand-built pattern outside that rule prints with the
//! nearest OSL spelling.

use std::fmt;

use super::symbol::Symbol;
use crate::algebra::{write_operands, Algebra, SetExpr};
use crate::automata::ir::Repetition;
use crate::print::write_parts;

/// What one slot of a vertex pattern accepts. No slot accepts STOP.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum SymbolPattern {
    /// `.` inside `<>`: any symbol (NONE and basic labels included).
    Any,
    /// One symbol (`x` is [`Symbol::None`]).
    One(Symbol),
    /// `[abc]` inside `<>`: one of these (none when empty).
    Set(Vec<Symbol>),
    /// `[^abc]`: any symbol except these.
    NotIn(Vec<Symbol>),
}

impl SymbolPattern {
    /// Whether the slot accepts `s`.
    pub fn accepts(&self, s: &Symbol) -> bool {
        match self {
            SymbolPattern::Any => true,
            SymbolPattern::One(x) => x == s,
            SymbolPattern::Set(xs) => xs.contains(s),
            SymbolPattern::NotIn(xs) => !xs.contains(s),
        }
    }

    /// The pattern accepting what any of `patterns` accepts (`[…]` inside `<>` joins its
    /// one-symbol items so; none: the empty set): the lists one after the other (as
    /// written, repeats kept), or, with blacklists among them, their common part less
    /// what the lists accept; `.` absorbs everything. Linear in the patterns' lengths,
    /// however long a set is.
    pub fn any_of(patterns: Vec<SymbolPattern>) -> SymbolPattern {
        use std::collections::HashSet;
        let mut listed = Vec::new();
        // The common part of the blacklists so far, if any was seen.
        let mut excluded: Option<Vec<Symbol>> = None;
        for p in patterns {
            match p {
                SymbolPattern::Any => return SymbolPattern::Any,
                SymbolPattern::One(s) => listed.push(s),
                SymbolPattern::Set(xs) => listed.extend(xs),
                SymbolPattern::NotIn(xs) => {
                    excluded = Some(match excluded {
                        None => xs,
                        Some(common) => {
                            let xs: HashSet<Symbol> = xs.into_iter().collect();
                            common.into_iter().filter(|s| xs.contains(s)).collect()
                        }
                    })
                }
            }
        }
        let Some(excluded) = excluded else {
            return SymbolPattern::Set(listed);
        };
        let listed: HashSet<Symbol> = listed.into_iter().collect();
        let rest: Vec<Symbol> = excluded
            .into_iter()
            .filter(|s| !listed.contains(s))
            .collect();
        if rest.is_empty() {
            SymbolPattern::Any
        } else {
            SymbolPattern::NotIn(rest)
        }
    }

    /// Every symbol the pattern names.
    pub fn symbols(&self) -> &[Symbol] {
        match self {
            SymbolPattern::Any => &[],
            SymbolPattern::One(x) => std::slice::from_ref(x),
            SymbolPattern::Set(xs) | SymbolPattern::NotIn(xs) => xs,
        }
    }
}

/// One whole vertex: `symbols[0]` matches the event, `symbols[1]` the scattering, the
/// rest the custom labels in order (a `( ... )` group in a slot contributes several
/// entries); then, if `eater` is `Some(excluded)`, zero or more further symbols none of
/// which is in `excluded` (OSL's eater: the basic and registered labels and NONE), then
/// STOP. With `eater: None` the vertex has exactly `symbols.len()` symbols.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct VertexPattern {
    /// One pattern per leading symbol.
    pub symbols: Vec<SymbolPattern>,
    /// What the eater may not skip, if the pattern has one.
    pub eater: Option<Vec<Symbol>>,
}

impl VertexPattern {
    /// Whether the pattern accepts the vertex of `symbols`. A vertex of fewer than two
    /// symbols is never accepted (in OSL the event and scattering slots exclude STOP).
    pub fn accepts(&self, symbols: &[Symbol]) -> bool {
        let k = self.symbols.len();
        symbols.len() >= k.max(2)
            && self.symbols.iter().zip(symbols).all(|(p, s)| p.accepts(s))
            && match &self.eater {
                None => symbols.len() == k,
                Some(ex) => symbols[k..].iter().all(|s| !ex.contains(s)),
            }
    }
}

/// An expression over vertex sequences.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Expr {
    /// One vertex.
    Vertex(VertexPattern),
    /// A sequence, at least two parts.
    Concat(Vec<Expr>),
    /// Alternatives, at least two.
    Alt(Vec<Expr>),
    /// `min..=max` repetitions; `{m,n}` with `m > n` is already `{m}`.
    Repeat(Box<Expr>, Repetition),
    /// The empty sequence: what a leading `{0}` item of a sequence leaves (OSL drops it).
    Empty,
    /// `[]`: matches no sequence.
    Nothing,
}

impl Expr {
    /// Visits every vertex pattern.
    pub fn for_each_vertex(&self, f: &mut impl FnMut(&VertexPattern)) {
        match self {
            Expr::Vertex(v) => f(v),
            Expr::Concat(es) | Expr::Alt(es) => es.iter().for_each(|e| e.for_each_vertex(f)),
            Expr::Repeat(e, _) => e.for_each_vertex(f),
            Expr::Empty | Expr::Nothing => {}
        }
    }

    /// The alternation of `alts` (at least one), nested alternations flattened as the
    /// parser flattens them: one expression alone is itself.
    pub fn alt(alts: Vec<Expr>) -> Expr {
        let mut flat = Vec::with_capacity(alts.len());
        for e in alts {
            match e {
                Expr::Alt(es) => flat.extend(es),
                e => flat.push(e),
            }
        }
        assert!(!flat.is_empty(), "empty alternation");
        if flat.len() == 1 {
            flat.pop().unwrap()
        } else {
            Expr::Alt(flat)
        }
    }

    /// Vertex-pattern positions after unrolling counted repetition (as
    /// [`crate::Expr::positions`] counts them), saturating.
    pub fn positions(&self) -> u64 {
        match self {
            Expr::Vertex(_) => 1,
            Expr::Concat(es) | Expr::Alt(es) => es
                .iter()
                .fold(0u64, |acc, e| acc.saturating_add(e.positions())),
            Expr::Repeat(e, r) => e.positions().saturating_mul(r.copies()),
            Expr::Empty | Expr::Nothing => 0,
        }
    }
}

/// What an OSL warning is about.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum WarningKind {
    /// `[^RD]`: labels of different slots in one negation; the whole list applies to the
    /// slot of the last label.
    MixedNegation,
    /// `{m,n}` with `m > n`: read as `{m}`.
    ReversedRange {
        /// `m`
        min: u32,
        /// `n`
        max: u32,
    },
}

/// A warning OSL prints on stderr while it accepts the expression, with the byte
/// position of the construct.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Warning {
    /// What.
    pub kind: WarningKind,
    /// Byte offset of the construct's opening `[` or `{`.
    pub pos: usize,
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.kind {
            WarningKind::MixedNegation => write!(
                f,
                "you are mixing labels of different type in [...] at char {} (the whole \
                 list applies to the slot of the last label)",
                self.pos
            ),
            WarningKind::ReversedRange { min, max } => write!(
                f,
                "{{{min},{max}}} at char {} has its bounds reversed: read as {{{min}}}",
                self.pos
            ),
        }
    }
}

/// A parsed OSL expression: the tree plus the warnings OSL prints on stderr; with set
/// algebra (this front end's extension, docs/language.md §18.5), the tree over its
/// operands.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Lpe {
    /// The expanded expression; for set algebra, its first operand only (match through
    /// [`Lpe::operands`] and [`Lpe::eval`], which see every one).
    pub expr: Expr,
    /// Accepted-but-dubious constructs, in source order (of every operand).
    pub warnings: Vec<Warning>,
    /// Set algebra over the operands, or `None` for a plain expression.
    pub algebra: Option<Algebra<Expr>>,
    /// The renderer's prefix the source was written with (`unoccluded` for
    /// `unoccluded;C.*L`), when its registration accepts prefixes
    /// ([`crate::osl::Registered::prefixes`]): it changes what is accumulated, never
    /// which paths match.
    pub prefix: Option<String>,
}

impl Lpe {
    /// Moves the positions of its warnings `by` bytes on: for an expression parsed from
    /// the rest of a longer source (after [`crate::osl::SOURCE_MARK`]), so that they
    /// count from the source as written.
    pub fn shift_warnings(&mut self, by: usize) {
        for w in &mut self.warnings {
            w.pos += by;
        }
    }

    /// A plain expression without warnings.
    pub fn new(expr: Expr) -> Lpe {
        Lpe {
            expr,
            warnings: Vec::new(),
            algebra: None,
            prefix: None,
        }
    }

    /// Set algebra without warnings; a lone leaf is a plain expression.
    pub fn from_algebra(tree: Algebra<Expr>) -> Lpe {
        match tree {
            Algebra::Leaf(expr) => Lpe::new(expr),
            tree => Lpe {
                expr: tree.leaves()[0].clone(),
                warnings: Vec::new(),
                algebra: Some(tree),
                prefix: None,
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

    /// Per expression, its set algebra over operand numbers ([`crate::algebra::formulas`]).
    pub fn formulas<'a>(lpes: impl IntoIterator<Item = &'a Lpe>) -> Vec<Algebra<usize>> {
        crate::algebra::formulas(lpes)
    }

    /// Whether a path is matched, given whether it matches each operand (asked once
    /// each, in [`Lpe::operands`] order).
    pub fn eval(&self, operand: &mut impl FnMut(&Expr) -> bool) -> bool {
        SetExpr::eval(self, operand)
    }

    /// Vertex positions of every operand together, saturating.
    pub fn positions(&self) -> u64 {
        self.operands()
            .iter()
            .fold(0u64, |n, e| n.saturating_add(e.positions()))
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

/// A label as it reads inside `<>`: one plain character bare, anything else quoted
/// (characters with a meaning inside `<>` included; `|` alternates inside a `( … )`,
/// where the printer may put custom labels).
fn write_label(f: &mut fmt::Formatter<'_>, l: &str) -> fmt::Result {
    let mut cs = l.chars();
    match (cs.next(), cs.next()) {
        (Some(c), None) if !"x.'[]()<>*+{}^|".contains(c) => write!(f, "{c}"),
        _ => write!(f, "'{l}'"),
    }
}

fn write_symbol(f: &mut fmt::Formatter<'_>, s: &Symbol) -> fmt::Result {
    match s {
        Symbol::None => f.write_str("x"),
        Symbol::Label(l) => write_label(f, l),
    }
}

impl fmt::Display for SymbolPattern {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // A set's items read as slots (`x` NONE, `.` any symbol, `(`, `[`, `<` and the
        // postfixes with their meaning), so its labels print as slot labels; in a
        // negation only known labels may go unquoted, so its labels are all quoted.
        let list = |f: &mut fmt::Formatter<'_>, open: &str, xs: &[Symbol], bare: bool| {
            f.write_str(open)?;
            for x in xs {
                match x {
                    Symbol::None => f.write_str("x")?,
                    Symbol::Label(l) if bare => write_label(f, l)?,
                    Symbol::Label(l) => write!(f, "'{l}'")?,
                }
            }
            f.write_str("]")
        };
        match self {
            SymbolPattern::Any => f.write_str("."),
            SymbolPattern::One(s) => write_symbol(f, s),
            SymbolPattern::Set(xs) => list(f, "[", xs, true),
            SymbolPattern::NotIn(xs) => list(f, "[^", xs, false),
        }
    }
}

impl fmt::Display for VertexPattern {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // Five or more custom symbols with an eater came from a `( … )` group (one custom
        // item): print them as one group, or the text would lose the eater.
        let grouped = self.eater.is_some() && self.symbols.len() >= 7;
        f.write_str("<")?;
        for (i, p) in self.symbols.iter().enumerate() {
            if grouped && i == 2 {
                f.write_str("(")?;
            }
            write!(f, "{p}")?;
        }
        if grouped {
            f.write_str(")")?;
        }
        f.write_str(">")
    }
}

impl fmt::Display for Expr {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Expr::Vertex(v) => write!(f, "{v}"),
            Expr::Concat(es) => write_parts(f, es, "", |e| matches!(e, Expr::Concat(_))),
            // `|` binds tighter than concatenation and takes one item on each side.
            Expr::Alt(es) => {
                write_parts(f, es, "|", |e| matches!(e, Expr::Concat(_) | Expr::Alt(_)))
            }
            Expr::Repeat(e, r) => {
                write_parts(f, std::slice::from_ref(&**e), "", |e| {
                    matches!(e, Expr::Concat(_) | Expr::Alt(_) | Expr::Repeat(..))
                })?;
                // OSL has no `?`: `{0,1}` is spelled out.
                match (r.min, r.max) {
                    (0, None) => f.write_str("*"),
                    (1, None) => f.write_str("+"),
                    (n, None) => write!(f, "{{{n},}}"),
                    (n, Some(m)) if n == m => write!(f, "{{{n}}}"),
                    (n, Some(m)) => write!(f, "{{{n},{m}}}"),
                }
            }
            // A leading `{0}` item: OSL drops it, and so does printing.
            Expr::Empty => Ok(()),
            Expr::Nothing => f.write_str("[]"),
        }
    }
}

impl fmt::Display for Lpe {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(p) = &self.prefix {
            write!(f, "{p};")?;
        }
        match &self.algebra {
            Some(t) => write_operands(f, t, |e| matches!(e, Expr::Alt(_))),
            None => write!(f, "{}", self.expr),
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
    fn vertex_pattern_acceptance() {
        let basic = vec![lbl("D"), Symbol::None];
        let p = VertexPattern {
            symbols: vec![
                SymbolPattern::One(lbl("R")),
                SymbolPattern::NotIn(vec![lbl("D")]),
            ],
            eater: Some(basic),
        };
        let acc = |v: &[&str]| p.accepts(&v.iter().map(|s| lbl(s)).collect::<Vec<_>>());
        assert!(acc(&["R", "G"]));
        assert!(acc(&["R", "G", "foo", "bar"]));
        assert!(!acc(&["R", "G", "D"]));
        assert!(!acc(&["R", "D"]));
        assert!(!acc(&["R"]));
        assert!(p.accepts(&[lbl("R"), Symbol::None]));
        let exact = VertexPattern {
            eater: None,
            ..p.clone()
        };
        assert!(exact.accepts(&[lbl("R"), lbl("G")]));
        assert!(!exact.accepts(&[lbl("R"), lbl("G"), lbl("foo")]));
        assert!(!SymbolPattern::Set(vec![]).accepts(&Symbol::None));
        let short = VertexPattern {
            symbols: vec![SymbolPattern::Any],
            eater: Some(vec![]),
        };
        assert!(!short.accepts(&[lbl("R")]));
        assert!(short.accepts(&[lbl("R"), lbl("D")]));
    }

    /// Planted fault caught: the blacklists' common part taken as their union fails the
    /// second assertion; listed labels not taken off a blacklist fail the first.
    #[test]
    fn any_of_accepts_what_one_of_the_patterns_accepts() {
        use SymbolPattern::{Any, NotIn, One, Set};
        let not_rt = NotIn(vec![lbl("R"), lbl("T")]);
        assert_eq!(
            SymbolPattern::any_of(vec![not_rt.clone(), One(lbl("R"))]),
            NotIn(vec![lbl("T")])
        );
        assert_eq!(
            SymbolPattern::any_of(vec![not_rt.clone(), NotIn(vec![lbl("T"), lbl("V")])]),
            NotIn(vec![lbl("T")])
        );
        assert_eq!(
            SymbolPattern::any_of(vec![not_rt, Set(vec![lbl("T"), lbl("R")])]),
            Any
        );
        assert_eq!(
            SymbolPattern::any_of(vec![One(Symbol::None), Set(vec![lbl("x")])]),
            Set(vec![Symbol::None, lbl("x")])
        );
        assert_eq!(SymbolPattern::any_of(vec![One(lbl("R")), Any]), Any);
        assert_eq!(SymbolPattern::any_of(vec![]), Set(vec![]));
        // A long set costs its length: 200 000 items parse at once.
        let long = format!("<[[^RT]{}]D>", "a".repeat(200_000));
        let e = crate::osl::parse(&long, &crate::osl::Registered::none()).unwrap();
        let mut first = None;
        e.expr
            .for_each_vertex(&mut |v| first = Some(v.symbols[0].clone()));
        assert_eq!(first, Some(NotIn(vec![lbl("R"), lbl("T")])));
    }

    #[test]
    fn positions_count_unrolled_vertices() {
        let v = Expr::Vertex(VertexPattern {
            symbols: vec![SymbolPattern::Any, SymbolPattern::Any],
            eater: None,
        });
        let e = Expr::Concat(vec![
            v.clone(),
            Expr::Repeat(
                Box::new(v.clone()),
                Repetition {
                    min: 2,
                    max: Some(4),
                },
            ),
            Expr::Empty,
            Expr::Nothing,
        ]);
        assert_eq!(e.positions(), 5);
        assert_eq!(
            Expr::Repeat(Box::new(v), Repetition { min: 3, max: None }).positions(),
            4
        );
    }
}
