//! # lpe-bench — the benchmarks of lpe, in one place
//!
//! The matcher benchmark shared by `lpe-check bench` (a table, [`run`] and [`table`])
//! and `cargo bench -p lpe-bench --bench matcher` (criterion): workloads, a path
//! sampler, the regex-automata baseline, and one timed loop per engine. The C-ABI step
//! bench is `cargo bench -p lpe-bench --bench step` (`benches/step.rs`: a step through
//! `lpe-capi`'s extern fns against a step from Rust); the Rust row that
//! `examples/c/step_bench.c` times stays an export of `lpe-capi` (`capi/src/bench.rs`),
//! since C links it from that library. The renderer's bench (`lpe-render bench`) stays
//! in `lpe-render`: it renders with the renderer's internals, and the `lpe-render`
//! binary that runs it would make the two packages depend on each other.
//!
//! Each dialect's rows are a sibling module with the same entry point, `run(cfg,
//! paths)`: [`renderman`] (every workload through every engine and caller shape, against
//! regex-automata) and [`osl`] (the OSL basic set on the same paths written as OSL
//! paths, timed round-robin with the RenderMan basic set, so their ratio is a same-run
//! comparison). What they share: `harness` (the flattened paths, the timed loop on
//! classes, the timing discipline, rows and errors), [`sample`] (the path sampler: the
//! paths are drawn as RenderMan paths, the vertices a renderer makes, and each dialect
//! writes them in its own notation), [`workload`] (the RenderMan AOV sets, the OSL rows'
//! peer among them), [`baseline`] (regex-automata's DFAs on their own encoding) and
//! [`shapes`] (the caller shapes: a renderer's loop, a bare table, a lazy DFA's own
//! cache).
//!
//! Every engine runs over the same sampled paths. The fast matcher is timed on vertices
//! (classification included: a label hash lookup per labelled vertex) and on classes
//! computed beforehand (what a renderer does once per material lobe); the regex-automata
//! DFAs step their own two-byte encoding, computed beforehand; the reference matcher runs
//! per whole path on a prefix of the paths. Before timing, every engine's answers are
//! compared with its dialect's reference on those paths.

pub mod baseline;
mod harness;
pub mod osl;
pub mod renderman;
pub mod sample;
pub mod shapes;
pub mod workload;

use std::time::Duration;

use tabled::builder::Builder;
use tabled::settings::object::Columns;
use tabled::settings::{Alignment, Style};

pub use harness::{classify, run_classes, BenchError, Config, Disagreement, Flat, Row};

/// Runs the benchmark: each dialect's rows on the same sampled paths; `Err` if any
/// engine disagrees with its dialect's reference.
pub fn run(cfg: &Config) -> Result<Vec<Row>, BenchError> {
    let paths = sample::paths(cfg.vertices, cfg.seed);
    let mut rows = Vec::new();
    let mut disagreements = Vec::new();
    for dialect_rows in [renderman::run, osl::run] {
        let (more, bad) = dialect_rows(cfg, &paths)?;
        rows.extend(more);
        disagreements.extend(bad);
    }
    if disagreements.is_empty() {
        Ok(rows)
    } else {
        Err(BenchError::Disagree(disagreements))
    }
}

fn human_bytes(b: usize) -> String {
    if b >= 1 << 20 {
        format!("{:.1} MiB", b as f64 / f64::from(1 << 20))
    } else {
        format!("{:.1} KiB", b as f64 / 1024.0)
    }
}

fn human_time(d: Duration) -> String {
    let us = d.as_secs_f64() * 1e6;
    if us >= 1000.0 {
        format!("{:.1} ms", us / 1000.0)
    } else {
        format!("{us:.0} µs")
    }
}

/// The rows as a Markdown table, the figure columns right-aligned.
pub fn table(rows: &[Row]) -> String {
    let mut b = Builder::default();
    b.push_record([
        "workload",
        "engine",
        "ns/vertex",
        "vs RA dense",
        "compile",
        "memory",
        "note",
    ]);
    for r in rows {
        b.push_record([
            r.workload.clone(),
            r.engine.clone(),
            r.ns_per_vertex.map_or("-".into(), |x| format!("{x:.2}")),
            r.ratio.map_or("-".into(), |x| format!("{x:.2}x")),
            r.compile.map_or("-".into(), human_time),
            r.memory.map_or("-".into(), human_bytes),
            r.note.clone(),
        ]);
    }
    let mut t = b.build();
    t.with(Style::markdown())
        .modify(Columns::new(FIGURES), Alignment::right());
    let text = t.to_string();
    // tabled pads the cells but writes no alignment row markers; Markdown readers need
    // `---:` to right-align the figure columns.
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    if let Some(rule) = lines.get_mut(1) {
        *rule = rule
            .split('|')
            .enumerate()
            .map(|(i, cell)| match i.checked_sub(1) {
                Some(col) if FIGURES.contains(&col) && cell.len() > 1 => {
                    format!("{}:", &cell[..cell.len() - 1])
                }
                _ => cell.to_string(),
            })
            .collect::<Vec<_>>()
            .join("|");
    }
    lines.join("\n") + "\n"
}

/// The right-aligned columns of [`table`]: ns/vertex, ratio, compile time, memory.
const FIGURES: std::ops::Range<usize> = 2..6;

#[cfg(test)]
mod tests {
    use super::*;
    use harness::row;

    #[test]
    fn table_is_markdown_with_right_aligned_figures() {
        let mut r = row("basic", "fast, on vertices");
        r.ns_per_vertex = Some(1.234);
        r.ratio = Some(0.5);
        r.compile = Some(Duration::from_micros(250));
        r.memory = Some(3 << 20);
        r.note = "DFA".into();
        let text = table(&[r, row("basic", "reference, per path")]);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 4, "{text}");
        assert!(lines[0].starts_with("| workload "), "{text}");
        let rule: Vec<&str> = lines[1].split('|').collect();
        assert!(rule[1].ends_with('-') && rule[3].ends_with(':'), "{text}");
        assert!(rule[6].ends_with(':') && rule[7].ends_with('-'), "{text}");
        let cells =
            |line: &str| -> Vec<String> { line.split('|').map(|c| c.trim().to_string()).collect() };
        let filled = [
            "",
            "basic",
            "fast, on vertices",
            "1.23",
            "0.50x",
            "250 µs",
            "3.0 MiB",
            "DFA",
            "",
        ];
        assert_eq!(cells(lines[2]), filled, "{text}");
        let empty = [
            "",
            "basic",
            "reference, per path",
            "-",
            "-",
            "-",
            "-",
            "",
            "",
        ];
        assert_eq!(cells(lines[3]), empty, "{text}");
        // Right-aligned: a figure's cell ends at the column rule.
        assert!(lines[2].contains(" 1.23 |"), "{text}");
    }
}
