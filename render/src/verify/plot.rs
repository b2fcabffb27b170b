//! Log-log plots of error against time for `lpe-render converge` (crate `plotters`,
//! bitmap and SVG backends).
//!
//! Text needs a TrueType font. plotters' `ab_glyph` feature takes one as bytes, so no
//! system font library is linked; we read DejaVu Sans (Debian `fonts-dejavu-core`) or
//! Liberation Sans from the usual paths, or `LPE_PLOT_FONT`. Without one, the plots are
//! drawn without text (lines and grid only) and the caller is told.

use crate::output::OutputError;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;
use std::sync::OnceLock;

/// One curve: its label and `(x, y)` points (both positive).
pub struct Line {
    pub label: String,
    pub points: Vec<(f64, f64)>,
}

/// One panel of the figure.
pub struct Panel {
    pub title: String,
    pub lines: Vec<Line>,
}

const FONT_PATHS: [&str; 3] = [
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf",
    "/usr/share/fonts/TTF/DejaVuSans.ttf",
];

/// Registers a font for "sans-serif" once; whether text can be drawn.
pub fn font_available() -> bool {
    static OK: OnceLock<bool> = OnceLock::new();
    *OK.get_or_init(|| {
        let env = std::env::var("LPE_PLOT_FONT").ok();
        let paths = env.iter().map(String::as_str).chain(FONT_PATHS);
        for p in paths {
            if let Ok(bytes) = std::fs::read(p) {
                // plotters keeps fonts for the life of the process.
                let bytes: &'static [u8] = Box::leak(bytes.into_boxed_slice());
                if plotters::style::register_font("sans-serif", FontStyle::Normal, bytes).is_ok() {
                    return true;
                }
            }
        }
        false
    })
}

/// Tableau 10 plus black and navy: `converge` draws 11 variants per panel, and a
/// repeated colour would make two of them indistinguishable.
const PALETTE: [RGBColor; 12] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(0, 0, 0),
    RGBColor(0, 0, 128),
];

/// Size of the whole figure: panels side by side in rows of two.
fn size(panels: usize) -> (u32, u32) {
    (1200, 450 * panels.div_ceil(2) as u32)
}

fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    panels: &[Panel],
    x_label: &str,
    y_label: &str,
    text: bool,
    file: &Path,
) -> Result<(), OutputError>
where
    DB::ErrorType: 'static,
{
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| OutputError::Plot {
        file: file.to_path_buf(),
        reason: e.to_string(),
    };
    root.fill(&WHITE).map_err(e)?;
    let areas = root.split_evenly((panels.len().div_ceil(2), 2));
    for (panel, area) in panels.iter().zip(areas.iter()) {
        let pts = || panel.lines.iter().flat_map(|l| l.points.iter());
        let pos = |v: f64| v > 0.0 && v.is_finite();
        let xs: Vec<f64> = pts().map(|p| p.0).filter(|v| pos(*v)).collect();
        let ys: Vec<f64> = pts().map(|p| p.1).filter(|v| pos(*v)).collect();
        if xs.is_empty() || ys.is_empty() {
            continue;
        }
        let range = |v: &[f64]| {
            let lo = v.iter().cloned().fold(f64::INFINITY, f64::min);
            let hi = v.iter().cloned().fold(0.0, f64::max);
            (lo / 1.5)..(hi * 1.5)
        };
        let mut builder = ChartBuilder::on(area);
        builder.margin(12);
        if text {
            builder
                .caption(&panel.title, ("sans-serif", 20))
                .x_label_area_size(40)
                .y_label_area_size(70);
        }
        let mut chart = builder
            .build_cartesian_2d(range(&xs).log_scale(), range(&ys).log_scale())
            .map_err(e)?;
        let mut mesh = chart.configure_mesh();
        if text {
            mesh.x_desc(x_label)
                .y_desc(y_label)
                .x_label_formatter(&|x| format!("{x:.0e}"))
                .y_label_formatter(&|y| format!("{y:.0e}"))
                .x_labels(6)
                .y_labels(6);
        } else {
            mesh.disable_x_axis().disable_y_axis();
        }
        mesh.draw().map_err(e)?;
        for (i, line) in panel.lines.iter().enumerate() {
            let color = PALETTE[i % PALETTE.len()];
            let points: Vec<(f64, f64)> = line
                .points
                .iter()
                .copied()
                .filter(|(x, y)| pos(*x) && pos(*y))
                .collect();
            let series = chart
                .draw_series(LineSeries::new(points.clone(), color.stroke_width(2)))
                .map_err(e)?;
            if text {
                series.label(&line.label).legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 16, y)], color.stroke_width(2))
                });
            }
            chart
                .draw_series(points.iter().map(|p| Circle::new(*p, 3, color.filled())))
                .map_err(e)?;
        }
        if text {
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK)
                .label_font(("sans-serif", 13))
                .position(SeriesLabelPosition::UpperRight)
                .draw()
                .map_err(e)?;
        }
    }
    root.present().map_err(e)
}

/// Writes the figure as `stem.png` and `stem.svg` in `dir`; returns whether text was
/// drawn.
pub fn write(
    dir: &Path,
    stem: &str,
    panels: &[Panel],
    x_label: &str,
    y_label: &str,
) -> Result<bool, OutputError> {
    let text = font_available();
    let file = dir.join(format!("{stem}.png"));
    let (w, h) = size(panels.len());
    let mut rgb = vec![0u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut rgb, (w, h)).into_drawing_area();
        draw(&root, panels, x_label, y_label, text, &file)?;
    }
    let img = image::RgbImage::from_raw(w, h, rgb).ok_or_else(|| OutputError::Plot {
        file: file.clone(),
        reason: "bitmap buffer of the wrong size".into(),
    })?;
    crate::output::write_file(&file, &crate::output::png_bytes(&img)?)?;
    let file = dir.join(format!("{stem}.svg"));
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (w, h)).into_drawing_area();
        draw(&root, panels, x_label, y_label, text, &file)?;
    }
    crate::output::write_file(&file, svg.as_bytes())?;
    Ok(text)
}
