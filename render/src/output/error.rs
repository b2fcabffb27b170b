//! Why an output could not be written: the error every writer of this module returns,
//! in a leaf of its own so that the writers do not import the module that re-exports
//! them.

use std::path::{Path, PathBuf};

/// Why an output could not be written (or read back).
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    #[error("writing {}: {source}", path.display())]
    Write {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("reading {}: {source}", path.display())]
    Read {
        path: PathBuf,
        source: ::exr::error::Error,
    },
    #[error("encoding EXR: {0}")]
    Exr(#[from] ::exr::error::Error),
    #[error("encoding PNG: {0}")]
    Png(#[from] image::ImageError),
    #[error("report JSON: {0}")]
    Json(#[from] serde_json::Error),
    #[error("CSV: {0}")]
    Csv(#[from] ::csv::Error),
    #[error("plot {}: {reason}", file.display())]
    Plot { file: PathBuf, reason: String },
}

impl OutputError {
    /// An I/O error writing `path`.
    pub fn write(path: &Path) -> impl FnOnce(std::io::Error) -> OutputError + '_ {
        move |source| OutputError::Write {
            path: path.to_path_buf(),
            source,
        }
    }
}
