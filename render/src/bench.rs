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
/// beauty only (matcher off) and with 32 AOVs, back to back in each round (alternating
/// which goes first, so neither always runs on a warmer cache). The overhead is the
/// median over rounds of the paired ratio of process CPU times, which resists load that
/// drifts during the run better than comparing separate best times, and does not count
/// the time a worker waits for a core on a shared machine; the wall-clock ratio is
/// reported beside it.
pub struct Bench {
    /// Best CPU time over rounds of the beauty-only render.
    pub beauty_seconds: f64,
    /// Best CPU time over rounds of the render with AOVs.
    pub aov_seconds: f64,
    /// Median over rounds of `aov CPU time / beauty CPU time`, minus 1.
    pub overhead: f64,
    /// The same median on wall-clock times.
    pub wall_overhead: f64,
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
    let aovs = aovs32(scene, parser)?;
    let none = AovList::default();
    let (mut tb, mut ta) = (f64::INFINITY, f64::INFINITY);
    let (mut cpu_ratios, mut wall_ratios) = (Vec::new(), Vec::new());
    let mut paths = 0;
    for round in 0..rounds {
        let (b, a) = if round % 2 == 0 {
            let b = render(scene, &none, lobes, settings)?;
            (b, render(scene, &aovs, lobes, settings)?)
        } else {
            let a = render(scene, &aovs, lobes, settings)?;
            (render(scene, &none, lobes, settings)?, a)
        };
        tb = tb.min(b.cpu_seconds);
        ta = ta.min(a.cpu_seconds);
        cpu_ratios.push(a.cpu_seconds / b.cpu_seconds);
        wall_ratios.push(a.seconds / b.seconds);
        paths = a.paths;
    }
    Ok(Bench {
        beauty_seconds: tb,
        aov_seconds: ta,
        overhead: median(&mut cpu_ratios) - 1.0,
        wall_overhead: median(&mut wall_ratios) - 1.0,
        aov_count: aovs.aovs.len(),
        paths,
    })
}

/// The bench's AOV list: the defaults, padded with distinct, plausible AOVs up to 32.
pub fn aovs32(scene: &Scene, parser: &Parser) -> Result<AovList, AovError> {
    let mut aovs = AovList::defaults(scene, parser)?;
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
    Ok(aovs)
}

fn median(xs: &mut [f64]) -> f64 {
    xs.sort_by(f64::total_cmp);
    xs[xs.len() / 2]
}
