//! Driving a run of `lpe-check diff --external`: generated (or given) cases sent to
//! the external matcher in pipelined batches, each judged against the engines
//! ([`super::judge`]), the totals and findings gathered in a [`Report`].

use std::collections::VecDeque;
use std::time::Duration;

use lpe::Dialect;

use super::answers::{interpret, requests, sources};
use super::judge::{judge, CaseText};
use super::report::Report;
use crate::dialect::{ShrinkDialect, WireDialect};
use crate::differential::{generate_case, Generate, Run};
use crate::engine::Engine;
use crate::external::client::{Client, StartError};
use crate::external::protocol::Body;

/// What to run, in dialect `D` (the dialect of the expressions and paths, and of the
/// `hello`).
#[derive(Clone, Debug)]
pub struct Setup<D: Dialect> {
    /// The external command line (split like a shell does).
    pub command: String,
    /// What [`Cases::Given`] is parsed under (OSL's registered labels); generated cases
    /// carry their own.
    pub registration: D::Registration,
    /// Per-request timeout.
    pub timeout: Duration,
    /// Stop after this many processes restarted after faults.
    pub max_restarts: u64,
    /// The renderer profile every compile request names (`--renderer`), if any.
    pub renderer: Option<String>,
}

/// Cases to ask.
#[derive(Clone, Debug)]
pub enum Cases {
    /// Generated, as `lpe-check diff` does.
    Generated(Run),
    /// One given set of expressions (source text) and paths (text): a replay.
    Given {
        /// Expressions, in order (AOVs `a0`, `a1`, ...).
        exprs: Vec<String>,
        /// Paths.
        paths: Vec<String>,
    },
}

/// Cases per pipelined batch.
const BATCH: usize = 64;

/// Runs the cases against the external matcher.
pub fn run<D: Generate>(
    setup: &Setup<D>,
    cases: &Cases,
    engines: &[&dyn Engine<D>],
) -> Result<Report<D>, StartError> {
    let mut client = Client::start(&setup.command, D::NAME, setup.timeout)?;
    client.renderer.clone_from(&setup.renderer);
    Ok(run_items(setup, client, engines, items(setup, cases)))
}

/// The items of `cases`, and the stop count (no limit for a given case).
fn items<D: Generate>(setup: &Setup<D>, cases: &Cases) -> (usize, Vec<CaseText<D>>) {
    match cases {
        Cases::Given { exprs, paths } => (
            usize::MAX,
            vec![CaseText {
                case: None,
                registration: setup.registration.clone(),
                exprs: exprs.to_vec(),
                paths: paths.to_vec(),
            }],
        ),
        Cases::Generated(run) => {
            // Set algebra is this toolkit's extension: other matchers do not speak it.
            let cfg = D::without_set_algebra(D::config(run.max_size));
            let list = (run.first..run.first.saturating_add(run.cases))
                .map(|i| {
                    let c = generate_case::<D>(run.seed, i, &cfg, run.paths);
                    CaseText {
                        case: Some(i),
                        registration: c.registration,
                        exprs: texts(&c.exprs),
                        paths: texts(&c.paths),
                    }
                })
                .collect();
            (run.max_failures, list)
        }
    }
}

fn texts<T: ToString>(xs: &[T]) -> Vec<String> {
    xs.iter().map(T::to_string).collect()
}

/// Runs the items against the external matcher, stopping after `max_failures`
/// disagreements.
fn run_items<D: ShrinkDialect + WireDialect>(
    setup: &Setup<D>,
    mut client: Client,
    engines: &[&dyn Engine<D>],
    (max_failures, list): (usize, Vec<CaseText<D>>),
) -> Report<D> {
    let mut report = Report::new(client.name.clone());
    let mut queue: VecDeque<_> = list.into();
    'batches: while !queue.is_empty() {
        if !client.may_continue(setup.max_restarts) {
            report.stopped = Some(format!(
                "the external process failed again after {} restart(s) (--max-restarts {})",
                client.restarts, setup.max_restarts
            ));
            break;
        }
        // One round trip per batch: every case's compile and match, pipelined.
        let batch: Vec<CaseText<D>> = queue.drain(..queue.len().min(BATCH)).collect();
        let bodies: Vec<Body> = batch
            .iter()
            .flat_map(|c| requests::<D>(&c.registration, &sources(&c.exprs), &c.paths))
            .collect();
        let (replies, fault) = client.pipeline(bodies);
        let answered = replies.len() / 2;
        let mut fault = fault;
        for (k, item) in batch.iter().enumerate() {
            if report.disagreements() >= max_failures {
                report.stopped = Some(format!("{max_failures} disagreement(s) found"));
                break 'batches;
            }
            let external = if k < answered {
                interpret(
                    &sources(&item.exprs),
                    &item.paths,
                    &replies[2 * k..2 * k + 2],
                )
            } else if let Some(f) = fault.take() {
                Err(f)
            } else {
                // Unanswered after a fault: asked again first in the next batch, so
                // that cases keep their order.
                for item in batch[k..].iter().rev() {
                    queue.push_front(item.clone());
                }
                break;
            };
            report.cases += 1;
            report.last_case = report.last_case.max(item.case);
            judge(
                setup.max_restarts,
                &mut client,
                engines,
                item,
                external,
                &mut report,
            );
        }
    }
    report.restarts = client.restarts;
    client.quit();
    report
}

#[cfg(test)]
mod tests {
    use lpe::osl::{Osl, Registered};
    use lpe::renderman::{Parser, RenderMan};

    use super::*;

    fn setup<D: Dialect>() -> Setup<D> {
        Setup {
            command: String::new(),
            registration: D::Registration::default(),
            timeout: Duration::from_secs(1),
            max_restarts: 0,
            renderer: None,
        }
    }

    /// Set algebra is this toolkit's extension: a generated run for an external matcher
    /// holds none, in either dialect (the in-process `diff` generates it).
    #[test]
    fn generated_external_cases_hold_no_set_algebra() {
        let run = Run {
            cases: 400,
            seed: 3,
            first: 0,
            max_size: 10,
            paths: 1,
            max_failures: 1,
        };
        let (_, osl) = items(&setup::<Osl>(), &Cases::Generated(run.clone()));
        let mut exprs = 0;
        for case in &osl {
            let registered: &Registered = &case.registration;
            for t in &case.exprs {
                let l = lpe::osl::parse(t, registered).unwrap();
                assert!(l.algebra.is_none(), "{t}");
                exprs += 1;
            }
        }
        // Without the filter about one in twelve would hold algebra.
        assert!(exprs >= 400, "{exprs}");
        let (_, renderman) = items(&setup::<RenderMan>(), &Cases::Generated(run));
        for case in &renderman {
            let parser: &Parser = &case.registration;
            for t in &case.exprs {
                assert!(parser.parse(t).unwrap().algebra.is_none(), "{t}");
            }
        }
    }
}
