//! Printing shared by both dialects' trees and paths: sequences and alternations with
//! parentheses exactly where the reader needs them. A leaf, so that the tree and path
//! modules can both use it.

use std::fmt;

/// Writes the parts of a sequence (`sep` empty) or an alternation (`sep` `|`), each in
/// parentheses where `paren` says so. Both dialects' printers use it: they share the
/// precedence (`|` binds tighter than concatenation, a quantifier tighter than `|`).
pub(crate) fn write_parts<E: fmt::Display>(
    f: &mut fmt::Formatter<'_>,
    parts: &[E],
    sep: &str,
    paren: impl Fn(&E) -> bool,
) -> fmt::Result {
    for (i, e) in parts.iter().enumerate() {
        if i > 0 {
            f.write_str(sep)?;
        }
        if paren(e) {
            write!(f, "({e})")?;
        } else {
            write!(f, "{e}")?;
        }
    }
    Ok(())
}
