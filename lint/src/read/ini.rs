//! `rendermn.ini`: macros and lobe mappings through [`lpe::renderman::Config`], plus partition
//! comments (`# lpe:partition a,b,c`).

use std::path::Path;

use crate::decl::{split_members, Document, Format, Location, PartitionDecl};
use crate::error::ReadError;
use crate::read::common::{as_text, partition_comment, read_bounded, Limits};

/// Reads an ini file on top of the defaults.
pub fn read(path: &Path, limits: &Limits) -> Result<Document, ReadError> {
    read_into(path, limits, &mut lpe::renderman::Config::default())
}

/// Reads an ini file on top of `config` (so several files stack, later lines winning);
/// the document holds the result.
pub fn read_into(
    path: &Path,
    limits: &Limits,
    config: &mut lpe::renderman::Config,
) -> Result<Document, ReadError> {
    let bytes = read_bounded(path, limits.ini_bytes, "ini")?;
    let text = as_text(&bytes, path, 0)?;
    config.load_ini(text).map_err(|error| ReadError::Ini {
        path: path.to_path_buf(),
        error,
    })?;
    let mut doc = Document::new(path, Format::Ini);
    doc.config = Some(config.clone());
    for (n, line) in text.lines().enumerate() {
        if let Some((name, list)) = partition_comment(line) {
            doc.partitions.push(PartitionDecl {
                name,
                members: split_members(list),
                location: Location::Line {
                    line: n + 1,
                    column: 1,
                },
            });
        }
    }
    Ok(doc)
}
