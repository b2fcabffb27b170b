//! Judging one case: the external answers against every engine's, and a disagreement
//! minimized ([`super::minimize`]), asked again of both sides and recorded as a
//! [`Finding`].

use lpe::Dialect;

use super::answers::{ask, ours, ours_on_one, parse_all, sources};
use super::minimize::minimize;
use super::report::{Answer, Disagreement, Finding, Report};
use crate::dialect::{ShrinkDialect, WireDialect};
use crate::engine::Engine;
use crate::external::client::{Client, Fault};
use crate::external::protocol::AovSource;

/// One case as the external process is asked it: its index (generated runs), its
/// registration, and its expressions and paths as text.
#[derive(Clone, Debug)]
pub struct CaseText<D: Dialect> {
    /// The case's index in a generated run.
    pub case: Option<u64>,
    /// What the expressions are parsed under.
    pub registration: D::Registration,
    /// The expressions, in order (AOVs `a0`, `a1`, ...).
    pub exprs: Vec<String>,
    /// The paths.
    pub paths: Vec<String>,
}

/// Compares the external answers on one case with every engine's; a disagreement is
/// minimized (re-asking the process, within `max_restarts` restarts) and recorded.
pub fn judge<D: ShrinkDialect + WireDialect>(
    max_restarts: u64,
    client: &mut Client,
    engines: &[&dyn Engine<D>],
    item: &CaseText<D>,
    external: Result<Option<Vec<Answer>>, Fault>,
    report: &mut Report<D>,
) {
    let CaseText {
        case,
        registration,
        exprs,
        paths: path_texts,
    } = item;
    let case = *case;
    let aovs = sources(exprs);
    let parsed = parse_all::<D>(registration, exprs);
    // Generated paths always parse; given ones are checked by the caller.
    let paths: Vec<D::Path> = path_texts
        .iter()
        .map(|p| p.parse().ok())
        .collect::<Option<_>>()
        .unwrap_or_default();
    let external = match external {
        Ok(Some(answers)) => answers,
        Ok(None) => {
            report.unsupported.0 += 1;
            report.unsupported.1.get_or_insert_with(|| {
                let at = case.map_or(String::new(), |c| format!("case {c}: "));
                format!("{at}{}", exprs.join(" ; "))
            });
            return;
        }
        Err(fault) => {
            report.findings.push(Finding::Fault { case, fault });
            return;
        }
    };
    let ours = ours(engines, registration, &parsed, &paths);
    if ours.iter().all(|(_, a)| a.iter().all(Option::is_none)) {
        report.uncompared += 1;
        return;
    }
    for (k, ext) in external.iter().enumerate() {
        let culprit = ours
            .iter()
            .position(|(_, a)| a.get(k).cloned().flatten().is_some_and(|o| !o.agrees(ext)));
        let Some(culprit) = culprit else {
            if let Answer::Matches(bits) = ext {
                report.pairs += bits.len() as u64;
                report.matched += bits.iter().filter(|&&b| b).count() as u64;
            }
            continue;
        };
        let original = (aovs.clone(), path_texts.get(k).cloned().unwrap_or_default());
        let (aovs_min, path_min) = match (&parsed, paths.get(k)) {
            (Ok(exprs), Some(path)) => {
                // Minimized against the first engine that disagrees (the reference, unless
                // the engines disagree among themselves): every candidate recompiles it,
                // and the automata engines pay for large counts on every one. All engines
                // answer on the result.
                let judge = &engines[culprit..=culprit];
                let (e, p) = minimize(
                    max_restarts,
                    client,
                    registration,
                    judge,
                    (case, exprs.clone(), path.clone()),
                    report,
                );
                (
                    sources(&e.iter().map(|x| x.to_string()).collect::<Vec<_>>()),
                    p.to_string(),
                )
            }
            _ => original.clone(),
        };
        // Ask both sides again on the minimized case, for the report; a case that no
        // longer disagrees (a flaky matcher) is replaced by the original one.
        let mut shown = asked_again(
            engines,
            client,
            max_restarts,
            registration,
            (aovs_min, path_min),
            ext,
        );
        let mut note = None;
        if !shown.disagrees() && shown.aovs != original.0 {
            note = Some(
                "the minimized case agreed when asked again; the original case is shown".into(),
            );
            shown = asked_again(
                engines,
                client,
                max_restarts,
                registration,
                original.clone(),
                ext,
            );
        }
        report
            .findings
            .push(Finding::Disagreement(Box::new(Disagreement {
                case,
                aovs: shown.aovs,
                path: shown.path,
                registration: registration.clone(),
                external: shown.external,
                engines: shown.engines,
                original,
                note,
            })));
        return;
    }
}

/// A case asked again of both sides: the set, the path, and every answer.
struct Asked {
    aovs: Vec<AovSource>,
    path: String,
    external: Answer,
    engines: Vec<(&'static str, Option<Answer>)>,
}

impl Asked {
    fn disagrees(&self) -> bool {
        self.engines
            .iter()
            .any(|(_, a)| a.as_ref().is_some_and(|o| !o.agrees(&self.external)))
    }
}

/// Asks the external process and the engines about one set and path given as text
/// (what the process is sent is what the engines judge); `fallback` stands for the
/// external answer if the process cannot answer, or could only after a restart past
/// the budget of `max_restarts`.
fn asked_again<D: WireDialect>(
    engines: &[&dyn Engine<D>],
    client: &mut Client,
    max_restarts: u64,
    registration: &D::Registration,
    (aovs, path): (Vec<AovSource>, String),
    fallback: &Answer,
) -> Asked {
    let exprs: Vec<String> = aovs.iter().map(|a| a.expr.clone()).collect();
    let parsed = parse_all::<D>(registration, &exprs);
    let paths: Vec<D::Path> = path.parse().ok().into_iter().collect();
    let asked = if client.may_continue(max_restarts) {
        ask::<D>(client, registration, &aovs, std::slice::from_ref(&path))
    } else {
        Ok(None)
    };
    let external = match asked {
        Ok(Some(mut a)) if !a.is_empty() => a.swap_remove(0),
        _ => fallback.clone(),
    };
    let engines = ours_on_one(engines, registration, &parsed, &paths);
    Asked {
        aovs,
        path,
        external,
        engines,
    }
}
