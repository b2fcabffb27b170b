//! Outputs: one OpenEXR file (beauty as `R G B`, each AOV as the layer `NAME.R NAME.G
//! NAME.B` of the same part, the layout every EXR reader understands), PNG previews, a
//! contact sheet, and the report (Markdown + JSON). Every file is written to a temporary
//! name in its directory and renamed into place, so a reader never sees half a file.

use image::RgbImage;
use std::path::{Path, PathBuf};

use lpe::Dialect;

use crate::aov::AovList;
use crate::film::Film;

/// Writes `bytes` to `path` atomically, naming the file in the error.
pub fn write_file(path: &Path, bytes: &[u8]) -> Result<(), OutputError> {
    atomic_write(path, bytes).map_err(OutputError::write(path))
}

mod error;
mod exr;
mod png;
mod report;
pub mod table;

pub use error::OutputError;
use exr::layer_names;
pub use exr::{exr_bytes, read_exr, ExrLayer};
pub use png::{contact_sheet, png_bytes, Tonemap};
pub use report::{AovEntry, Report, Timing};

/// Writes `bytes` to `path` atomically (temporary file in the same directory, then
/// rename, which replaces the target in one step on POSIX file systems).
pub fn atomic_write(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let dir = path.parent().unwrap_or(Path::new("."));
    std::fs::create_dir_all(dir)?;
    let name = path
        .file_name()
        .map_or("out".into(), |n| n.to_string_lossy().into_owned());
    let tmp = dir.join(format!(".{name}.tmp-{}", std::process::id()));
    let result = std::fs::write(&tmp, bytes).and_then(|_| std::fs::rename(&tmp, path));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// Writes the EXR, the PNG previews, the contact sheet and the report into `dir`;
/// returns the files written.
pub fn write_all<D: Dialect>(
    dir: &Path,
    film: &Film,
    aovs: &AovList<D>,
    report: &mut Report,
) -> Result<Vec<PathBuf>, OutputError> {
    let mut files = Vec::new();
    let exr = dir.join(format!("{}.exr", report.scene));
    write_file(&exr, &exr_bytes(film, aovs)?)?;
    files.push(exr);
    let tonemap = Tonemap::from_beauty(film);
    let images: Vec<RgbImage> = (0..film.layers).map(|l| tonemap.image(film, l)).collect();
    for (img, name) in images.iter().zip(layer_names(aovs)) {
        let p = dir
            .join("png")
            .join(format!("{}.png", name.unwrap_or("beauty")));
        write_file(&p, &png_bytes(img)?)?;
        files.push(p);
    }
    let sheet = dir.join("contact_sheet.png");
    let names: Vec<&str> = layer_names(aovs)
        .into_iter()
        .map(|n| n.unwrap_or("beauty"))
        .collect();
    write_file(&sheet, &png_bytes(&contact_sheet(&images, &names))?)?;
    files.push(sheet);
    let md = dir.join("report.md");
    let json = dir.join("report.json");
    report.files = files
        .iter()
        .chain([&md, &json])
        .map(|p| p.display().to_string())
        .collect();
    report.contact_sheet_order = layer_names(aovs)
        .into_iter()
        .map(|n| n.unwrap_or("beauty").to_string())
        .collect();
    write_file(&md, report.markdown().as_bytes())?;
    let j = serde_json::to_string_pretty(report)?;
    write_file(&json, j.as_bytes())?;
    files.push(md);
    files.push(json);
    Ok(files)
}
