//! The reference front ends' errors and limits: what went wrong, where (a byte offset
//! in the whole source), and the bounds that keep every input finite.
//!
//! Both dialects share these two plain types; neither is lpe's (`lpe::renderman::Error`,
//! `lpe::osl::Error`, `lpe::Limits`), so the front ends share no type with lpe's parsers.

use std::fmt;

/// What kind of mistake an error reports. RenderMan's kinds follow docs/language.md §9.2;
/// the OSL dialect reports [`ErrorKind::Syntax`] for its parse errors and
/// [`ErrorKind::Algebra`] for set-algebra errors (§18.5, §18.6), [`ErrorKind::Limit`] for
/// limits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorKind {
    /// Nothing to match: an empty source, body, group, class or triple.
    Empty,
    /// A token where it cannot stand, or no token at all.
    Syntax,
    /// A letter or label in the wrong position of `<type event label>`.
    TriplePosition,
    /// A malformed or misplaced quantifier.
    Quantifier,
    /// A lobe number out of range.
    Lobe,
    /// An identifier-like body that names no macro and is no expression.
    UnknownMacro,
    /// A name before `;` that is no prefix.
    UnknownPrefix,
    /// A limit exceeded (counts, positions, nesting, macro chains).
    Limit,
    /// A set-algebra operand missing, an unbalanced algebra group, an operator inside an
    /// expression group.
    Algebra,
}

/// A parse error of a reference front end: a kind, the byte offset in the whole source
/// and a message.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FrontError {
    /// Byte offset from the start of the whole source.
    pub pos: usize,
    /// What kind of mistake.
    pub kind: ErrorKind,
    /// What is wrong, in words.
    pub message: String,
}

impl FrontError {
    /// An error of `kind` at byte `pos`.
    pub fn new(kind: ErrorKind, pos: usize, message: impl Into<String>) -> FrontError {
        FrontError {
            pos,
            kind,
            message: message.into(),
        }
    }
}

impl fmt::Display for FrontError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "byte {}: {} ({:?})", self.pos, self.message, self.kind)
    }
}

impl std::error::Error for FrontError {}

/// The bounds of docs/language.md §10 (and §18.7 for OSL), as plain numbers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// The largest count in `{n}`, `{n,}`, `{n,m}`.
    pub max_repeat: u32,
    /// Atom (vertex pattern) positions after unrolling counted repetition, over the
    /// whole source.
    pub max_positions: u64,
    /// Nesting of groups and classes (and of set-algebra groups).
    pub max_depth: usize,
    /// Macros expanded in one chain.
    pub max_macro_depth: usize,
}

impl Default for Limits {
    /// 256, 65 536, 128 and 16, as docs/language.md §10 gives them.
    fn default() -> Limits {
        Limits {
            max_repeat: 256,
            max_positions: 65_536,
            max_depth: 128,
            max_macro_depth: 16,
        }
    }
}

/// A repetition count `{min,max}` (`max` `None`: unbounded).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Count {
    /// The least number of iterations.
    pub min: u32,
    /// The most, or `None` for no upper bound.
    pub max: Option<u32>,
}

impl Count {
    /// How many times §10 counts the body's positions: `max(n, m)` for `{n,m}`, `n + 1`
    /// for `{n,}`.
    pub fn unrolled(self) -> u64 {
        match self.max {
            Some(m) => u64::from(self.min.max(m)),
            None => u64::from(self.min) + 1,
        }
    }

    /// The shortest text of the count: `*`, `+`, `?`, `{n}`, `{n,}`, `{n,m}`.
    pub fn text(self, question_mark: bool) -> String {
        match (self.min, self.max) {
            (0, None) => "*".into(),
            (1, None) => "+".into(),
            (0, Some(1)) if question_mark => "?".into(),
            (n, None) => format!("{{{n},}}"),
            (n, Some(m)) if n == m => format!("{{{n}}}"),
            (n, Some(m)) => format!("{{{n},{m}}}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_print_their_byte_message_and_kind() {
        let e = FrontError::new(ErrorKind::Limit, 7, "too deep");
        assert_eq!(e.to_string(), "byte 7: too deep (Limit)");
    }

    #[test]
    fn counts_unroll_and_print_as_section_10_says() {
        let c = |min, max| Count { min, max };
        assert_eq!(c(3, None).unrolled(), 4);
        assert_eq!(c(3, Some(5)).unrolled(), 5);
        assert_eq!(c(5, Some(3)).unrolled(), 5);
        assert_eq!(c(0, None).text(true), "*");
        assert_eq!(c(1, None).text(true), "+");
        assert_eq!(c(0, Some(1)).text(true), "?");
        assert_eq!(c(0, Some(1)).text(false), "{0,1}");
        assert_eq!(c(2, None).text(false), "{2,}");
        assert_eq!(c(2, Some(2)).text(false), "{2}");
        assert_eq!(c(2, Some(3)).text(false), "{2,3}");
    }
}
