//! The cursor both reference parsers read their text with: a byte range of the whole
//! source, the next character, and the nesting check made before every recursion.

use crate::error::{ErrorKind, FrontError};

/// A position in `src[..end]`, moving one character at a time.
pub struct Scanner<'s> {
    /// The whole source (error positions count from its start).
    pub src: &'s str,
    /// The next byte to read.
    pub pos: usize,
    /// Where this range ends.
    pub end: usize,
}

impl Scanner<'_> {
    /// The next character, if any.
    pub fn peek(&self) -> Option<char> {
        self.src[self.pos..self.end].chars().next()
    }

    /// Reads the next character.
    pub fn bump(&mut self) -> Option<char> {
        let c = self.peek()?;
        self.pos += c.len_utf8();
        Some(c)
    }

    /// `depth + 1`, or a `Limit` error at the cursor when that is over `max`.
    pub fn deeper(&self, depth: usize, max: usize) -> Result<usize, FrontError> {
        if depth + 1 > max {
            return Err(FrontError::new(
                ErrorKind::Limit,
                self.pos,
                format!("nested deeper than {max}"),
            ));
        }
        Ok(depth + 1)
    }
}
