//! `lpe-render bench`: the cost of LPE tracking.

use lpe_render::aov::SceneDialect;
use lpe_render::integrator::{self, Settings};
use lpe_render::scene::Scene;

use crate::args::InputError;

pub fn run<D: SceneDialect>(
    scene: &str,
    spp: u32,
    res: (usize, usize),
    threads: Option<usize>,
    rounds: usize,
) -> Result<bool, InputError> {
    let lobes = lpe::renderman::LobeMap::default();
    let scene = Scene::load(scene, &lobes)?;
    let settings = Settings {
        width: res.0,
        height: res.1,
        spp,
        threads,
        ..Settings::default()
    };
    let b = lpe_render::bench::bench::<D>(&scene, &lobes, &settings, rounds)?;
    println!(
        "bench `{}` {}x{} {} spp, {} thread(s), {rounds} rounds, matcher: {}",
        scene.name,
        res.0,
        res.1,
        spp,
        threads.map_or("all".to_string(), |t| t.to_string()),
        integrator::ENGINE
    );
    print!(
        "{}",
        lpe_render::output::table::markdown(
            &["configuration", "best CPU s", "paths per CPU s"],
            [
                ("beauty only".to_string(), b.beauty_seconds),
                (format!("{} AOVs ({})", b.aov_count, D::NAME), b.aov_seconds),
            ]
            .map(|(what, t)| vec![
                what,
                format!("{t:.3}"),
                format!("{:.0}", b.paths as f64 / t)
            ]),
        )
    );
    println!(
        "LPE tracking overhead (median of {rounds} paired rounds): {:+.1}% CPU time, {:+.1}% wall clock",
        b.overhead * 100.0,
        b.wall_overhead * 100.0
    );
    Ok(true)
}
