//! The readers, one per format, and the limits they enforce.
//!
//! | format | read | limit |
//! |---|---|---|
//! | USD | whole file, by `openusd` | [`Limits::usd_bytes`] (64 MiB) |
//! | RIB | streamed line by line, only `DisplayChannel` lines kept | [`Limits::line_bytes`] per line (1 MiB), [`Limits::channels`] channels (4096); any file size |
//! | ini | whole file | [`Limits::ini_bytes`] (1 MiB) |

pub mod ini;
pub mod rib;
pub mod usd;

use std::path::Path;

use crate::decl::{Document, Format};
use crate::error::ReadError;

/// Size limits of the readers. Over a limit a reader stops with
/// [`ReadError::TooLarge`] or [`crate::RibProblem`], before reading on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Largest USD file (the USD library holds the whole layer in memory).
    pub usd_bytes: u64,
    /// Largest ini file.
    pub ini_bytes: u64,
    /// Longest RIB line.
    pub line_bytes: usize,
    /// Most `DisplayChannel` lines in one RIB file.
    pub channels: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            usd_bytes: 64 << 20,
            ini_bytes: 1 << 20,
            line_bytes: 1 << 20,
            channels: 4096,
        }
    }
}

/// The format a file's extension names.
pub fn format_of(path: &Path) -> Option<Format> {
    let ext = path.extension()?.to_str()?.to_ascii_lowercase();
    match ext.as_str() {
        "usda" | "usdc" | "usd" | "usdz" => Some(Format::Usd),
        "rib" => Some(Format::Rib),
        "ini" => Some(Format::Ini),
        _ => None,
    }
}

/// Reads one file with the reader its extension names.
pub fn read_file(path: &Path, limits: &Limits) -> Result<Document, ReadError> {
    match format_of(path) {
        Some(Format::Usd) => usd::read(path, limits),
        Some(Format::Rib) => rib::read(path, limits),
        Some(Format::Ini) => ini::read(path, limits),
        None => Err(ReadError::UnknownFormat {
            path: path.to_path_buf(),
        }),
    }
}

/// The whole file, if it is at most `limit` bytes.
fn read_bounded(path: &Path, limit: u64, what: &'static str) -> Result<Vec<u8>, ReadError> {
    use std::io::Read;
    let io = |source| ReadError::Io {
        path: path.to_path_buf(),
        source,
    };
    let file = std::fs::File::open(path).map_err(io)?;
    let mut bytes = Vec::new();
    // Read one byte past the limit instead of trusting metadata (pipes, growing files).
    file.take(limit + 1).read_to_end(&mut bytes).map_err(io)?;
    if bytes.len() as u64 > limit {
        let total = std::fs::metadata(path).map_or(bytes.len() as u64, |m| m.len());
        return Err(ReadError::TooLarge {
            path: path.to_path_buf(),
            bytes: total,
            limit,
            what,
        });
    }
    Ok(bytes)
}

/// `bytes` as text, or the offset of the first NUL byte or invalid UTF-8 sequence
/// (`base` is added to offsets, for streamed lines).
fn as_text<'a>(bytes: &'a [u8], path: &Path, base: u64) -> Result<&'a str, ReadError> {
    let not_text = |i: usize| ReadError::NotText {
        path: path.to_path_buf(),
        offset: base + i as u64,
    };
    let valid = std::str::from_utf8(bytes).map_or_else(|e| e.valid_up_to(), str::len);
    // The first bad byte, whichever kind it is.
    if let Some(i) = bytes[..valid].iter().position(|&b| b == 0) {
        return Err(not_text(i));
    }
    std::str::from_utf8(bytes).map_err(|_| not_text(valid))
}

/// `# lpe:partition a,b,c` (named `beauty`) or `# lpe:partition:NAME a,b,c`: the comment
/// convention of RIB and ini files, the same key as the USD attribute.
fn partition_comment(line: &str) -> Option<(String, &str)> {
    let rest = line.trim_start().strip_prefix('#')?.trim_start();
    let rest = rest.strip_prefix("lpe:partition")?;
    let (name, list) = match rest.strip_prefix(':') {
        Some(named) => named.split_once(char::is_whitespace)?,
        None if rest.starts_with(char::is_whitespace) => ("beauty", rest),
        None => return None,
    };
    Some((name.to_string(), list))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn partition_comments() {
        assert_eq!(
            partition_comment("# lpe:partition a,b"),
            Some(("beauty".into(), " a,b"))
        );
        assert_eq!(
            partition_comment("  #lpe:partition:groups x y"),
            Some(("groups".into(), "x y"))
        );
        assert_eq!(partition_comment("# lpe:partitions a"), None);
        assert_eq!(partition_comment("DisplayChannel # lpe:partition a"), None);
    }

    #[test]
    fn formats_by_extension() {
        assert_eq!(format_of(Path::new("a/b.USDA")), Some(Format::Usd));
        assert_eq!(format_of(Path::new("rendermn.ini")), Some(Format::Ini));
        assert_eq!(format_of(Path::new("x.rib")), Some(Format::Rib));
        assert_eq!(format_of(Path::new("x.txt")), None);
        assert_eq!(format_of(Path::new("rib")), None);
    }

    #[test]
    fn text_check_gives_the_offset() {
        let p = Path::new("f");
        assert!(as_text(b"ok", p, 0).is_ok());
        match as_text(b"ab\0c", p, 10) {
            Err(ReadError::NotText { offset, .. }) => assert_eq!(offset, 12),
            other => panic!("{other:?}"),
        }
        match as_text(b"a\0\xff", p, 0) {
            Err(ReadError::NotText { offset, .. }) => assert_eq!(offset, 1),
            other => panic!("{other:?}"),
        }
        match as_text(b"abc\xff", p, 0) {
            Err(ReadError::NotText { offset, .. }) => assert_eq!(offset, 3),
            other => panic!("{other:?}"),
        }
    }
}
