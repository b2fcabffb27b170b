//! Why an OSL expression did not parse: OSL's own message where OSL reports one, a clear
//! one where OSL crashes, and the byte position either way.

use std::fmt;

/// What went wrong. The first group are OSL's errors with OSL's message text; the rest are
/// inputs OSL accepts and then crashes on, and this front end's explicit limits.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum ErrorKind {
    /// An unknown single character outside `<>` (empty for `x`, for an unclosed quote and
    /// at the end of the text): "Unrecognized basic label: `sym`".
    UnrecognizedBasicLabel(String),
    /// An unquoted unknown label, `x` or `.` inside `[^...]`.
    UnrecognizedLabel,
    /// `|` at the start of a sequence.
    NoLeftExpression,
    /// Unclosed `(`.
    UnclosedParen,
    /// Unclosed `<`.
    UnclosedGroup,
    /// Unclosed `[`.
    UnclosedOrList,
    /// Unclosed `[^`.
    UnclosedNegativeOrList,
    /// `[^]`.
    EmptyNegation,
    /// Unclosed `'` (inside `<>` or `[^...]`).
    UnclosedLiteral,
    /// A `{}` range without a lower bound, with a non-digit, or unclosed.
    BadRange,
    /// `<` inside `<>`.
    NestedGroup,
    /// `*`, `+` or `{` inside `<>`.
    RepetitionInGroup,
    /// The empty expression (OSL accepts it and crashes).
    Empty,
    /// `()`: a group with nothing inside (OSL crashes).
    EmptyGroup,
    /// An empty alternative of a group inside `<…>`: `<(|R)D>`, `<(R|)D>` (OSL refuses
    /// both).
    EmptyAlternative,
    /// A `<…>` whose groups' alternatives multiply past the limit of vertex patterns one
    /// `<…>` may stand for.
    TooManyAlternatives {
        /// The limit.
        max: usize,
    },
    /// A `{0}` item that is not among the leading items of a sequence, or is the whole
    /// expression, an alternative or a repeated body (OSL crashes on all of these).
    ZeroRepeat,
    /// `'__stop__'`: OSL's end-of-vertex mark is not a label.
    StopLabel,
    /// A repetition count over [`crate::limits::Limits::max_repeat`].
    RepeatTooLarge {
        /// The limit.
        max: u32,
    },
    /// Groups and lists nested deeper than [`crate::limits::Limits::max_depth`].
    TooDeep {
        /// The limit.
        max: usize,
    },
    /// Set algebra (`A - B`, `A & B`, `^A`) that does not parse: an operand missing, an
    /// unbalanced algebra group, an operator inside an operand, too deep or too many
    /// operands.
    Algebra(crate::algebra::AlgebraError),
    /// A `name;` prefix the registration's renderer does not accept
    /// ([`crate::osl::Registered::prefixes`]).
    UnacceptedPrefix {
        /// The prefix as written, without its `;`.
        prefix: String,
        /// The prefixes the renderer accepts.
        accepted: Vec<String>,
    },
    /// A whole source that is a name, not an expression, and none of the renderer's
    /// built-in AOVs ([`crate::osl::Registered::builtins`]).
    UnknownBuiltin {
        /// The name as written.
        name: String,
        /// The nearest built-in names, best first.
        nearest: Vec<String>,
    },
    /// More vertex positions after unrolling than [`crate::limits::Limits::max_positions`].
    TooManyPositions {
        /// The expression's positions.
        positions: u64,
        /// The limit.
        max: usize,
    },
}

/// A parse error: what, and the byte position where it was found.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Error {
    /// What went wrong.
    pub kind: ErrorKind,
    /// Byte offset in the expression (its length for "end of line" errors).
    pub pos: usize,
}

impl Error {
    /// The message without the position: OSL's text for OSL's errors.
    pub fn message(&self) -> String {
        match &self.kind {
            ErrorKind::UnrecognizedBasicLabel(s) => format!("Unrecognized basic label: {s}"),
            ErrorKind::UnrecognizedLabel => "Unrecognized basic label".into(),
            ErrorKind::NoLeftExpression => "No left expression to or with |".into(),
            ErrorKind::UnclosedParen => "Reached end of line looking for )".into(),
            ErrorKind::UnclosedGroup => "Reached end of line looking for > to end a group".into(),
            ErrorKind::UnclosedOrList => {
                "Reached end of line looking for ] to end an or list".into()
            }
            ErrorKind::UnclosedNegativeOrList => {
                "Reached end of line looking for ] to end an negative or list'".into()
            }
            ErrorKind::EmptyNegation => "Empty or list [^] not allowed".into(),
            ErrorKind::UnclosedLiteral => {
                "Reached end of line looking for ' to end a literal".into()
            }
            ErrorKind::BadRange => "Bad {} range definition".into(),
            ErrorKind::NestedGroup => "No groups allowed inside of groups".into(),
            ErrorKind::RepetitionInGroup => "Repetitions not allowed inside '<...>'".into(),
            ErrorKind::Empty => "Empty expression".into(),
            ErrorKind::EmptyGroup => "Empty group () not allowed".into(),
            ErrorKind::EmptyAlternative => "Empty alternative in a group inside '<...>'".into(),
            ErrorKind::TooManyAlternatives { max } => {
                format!("The groups inside '<...>' spell out more than {max} alternative vertices")
            }
            ErrorKind::ZeroRepeat => "A {0} item matches nothing here: only the leading \
                                      items of a sequence may repeat zero times"
                .into(),
            ErrorKind::StopLabel => "'__stop__' is the end-of-vertex mark, not a label".into(),
            ErrorKind::RepeatTooLarge { max } => {
                format!("Repetition count over the limit of {max}")
            }
            ErrorKind::TooDeep { max } => format!("Groups nested deeper than {max}"),
            ErrorKind::Algebra(e) => {
                let mut m = e.to_string();
                m[..1].make_ascii_uppercase();
                format!("{m} ({})", e.help())
            }
            ErrorKind::UnacceptedPrefix { prefix, accepted } => {
                let list: Vec<String> = accepted.iter().map(|p| format!("`{p};`")).collect();
                let accepted = if list.is_empty() {
                    "none".to_string()
                } else {
                    list.join(", ")
                };
                format!("`{prefix};` is not a prefix this renderer reads (it reads: {accepted})")
            }
            ErrorKind::UnknownBuiltin { name, nearest } => {
                let hint = match nearest.first() {
                    Some(n) => format!("; did you mean `{n}`?"),
                    None => String::new(),
                };
                format!("`{name}` is no expression and none of this renderer's built-in AOVs{hint}")
            }
            ErrorKind::TooManyPositions { positions, max } => format!(
                "The expression unrolls to {positions} vertex positions, over the limit of {max}"
            ),
        }
    }
}

impl fmt::Display for Error {
    /// OSL's format without its `[pathexp] Parse error` prefix: `<message> at char <pos>`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} at char {}", self.message(), self.pos)
    }
}

impl std::error::Error for Error {}
