//! `lpe-render bench`: what LPE tracking costs.

use lpe::renderman::{LobeMap, Parser};
use lpe::DialectName;

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
/// beauty only (matcher off) and with 32 AOVs (in either dialect), back to back in each round (alternating
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

/// Distinct, plausible AOVs the bench pads its list with, per dialect.
const RENDERMAN_EXTRA: [(&str, &str); 8] = [
    ("caustics", "lpe:caustics"),
    ("diffuseLegacy", "lpe:diffuse"),
    ("specularLegacy", "lpe:specular"),
    ("emissionLegacy", "lpe:emission"),
    ("twoBounce", "C.{2}[<L.>O]"),
    ("threeBounce", "C.{3}[<L.>O]"),
    ("diffuseOnly", "C<RD>+[<L.>O]"),
    ("specThenDiffuse", "C<RS>.*<RD>.*[<L.>O]"),
];
const OSL_EXTRA: [(&str, &str); 25] = [
    ("glossy", "C<.G>.*[LO]"),
    ("delta", "C<.S>.*[LO]"),
    ("directGlossy", "C<RG>[LO]"),
    ("indirectGlossy", "C<RG>.+[LO]"),
    ("directDelta", "C<RS>[LO]"),
    ("indirectDelta", "C<RS>.+[LO]"),
    ("glossyTransmission", "C<TG>.*[LO]"),
    ("deltaTransmission", "C<TS>.*[LO]"),
    ("caustics", "C<.D>.*<.[GS]>.*[LO]"),
    ("key", "C.*<L.'key'>"),
    ("fill", "C.*<L.'fill'>"),
    ("rim", "C.*<L.'rim'>"),
    ("lights", "C.*L"),
    ("objects", "C.*O"),
    ("floor", "C<.D'floor'>.*[LO]"),
    ("glass", "C<.S'glass'>.*[LO]"),
    ("directKey", "C<RD><L.'key'>"),
    ("indirectKey", "C<RD>.+<L.'key'>"),
    ("twoBounce", "C.{2}[LO]"),
    ("threeBounce", "C.{3}[LO]"),
    ("diffuseOnly", "C<RD>+[LO]"),
    ("specThenDiffuse", "C<R[GS]>.*<RD>.*[LO]"),
    ("diffuseThenGlossy", "C<RD>.*<RG>.*[LO]"),
    ("noDelta", "C[^S]*[LO]"),
    ("fourBouncesOrMore", "C.{4,}[LO]"),
];

/// The bench's 32 AOVs in `dialect`: the defaults, the extras above, then
/// `bounces{k}`, paths of at least `4 + k` bounces.
pub fn aovs(dialect: DialectName, scene: &Scene, parser: &Parser) -> Result<AovList, AovError> {
    let (mut aovs, extra, emitter) = match dialect {
        DialectName::RenderMan => (
            AovList::defaults(scene, parser)?,
            &RENDERMAN_EXTRA[..],
            "[<L.>O]",
        ),
        DialectName::Osl => (
            AovList::basic::<lpe::osl::Osl>(parser)?,
            &OSL_EXTRA[..],
            "[LO]",
        ),
    };
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
            &format!("C.{{{},}}{emitter}", 4 + k),
            parser,
        )?;
        k += 1;
    }
    Ok(aovs)
}

pub fn bench(
    scene: &Scene,
    lobes: &LobeMap,
    parser: &Parser,
    settings: &Settings,
    rounds: usize,
) -> Result<Bench, BenchError> {
    bench_in(
        DialectName::RenderMan,
        scene,
        lobes,
        parser,
        settings,
        rounds,
    )
}

/// [`bench`] with the 32 AOVs of [`aovs`] in `dialect`.
pub fn bench_in(
    dialect: DialectName,
    scene: &Scene,
    lobes: &LobeMap,
    parser: &Parser,
    settings: &Settings,
    rounds: usize,
) -> Result<Bench, BenchError> {
    let aovs = aovs(dialect, scene, parser)?;
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

fn median(xs: &mut [f64]) -> f64 {
    xs.sort_by(f64::total_cmp);
    xs[xs.len() / 2]
}

#[cfg(test)]
mod tests {
    use super::*;
    use lpe::renderman::Config;
    use lpe::with_dialect;
    use lpe::{AovSet, Options};

    /// The bench measures the eager DFA step in both dialects: a padding AOV that blew
    /// the set up (OSL sets attempt the DFA within 1 MiB) would time the lazy DFA, or
    /// fail to compile, instead.
    #[test]
    fn the_bench_sets_have_32_distinct_aovs_and_an_eager_dfa() {
        let cfg = Config::default();
        let parser = Parser::new(cfg.limits.clone(), cfg.macros.clone());
        for name in ["cornell", "still-life"] {
            let scene = Scene::load(name, &cfg.lobes).unwrap();
            for dialect in DialectName::ALL {
                let list = aovs(dialect, &scene, &parser).unwrap();
                assert_eq!(list.aovs.len(), 32, "{name} {dialect}");
                assert_eq!(list.dialect, dialect);
                let mut names: Vec<&str> = list.aovs.iter().map(|a| a.name.as_str()).collect();
                names.sort_unstable();
                names.dedup();
                assert_eq!(names.len(), 32, "{name} {dialect}: duplicate names");
                let (uses_dfa, warnings) = with_dialect!(dialect, D => {
                    let set = AovSet::<D>::compile_under(
                        &list.named::<D>(),
                        &Default::default(),
                        &Options::default(),
                    )
                    .unwrap();
                    (set.uses_dfa(), set.warnings().to_vec())
                });
                assert!(uses_dfa, "{name} {dialect}: lazy");
                assert!(warnings.is_empty(), "{name} {dialect}: {warnings:?}");
            }
        }
    }
}
