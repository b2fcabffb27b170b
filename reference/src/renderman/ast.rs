//! The reference front end's own tree of a RenderMan expression (docs/language.md §4–§7):
//! no type of lpe's parser appears here.

use crate::algebra::Algebra;
use crate::error::Count;

/// A vertex type letter (§2.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Type {
    /// Camera.
    C,
    /// Reflection.
    R,
    /// Transmission.
    T,
    /// Light.
    L,
    /// Emissive object.
    O,
}

impl Type {
    /// The type of a letter, either case.
    pub fn from_letter(c: char) -> Option<Type> {
        Some(match c.to_ascii_uppercase() {
            'C' => Type::C,
            'R' => Type::R,
            'T' => Type::T,
            'L' => Type::L,
            'O' => Type::O,
            _ => return None,
        })
    }

    /// The upper-case letter.
    pub fn letter(self) -> char {
        match self {
            Type::C => 'C',
            Type::R => 'R',
            Type::T => 'T',
            Type::L => 'L',
            Type::O => 'O',
        }
    }
}

/// An event kind letter with its lobe range (§3.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Kind {
    /// Diffuse, lobes 1–4.
    D,
    /// Specular, lobes 1–8.
    S,
    /// User, lobes 1–12.
    U,
}

impl Kind {
    /// The kind of a letter, either case.
    pub fn from_letter(c: char) -> Option<Kind> {
        Some(match c.to_ascii_uppercase() {
            'D' => Kind::D,
            'S' => Kind::S,
            'U' => Kind::U,
            _ => return None,
        })
    }

    /// The upper-case letter.
    pub fn letter(self) -> char {
        match self {
            Kind::D => 'D',
            Kind::S => 'S',
            Kind::U => 'U',
        }
    }

    /// The highest lobe number of the kind.
    pub fn max_lobe(self) -> u8 {
        match self {
            Kind::D => 4,
            Kind::S => 8,
            Kind::U => 12,
        }
    }
}

/// An event pattern: a kind, and a lobe or any lobe of it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Event {
    /// D, S or U.
    pub kind: Kind,
    /// Exactly this lobe, or `None`: any.
    pub lobe: Option<u8>,
}

/// One position of a triple: `.` (or omitted), one value, or a class of values.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Position<T> {
    /// `.` or omitted.
    Any,
    /// One value.
    One(T),
    /// `[…]` or `[^…]`.
    Class {
        /// `[^…]`.
        negated: bool,
        /// The listed values (never empty).
        items: Vec<T>,
    },
}

/// `<type event label>` (§4.2).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Triple {
    /// The type position.
    pub ty: Position<Type>,
    /// The event position.
    pub event: Position<Event>,
    /// The label position.
    pub label: Position<String>,
}

/// A single-vertex item (§4.1, §4.2).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Item {
    /// `C R T L O`.
    Type(Type),
    /// `D S U` with an optional lobe.
    Event(Event),
    /// `.`.
    Any,
    /// `'g'`.
    Label(String),
    /// `<t e l>`.
    Triple(Triple),
}

/// One atom: an item, or a class of items (§4.3).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Atom {
    /// One item.
    Item(Item),
    /// `[…]` or `[^…]`.
    Class {
        /// `[^…]`.
        negated: bool,
        /// The items (never empty).
        items: Vec<Item>,
    },
}

/// An expression (§5).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Expr {
    /// One vertex.
    Atom(Atom),
    /// Concatenation, two or more parts.
    Seq(Vec<Expr>),
    /// Alternation, two or more choices.
    Alt(Vec<Expr>),
    /// A body with its quantifier.
    Repeat(Box<Expr>, Count),
}

/// The prefixes of §7, in the order of its table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Prefix {
    /// `unoccluded`.
    Unoccluded,
    /// `shadows`.
    Shadows,
    /// `holdouts`.
    Holdouts,
    /// `nothruput`.
    Nothruput,
    /// `noclamp`.
    Noclamp,
    /// `overwrite`.
    Overwrite,
    /// `noinfinitecheck`.
    Noinfinitecheck,
}

impl Prefix {
    /// Every prefix, in the order of §7's table.
    pub const ALL: [Prefix; 7] = [
        Prefix::Unoccluded,
        Prefix::Shadows,
        Prefix::Holdouts,
        Prefix::Nothruput,
        Prefix::Noclamp,
        Prefix::Overwrite,
        Prefix::Noinfinitecheck,
    ];

    /// Its name, lower case.
    pub fn name(self) -> &'static str {
        match self {
            Prefix::Unoccluded => "unoccluded",
            Prefix::Shadows => "shadows",
            Prefix::Holdouts => "holdouts",
            Prefix::Nothruput => "nothruput",
            Prefix::Noclamp => "noclamp",
            Prefix::Overwrite => "overwrite",
            Prefix::Noinfinitecheck => "noinfinitecheck",
        }
    }
}

/// A parsed source: its prefixes (sorted, each once) and the set algebra over its
/// expressions (a plain expression is one operand), macros expanded.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Lpe {
    /// The prefixes, in §7's order, each once.
    pub prefixes: Vec<Prefix>,
    /// The expressions and the algebra over them.
    pub body: Algebra<Expr>,
}
