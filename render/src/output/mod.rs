//! Outputs: one OpenEXR file (beauty as `R G B`, each AOV as the layer `NAME.R NAME.G
//! NAME.B` of the same part, the layout every EXR reader understands), PNG previews, a
//! contact sheet, and the report (Markdown + JSON). Every file is written to a temporary
//! name in its directory and renamed into place, so a reader never sees half a file.

use image::RgbImage;
use std::path::{Path, PathBuf};

use crate::aov::AovList;
use crate::film::Film;

mod exr;
mod png;
mod report;

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

/// Layer names in file order: `None` is beauty.
pub(crate) fn layer_names(aovs: &AovList) -> Vec<Option<&str>> {
    std::iter::once(None)
        .chain(aovs.aovs.iter().map(|a| Some(a.name.as_str())))
        .collect()
}

/// Writes the EXR, the PNG previews, the contact sheet and the report into `dir`;
/// returns the files written.
pub fn write_all(
    dir: &Path,
    film: &Film,
    aovs: &AovList,
    report: &mut Report,
) -> Result<Vec<PathBuf>, String> {
    let io = |p: &Path, e: std::io::Error| format!("writing {}: {e}", p.display());
    let mut files = Vec::new();
    let exr = dir.join(format!("{}.exr", report.scene));
    atomic_write(&exr, &exr_bytes(film, aovs)?).map_err(|e| io(&exr, e))?;
    files.push(exr);
    let tonemap = Tonemap::from_beauty(film);
    let images: Vec<RgbImage> = (0..film.layers).map(|l| tonemap.image(film, l)).collect();
    for (img, name) in images.iter().zip(layer_names(aovs)) {
        let p = dir
            .join("png")
            .join(format!("{}.png", name.unwrap_or("beauty")));
        atomic_write(&p, &png_bytes(img)?).map_err(|e| io(&p, e))?;
        files.push(p);
    }
    let sheet = dir.join("contact_sheet.png");
    atomic_write(&sheet, &png_bytes(&contact_sheet(&images))?).map_err(|e| io(&sheet, e))?;
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
    atomic_write(&md, report.markdown().as_bytes()).map_err(|e| io(&md, e))?;
    let j = serde_json::to_string_pretty(report).map_err(|e| format!("report JSON: {e}"))?;
    atomic_write(&json, j.as_bytes()).map_err(|e| io(&json, e))?;
    files.push(md);
    files.push(json);
    Ok(files)
}
