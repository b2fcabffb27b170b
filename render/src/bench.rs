//! `lpe-render bench`: what LPE tracking costs.

use lpe::renderman::LobeMap;

use crate::aov::{AovError, AovList, SceneDialect};
use crate::integrator::{render, RenderError, Settings};
use crate::scene::Scene;

/// Why the bench could not run.
#[derive(Debug, thiserror::Error)]
pub enum BenchError {
    #[error(transparent)]
    Aov(#[from] AovError),
    #[error(transparent)]
    Render(#[from] RenderError),
}

/// `lpe-render bench`: cost of LPE tracking, the same scene and samples rendered with
/// beauty only (matcher off) and with 32 AOVs (in any dialect), back to back in each round (alternating
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

/// The bench's 32 AOVs in dialect `D`: its defaults, its extras
/// ([`SceneDialect::BENCH_EXTRA`]), then `bounces{k}`, paths of at least `4 + k` bounces.
pub fn aovs<D: SceneDialect>(
    scene: &Scene,
    registration: &D::Registration,
) -> Result<AovList<D>, AovError> {
    let mut aovs = AovList::defaults(scene, registration)?;
    for (n, s) in D::BENCH_EXTRA {
        if aovs.aovs.len() >= 32 {
            break;
        }
        aovs.push(n, s, registration)?;
    }
    let mut k = 0;
    while aovs.aovs.len() < 32 {
        aovs.push(
            &format!("bounces{k}"),
            &format!("C.{{{},}}{}", 4 + k, D::EMITTER),
            registration,
        )?;
        k += 1;
    }
    Ok(aovs)
}

/// The bench with the 32 AOVs of [`aovs`] in dialect `D`, nothing registered.
pub fn bench<D: SceneDialect>(
    scene: &Scene,
    lobes: &LobeMap,
    settings: &Settings,
    rounds: usize,
) -> Result<Bench, BenchError> {
    let aovs = aovs::<D>(scene, &D::Registration::default())?;
    let none = AovList::<D>::new();
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
    use lpe::renderman::{Config, RenderMan};
    use lpe::{AovSet, Options};

    /// The bench measures the eager DFA step in both dialects: a padding AOV that blew
    /// the set up (OSL sets attempt the DFA within 1 MiB) would time the lazy DFA, or
    /// fail to compile, instead.
    #[test]
    fn the_bench_sets_have_32_distinct_aovs_and_an_eager_dfa() {
        for name in ["cornell", "still-life"] {
            let scene = Scene::load(name, &Config::default().lobes).unwrap();
            has_32_distinct_aovs_and_an_eager_dfa::<RenderMan>(&scene);
            has_32_distinct_aovs_and_an_eager_dfa::<lpe::osl::Osl>(&scene);
        }
    }

    fn has_32_distinct_aovs_and_an_eager_dfa<D: SceneDialect>(scene: &Scene) {
        let (name, dialect) = (&scene.name, D::NAME);
        let list = aovs::<D>(scene, &Default::default()).unwrap();
        assert_eq!(list.aovs.len(), 32, "{name} {dialect}");
        let mut names: Vec<&str> = list.names().collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), 32, "{name} {dialect}: duplicate names");
        let set =
            AovSet::<D>::compile_under(&list.named(), &Default::default(), &Options::default())
                .unwrap();
        assert!(set.uses_dfa(), "{name} {dialect}: lazy");
        let warnings = set.warnings();
        assert!(warnings.is_empty(), "{name} {dialect}: {warnings:?}");
    }
}
