//! Outputs: one OpenEXR file (beauty as `R G B`, each AOV as the layer `NAME.R NAME.G
//! NAME.B` of the same part, the layout every EXR reader understands), PNG previews, a
//! contact sheet, and the report (Markdown + JSON). Every file is written to a temporary
//! name in its directory and renamed into place, so a reader never sees half a file.

use exr::prelude::{
    read_all_flat_layers_from_file, AnyChannel, AnyChannels, Encoding, FlatSamples, Image, Layer,
    LayerAttributes, SmallVec, Vec2, WritableImage,
};
use glam::DVec3;
use image::{ImageFormat, Rgb, RgbImage};
use serde::Serialize;
use std::io::Cursor;
use std::path::{Path, PathBuf};

use crate::aovs::AovList;
use crate::check::Invariant;
use crate::film::Film;

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
fn layer_names(aovs: &AovList) -> Vec<Option<&str>> {
    std::iter::once(None)
        .chain(aovs.aovs.iter().map(|a| Some(a.name.as_str())))
        .collect()
}

/// The EXR file as bytes: 32-bit float channels, ZIP-compressed (lossless).
pub fn exr_bytes(film: &Film, aovs: &AovList) -> Result<Vec<u8>, String> {
    let size = Vec2(film.width, film.height);
    let mut channels = Vec::new();
    for (layer, name) in layer_names(aovs).into_iter().enumerate() {
        let pixels = film.layer(layer);
        for (c, letter) in ["R", "G", "B"].iter().enumerate() {
            let samples: Vec<f32> = pixels.iter().map(|p| p[c] as f32).collect();
            let channel = match name {
                None => letter.to_string(),
                Some(n) => format!("{n}.{letter}"),
            };
            channels.push(AnyChannel::new(channel.as_str(), FlatSamples::F32(samples)));
        }
    }
    let layer = Layer::new(
        size,
        LayerAttributes::default(),
        Encoding::SMALL_LOSSLESS,
        AnyChannels::sort(SmallVec::from_vec(channels)),
    );
    let mut buf = Cursor::new(Vec::new());
    Image::from_layer(layer)
        .write()
        .to_buffered(&mut buf)
        .map_err(|e| format!("encoding EXR: {e}"))?;
    Ok(buf.into_inner())
}

/// One RGB layer read back from an EXR file.
#[derive(Clone, Debug)]
pub struct ExrLayer {
    /// The layer name, `beauty` for the unprefixed `R G B` channels.
    pub name: String,
    pub width: usize,
    pub height: usize,
    /// Row-major RGB.
    pub pixels: Vec<[f32; 3]>,
}

/// Reads an EXR written by [`exr_bytes`] (or any RGB EXR with `NAME.R` layers) back.
pub fn read_exr(path: &Path) -> Result<Vec<ExrLayer>, String> {
    let image =
        read_all_flat_layers_from_file(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut layers: Vec<ExrLayer> = Vec::new();
    for part in &image.layer_data {
        let (w, h) = (part.size.0, part.size.1);
        for ch in &part.channel_data.list {
            let full = ch.name.to_string();
            let (layer, letter) = match full.rsplit_once('.') {
                Some((l, c)) => (l.to_string(), c.to_string()),
                None => ("beauty".to_string(), full.clone()),
            };
            let Some(c) = ["R", "G", "B"].iter().position(|x| *x == letter) else {
                continue;
            };
            let idx = match layers.iter().position(|l| l.name == layer) {
                Some(i) => i,
                None => {
                    layers.push(ExrLayer {
                        name: layer,
                        width: w,
                        height: h,
                        pixels: vec![[0.0; 3]; w * h],
                    });
                    layers.len() - 1
                }
            };
            for (p, v) in ch.sample_data.values_as_f32().enumerate() {
                layers[idx].pixels[p][c] = v;
            }
        }
    }
    Ok(layers)
}

/// Display transform shared by all previews: one exposure (from beauty) for every layer
/// so AOVs compare visually with beauty, then sRGB encoding with clipping.
pub struct Tonemap {
    exposure: f64,
}

impl Tonemap {
    /// Exposure that maps the mean beauty luminance to 0.18 (middle grey).
    pub fn from_beauty(film: &Film) -> Tonemap {
        let b = film.layer(0);
        let lum: f64 = b
            .iter()
            .filter(|v| v.is_finite())
            .map(|v| 0.2126 * v.x + 0.7152 * v.y + 0.0722 * v.z)
            .sum::<f64>()
            / b.len().max(1) as f64;
        Tonemap {
            exposure: if lum > 0.0 { 0.18 / lum } else { 1.0 },
        }
    }

    fn srgb(x: f64) -> u8 {
        let x = if x.is_finite() {
            x.clamp(0.0, 1.0)
        } else {
            0.0
        };
        let y = if x <= 0.003_130_8 {
            12.92 * x
        } else {
            1.055 * x.powf(1.0 / 2.4) - 0.055
        };
        (y * 255.0 + 0.5) as u8
    }

    pub fn image(&self, film: &Film, layer: usize) -> RgbImage {
        let px = film.layer(layer);
        RgbImage::from_fn(film.width as u32, film.height as u32, |x, y| {
            let v: DVec3 = px[y as usize * film.width + x as usize] * self.exposure;
            Rgb([Self::srgb(v.x), Self::srgb(v.y), Self::srgb(v.z)])
        })
    }
}

pub(crate) fn png_bytes(img: &RgbImage) -> Result<Vec<u8>, String> {
    let mut buf = Cursor::new(Vec::new());
    img.write_to(&mut buf, ImageFormat::Png)
        .map_err(|e| format!("encoding PNG: {e}"))?;
    Ok(buf.into_inner())
}

/// Columns of the contact sheet.
const SHEET_COLUMNS: usize = 6;

/// All layer images (same size, non-empty) side by side, in order, row by row.
pub fn contact_sheet(layers: &[RgbImage]) -> RgbImage {
    let (width, height) = layers[0].dimensions();
    let thumb_w = width.min(160);
    let thumb_h = ((height * thumb_w) / width).max(1);
    let gap = 4;
    let cols = SHEET_COLUMNS.min(layers.len()) as u32;
    let rows = layers.len().div_ceil(SHEET_COLUMNS) as u32;
    let mut sheet = RgbImage::from_pixel(
        cols * (thumb_w + gap) + gap,
        rows * (thumb_h + gap) + gap,
        Rgb([32, 32, 32]),
    );
    for (layer, img) in layers.iter().enumerate() {
        let thumb = image::imageops::thumbnail(img, thumb_w, thumb_h);
        let (c, r) = (
            (layer % SHEET_COLUMNS) as u32,
            (layer / SHEET_COLUMNS) as u32,
        );
        image::imageops::overlay(
            &mut sheet,
            &thumb,
            (gap + c * (thumb_w + gap)) as i64,
            (gap + r * (thumb_h + gap)) as i64,
        );
    }
    sheet
}

/// Timing of a render.
#[derive(Clone, Debug, Serialize)]
pub struct Timing {
    pub render_seconds: f64,
    pub total_seconds: f64,
    pub paths: u64,
    pub rays: u64,
    pub paths_per_second: f64,
    pub rays_per_second: f64,
}

#[derive(Clone, Debug, Serialize)]
pub struct AovEntry {
    pub name: String,
    pub source: String,
    pub expression: String,
}

/// Everything the report says, serialized as JSON and rendered as Markdown.
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    pub scene: String,
    pub width: usize,
    pub height: usize,
    pub spp: u32,
    pub seed: u64,
    pub threads: usize,
    pub matcher: String,
    pub timing: Timing,
    pub effects_plan: Vec<String>,
    /// The same plan as flags, for tools.
    pub effects: crate::plan::Plan,
    pub aovs: Vec<AovEntry>,
    pub invariants: Vec<Invariant>,
    pub notes: Vec<String>,
    pub rejected_samples: u64,
    pub rejected_aov_values: u64,
    pub files: Vec<String>,
    pub contact_sheet_order: Vec<String>,
}

impl Report {
    pub fn markdown(&self) -> String {
        let mut s = String::new();
        let t = &self.timing;
        s += &format!("# lpe-render report: `{}`\n\n", self.scene);
        s += &format!(
            "{}x{} pixels, {} samples per pixel, seed {}, {} threads, matcher: {}.\n\n",
            self.width, self.height, self.spp, self.seed, self.threads, self.matcher
        );
        s += "## Timing\n\n| render s | total s | paths | rays | paths/s | rays/s |\n|---|---|---|---|---|---|\n";
        s += &format!(
            "| {:.2} | {:.2} | {} | {} | {:.0} | {:.0} |\n\n",
            t.render_seconds,
            t.total_seconds,
            t.paths,
            t.rays,
            t.paths_per_second,
            t.rays_per_second
        );
        s += "## Effects plan\n\n";
        for l in &self.effects_plan {
            s += &format!("- `{l}`\n");
        }
        s += "\n## Invariants\n\n| invariant | measured | tolerance | result | detail |\n|---|---|---|---|---|\n";
        for i in &self.invariants {
            let r = match i.passed {
                Some(true) => "pass",
                Some(false) => "**FAIL**",
                None => "not checked",
            };
            s += &format!(
                "| {} | {:.3e} | {:.3e} | {} | {} |\n",
                i.name,
                i.measured,
                i.tolerance,
                r,
                i.detail.replace('|', "\\|")
            );
        }
        s += &format!(
            "\nSamples rejected as non-finite: {}; AOV-only values dropped: {}.\n",
            self.rejected_samples, self.rejected_aov_values
        );
        if !self.notes.is_empty() {
            s += "\n## Notes\n\n";
            for n in &self.notes {
                s += &format!("- {n}\n");
            }
        }
        s += "\n## AOVs\n\n| layer | source | expression |\n|---|---|---|\n";
        for a in &self.aovs {
            s += &format!(
                "| `{}` | `{}` | `{}` |\n",
                a.name,
                a.source.replace('|', "\\|"),
                a.expression.replace('|', "\\|")
            );
        }
        s += &format!(
            "\n## Files\n\n{}\n\nContact sheet, left to right, top to bottom: {}.\n",
            self.files
                .iter()
                .map(|f| format!("- `{f}`"))
                .collect::<Vec<_>>()
                .join("\n"),
            self.contact_sheet_order.join(", ")
        );
        s
    }
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
