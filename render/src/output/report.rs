//! The report (Markdown + JSON): what was rendered, how long it took, the effects plan,
//! the invariants and the files written.

use serde::Serialize;

use super::table::markdown;

use lpe::Dialect;

use crate::aov::AovList;
use crate::integrator::{Render, Settings};
use crate::invariant::Invariant;
use crate::scene::Scene;

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
    /// The dialect the AOVs are written in (`renderman` or `osl`).
    pub dialect: String,
    pub timing: Timing,
    pub effects_plan: Vec<String>,
    /// The same plan as flags, for tools.
    pub effects: crate::aov::plan::Plan,
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
            "{}x{} pixels, {} samples per pixel, seed {}, {} threads, matcher: {}, AOVs in the \
             {} dialect.\n\n",
            self.width, self.height, self.spp, self.seed, self.threads, self.matcher, self.dialect
        );
        s += "## Timing\n\n";
        s += &markdown(
            &["render s", "total s", "paths", "rays", "paths/s", "rays/s"],
            [vec![
                format!("{:.2}", t.render_seconds),
                format!("{:.2}", t.total_seconds),
                t.paths.to_string(),
                t.rays.to_string(),
                format!("{:.0}", t.paths_per_second),
                format!("{:.0}", t.rays_per_second),
            ]],
        );
        s += "\n";
        s += "## Effects plan\n\n";
        for l in &self.effects_plan {
            s += &format!("- `{l}`\n");
        }
        s += "\n## Invariants\n\n";
        s += &markdown(
            &["invariant", "measured", "tolerance", "result", "detail"],
            self.invariants.iter().map(|i| {
                let r = match i.passed {
                    Some(true) => "pass",
                    Some(false) => "**FAIL**",
                    None => "not checked",
                };
                vec![
                    i.name.clone(),
                    i.measured_text(),
                    i.tolerance_text(),
                    r.to_string(),
                    i.detail.replace('|', "\\|"),
                ]
            }),
        );
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
        s += "\n## AOVs\n\n";
        s += &markdown(
            &["layer", "source", "expression"],
            self.aovs.iter().map(|a| {
                vec![
                    format!("`{}`", a.name),
                    format!("`{}`", a.source.replace('|', "\\|")),
                    format!("`{}`", a.expression.replace('|', "\\|")),
                ]
            }),
        );
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

impl Report {
    /// The report of one render: `threads` is the worker count it ran with; the files,
    /// the contact sheet order and the total time are filled in when the outputs are
    /// written.
    pub fn new<D: Dialect>(
        scene: &Scene,
        settings: &Settings,
        threads: usize,
        aovs: &AovList<D>,
        render: &Render,
        invariants: Vec<Invariant>,
    ) -> Report {
        Report {
            scene: scene.name.clone(),
            width: settings.width,
            height: settings.height,
            spp: settings.spp,
            seed: settings.seed,
            threads,
            matcher: crate::integrator::ENGINE.into(),
            dialect: D::NAME.to_string(),
            timing: Timing {
                render_seconds: render.seconds,
                total_seconds: 0.0,
                paths: render.paths,
                rays: render.rays,
                paths_per_second: render.paths as f64 / render.seconds,
                rays_per_second: render.rays as f64 / render.seconds,
            },
            effects_plan: render.plan.describe(),
            effects: render.plan,
            aovs: aovs
                .aovs
                .iter()
                .map(|a| AovEntry {
                    name: a.name.clone(),
                    source: a.source.clone(),
                    expression: a.expr.to_string(),
                })
                .collect(),
            invariants,
            notes: aovs.notes.clone(),
            rejected_samples: render.film.rejected,
            rejected_aov_values: render.film.aov_rejected,
            files: Vec::new(),
            contact_sheet_order: Vec::new(),
        }
    }
}
