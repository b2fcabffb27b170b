//! PNG previews and the contact sheet.

use glam::DVec3;
use image::{ImageFormat, Rgb, RgbImage};
use std::io::Cursor;

use super::OutputError;
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
