//! The pieces of `regex_syntax` patterns that every dialect's translation builds the same
//! way: a byte class, a repetition with the expression's raw bounds, and the end anchor
//! of a pattern that must match the whole path.

use lpe::automata::ir::Repetition;
use regex_syntax::hir::{Class, ClassBytes, ClassBytesRange, Hir, Look};

/// `sub{min,max}` with the expression's raw bounds: `{2,200}` stays `{2,200}`, since the
/// fast matcher's `{n,m}` -> `{n,}` rewrite must be tested, not shared.
pub fn repeat(sub: Hir, r: Repetition) -> Hir {
    Hir::repetition(regex_syntax::hir::Repetition {
        min: r.min,
        max: r.max,
        greedy: true,
        sub: Box::new(sub),
    })
}

/// The class of exactly these bytes (empty: never matches).
pub fn byte_class(bytes: impl IntoIterator<Item = u8>) -> Hir {
    let ranges = bytes.into_iter().map(|b| ClassBytesRange::new(b, b));
    Hir::class(Class::Bytes(ClassBytes::new(ranges)))
}

/// `pattern` matching up to the end of the path only (the search anchors the start).
pub fn to_the_end(pattern: Hir) -> Hir {
    Hir::concat(vec![pattern, Hir::look(Look::End)])
}
