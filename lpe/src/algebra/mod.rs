//! Set algebra over whole expressions: `A & B` (paths both match), `A - B` (paths `A`
//! matches and `B` does not), `^A` (paths of the path model `A` does not match), with
//! the lowest precedence, `&` and `-` left-associative, `^` a prefix on one operand.
//!
//! The layer is dialect-independent: [`parse`] finds the operators in the source text
//! and hands each operand's text to the dialect's parser, and the tree [`Algebra`] has a
//! dialect expression at each leaf. Matchers evaluate it with [`Algebra::eval`] over
//! their per-operand answers; the automata of [`crate::AovSet`] compile each operand as
//! a hidden AOV and compute the visible masks from the hidden ones once, when the DFA is
//! built.

mod parse;
mod tree;

pub use parse::{has_algebra, parse, AlgebraError, ParseError, MAX_OPERANDS};
pub(crate) use tree::write_operands;
pub use tree::{formulas, Algebra, SetExpr};
