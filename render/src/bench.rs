//! `lpe-render bench`: what LPE tracking costs.

use lpe::{LobeMap, Parser};

use crate::aov::{AovError, AovList};
use crate::integrator::RenderError;

/// Why the bench could not run.
#[derive(Debug, thiserror::Error)]
pub enum BenchError {
    #[error(transparent)]
    Aov(#[from] AovError),
    #[error(transparent)]
    Render(#[from] RenderError),
}
use crate::integrator::{render, Settings};
use crate::scene::Scene;

/// `lpe-render bench`: cost of LPE tracking, the same scene and samples rendered with
/// beauty only (matcher off) and with 32 AOVs, back to back in each round. The overhead
/// is the median over rounds of the paired time ratio, which resists load that drifts
/// during the run better than comparing separate best times.
pub struct Bench {
    pub beauty_seconds: f64,
    pub aov_seconds: f64,
    /// Median over rounds of `aov time / beauty time`, minus 1.
    pub overhead: f64,
    pub aov_count: usize,
    pub paths: u64,
}

pub fn bench(
    scene: &Scene,
    lobes: &LobeMap,
    parser: &Parser,
    settings: &Settings,
    rounds: usize,
) -> Result<Bench, BenchError> {
    let mut aovs = AovList::defaults(scene, parser)?;
    // Pad with distinct, plausible AOVs up to 32.
    let extra = [
        ("caustics", "lpe:caustics"),
        ("diffuseLegacy", "lpe:diffuse"),
        ("specularLegacy", "lpe:specular"),
        ("emissionLegacy", "lpe:emission"),
        ("twoBounce", "C.{2}[<L.>O]"),
        ("threeBounce", "C.{3}[<L.>O]"),
        ("diffuseOnly", "C<RD>+[<L.>O]"),
        ("specThenDiffuse", "C<RS>.*<RD>.*[<L.>O]"),
    ];
    for (n, s) in extra {
        if aovs.aovs.len() >= 32 {
            break;
        }
        aovs.push(n, s, parser)?;
    }
    let mut k = 0;
    while aovs.aovs.len() < 32 {
        aovs.push(
            &format!("bounces{k}"),
            &format!("C.{{{},}}[<L.>O]", 4 + k),
            parser,
        )?;
        k += 1;
    }
    let none = AovList::default();
    let (mut tb, mut ta) = (f64::INFINITY, f64::INFINITY);
    let mut ratios = Vec::new();
    let mut paths = 0;
    for _ in 0..rounds {
        let b = render(scene, &none, lobes, settings)?;
        let a = render(scene, &aovs, lobes, settings)?;
        tb = tb.min(b.seconds);
        ta = ta.min(a.seconds);
        ratios.push(a.seconds / b.seconds);
        paths = a.paths;
    }
    ratios.sort_by(f64::total_cmp);
    Ok(Bench {
        beauty_seconds: tb,
        aov_seconds: ta,
        overhead: ratios[ratios.len() / 2] - 1.0,
        aov_count: aovs.aovs.len(),
        paths,
    })
}
