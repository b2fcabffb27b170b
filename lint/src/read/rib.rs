//! RIB: `DisplayChannel "color NAME" "string source" ["color lpe:EXPR"]` lines, streamed
//! so a RIB of any size is read in bounded memory; other lines are skipped unparsed.

use std::io::{BufRead, BufReader, Read};
use std::path::Path;

use crate::decl::{split_members, AovDecl, Document, Format, Location, PartitionDecl};
use crate::error::{ReadError, RibProblem};
use crate::read::common::{as_text, partition_comment, Limits};

/// Reads the LPE channels and partition comments of a RIB file.
pub fn read(path: &Path, limits: &Limits) -> Result<Document, ReadError> {
    let file = std::fs::File::open(path).map_err(|source| ReadError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    read_from(BufReader::new(file), path, limits)
}

/// Reads RIB text from any reader (`path` names it in errors).
pub fn read_from(
    mut reader: impl BufRead,
    path: &Path,
    limits: &Limits,
) -> Result<Document, ReadError> {
    let mut doc = Document::new(path, Format::Rib);
    let mut buf = Vec::new();
    let mut offset = 0u64;
    let mut channels = 0usize;
    for line in 1.. {
        let fail = |problem| ReadError::Rib {
            path: path.to_path_buf(),
            line,
            problem,
        };
        buf.clear();
        let n = reader
            .by_ref()
            .take(limits.line_bytes as u64 + 1)
            .read_until(b'\n', &mut buf)
            .map_err(|source| ReadError::Io {
                path: path.to_path_buf(),
                source,
            })?;
        if n == 0 {
            break;
        }
        let body = buf.strip_suffix(b"\n").unwrap_or(&buf);
        if body.len() > limits.line_bytes {
            return Err(fail(RibProblem::LineTooLong {
                limit: limits.line_bytes,
            }));
        }
        let text = as_text(body, path, offset)?;
        offset += n as u64;
        if let Some((name, list)) = partition_comment(text) {
            doc.partitions.push(PartitionDecl {
                name,
                members: split_members(list),
                location: Location::Line { line, column: 1 },
            });
            continue;
        }
        let Some(decl) = display_channel(text).map_err(fail)? else {
            continue;
        };
        channels += 1;
        if channels > limits.channels {
            return Err(fail(RibProblem::TooManyChannels {
                limit: limits.channels,
            }));
        }
        if let Channel::Lpe {
            name,
            source,
            column,
        } = decl
        {
            doc.aovs.push(AovDecl {
                name,
                source,
                location: Location::Line { line, column },
                source_type: None,
            });
        }
    }
    Ok(doc)
}

/// One `DisplayChannel` line, read.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Channel {
    /// An LPE channel.
    Lpe {
        /// The channel name (last word of the declaration).
        name: String,
        /// The source after its type, `lpe:` included.
        source: String,
        /// 1-based byte column of the source in the line.
        column: usize,
    },
    /// No `"string source"`: beauty, or a shader output.
    NoSource {
        /// The channel name.
        name: String,
    },
    /// A source that is not an LPE (`Ci`, a primvar).
    Other {
        /// The channel name.
        name: String,
        /// The source after its type.
        source: String,
    },
}

/// Reads one RIB line: `None` when it is not a `DisplayChannel` line.
pub fn display_channel(line: &str) -> Result<Option<Channel>, RibProblem> {
    let lead = line.len() - line.trim_start().len();
    let Some(rest) = line[lead..].strip_prefix("DisplayChannel") else {
        return Ok(None);
    };
    // (byte offset in `line` of the string's first byte, its text)
    let mut quoted = Vec::new();
    let mut at = lead + "DisplayChannel".len();
    let mut rest = rest;
    while let Some(start) = rest.find('"') {
        let Some(len) = rest[start + 1..].find('"') else {
            return Err(RibProblem::UnterminatedString);
        };
        quoted.push((at + start + 1, &rest[start + 1..start + 1 + len]));
        at += start + 2 + len;
        rest = &rest[start + 2 + len..];
    }
    let Some((_, decl)) = quoted.first() else {
        return Err(RibProblem::NoDeclaration);
    };
    let name = decl
        .split_whitespace()
        .last()
        .unwrap_or_default()
        .to_string();
    let Some(pos) = quoted
        .iter()
        .position(|(_, q)| q.split_whitespace().eq(["string", "source"]))
    else {
        return Ok(Some(Channel::NoSource { name }));
    };
    let Some(&(start, value)) = quoted.get(pos + 1) else {
        return Err(RibProblem::SourceWithoutValue { name });
    };
    // The value is "TYPE SOURCE", e.g. "color lpe:C<RD>[<L.>O]".
    let after_type = value
        .trim_start()
        .find(char::is_whitespace)
        .map_or(0, |i| value.len() - value.trim_start().len() + i);
    let source = value[after_type..].trim_start();
    let column = start + (value.len() - source.len()) + 1;
    let source = source.trim_end().to_string();
    Ok(Some(if source.starts_with("lpe:") {
        Channel::Lpe {
            name,
            source,
            column,
        }
    } else {
        Channel::Other { name, source }
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read_str(text: &str, limits: &Limits) -> Result<Document, ReadError> {
        read_from(text.as_bytes(), Path::new("t.rib"), limits)
    }

    #[test]
    fn channels_with_lines_and_columns() {
        let text = "# lpe:partition diffuse, rest\n\
                    Display \"x.exr\" \"openexr\" \"rgba\"\n\
                    DisplayChannel \"color diffuse\" \"string source\" [\"color lpe:C<RD>L\"]\n\
                    \x20 DisplayChannel \"varying color rest\" \"string source\" \"color  lpe:C.*O\"\n\
                    DisplayChannel \"color Ci\"\n\
                    DisplayChannel \"color a\" \"string source\" [\"color Ci\"]\n";
        let doc = read_str(text, &Limits::default()).unwrap();
        let got: Vec<(&str, &str, String)> = doc
            .aovs
            .iter()
            .map(|a| (a.name.as_str(), a.source.as_str(), a.location.to_string()))
            .collect();
        assert_eq!(
            got,
            [
                ("diffuse", "lpe:C<RD>L", "3:56".to_string()),
                ("rest", "lpe:C.*O", "4:63".to_string()),
            ]
        );
        // The columns point at the expression in the line.
        let line3 = text.lines().nth(2).unwrap();
        assert!(line3[55..].starts_with("lpe:C<RD>L"));
        let line4 = text.lines().nth(3).unwrap();
        assert!(line4[62..].starts_with("lpe:C.*O"));
        assert_eq!(doc.partitions.len(), 1);
        assert_eq!(doc.partitions[0].members, ["diffuse", "rest"]);
    }

    #[test]
    fn bad_lines_name_their_line() {
        let e = read_str("\nDisplayChannel \"color x", &Limits::default()).unwrap_err();
        assert_eq!(e.to_string(), "t.rib:2: unterminated string");
        let e = read_str(
            "DisplayChannel \"color x\" \"string source\"",
            &Limits::default(),
        )
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            "t.rib:1: channel `x`: \"string source\" needs a value"
        );
        let e = read_str("DisplayChannel\n", &Limits::default()).unwrap_err();
        assert!(e.to_string().starts_with("t.rib:1: expected"), "{e}");
    }

    #[test]
    fn limits_stop_the_stream() {
        let limits = Limits {
            line_bytes: 16,
            channels: 1,
            ..Limits::default()
        };
        let long = format!("ok\n{}\n", "x".repeat(17));
        let e = read_str(&long, &limits).unwrap_err();
        assert_eq!(e.to_string(), "t.rib:2: line longer than 16 bytes");
        // Exactly at the limit is fine.
        assert!(read_str(&"x".repeat(16), &limits).is_ok());
        let two = "DisplayChannel \"color a\"\nDisplayChannel \"color b\"\n";
        let limits = Limits {
            line_bytes: 64,
            ..limits
        };
        let e = read_str(two, &limits).unwrap_err();
        assert_eq!(e.to_string(), "t.rib:2: more than 1 DisplayChannel lines");
    }

    #[test]
    fn binary_bytes_are_refused_with_their_offset() {
        let e = read_from(
            &b"Option\n\x00\x01"[..],
            Path::new("b.rib"),
            &Limits::default(),
        )
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            "b.rib: byte 7: not text (binary data or a truncated download?)"
        );
    }
}
