//! The readers, one per format, and the limits they enforce.
//!
//! | format | read | limit |
//! |---|---|---|
//! | USD text (`.usda`) | streamed through [`skim`], which drops the values lint never reads; a layer that composes nothing read from that text prim by prim ([`flat`]), any other by `openusd` | [`Limits::usd_bytes`] (64 MiB) of kept text (read flat: per piece of it); any file size |
//! | USD otherwise (`.usdc`, `.usdz`, `.usd`) | whole file, by `openusd` | [`Limits::usd_bytes`] (64 MiB) |
//! | RIB | streamed line by line, only `DisplayChannel` lines kept | [`Limits::line_bytes`] per line (1 MiB), [`Limits::channels`] channels (4096); any file size |
//! | ini | whole file | [`Limits::ini_bytes`] (1 MiB) |

mod common;
pub mod flat;
pub mod ini;
pub mod rib;
pub mod skim;
pub mod usd;

pub use common::Limits;

use std::path::Path;

use crate::decl::{Document, Format};
use crate::error::ReadError;

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
        Some(Format::Usd) => read_usd(path, limits),
        Some(Format::Rib) => rib::read(path, limits),
        Some(Format::Ini) => ini::read(path, limits),
        None => Err(ReadError::UnknownFormat {
            path: path.to_path_buf(),
        }),
    }
}

/// Reads a USD stage: a `.usda` file that composes nothing straight from its skimmed
/// text ([`flat`]), any other composed through `openusd` ([`usd::read`]), to the same
/// document.
pub fn read_usd(path: &Path, limits: &Limits) -> Result<Document, ReadError> {
    if usd::is_usda(path) {
        if let Ok(doc) = flat::read(path, limits)? {
            return Ok(doc);
        }
    }
    usd::read(path, limits)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_by_extension() {
        assert_eq!(format_of(Path::new("a/b.USDA")), Some(Format::Usd));
        assert_eq!(format_of(Path::new("rendermn.ini")), Some(Format::Ini));
        assert_eq!(format_of(Path::new("x.rib")), Some(Format::Rib));
        assert_eq!(format_of(Path::new("x.txt")), None);
        assert_eq!(format_of(Path::new("rib")), None);
    }
}
