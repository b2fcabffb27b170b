//! `lpe-check diff --external 'CMD ARGS' --suite DIR`: the conformance suite (every
//! `*.toml` case file under DIR, `tests/testdata/README.md`) replayed through the
//! external-matcher protocol (docs/protocol.md).
//!
//! Each case's expressions are compiled as one set (`expr` then `same_as` as AOVs `e0`,
//! `e1`, ..., or the case's own AOVs) and its paths matched; each path must land in
//! exactly the AOVs the case expects. An `error` case must be rejected at `compile`.
//! One process is started per dialect the suite holds (the `hello` names it); a dialect
//! the matcher refuses in its hello is not run, and said so. Not sent: `ini` macros
//! (the protocol has no macro definitions) and `bad_path` checks (path texts are the
//! harness's to parse), counted as skipped.
//!
//! Every failure is printed as `FILE: case `NAME`: ...`, then a summary. Exit 0: every
//! case run passed; 3: any failure; 2: bad input (the suite does not load, the command
//! cannot start, or the matcher refuses every dialect of the suite).

use std::process::ExitCode;
use std::time::Duration;

use lpe::DialectName;
use lpe_engines::external::{AovSource, Client, Reply, StartError};
use lpe_engines::WireRegistration;
use lpe_testkit::suite::{load_dir, Loaded, Plan};

use super::args::Args;
use crate::input::bad_input;

/// What one replay found.
#[derive(Debug, Default)]
struct Tally {
    /// Cases sent.
    run: usize,
    /// Answers compared (per path and AOV, plus one per expected rejection).
    checked: usize,
    /// Cases the matcher answered `unsupported`.
    unsupported: usize,
    /// Cases the protocol cannot carry (`ini` macros, `bad_path`).
    skipped: usize,
    /// Cases of a dialect whose hello was refused.
    refused: usize,
    /// `FILE: case `NAME`: what went wrong`.
    failures: Vec<String>,
}

/// Runs `diff --external CMD --suite DIR`.
pub fn run(args: &Args, command: &str, dir: &std::path::Path) -> ExitCode {
    let cases = match load_dir(dir) {
        Ok(c) => c,
        Err(e) => return bad_input(format!("error: --suite {}: {e}", dir.display())),
    };
    if cases.is_empty() {
        return bad_input(format!(
            "error: --suite {}: no case files (*.toml) found",
            dir.display()
        ));
    }
    let timeout = Duration::from_millis(args.timeout_ms);
    let mut tally = Tally::default();
    println!("external: {command}; suite: {}", dir.display());
    for dialect in DialectName::ALL {
        let of_dialect: Vec<&Loaded> = cases.iter().filter(|c| c.dialect == dialect).collect();
        if of_dialect.is_empty() {
            continue;
        }
        let mut client = match Client::start(command, &dialect.to_string(), timeout) {
            Ok(c) => c,
            Err(StartError::Refused(why)) => {
                println!(
                    "{dialect}: {} cases not run: the matcher refused the hello: {why}",
                    of_dialect.len()
                );
                tally.refused += of_dialect.len();
                continue;
            }
            Err(e) => return bad_input(format!("error: {e}")),
        };
        for case in of_dialect {
            replay(&mut client, case, &mut tally);
        }
        client.quit();
    }
    if tally.run == 0 && tally.refused > 0 {
        return bad_input("error: the external matcher refused every dialect of the suite");
    }
    for f in &tally.failures {
        println!("{f}");
    }
    println!(
        "suite: {} cases run ({} answers checked), {} failed, {} unsupported by the matcher, \
         {} skipped (ini macros or path-text checks), {} not run (dialect refused)",
        tally.run,
        tally.checked,
        tally.failures.len(),
        tally.unsupported,
        tally.skipped,
        tally.refused
    );
    if tally.failures.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(3)
    }
}

fn answer_text(m: bool) -> &'static str {
    if m {
        "match"
    } else {
        "no-match"
    }
}

/// What `pick` takes out of `reply`; else `None`, with the reply counted: as unsupported,
/// or as a failure of the case at `case_at` that expected `expected`.
fn expect<T>(
    reply: Result<Reply, impl std::fmt::Display>,
    expected: &str,
    case_at: &str,
    tally: &mut Tally,
    pick: impl FnOnce(Reply) -> Result<T, Reply>,
) -> Option<T> {
    let failure = match reply.map(pick) {
        Ok(Ok(t)) => return Some(t),
        Ok(Err(Reply::Unsupported(_))) => {
            tally.unsupported += 1;
            return None;
        }
        Ok(Err(Reply::Rejected(r))) => {
            format!("expected {expected}, got a rejection: {}", r.message)
        }
        Ok(Err(other)) => format!("expected {expected}, got {other:?}"),
        Err(fault) => fault.to_string(),
    };
    tally.failures.push(format!("{case_at}: {failure}"));
    None
}

/// Sends one case and checks its answers.
fn replay(client: &mut Client, loaded: &Loaded, tally: &mut Tally) {
    let case = &loaded.case;
    let at = loaded.location();
    if case.ini.is_some() || (case.expr.is_none() && case.aovs.is_empty()) {
        tally.skipped += 1;
        return;
    }
    tally.run += 1;
    let plan = Plan::of(case);
    let names: Vec<String> = if case.aovs.is_empty() {
        (0..plan.sources.len()).map(|i| format!("e{i}")).collect()
    } else {
        case.aovs.iter().map(|a| a.name.clone()).collect()
    };
    let aovs: Vec<AovSource> = names
        .iter()
        .zip(&plan.sources)
        .map(|(name, expr)| AovSource {
            name: name.clone(),
            expr: expr.to_string(),
        })
        .collect();
    let registered =
        (loaded.dialect == DialectName::Osl).then(|| WireRegistration::from(&loaded.registered));
    client.renderer.clone_from(&loaded.profile);
    let compiled = client.compile(aovs, registered);
    if let Some(want) = &case.error {
        tally.checked += 1;
        match compiled {
            Ok(Reply::Rejected(_)) => {}
            Ok(Reply::Unsupported(_)) => tally.unsupported += 1,
            Ok(other) => tally.failures.push(format!(
                "{at}: `{}`: expected a rejection (a {} error at byte {}), got {other:?}",
                plan.label, want.kind, want.at
            )),
            Err(fault) => tally
                .failures
                .push(format!("{at}: `{}`: {fault}", plan.label)),
        }
        return;
    }
    let case_at = format!("{at}: `{}`", plan.label);
    let done = |r| match r {
        Reply::Done => Ok(()),
        other => Err(other),
    };
    if expect(compiled, "a compiled set", &case_at, tally, done).is_none() {
        return;
    }
    let paths: Vec<String> = plan.expected.iter().map(|(p, _)| p.to_string()).collect();
    let matches = |r| match r {
        Reply::Matches(m) => Ok(m),
        other => Err(other),
    };
    let Some(lands) = expect(
        client.match_paths(paths),
        "answers",
        &case_at,
        tally,
        matches,
    ) else {
        return;
    };
    for ((path, want), got) in plan.expected.iter().zip(&lands) {
        for (j, (&w, name)) in want.iter().zip(&names).enumerate() {
            tally.checked += 1;
            let g = got.contains(name);
            if g != w {
                let expr = if case.aovs.is_empty() {
                    plan.sources[j].to_string()
                } else {
                    format!("{name}={}", plan.sources[j])
                };
                tally.failures.push(format!(
                    "{at}: `{expr}` on `{path}`: expected {}, got {}",
                    answer_text(w),
                    answer_text(g)
                ));
            }
        }
        if let Some(extra) = got.iter().find(|n| !names.contains(n)) {
            tally.failures.push(format!(
                "{at}: on `{path}`: landed in `{extra}`, which is not an AOV of the set"
            ));
        }
    }
}
