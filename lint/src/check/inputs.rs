//! The files `lpe-check lint` is given, read in its order: ini files first (positional
//! or `--ini`: their macros and lobe mappings configure the parsing of every other
//! file), then the others; each file's [`FileStatus`] for the reports, and the
//! documents that could be read. `--partition` lists become [`PartitionDecl`]s over the
//! AOVs of every file.

use std::path::{Path, PathBuf};

use super::json::FileStatus;
use crate::read::{self, Limits};
use crate::{Document, Format, Location, PartitionDecl, ReadError};

/// The files as given (`ini` first), split into ini files and the others, each in order.
pub fn split<'a>(ini: Option<&'a Path>, files: &'a [PathBuf]) -> (Vec<&'a Path>, Vec<&'a Path>) {
    ini.into_iter()
        .chain(files.iter().map(PathBuf::as_path))
        .partition(|p| read::format_of(p) == Some(Format::Ini))
}

/// Every file read: the configuration the ini files built, one status per file, and the
/// documents of the files that could be read.
pub struct Inputs {
    /// Built-in macros and lobe mappings plus every ini file's.
    pub config: lpe::renderman::Config,
    /// One per file, in reading order.
    pub statuses: Vec<FileStatus>,
    /// The files read, in reading order.
    pub docs: Vec<Document>,
}

/// Reads `inis` into the configuration (and their partitions), then `others`; a file
/// that cannot be read is recorded in its status, and the other files are still read.
pub fn read_all(inis: &[&Path], others: &[&Path], limits: &Limits) -> Inputs {
    read_all_by(inis, others, limits, &mut |path| {
        read::read_file(path, limits)
    })
}

/// [`read_all`], with the files other than ini files read by `read_other` (the Python
/// package hands over a stage it read through Pixar's USD).
pub fn read_all_by(
    inis: &[&Path],
    others: &[&Path],
    limits: &Limits,
    read_other: &mut dyn FnMut(&Path) -> Result<Document, ReadError>,
) -> Inputs {
    let mut config = lpe::renderman::Config::default();
    let mut statuses = Vec::new();
    let mut docs = Vec::new();
    for &path in inis {
        let read = read::ini::read_into(path, limits, &mut config);
        record(path, read, &mut statuses, &mut docs);
    }
    for &path in others {
        record(path, read_other(path), &mut statuses, &mut docs);
    }
    Inputs {
        config,
        statuses,
        docs,
    }
}

/// `--partition` lists (`NAME,NAME,...`), named `--partition #1`, `#2`, ... in order.
pub fn command_line_partitions(lists: &[String]) -> Vec<PartitionDecl> {
    lists
        .iter()
        .enumerate()
        .map(|(i, list)| PartitionDecl {
            name: format!("--partition #{}", i + 1),
            members: crate::decl::split_members(list),
            location: Location::Line { line: 0, column: 0 },
        })
        .collect()
}

fn record(
    path: &Path,
    read: Result<Document, ReadError>,
    statuses: &mut Vec<FileStatus>,
    docs: &mut Vec<Document>,
) {
    statuses.push(FileStatus {
        file: path.display().to_string(),
        format: read::format_of(path).map(Format::name),
        error: read.as_ref().err().map(ToString::to_string),
    });
    if let Ok(doc) = read {
        docs.push(doc);
    }
}
