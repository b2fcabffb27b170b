//! `lpe-render converge --quick`: regenerates bit for bit, its slopes say what the
//! estimators are (about -1 unbiased, about 0 at the clamp's bias floor), and it writes
//! its CSV, Markdown and plots.

use lpe_render::verify::converge::{self, Config, Summary};

fn run(dir: &std::path::Path, threads: usize) -> Vec<Summary> {
    let cfg = Config {
        threads: Some(threads),
        ..Config::quick()
    };
    converge::run(&cfg, dir, &mut |_| {}).unwrap().summary
}

fn find<'a>(rows: &'a [Summary], scene: &str, variant: &str, layer: &str) -> &'a Summary {
    rows.iter()
        .find(|r| r.last.scene == scene && r.last.variant == variant && r.last.layer == layer)
        .unwrap_or_else(|| panic!("{scene} / {variant} / {layer}"))
}

#[test]
fn quick_converge_is_deterministic_and_its_slopes_mean_what_they_say() {
    let dir = std::env::temp_dir().join(format!("lpe-converge-{}", std::process::id()));
    let a = run(&dir, 1);
    // Second run: cornell's reference now comes from the cache, and two threads.
    let b = run(&dir, 2);
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(
            x.last.mse.to_bits(),
            y.last.mse.to_bits(),
            "{} / {} / {}",
            x.last.scene,
            x.last.variant,
            x.last.layer
        );
    }
    for f in [
        "converge.csv",
        "converge.md",
        "converge.json",
        "converge.png",
        "converge.svg",
    ] {
        let len = std::fs::metadata(dir.join(f)).map(|m| m.len()).unwrap_or(0);
        assert!(len > 100, "{f}: {len} bytes");
    }
    for scene in ["point-over-plane", "sphere-over-plane"] {
        // Unbiased: MSE falls like 1/spp (the fit over 5 steps of one seed is loose).
        let s = find(&a, scene, "MIS", "beauty").slope.unwrap();
        assert!((-1.5..=-0.6).contains(&s), "{scene} MIS slope {s}");
        // Clamped: the bias dominates, the curve is flat.
        let c = find(&a, scene, "MIS, clamp 1x mean", "beauty")
            .slope
            .unwrap();
        assert!(c.abs() < 0.3, "{scene} clamp slope {c}");
    }
    // Every matcher engine renders the same image, beauty and every AOV, on every scene:
    // only the time differs.
    let mut compared = 0;
    for e in converge::MatcherRow::ALL.into_iter().skip(1) {
        let variant = format!("MIS, {}", e.name());
        for r in a.iter().filter(|r| r.last.variant == variant) {
            let m = find(&a, &r.last.scene, "MIS", &r.last.layer);
            assert_eq!(
                m.last.mse.to_bits(),
                r.last.mse.to_bits(),
                "{} / {variant} / {}",
                r.last.scene,
                r.last.layer
            );
            compared += 1;
        }
    }
    assert!(compared >= 4 * 4, "{compared} engine rows");
    // BSDF sampling never reaches a point light: relMSE ~ 1 (a black image).
    let r = find(&a, "point-over-plane", "BSDF only", "beauty")
        .last
        .rel_mse;
    assert!(r > 0.9, "{r}");
    let _ = std::fs::remove_dir_all(&dir);
}
