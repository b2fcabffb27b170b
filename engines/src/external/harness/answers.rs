//! Each side's answers on one set and its paths: the external process's, asked over the
//! protocol in one round trip ([`ask`], [`requests`] and [`interpret`] for pipelined
//! batches), and the engines' ([`ours`]), on the expressions parsed as the CLI parses
//! them ([`parse_all`]).

use lpe::Dialect;

use super::report::Answer;
use crate::dialect::WireDialect;
use crate::engine::{bits, Engine};
use crate::external::client::{Client, Fault, FaultKind};
use crate::external::protocol::{AovSource, Body, Reply, Violation};

/// The AOV names of a set of `n`: `a0`, `a1`, ...
fn names(n: usize) -> Vec<String> {
    (0..n).map(|i| format!("a{i}")).collect()
}

/// Expression texts as the AOVs of a set, named `a0`, `a1`, ...
pub fn sources(exprs: &[String]) -> Vec<AovSource> {
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
pub fn requests<D: WireDialect>(
    registration: &D::Registration,
    aovs: &[AovSource],
    paths: &[String],
) -> [Body; 2] {
    [
        Body::Compile {
            aovs: aovs.to_vec(),
            registered: D::wire_registration(registration),
            // The client names its renderer, if it has one.
            renderer: None,
        },
        Body::Match {
            paths: paths.to_vec(),
        },
    ]
}

/// The external side of one set, asked in one round trip: one answer per path (a
/// rejection repeated), or `Ok(None)`: unsupported.
pub fn ask<D: WireDialect>(
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
pub fn interpret(
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
pub fn ours<D: Dialect>(
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

/// [`ours`] on at most one path: each engine's answer on it.
pub fn ours_on_one<D: Dialect>(
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

/// Parses expression texts as the CLI does, the first error as a rejection.
pub fn parse_all<D: WireDialect>(
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
