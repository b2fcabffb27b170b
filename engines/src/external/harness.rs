//! `lpe-check diff --external`: generated (or given) cases asked of an external matcher
//! and of the registered engines, disagreements minimized by re-asking the external
//! process, protocol faults reported with their request.
//!
//! Per case: `compile` the AOV set, then one batched `match` of all its paths. An
//! external `unsupported` reply (to `compile` or `match`) makes the case *unsupported*:
//! counted and reported in the summary, never a disagreement, and the minimizer never
//! steps onto an unsupported input. Whether an expression is an error is compared too:
//! the external rejecting a set every engine accepts, or accepting one lpe rejects, is a
//! disagreement (byte positions are shown, not compared: they legitimately differ).

use std::fmt;
use std::time::Duration;

use lpe::renderman::RenderMan;
use lpe::Dialect;

use super::client::{Client, Fault, FaultKind, StartError};
use super::protocol::{AovSource, Body, Reply, Violation};
use crate::dialect::EngineDialect;
use crate::differential::{generate_case, minimize_by, Generate, Run};
use crate::engine::{bits, Engine};

/// One side's verdict on a set and a path.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Answer {
    /// Per AOV, whether the path lands in it.
    Matches(Vec<bool>),
    /// The set does not compile: which AOV, where, why.
    Rejected {
        /// The AOV's index, if known.
        aov: Option<usize>,
        /// Byte position in its expression, if known.
        position: Option<usize>,
        /// The message.
        message: String,
    },
}

impl Answer {
    fn agrees(&self, other: &Answer) -> bool {
        match (self, other) {
            (Answer::Matches(a), Answer::Matches(b)) => a == b,
            // Both reject: positions and wording may differ between implementations.
            (Answer::Rejected { .. }, Answer::Rejected { .. }) => true,
            _ => false,
        }
    }

    fn show(&self, names: &[String]) -> String {
        match self {
            Answer::Matches(bits) => {
                let hit: Vec<&str> = names
                    .iter()
                    .zip(bits)
                    .filter(|(_, &b)| b)
                    .map(|(n, _)| n.as_str())
                    .collect();
                if hit.is_empty() {
                    "no AOV".into()
                } else {
                    hit.join(" ")
                }
            }
            Answer::Rejected {
                aov,
                position,
                message,
            } => {
                let aov = aov.map_or(String::new(), |i| {
                    format!(" in {}", names.get(i).map_or("?", |s| s.as_str()))
                });
                let at = position.map_or(String::new(), |p| format!(" at byte {p}"));
                format!("error{aov}{at}: {message}")
            }
        }
    }
}

/// A minimized disagreement between the external matcher and the engines.
#[derive(Clone, Debug)]
pub struct Disagreement {
    /// Case index (generated runs).
    pub case: Option<u64>,
    /// The minimized AOV set.
    pub aovs: Vec<AovSource>,
    /// The minimized path, in text form.
    pub path: String,
    /// What the case's expressions share (OSL: `registered: …`), or empty.
    pub context: String,
    /// The external answer on them.
    pub external: Answer,
    /// Each engine's answer on them (`None`: it could not build the set).
    pub engines: Vec<(&'static str, Option<Answer>)>,
    /// The case before minimization.
    pub original: (Vec<AovSource>, String),
    /// A command line that replays the minimized case.
    pub replay: String,
    /// Set when the minimized case no longer disagreed when asked again (a flaky
    /// matcher): the case shown is then the original one.
    pub note: Option<String>,
}

/// Something the run found.
#[derive(Clone, Debug)]
pub enum Finding {
    /// The external matcher answers differently from the engines.
    Disagreement(Box<Disagreement>),
    /// The external process misbehaved.
    Fault {
        /// Case index, if in a generated run.
        case: Option<u64>,
        /// What happened, with the request.
        fault: Fault,
    },
}

impl Finding {
    /// One line for the summary.
    pub fn summary(&self) -> String {
        match self {
            Finding::Disagreement(d) => {
                let exprs: Vec<&str> = d.aovs.iter().map(|a| a.expr.as_str()).collect();
                format!(
                    "disagreement{}: {} on `{}`",
                    d.case.map_or(String::new(), |c| format!(" (case {c})")),
                    exprs.join(" ; "),
                    d.path
                )
            }
            Finding::Fault { case, fault } => format!(
                "{}{}",
                fault.kind.label(),
                case.map_or(String::new(), |c| format!(" (case {c})"))
            ),
        }
    }
}

impl fmt::Display for Finding {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Finding::Fault { case, fault } => {
                if let Some(c) = case {
                    write!(f, "case {c}: ")?;
                }
                write!(f, "{fault}")
            }
            Finding::Disagreement(d) => {
                let names: Vec<String> = d.aovs.iter().map(|a| a.name.clone()).collect();
                match d.case {
                    Some(c) => {
                        writeln!(f, "case {c}: the external matcher disagrees (minimized):")?
                    }
                    None => writeln!(f, "the external matcher disagrees (minimized):")?,
                }
                if !d.context.is_empty() {
                    writeln!(f, "  {}", d.context)?;
                }
                for a in &d.aovs {
                    writeln!(f, "  aov {}: {}", a.name, a.expr)?;
                }
                writeln!(f, "  path:   {}", d.path)?;
                writeln!(f, "  {:>12}: {}", "external", d.external.show(&names))?;
                for (name, answer) in &d.engines {
                    match answer {
                        Some(a) => writeln!(f, "  {name:>12}: {}", a.show(&names))?,
                        None => writeln!(f, "  {name:>12}: could not build the set")?,
                    }
                }
                writeln!(f, "  from the original case:")?;
                for a in &d.original.0 {
                    writeln!(f, "    aov {}: {}", a.name, a.expr)?;
                }
                writeln!(f, "    path:   {}", d.original.1)?;
                if let Some(note) = &d.note {
                    writeln!(f, "  note: {note}")?;
                }
                write!(f, "  replay: {}", d.replay)
            }
        }
    }
}

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

/// Totals of a run.
#[derive(Debug, Default)]
pub struct Report {
    /// The matcher's name from its hello.
    pub name: Option<String>,
    /// Cases asked.
    pub cases: u64,
    /// The highest case index asked (generated runs).
    pub last_case: Option<u64>,
    /// Set/path pairs compared (one per AOV per path).
    pub pairs: u64,
    /// Pairs that matched.
    pub matched: u64,
    /// Cases the external answered `unsupported`, and the first reason.
    pub unsupported: (u64, Option<String>),
    /// Cases no engine could build (nothing to compare with).
    pub uncompared: u64,
    /// Everything found, in order.
    pub findings: Vec<Finding>,
    /// Processes restarted after faults.
    pub restarts: u64,
    /// Why the run stopped before its last case, if it did.
    pub stopped: Option<String>,
}

impl Report {
    /// Disagreements found.
    pub fn disagreements(&self) -> usize {
        self.findings
            .iter()
            .filter(|f| matches!(f, Finding::Disagreement(_)))
            .count()
    }
}

/// The AOV names of a set of `n`: `a0`, `a1`, ...
fn names(n: usize) -> Vec<String> {
    (0..n).map(|i| format!("a{i}")).collect()
}

fn sources(exprs: &[String]) -> Vec<AovSource> {
    names(exprs.len())
        .into_iter()
        .zip(exprs)
        .map(|(name, expr)| AovSource {
            name,
            expr: expr.clone(),
        })
        .collect()
}

/// The two requests that ask about one set: `compile`, then `match` of all its paths.
fn requests<D: EngineDialect>(
    registration: &D::Registration,
    aovs: &[AovSource],
    paths: &[String],
) -> [Body; 2] {
    [
        Body::Compile {
            aovs: aovs.to_vec(),
            registered: D::wire_registration(registration),
        },
        Body::Match {
            paths: paths.to_vec(),
        },
    ]
}

/// The external side of one set, asked in one round trip: one answer per path (a
/// rejection repeated), or `Ok(None)`: unsupported.
fn ask<D: EngineDialect>(
    client: &mut Client,
    registration: &D::Registration,
    aovs: &[AovSource],
    paths: &[String],
) -> Result<Option<Vec<Answer>>, Fault> {
    let (replies, fault) = client.pipeline(requests::<D>(registration, aovs, paths).into());
    match fault {
        Some(f) => Err(f),
        None => interpret(aovs, paths, &replies),
    }
}

/// The replies to [`requests`] as answers. After a rejected compile the match reply
/// is read but not used.
fn interpret(
    aovs: &[AovSource],
    paths: &[String],
    replies: &[Reply],
) -> Result<Option<Vec<Answer>>, Fault> {
    let lists = match replies {
        [Reply::Rejected(r), _] => {
            let rejected = Answer::Rejected {
                aov: r.aov,
                position: r.position,
                message: r.message.clone(),
            };
            return Ok(Some(vec![rejected; paths.len()]));
        }
        [Reply::Unsupported(_), _] | [_, Reply::Unsupported(_)] => return Ok(None),
        [Reply::Done, Reply::Matches(m)] => m,
        other => unreachable!("replies are checked against their requests: {other:?}"),
    };
    let mut answers = Vec::with_capacity(lists.len());
    for list in lists {
        let mut bits = vec![false; aovs.len()];
        for name in list {
            match aovs.iter().position(|a| &a.name == name) {
                Some(i) => bits[i] = true,
                None => {
                    return Err(Fault {
                        request: format!("match {paths:?}"),
                        kind: FaultKind::Reply {
                            line: format!("AOV name {name:?}"),
                            violation: Violation::Unknown(format!(
                                "the reply names `{name}`, not an AOV of the set"
                            )),
                        },
                    })
                }
            }
        }
        answers.push(Answer::Matches(bits));
    }
    Ok(Some(answers))
}

/// Our side: each engine's answer per path (`None`: could not build), or the parse
/// error shared by every engine.
fn ours<D: EngineDialect>(
    engines: &[&dyn Engine<D>],
    registration: &D::Registration,
    parsed: &Result<Vec<D::Lpe>, Answer>,
    paths: &[D::Path],
) -> Vec<(&'static str, Vec<Option<Answer>>)> {
    engines
        .iter()
        .map(|e| {
            let answers = match parsed {
                Err(rejected) => vec![Some(rejected.clone()); paths.len()],
                Ok(exprs) => match e.compile(exprs, registration) {
                    Ok(m) => paths
                        .iter()
                        .map(|p| Some(Answer::Matches(bits(m.which(p), exprs.len()))))
                        .collect(),
                    Err(_) => vec![None; paths.len()],
                },
            };
            (e.name(), answers)
        })
        .collect()
}

/// Parses expression texts as the CLI does, the first error as a rejection.
fn parse_all<D: EngineDialect>(
    registration: &D::Registration,
    exprs: &[String],
) -> Result<Vec<D::Lpe>, Answer> {
    exprs
        .iter()
        .enumerate()
        .map(|(i, e)| {
            D::parse(e, registration).map_err(|err| {
                let (position, message) = D::parse_error(&err);
                Answer::Rejected {
                    aov: Some(i),
                    position: Some(position),
                    message,
                }
            })
        })
        .collect()
}

/// A case: its index (generated runs), registration, expressions and paths as text.
type Item<D> = (
    Option<u64>,
    <D as Dialect>::Registration,
    Vec<String>,
    Vec<String>,
);

/// Cases per pipelined batch.
const BATCH: usize = 64;

/// Runs the cases against the external matcher.
pub fn run<D: Generate>(
    setup: &Setup<D>,
    cases: &Cases,
    engines: &[&dyn Engine<D>],
) -> Result<Report, StartError> {
    let client = Client::start(&setup.command, D::NAME, setup.timeout)?;
    Ok(run_items(setup, client, engines, items(setup, cases)))
}

/// The items of `cases`, and the stop count (no limit for a given case).
fn items<D: Generate>(setup: &Setup<D>, cases: &Cases) -> (usize, Vec<Item<D>>) {
    match cases {
        Cases::Given { exprs, paths } => (
            usize::MAX,
            vec![(
                None,
                setup.registration.clone(),
                exprs.to_vec(),
                paths.to_vec(),
            )],
        ),
        Cases::Generated(run) => {
            // Set algebra is this toolkit's extension: other matchers do not speak it.
            let cfg = D::without_set_algebra(D::config(run.max_size));
            let list = (run.first..run.first.saturating_add(run.cases))
                .map(|i| {
                    let c = generate_case::<D>(run.seed, i, &cfg, run.paths);
                    (Some(i), c.registration, texts(&c.exprs), texts(&c.paths))
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
fn run_items<D: EngineDialect>(
    setup: &Setup<D>,
    mut client: Client,
    engines: &[&dyn Engine<D>],
    (max_failures, list): (usize, Vec<Item<D>>),
) -> Report {
    let mut report = Report {
        name: client.name.clone(),
        ..Report::default()
    };
    let mut queue: std::collections::VecDeque<_> = list.into();
    'batches: while !queue.is_empty() {
        if !client.may_continue(setup.max_restarts) {
            report.stopped = Some(format!(
                "the external process failed again after {} restart(s) (--max-restarts {})",
                client.restarts, setup.max_restarts
            ));
            break;
        }
        // One round trip per batch: every case's compile and match, pipelined.
        let batch: Vec<Item<D>> = queue.drain(..queue.len().min(BATCH)).collect();
        let bodies: Vec<Body> = batch
            .iter()
            .flat_map(|(_, reg, exprs, paths)| requests::<D>(reg, &sources(exprs), paths))
            .collect();
        let (replies, fault) = client.pipeline(bodies);
        let answered = replies.len() / 2;
        let mut fault = fault;
        for (k, (case, registration, exprs, paths)) in batch.iter().enumerate() {
            if report.disagreements() >= max_failures {
                report.stopped = Some(format!("{max_failures} disagreement(s) found"));
                break 'batches;
            }
            let external = if k < answered {
                interpret(&sources(exprs), paths, &replies[2 * k..2 * k + 2])
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
            report.last_case = report.last_case.max(*case);
            judge(
                setup,
                &mut client,
                engines,
                *case,
                registration,
                exprs,
                paths,
                external,
                &mut report,
            );
        }
    }
    report.restarts = client.restarts;
    client.quit();
    report
}

/// Compares the external answers on one case with every engine's; a disagreement is
/// minimized and recorded.
#[allow(clippy::too_many_arguments)]
fn judge<D: EngineDialect>(
    setup: &Setup<D>,
    client: &mut Client,
    engines: &[&dyn Engine<D>],
    case: Option<u64>,
    registration: &D::Registration,
    exprs: &[String],
    path_texts: &[String],
    external: Result<Option<Vec<Answer>>, Fault>,
    report: &mut Report,
) {
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
                    setup,
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
        let budget = setup.max_restarts;
        let mut shown = asked_again(
            engines,
            client,
            budget,
            registration,
            (aovs_min, path_min),
            ext,
        );
        let mut note = None;
        if !shown.disagrees() && shown.aovs != original.0 {
            note = Some(
                "the minimized case agreed when asked again; the original case is shown".into(),
            );
            shown = asked_again(engines, client, budget, registration, original.clone(), ext);
        }
        let exprs_shown: Vec<String> = shown.aovs.iter().map(|a| a.expr.clone()).collect();
        report
            .findings
            .push(Finding::Disagreement(Box::new(Disagreement {
                case,
                replay: replay::<D>(setup, registration, &exprs_shown, &shown.path),
                aovs: shown.aovs,
                path: shown.path,
                context: D::context(registration),
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
fn asked_again<D: EngineDialect>(
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

fn ours_on_one<D: EngineDialect>(
    engines: &[&dyn Engine<D>],
    registration: &D::Registration,
    parsed: &Result<Vec<D::Lpe>, Answer>,
    paths: &[D::Path],
) -> Vec<(&'static str, Option<Answer>)> {
    ours(engines, registration, parsed, paths)
        .into_iter()
        .map(|(n, mut a)| (n, if a.is_empty() { None } else { a.swap_remove(0) }))
        .collect()
}

/// Shrinks a disagreement of case `case`, re-asking the external process at every
/// candidate. A candidate is what the process is sent: its printed text, which the
/// engines judge re-parsed (a tree whose text reads differently, or not at all, is
/// judged as that text). Each text is asked once: a candidate seen before keeps its
/// verdict, so one that crashed the process is never sent again. Faults met on the way
/// are findings of that case too; the candidate that caused one does not count as a
/// disagreement.
fn minimize<D: EngineDialect>(
    setup: &Setup<D>,
    client: &mut Client,
    registration: &D::Registration,
    engines: &[&dyn Engine<D>],
    (case, exprs, path): (Option<u64>, Vec<D::Lpe>, D::Path),
    report: &mut Report,
) -> (Vec<D::Lpe>, D::Path) {
    let mut verdicts: std::collections::HashMap<(Vec<String>, String), bool> =
        std::collections::HashMap::new();
    minimize_by::<D>(registration, exprs, path, |exprs, path| {
        let texts: Vec<String> = exprs.iter().map(|e| e.to_string()).collect();
        let key = (texts, path.to_string());
        if let Some(&verdict) = verdicts.get(&key) {
            return verdict;
        }
        if !client.may_continue(setup.max_restarts) {
            return false;
        }
        let verdict = disagrees_on_text(client, registration, engines, &key, case, report);
        verdicts.insert(key, verdict);
        verdict
    })
}

/// Whether the external process and some engine answer differently on one candidate,
/// given as the texts the process is sent.
fn disagrees_on_text<D: EngineDialect>(
    client: &mut Client,
    registration: &D::Registration,
    engines: &[&dyn Engine<D>],
    (texts, path): &(Vec<String>, String),
    case: Option<u64>,
    report: &mut Report,
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

/// The one-line command that replays a case.
fn replay<D: EngineDialect>(
    setup: &Setup<D>,
    registration: &D::Registration,
    exprs: &[String],
    path: &str,
) -> String {
    let mut words = vec![
        "lpe-check".to_string(),
        "diff".into(),
        "--external".into(),
        setup.command.clone(),
    ];
    // RenderMan is `--dialect`'s default.
    if D::NAME != RenderMan::NAME {
        words.extend(["--dialect".into(), D::NAME.to_string()]);
    }
    words.extend(D::replay_args(registration));
    for e in exprs {
        words.extend(["--expr".into(), e.clone()]);
    }
    words.extend(["--path".into(), path.to_string()]);
    shell_words::join(words)
}

#[cfg(test)]
mod tests {
    use lpe::osl::{Osl, Registered};
    use lpe::renderman::Parser;

    use super::*;

    fn setup<D: Dialect>() -> Setup<D> {
        Setup {
            command: String::new(),
            registration: D::Registration::default(),
            timeout: Duration::from_secs(1),
            max_restarts: 0,
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
        for (_, registered, texts, _) in &osl {
            let registered: &Registered = registered;
            for t in texts {
                let l = lpe::osl::parse(t, registered).unwrap();
                assert!(l.algebra.is_none(), "{t}");
                exprs += 1;
            }
        }
        // Without the filter about one in twelve would hold algebra.
        assert!(exprs >= 400, "{exprs}");
        let (_, renderman) = items(&setup::<RenderMan>(), &Cases::Generated(run));
        for (_, parser, texts, _) in &renderman {
            let parser: &Parser = parser;
            for t in texts {
                assert!(parser.parse(t).unwrap().algebra.is_none(), "{t}");
            }
        }
    }
}
