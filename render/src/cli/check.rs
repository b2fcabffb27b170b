//! `lpe-render check`: the invariant suite.

use std::time::Instant;

use lpe_render::aov::SceneDialect;

use crate::args::InputError;
use crate::render::print_invariants;

pub fn run<D: SceneDialect>(threads: Option<usize>) -> Result<bool, InputError> {
    let t0 = Instant::now();
    let list =
        lpe_render::verify::suite::check_suite::<D>(threads, &mut |s| eprintln!("  rendered {s}"))?;
    eprintln!("invariants:");
    let ok = print_invariants(&list);
    let failed = list.iter().filter(|i| i.failed()).count();
    eprintln!(
        "{} invariants, {} failed, {} not checked, in {:.1}s",
        list.len(),
        failed,
        list.iter().filter(|i| i.passed.is_none()).count(),
        t0.elapsed().as_secs_f64()
    );
    Ok(ok)
}
