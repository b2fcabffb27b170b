//! PNG previews and the contact sheet.

use glam::DVec3;
use image::{ImageFormat, Rgb, RgbImage};
use std::io::Cursor;

use super::error::OutputError;
use crate::film::Film;

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

pub fn png_bytes(img: &RgbImage) -> Result<Vec<u8>, OutputError> {
    let mut buf = Cursor::new(Vec::new());
    img.write_to(&mut buf, ImageFormat::Png)?;
    Ok(buf.into_inner())
}

/// Columns of the contact sheet.
const SHEET_COLUMNS: usize = 6;

/// Glyph cell of the bundled bitmap font (`font8x8`: 8 x 8 pixels, no system font
/// needed), with one pixel of leading.
const GLYPH: u32 = 8;
const LINE: u32 = GLYPH + 1;
/// A tile is at least this many glyphs wide, and a label wraps onto at most this many
/// lines, so AOV names up to 40 characters show whole.
const LABEL_CHARS: u32 = 20;
const LABEL_LINES: usize = 2;

/// `name` broken into lines of at most `per_line` characters, at most
/// [`LABEL_LINES`] of them; a longer name ends in `~`.
fn label_lines(name: &str, per_line: usize) -> Vec<String> {
    let chars: Vec<char> = name.chars().collect();
    let mut lines: Vec<String> = chars
        .chunks(per_line.max(1))
        .take(LABEL_LINES)
        .map(|c| c.iter().collect())
        .collect();
    if chars.len() > per_line.max(1) * LABEL_LINES {
        if let Some(last) = lines.last_mut() {
            last.pop();
            last.push('~');
        }
    }
    lines
}

/// Draws `text` with its top-left corner at `(x, y)`, clipped to the image.
fn draw_text(img: &mut RgbImage, x: u32, y: u32, text: &str, color: Rgb<u8>) {
    use font8x8::UnicodeFonts;
    for (k, ch) in text.chars().enumerate() {
        let glyph = font8x8::BASIC_FONTS
            .get(ch)
            .or_else(|| font8x8::BASIC_FONTS.get('?'))
            .unwrap_or([0; 8]);
        for (row, bits) in glyph.iter().enumerate() {
            for col in 0..GLYPH {
                if bits >> col & 1 == 1 {
                    let (px, py) = (x + k as u32 * GLYPH + col, y + row as u32);
                    if px < img.width() && py < img.height() {
                        img.put_pixel(px, py, color);
                    }
                }
            }
        }
    }
}

/// All layer images (same size, non-empty) side by side, in order, row by row, each
/// tile labelled with its layer's name (`names[i]` for `layers[i]`).
pub fn contact_sheet(layers: &[RgbImage], names: &[&str]) -> RgbImage {
    let (width, height) = layers[0].dimensions();
    let thumb_w = width.min(160);
    let thumb_h = ((height * thumb_w) / width).max(1);
    let tile_w = thumb_w.max(LABEL_CHARS * GLYPH);
    let label_h = LABEL_LINES as u32 * LINE + 2;
    let gap = 8;
    let cols = SHEET_COLUMNS.min(layers.len()) as u32;
    let rows = layers.len().div_ceil(SHEET_COLUMNS) as u32;
    let mut sheet = RgbImage::from_pixel(
        cols * (tile_w + gap) + gap,
        rows * (thumb_h + label_h + gap) + gap,
        Rgb([32, 32, 32]),
    );
    for (layer, img) in layers.iter().enumerate() {
        let thumb = image::imageops::thumbnail(img, thumb_w, thumb_h);
        let (c, r) = (
            (layer % SHEET_COLUMNS) as u32,
            (layer / SHEET_COLUMNS) as u32,
        );
        let (x0, y0) = (
            gap + c * (tile_w + gap),
            gap + r * (thumb_h + label_h + gap),
        );
        image::imageops::overlay(
            &mut sheet,
            &thumb,
            (x0 + (tile_w - thumb_w) / 2) as i64,
            y0 as i64,
        );
        let name = names.get(layer).copied().unwrap_or("");
        for (k, line) in label_lines(name, (tile_w / GLYPH) as usize)
            .iter()
            .enumerate()
        {
            draw_text(
                &mut sheet,
                x0,
                y0 + thumb_h + 2 + k as u32 * LINE,
                line,
                Rgb([230, 230, 230]),
            );
        }
    }
    sheet
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn labels_wrap_and_mark_what_they_cut() {
        assert_eq!(label_lines("beauty", 20), ["beauty"]);
        assert_eq!(
            label_lines("directSpecularIridescenceLobe", 20),
            ["directSpecularIrides", "cenceLobe"]
        );
        let long = "a".repeat(45);
        let cut = label_lines(&long, 20);
        assert_eq!(cut.len(), 2);
        assert_eq!(cut[1], format!("{}~", "a".repeat(19)));
    }

    #[test]
    fn every_tile_carries_ink_below_its_thumbnail() {
        let img = RgbImage::from_pixel(32, 32, Rgb([0, 0, 0]));
        let sheet = contact_sheet(&[img.clone(), img], &["beauty", "emissive"]);
        let band_has_ink = |x0: u32| {
            (x0..x0 + 8 * 6).any(|x| (40..40 + 9).any(|y| sheet.get_pixel(x, y)[0] > 200))
        };
        assert!(band_has_ink(8) && band_has_ink(8 + 160 + 8));
    }
}
