//! The tables of `converge` and `stress` (Markdown through [`crate::output::table`]) and
//! `converge.csv` (through `csv`, one serde row per measurement).

use serde::Serialize;

use super::stress::Row;
use crate::film::Accumulation;
use crate::output::table::markdown;
use crate::output::OutputError;

/// One measurement: a variant on a scene at one spp, one layer.
#[derive(Clone, Debug, Serialize)]
pub struct Point {
    pub scene: String,
    pub variant: String,
    pub layer: String,
    pub spp: u32,
    pub seconds: f64,
    pub mse: f64,
    pub rel_mse: f64,
    /// Largest relative error of the basic-AOV partition vs beauty (cornell only).
    pub partition_error: Option<f64>,
}

/// One row of the summary: a (scene, variant, layer) series at its largest spp.
#[derive(Clone, Debug, Serialize)]
pub struct Summary {
    /// The series' measurement at its largest spp.
    #[serde(flatten)]
    pub last: Point,
    /// Slope of ln MSE vs ln spp (None: MSE is 0, the layer is exact).
    pub slope: Option<f64>,
    /// `1 / (MSE x seconds)` at the largest spp.
    pub efficiency: f64,
}

/// One line of `converge.csv`: numbers formatted as before (seconds to the microsecond,
/// errors in scientific notation), an empty cell when there is no partition.
#[derive(Serialize)]
struct CsvRow<'a> {
    scene: &'a str,
    variant: &'a str,
    layer: &'a str,
    spp: u32,
    seconds: String,
    mse: String,
    rel_mse: String,
    partition_error: String,
}

/// `converge.csv`: every measurement.
pub fn csv(points: &[Point]) -> Result<String, OutputError> {
    let mut w = ::csv::Writer::from_writer(Vec::new());
    for p in points {
        w.serialize(CsvRow {
            scene: &p.scene,
            variant: &p.variant,
            layer: &p.layer,
            spp: p.spp,
            seconds: format!("{:.6}", p.seconds),
            mse: format!("{:.6e}", p.mse),
            rel_mse: format!("{:.6e}", p.rel_mse),
            partition_error: p
                .partition_error
                .map_or(String::new(), |e| format!("{e:.3e}")),
        })?;
    }
    let bytes = w
        .into_inner()
        .map_err(|e| OutputError::Csv(e.into_error().into()))?;
    Ok(String::from_utf8(bytes).expect("the CSV writer writes the UTF-8 it is given"))
}

/// The table of [`Summary`] rows (`layers`: which layers to include, all if empty).
pub fn converge(rows: &[Summary], layers: &[&str]) -> String {
    markdown(
        &[
            "scene",
            "variant",
            "layer",
            "spp",
            "time s",
            "MSE",
            "relMSE",
            "slope",
            "efficiency 1/(MSE·s)",
            "partition err",
        ],
        rows.iter()
            .filter(|r| layers.is_empty() || layers.contains(&r.last.layer.as_str()))
            .map(|r| {
                let p = &r.last;
                vec![
                    p.scene.clone(),
                    p.variant.clone(),
                    p.layer.clone(),
                    p.spp.to_string(),
                    format!("{:.3}", p.seconds),
                    format!("{:.3e}", p.mse),
                    format!("{:.3e}", p.rel_mse),
                    r.slope.map_or("exact".into(), |x| format!("{x:.2}")),
                    if p.mse > 0.0 {
                        format!("{:.3e}", r.efficiency)
                    } else {
                        "∞".into()
                    },
                    p.partition_error.map_or("".into(), |e| format!("{e:.1e}")),
                ]
            }),
    )
}

/// Basic-AOV partition error of every film after `spp` mixed samples in one pixel.
pub fn accumulation(errors: &[(Accumulation, f64)], spp: u32) -> String {
    markdown(
        &[
            "film",
            "samples in the pixel",
            "basic AOVs vs beauty (max rel.)",
            "within 1e-6",
        ],
        errors.iter().map(|(a, e)| {
            vec![
                a.name().to_string(),
                spp.to_string(),
                format!("{e:.2e}"),
                if *e <= 1e-6 { "yes" } else { "**no**" }.to_string(),
            ]
        }),
    )
}

/// The `stress` table: one row per measured property.
pub fn stress(rows: &[Row]) -> String {
    markdown(
        &["case", "measure", "value", "bound", "ok"],
        rows.iter().map(|r| {
            vec![
                r.case.clone(),
                r.measure.clone(),
                format!("{:.3e}", r.value),
                format!("{:.3e}", r.bound),
                if r.passed { "yes" } else { "**NO**" }.to_string(),
            ]
        }),
    )
}
