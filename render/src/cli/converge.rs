//! `lpe-render converge`: accuracy against time on the known-answer scenes.

use std::time::Instant;

use lpe_render::verify::converge;

use crate::args::InputError;

pub fn run(quick: bool, out: &std::path::Path, threads: Option<usize>) -> Result<bool, InputError> {
    let mut cfg = if quick {
        converge::Config::quick()
    } else {
        converge::Config::default_run()
    };
    cfg.threads = threads;
    let t0 = Instant::now();
    let o = converge::run(&cfg, out, &mut |s| eprintln!("  {s}"))?;
    println!(
        "{}",
        lpe_render::verify::tables::converge(
            &o.summary,
            &["beauty", "direct", "bounce3", "directDiffuse"]
        )
    );
    println!("{}", o.accumulation);
    if !o.plot_text {
        eprintln!("note: no TrueType font found (set LPE_PLOT_FONT): plots drawn without text");
    }
    eprintln!(
        "converge: {} series in {:.1}s; wrote {}",
        o.summary.len(),
        t0.elapsed().as_secs_f64(),
        o.files
            .iter()
            .map(|f| f.display().to_string())
            .collect::<Vec<_>>()
            .join(", ")
    );
    Ok(true)
}
