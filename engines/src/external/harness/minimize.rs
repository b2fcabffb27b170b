//! Minimizing a disagreement with an external matcher: the differential harness's
//! minimizer ([`crate::differential::minimize_by`], the dialect's shrinking moves) with
//! a failure test that re-asks the external process at every candidate.

use std::collections::HashMap;

use super::answers::{ask, ours, parse_all, sources};
use super::report::{Finding, Report};
use crate::dialect::{ShrinkDialect, WireDialect};
use crate::differential::minimize_by;
use crate::engine::Engine;
use crate::external::client::Client;

/// Shrinks a disagreement of case `case`, re-asking the external process at every
/// candidate (while it may restart, within `max_restarts`). A candidate is what the
/// process is sent: its printed text, which the engines judge re-parsed (a tree whose
/// text reads differently, or not at all, is judged as that text). Each text is asked
/// once: a candidate seen before keeps its verdict, so one that crashed the process is
/// never sent again. Faults met on the way are findings of that case too; the candidate
/// that caused one does not count as a disagreement.
pub fn minimize<D: ShrinkDialect + WireDialect>(
    max_restarts: u64,
    client: &mut Client,
    registration: &D::Registration,
    engines: &[&dyn Engine<D>],
    (case, exprs, path): (Option<u64>, Vec<D::Lpe>, D::Path),
    report: &mut Report<D>,
) -> (Vec<D::Lpe>, D::Path) {
    let mut verdicts: HashMap<(Vec<String>, String), bool> = HashMap::new();
    minimize_by::<D>(registration, exprs, path, |exprs, path| {
        let texts: Vec<String> = exprs.iter().map(|e| e.to_string()).collect();
        let key = (texts, path.to_string());
        if let Some(&verdict) = verdicts.get(&key) {
            return verdict;
        }
        if !client.may_continue(max_restarts) {
            return false;
        }
        let verdict = disagrees_on_text(client, registration, engines, &key, case, report);
        verdicts.insert(key, verdict);
        verdict
    })
}

/// Whether the external process and some engine answer differently on one candidate,
/// given as the texts the process is sent.
fn disagrees_on_text<D: WireDialect>(
    client: &mut Client,
    registration: &D::Registration,
    engines: &[&dyn Engine<D>],
    (texts, path): &(Vec<String>, String),
    case: Option<u64>,
    report: &mut Report<D>,
) -> bool {
    let aovs = sources(texts);
    let ext = match ask::<D>(client, registration, &aovs, std::slice::from_ref(path)) {
        Ok(Some(mut a)) if a.len() == 1 => a.swap_remove(0),
        Ok(_) => return false,
        Err(fault) => {
            report.findings.push(Finding::Fault { case, fault });
            return false;
        }
    };
    let Ok(path) = path.parse::<D::Path>() else {
        return false;
    };
    let parsed = parse_all::<D>(registration, texts);
    ours(engines, registration, &parsed, std::slice::from_ref(&path))
        .iter()
        .any(|(_, a)| a[0].as_ref().is_some_and(|o| !o.agrees(&ext)))
}
