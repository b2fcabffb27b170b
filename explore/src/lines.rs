//! The AOV list as the explorer reads it: one `name = expression` per line, blank lines
//! and `#` comments skipped, a line without `name =` named after its number (`line3`).
//! Each [`Line`] keeps where its expression starts so that a parse error's caret lands
//! under the line as the user typed it.

/// One AOV line of the list.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Line {
    /// 1-based line number in the list's text.
    pub number: usize,
    /// The AOV's name: the text before `=`, or `lineN`.
    pub name: String,
    /// The whole line as written (without its line break).
    pub text: String,
    /// The expression: the text after `name =`, trimmed.
    pub source: String,
    /// Byte offset of [`Line::source`] in [`Line::text`].
    pub offset: usize,
}

/// Whether `s` reads as an AOV name: letters, digits and `_ . : - /`, as renderers and
/// stages name their outputs (`directDiffuse`, `lpe:diffuse`, `C.key`,
/// `/Render/Vars/diffuse`). Nothing else is taken as a name, so an expression alone on
/// its line is never split at a `=` inside it.
fn is_name(s: &str) -> bool {
    !s.is_empty()
        && s.chars()
            .all(|c| c.is_alphanumeric() || matches!(c, '_' | '.' | ':' | '-' | '/'))
}

/// The AOV lines of `text`, in order.
///
/// ```
/// let lines = lpe_explore::lines::read("diffuse = C<RD>L\n\n# note\nC.*L\n");
/// assert_eq!(lines.len(), 2);
/// assert_eq!((lines[0].name.as_str(), lines[0].source.as_str()), ("diffuse", "C<RD>L"));
/// assert_eq!((lines[1].name.as_str(), lines[1].number), ("line4", 4));
/// ```
pub fn read(text: &str) -> Vec<Line> {
    let mut out = Vec::new();
    for (i, raw) in text.split('\n').enumerate() {
        let line = raw.strip_suffix('\r').unwrap_or(raw);
        let trimmed = line.trim_start();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        let number = i + 1;
        let (name, start) = match line.split_once('=') {
            Some((before, _)) if is_name(before.trim()) => {
                (before.trim().to_string(), before.len() + 1)
            }
            _ => (format!("line{number}"), 0),
        };
        let rest = &line[start..];
        let offset = start + (rest.len() - rest.trim_start().len());
        out.push(Line {
            number,
            name,
            text: line.to_string(),
            source: rest.trim().to_string(),
            offset,
        });
    }
    out
}

/// The caret display of a span of `line`: the line (control characters shown as spaces,
/// so a tab cannot shift the caret), a line break, and `^` under the span's characters
/// (at least one). Returns it with the 1-based character column and the span's length in
/// characters. `span` is in bytes, widened to whole characters and cut at the line's end.
pub fn caret(line: &str, span: std::ops::Range<usize>) -> (String, usize, usize) {
    let mut start = span.start.min(line.len());
    while !line.is_char_boundary(start) {
        start -= 1;
    }
    let mut end = span.end.clamp(start, line.len());
    while !line.is_char_boundary(end) {
        end += 1;
    }
    let column = line[..start].chars().count();
    let length = line[start..end].chars().count().max(1);
    let shown: String = line
        .chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect();
    let text = format!("{shown}\n{}{}", " ".repeat(column), "^".repeat(length));
    (text, column + 1, length)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Caught a planted fault: `offset` counted from the trimmed remainder (the caret of
    /// every named line then sat under the name).
    #[test]
    fn names_offsets_and_skipped_lines() {
        let text = "  # comment\r\ndiffuse =  C<RD>L\r\n\n\tC.*L  \nx y = C L\n/Render/Vars/d=C";
        let lines = read(text);
        assert_eq!(lines.len(), 4);
        assert_eq!(lines[0].number, 2);
        assert_eq!(lines[0].name, "diffuse");
        assert_eq!(lines[0].source, "C<RD>L");
        assert_eq!(lines[0].offset, 11);
        assert_eq!(&lines[0].text[11..], "C<RD>L");
        assert_eq!(lines[1].name, "line4");
        assert_eq!((lines[1].source.as_str(), lines[1].offset), ("C.*L", 1));
        // `x y` is no name: the whole line is the expression.
        assert_eq!(lines[2].name, "line5");
        assert_eq!(lines[2].source, "x y = C L");
        assert_eq!(
            (lines[3].name.as_str(), lines[3].source.as_str()),
            ("/Render/Vars/d", "C")
        );
    }

    /// Caught a planted fault: the column counted bytes (`é` is two), putting the caret
    /// one place too far right. Kills the mutant `end += 1` as `end -= 1` (a span ending
    /// inside `é` cut before it).
    #[test]
    fn caret_counts_characters_and_hides_tabs() {
        let (text, column, length) = caret("é\tab", 3..5);
        assert_eq!(text, "é ab\n  ^^");
        assert_eq!((column, length), (3, 2));
        // An empty span at the end still shows one caret.
        let (text, column, length) = caret("ab", 2..2);
        assert_eq!(text, "ab\n  ^");
        assert_eq!((column, length), (3, 1));
        // A span inside a character is widened to it.
        let (text, column, length) = caret("aéb", 2..3);
        assert_eq!(text, "aéb\n ^");
        assert_eq!((column, length), (2, 1));
        // A span ending inside a character is widened to its end.
        let (text, column, length) = caret("aéb", 0..2);
        assert_eq!(text, "aéb\n^^");
        assert_eq!((column, length), (1, 2));
    }
}
