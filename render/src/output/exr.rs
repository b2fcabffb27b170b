//! The OpenEXR file: beauty as `R G B`, each AOV as the layer `NAME.R NAME.G NAME.B` of
//! the same part, the layout every EXR reader understands.

use exr::prelude::{
    read_all_flat_layers_from_file, AnyChannel, AnyChannels, Encoding, FlatSamples, Image, Layer,
    LayerAttributes, SmallVec, Vec2, WritableImage,
};
use std::io::Cursor;
use std::path::Path;

use super::error::OutputError;
use lpe::Dialect;

use crate::aov::AovList;
use crate::film::Film;

/// The EXR file as bytes: 32-bit float channels, ZIP-compressed (lossless).
pub fn exr_bytes<D: Dialect>(film: &Film, aovs: &AovList<D>) -> Result<Vec<u8>, OutputError> {
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
    Image::from_layer(layer).write().to_buffered(&mut buf)?;
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
pub fn read_exr(path: &Path) -> Result<Vec<ExrLayer>, OutputError> {
    let image = read_all_flat_layers_from_file(path).map_err(|e| OutputError::Read {
        path: path.to_path_buf(),
        source: e,
    })?;
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

/// Layer names in file order: `None` is beauty.
pub(crate) fn layer_names<D: Dialect>(aovs: &AovList<D>) -> Vec<Option<&str>> {
    std::iter::once(None)
        .chain(aovs.aovs.iter().map(|a| Some(a.name.as_str())))
        .collect()
}
