//! `lpe-check bench --analysis`: the equivalence check of `C.*D.{k}L` against
//! `C.*D.{k}[LO]` (they differ only in the last vertex; each side's DFA has `2^k`
//! states) timed on the two routes of `lpe::analysis`: the NFA route
//! (`compare_within`, antichain search) and the lazy-DFA search it replaced
//! (`compare_by_lazy_dfa`), each within the default budget. A Markdown table, one row
//! per `k`; a route that runs out of budget shows `undecided` with its time.

use std::time::Instant;

use lpe::analysis::{self, AnalysisBudget, Comparison, Decision};
use lpe::renderman::{parse, Path};

/// One route's answer on one `k`: seconds, and the witness length or `None` (undecided).
fn timed(
    route: impl FnOnce() -> Result<Decision<Comparison<Path>>, analysis::AnalysisError>,
) -> (f64, Option<usize>) {
    let start = Instant::now();
    let answer = route();
    let secs = start.elapsed().as_secs_f64();
    let len = match answer {
        Ok(Decision::Decided(c)) => c.second_only.map(|p| p.len()),
        _ => None,
    };
    (secs, len)
}

/// The table for `k` in `ks`; the lazy-DFA route is skipped past the first `k` it
/// leaves undecided (every larger `k` needs more states).
pub fn table(ks: std::ops::RangeInclusive<u32>) -> String {
    let budget = AnalysisBudget::default();
    let mut out = String::from(
        "| k | NFA route (s) | witness | lazy-DFA route (s) | witness |\n|---|---|---|---|---|\n",
    );
    let mut old_gave_up = false;
    for k in ks {
        let a = parse(&format!("C.*D.{{{k}}}L")).expect("the benchmark expression parses");
        let b = parse(&format!("C.*D.{{{k}}}[LO]")).expect("the benchmark expression parses");
        let (new_secs, new_len) = timed(|| analysis::compare_within(&a, &b, &budget));
        let cell = |len: Option<usize>| len.map_or("undecided".to_string(), |l| l.to_string());
        let old = if old_gave_up {
            "(skipped) | ".to_string()
        } else {
            let (secs, len) = timed(|| analysis::compare_by_lazy_dfa(&a, &b, &budget));
            old_gave_up = len.is_none();
            format!("{secs:.4} | {}", cell(len))
        };
        out.push_str(&format!(
            "| {k} | {new_secs:.4} | {} | {old} |\n",
            cell(new_len)
        ));
    }
    out
}
