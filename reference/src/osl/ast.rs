//! The reference front end's own tree of an OSL expression (docs/language.md §18.2–§18.5),
//! kept at the level of symbols: a vertex pattern is its slot items (a `( … )` item
//! inside `<…>` stays a sub-expression over symbols, not multiplied out), then the eater
//! and STOP. No type of lpe's parser appears here.

use crate::algebra::Algebra;
use crate::error::{Count, Limits};

/// The built-in event labels (slot 0), §18.1.
pub const EVENTS: [&str; 7] = ["C", "L", "B", "V", "T", "R", "O"];
/// The built-in scattering labels (slot 1), §18.1.
pub const SCATTERINGS: [&str; 4] = ["D", "G", "S", "s"];
/// OSL's internal end-of-vertex label, rejected in expressions (§18.9).
pub const STOP: &str = "__stop__";

/// One symbol: NONE or a label.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Sym {
    /// NONE (`x` in an expression).
    None,
    /// A label.
    Label(String),
}

/// What one slot accepts of one symbol (never STOP).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Pattern {
    /// `.`: any symbol, NONE and basic labels included.
    Any,
    /// Exactly this symbol.
    Is(Sym),
    /// A `[…]` inside `<…>` of one-symbol items: any of these patterns (none when
    /// empty).
    Either(Vec<Pattern>),
    /// A blacklist `[^…]`.
    NotIn(Vec<Sym>),
}

/// One slot item of a vertex pattern.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Slot {
    /// One symbol.
    One(Pattern),
    /// `( … )`: alternatives, each a sequence of slot items, over symbols.
    Group(Vec<Vec<Slot>>),
}

/// A vertex pattern: its slot items (at least two), then, with fewer than five custom
/// items, the eater skipping symbols outside `eater` (the basic labels and NONE), then
/// STOP.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Vertex {
    /// Event, scattering, then custom items.
    pub slots: Vec<Slot>,
    /// The eater's exclusions, or `None`: no eater (five or more custom items).
    pub eater: Option<Vec<Sym>>,
}

/// An OSL expression over vertices.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Expr {
    /// One vertex pattern.
    Vertex(Vertex),
    /// Concatenation, two or more parts.
    Seq(Vec<Expr>),
    /// Alternation (`|`, or a `[…]` list outside `<…>`), two or more choices.
    Alt(Vec<Expr>),
    /// A body with its postfix.
    Repeat(Box<Expr>, Count),
    /// `[]`: no sequence at all.
    Nothing,
}

/// A parsed OSL source: the set algebra over its expressions (a plain expression is one
/// operand).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Lpe {
    /// The expressions and the algebra over them.
    pub body: Algebra<Expr>,
}

/// What an OSL parse is registered with: the user event and scattering labels
/// (`events=…;scatters=…`, OSL's `addEventType` / `addScatteringType`) as plain
/// strings, a renderer's prefixes and built-in AOV names, and the limits.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Registration {
    /// Extra event labels.
    pub events: Vec<String>,
    /// Extra scattering labels.
    pub scatters: Vec<String>,
    /// A renderer's prefixes (`unoccluded` for `unoccluded;C<RD>L`), read and dropped.
    pub prefixes: Vec<String>,
    /// A renderer's built-in AOVs: a source that is one of the names reads as its
    /// expression.
    pub builtins: Vec<(String, String)>,
    /// The parse limits.
    pub limits: Limits,
}

impl Registration {
    /// Whether `l` is an event label, built in or registered.
    pub fn is_event(&self, l: &str) -> bool {
        EVENTS.contains(&l) || self.events.iter().any(|e| e == l)
    }

    /// Whether `l` is a scattering label, built in or registered.
    pub fn is_scattering(&self, l: &str) -> bool {
        SCATTERINGS.contains(&l) || self.scatters.iter().any(|e| e == l)
    }

    /// The basic set the eater excludes: every built-in and registered label, and NONE.
    pub fn basic(&self) -> Vec<Sym> {
        let mut out = vec![Sym::None];
        for l in EVENTS
            .iter()
            .chain(SCATTERINGS.iter())
            .copied()
            .chain(self.events.iter().map(String::as_str))
            .chain(self.scatters.iter().map(String::as_str))
        {
            let s = Sym::Label(l.to_string());
            if !out.contains(&s) {
                out.push(s);
            }
        }
        out
    }
}
