//! What `lpe-check diff --external` found, and how it prints: each side's [`Answer`], a
//! minimized [`Disagreement`], a [`Finding`] (a disagreement or a protocol fault), and
//! the [`Report`] of a run. Structured data only: the command line that replays a
//! finding is the caller's to write (`lpe-check` writes its own).

use std::fmt;

use lpe::Dialect;

use crate::dialect::WireDialect;
use crate::external::client::Fault;
use crate::external::protocol::AovSource;

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
    /// Whether two answers agree: the same matches, or both a rejection (positions and
    /// wording may differ between implementations).
    pub fn agrees(&self, other: &Answer) -> bool {
        match (self, other) {
            (Answer::Matches(a), Answer::Matches(b)) => a == b,
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

/// A minimized disagreement between the external matcher and the engines, in dialect
/// `D`: everything a replay of it needs (the set, the path, the registration).
#[derive(Clone, Debug)]
pub struct Disagreement<D: Dialect> {
    /// Case index (generated runs).
    pub case: Option<u64>,
    /// The minimized AOV set.
    pub aovs: Vec<AovSource>,
    /// The minimized path, in text form.
    pub path: String,
    /// What the case's expressions were parsed under (OSL's registered labels).
    pub registration: D::Registration,
    /// The external answer on them.
    pub external: Answer,
    /// Each engine's answer on them (`None`: it could not build the set).
    pub engines: Vec<(&'static str, Option<Answer>)>,
    /// The case before minimization.
    pub original: (Vec<AovSource>, String),
    /// Set when the minimized case no longer disagreed when asked again (a flaky
    /// matcher): the case shown is then the original one.
    pub note: Option<String>,
}

impl<D: Dialect> Disagreement<D> {
    /// The expressions of the set shown, in order.
    pub fn exprs(&self) -> Vec<String> {
        self.aovs.iter().map(|a| a.expr.clone()).collect()
    }
}

/// Something the run found.
#[derive(Clone, Debug)]
pub enum Finding<D: Dialect> {
    /// The external matcher answers differently from the engines.
    Disagreement(Box<Disagreement<D>>),
    /// The external process misbehaved.
    Fault {
        /// Case index, if in a generated run.
        case: Option<u64>,
        /// What happened, with the request.
        fault: Fault,
    },
}

impl<D: Dialect> Finding<D> {
    /// One line for the summary.
    pub fn summary(&self) -> String {
        match self {
            Finding::Disagreement(d) => format!(
                "disagreement{}: {} on `{}`",
                d.case.map_or(String::new(), |c| format!(" (case {c})")),
                d.exprs().join(" ; "),
                d.path
            ),
            Finding::Fault { case, fault } => format!(
                "{}{}",
                fault.kind.label(),
                case.map_or(String::new(), |c| format!(" (case {c})"))
            ),
        }
    }
}

/// The finding in full: a disagreement with the registration, each side's answer and
/// the original case; a fault with its request.
impl<D: WireDialect> fmt::Display for Finding<D> {
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
                let context = D::context(&d.registration);
                if !context.is_empty() {
                    writeln!(f, "  {context}")?;
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
                write!(f, "    path:   {}", d.original.1)?;
                if let Some(note) = &d.note {
                    write!(f, "\n  note: {note}")?;
                }
                Ok(())
            }
        }
    }
}

/// Totals of a run.
#[derive(Debug)]
pub struct Report<D: Dialect> {
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
    pub findings: Vec<Finding<D>>,
    /// Processes restarted after faults.
    pub restarts: u64,
    /// Why the run stopped before its last case, if it did.
    pub stopped: Option<String>,
}

impl<D: Dialect> Report<D> {
    /// The report of a run not started yet, with a matcher called `name`.
    pub fn new(name: Option<String>) -> Report<D> {
        Report {
            name,
            cases: 0,
            last_case: None,
            pairs: 0,
            matched: 0,
            unsupported: (0, None),
            uncompared: 0,
            findings: Vec::new(),
            restarts: 0,
            stopped: None,
        }
    }

    /// Disagreements found.
    pub fn disagreements(&self) -> usize {
        self.findings
            .iter()
            .filter(|f| matches!(f, Finding::Disagreement(_)))
            .count()
    }
}
