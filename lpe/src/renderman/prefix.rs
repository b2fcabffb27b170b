//! Expression prefixes: `unoccluded;`, `shadows;` … (docs/language.md §7).
//!
//! Prefixes change what the renderer accumulates, never what matches. They travel with
//! the expression in [`crate::renderman::ast::Lpe::prefixes`]. A prefix given twice is the same as
//! once; the canonical printer writes each set prefix once, in [`Prefix::ALL`] order.

use std::fmt;

/// One prefix.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Prefix {
    /// Ignore shadowing: next-event estimation without visibility.
    Unoccluded,
    /// Bypass clamping.
    Noclamp,
    /// No accumulated throughput.
    Nothruput,
    /// Unoccluded minus occluded: the shadow alone.
    Shadows,
    /// Only paths with a holdout vertex.
    Holdouts,
    /// Last value wins (for user lobes).
    Overwrite,
    /// Keep non-finite values.
    Noinfinitecheck,
}

impl Prefix {
    /// Every prefix, in canonical order.
    pub const ALL: [Prefix; 7] = [
        Prefix::Unoccluded,
        Prefix::Noclamp,
        Prefix::Nothruput,
        Prefix::Shadows,
        Prefix::Holdouts,
        Prefix::Overwrite,
        Prefix::Noinfinitecheck,
    ];

    /// The name as written in expressions.
    pub fn name(self) -> &'static str {
        match self {
            Prefix::Unoccluded => "unoccluded",
            Prefix::Noclamp => "noclamp",
            Prefix::Nothruput => "nothruput",
            Prefix::Shadows => "shadows",
            Prefix::Holdouts => "holdouts",
            Prefix::Overwrite => "overwrite",
            Prefix::Noinfinitecheck => "noinfinitecheck",
        }
    }

    /// Looks a prefix up by name, ignoring case.
    pub fn from_name(name: &str) -> Option<Prefix> {
        Prefix::ALL
            .into_iter()
            .find(|p| p.name().eq_ignore_ascii_case(name))
    }

    fn bit(self) -> u8 {
        1 << (self as u8)
    }
}

impl fmt::Display for Prefix {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A set of prefixes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Prefixes(u8);

impl Prefixes {
    /// No prefix.
    pub const NONE: Prefixes = Prefixes(0);

    /// Whether `p` is set.
    pub fn contains(self, p: Prefix) -> bool {
        self.0 & p.bit() != 0
    }

    /// Sets `p`.
    pub fn insert(&mut self, p: Prefix) {
        self.0 |= p.bit();
    }

    /// The union of two sets.
    pub fn union(self, other: Prefixes) -> Prefixes {
        Prefixes(self.0 | other.0)
    }

    /// Whether no prefix is set.
    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// The set prefixes in canonical order.
    pub fn iter(self) -> impl Iterator<Item = Prefix> {
        Prefix::ALL.into_iter().filter(move |p| self.contains(*p))
    }
}

impl FromIterator<Prefix> for Prefixes {
    fn from_iter<I: IntoIterator<Item = Prefix>>(iter: I) -> Prefixes {
        let mut s = Prefixes::NONE;
        iter.into_iter().for_each(|p| s.insert(p));
        s
    }
}
