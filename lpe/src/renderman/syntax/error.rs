//! The one error type of the expression front end: what went wrong, where (a byte span
//! into the source), and how to fix it when we can tell.

use std::fmt;
use std::ops::Range;

/// What kind of mistake an [`Error`] reports, for callers that branch on it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ErrorKind {
    /// Nothing to match: an empty expression, `()`, `[]`, `<>`.
    Empty,
    /// A token where it cannot stand, or a character that is no token.
    Syntax,
    /// A letter in the wrong position of a `<type event label>` triple.
    TriplePosition,
    /// A malformed or contradictory quantifier (`{,m}`, `{3,2}`, `C.**L`, `<R*>`).
    Quantifier,
    /// A lobe number out of range (D1-4, S1-8, U1-12).
    Lobe,
    /// An identifier-like body that names no macro.
    UnknownMacro,
    /// A prefix that is not one of the known ones.
    UnknownPrefix,
    /// A configured limit (repetition count, expanded size, nesting, macro depth) exceeded.
    Limit,
}

/// A parse error with its span in the source.
///
/// `Display` renders the message, the source line with a caret under the span, and a
/// suggestion when there is one:
///
/// ```text
/// error at byte 1: the label belongs in the third position of a triple
///   | C<L'key'>
///   |    ^^^^^
///   = help: write `<L.'key'>`
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Error {
    kind: ErrorKind,
    span: Range<usize>,
    message: String,
    help: Option<String>,
    source: String,
}

impl Error {
    pub(crate) fn new(
        kind: ErrorKind,
        span: Range<usize>,
        message: impl Into<String>,
        source: &str,
    ) -> Error {
        // Snap to character boundaries so the caret can always be rendered.
        let mut end = span.end.min(source.len());
        while !source.is_char_boundary(end) {
            end += 1;
        }
        let mut start = span.start.min(end);
        while !source.is_char_boundary(start) {
            start -= 1;
        }
        Error {
            kind,
            span: start..end,
            message: message.into(),
            help: None,
            source: source.to_owned(),
        }
    }

    pub(crate) fn with_help(mut self, help: impl Into<String>) -> Error {
        self.help = Some(help.into());
        self
    }

    /// The kind of mistake.
    pub fn kind(&self) -> ErrorKind {
        self.kind
    }

    /// Byte range of the offending text in [`Error::source_text`].
    pub fn span(&self) -> Range<usize> {
        self.span.clone()
    }

    /// The message, without position or caret.
    pub fn message(&self) -> &str {
        &self.message
    }

    /// A suggested fix, if there is one.
    pub fn help(&self) -> Option<&str> {
        self.help.as_deref()
    }

    /// The text that was parsed.
    pub fn source_text(&self) -> &str {
        &self.source
    }

    /// One line: `byte N: message (help: …)`, for line-oriented output such as
    /// `lpe-check match --batch`.
    pub fn one_line(&self) -> String {
        let mut s = format!("byte {}: {}", self.span.start, self.message);
        if let Some(h) = &self.help {
            s.push_str(&format!(" ({h})"));
        }
        s
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "error at byte {}: {}", self.span.start, self.message)?;
        // Show the source on one line (control characters would break the caret).
        let shown: String = self
            .source
            .chars()
            .map(|c| if c.is_control() { ' ' } else { c })
            .collect();
        let col = self.source[..self.span.start].chars().count();
        let width = self.source[self.span.clone()].chars().count().max(1);
        writeln!(f, "  | {shown}")?;
        write!(f, "  | {}{}", " ".repeat(col), "^".repeat(width))?;
        if let Some(h) = &self.help {
            write!(f, "\n  = help: {h}")?;
        }
        Ok(())
    }
}

impl std::error::Error for Error {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn caret_sits_under_the_span() {
        let e = Error::new(ErrorKind::Syntax, 5..6, "bad", "ab€de");
        let text = e.to_string();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[1], "  | ab€de");
        assert_eq!(lines[2], "  |    ^");
        // A span inside a multi-byte character is widened to the whole character.
        let inside = Error::new(ErrorKind::Syntax, 3..4, "bad", "ab€de");
        assert_eq!(inside.span(), 2..5);
        assert!(inside.to_string().ends_with("  |   ^"));
    }
}
