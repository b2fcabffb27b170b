//! What the readers share: their size limits, bounded reading, the text check, and the
//! partition comment of RIB and ini files. A leaf below the readers, so that they do
//! not import the module that dispatches to them.

use std::path::Path;

use crate::error::ReadError;

/// Size limits of the readers. Over a limit a reader stops with
/// [`ReadError::TooLarge`] or [`crate::RibProblem`], before reading on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Largest USD file read whole (`.usdc`, `.usdz`, `.usd`: the USD library holds
    /// the whole layer in memory); for `.usda`, the most text kept after the skim.
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

/// The whole file, if it is at most `limit` bytes.
pub(crate) fn read_bounded(
    path: &Path,
    limit: u64,
    what: &'static str,
) -> Result<Vec<u8>, ReadError> {
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
pub(crate) fn as_text<'a>(bytes: &'a [u8], path: &Path, base: u64) -> Result<&'a str, ReadError> {
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
pub(crate) fn partition_comment(line: &str) -> Option<(String, &str)> {
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
