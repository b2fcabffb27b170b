//! The external-matcher harness against real processes: the independent Python matcher
//! (clean: agreement; with its planted bug: found and minimized), and adapters that
//! break the protocol on purpose (each misbehaviour a finding, the run finishes).
//!
//! Needs `python3`: a test that runs an adapter fails, naming what to install, when it is
//! not installed (a skip would read as a pass).

use std::path::PathBuf;
use std::time::Duration;

use lpe::renderman::RenderMan;
use lpe_engines::differential::Run;
use lpe_engines::external::{self, Answer, Cases, FaultKind, Finding, Report, Setup};

fn repo(rel: &str) -> String {
    let p: PathBuf = [env!("CARGO_MANIFEST_DIR"), "..", rel].iter().collect();
    p.to_string_lossy().into_owned()
}

fn setup(command: String, timeout_ms: u64) -> Setup<RenderMan> {
    Setup {
        command,
        registration: lpe::renderman::Parser::default(),
        timeout: Duration::from_millis(timeout_ms),
        max_restarts: 20,
        renderer: None,
    }
}

fn generated(cases: u64, seed: u64) -> Cases {
    Cases::Generated(Run {
        cases,
        seed,
        first: 0,
        max_size: 10,
        paths: 4,
        max_failures: 1,
    })
}

fn naive(flags: &str) -> String {
    format!(
        "python3 {} {flags}",
        shell_quote(&repo("examples/python/naive_matcher.py"))
    )
}

fn shell_quote(s: &str) -> String {
    format!("'{}'", s.replace('\'', r"'\''"))
}

fn run(command: String, cases: &Cases, timeout_ms: u64) -> Report<RenderMan> {
    external::run(
        &setup(command, timeout_ms),
        cases,
        &lpe_engines::all::<RenderMan>(),
    )
    .expect("starts")
}

#[test]
fn the_naive_python_matcher_agrees_with_every_engine() {
    lpe_testkit::host::require_python3();
    let r = run(naive(""), &generated(300, 11), 5000);
    if let Some(f) = r.findings.first() {
        panic!("{f}");
    }
    assert_eq!(r.cases, 300);
    assert_eq!(r.unsupported.0, 0, "{:?}", r.unsupported);
    assert_eq!(r.uncompared, 0);
    // Every case compared its AOVs on its paths, and both answers occur.
    assert!(r.pairs >= 300 * 4, "{}", r.pairs);
    assert!(r.matched > 0 && r.matched < r.pairs);
    assert_eq!(r.restarts, 0);
}

#[test]
fn the_planted_bug_is_found_and_minimized_by_re_asking() {
    lpe_testkit::host::require_python3();
    let r = run(naive("--plant-bug"), &generated(400, 11), 5000);
    let Some(Finding::Disagreement(d)) = r.findings.first() else {
        panic!("the planted `{{n,m}}` bug went unnoticed: {:?}", r.findings);
    };
    assert!(d.path.split(' ').count() <= 3, "{}", d.path);
    assert_eq!(d.aovs.len(), 1, "{:?}", d.aovs);
    // The bug lives in `{n,m}` with both bounds written: the minimized expression
    // keeps one.
    let e = &d.aovs[0].expr;
    assert!(
        e.contains('{') && e.contains(','),
        "minimized to {e}, which has no {{n,m}}"
    );
    // The minimized case still disagrees, asked afresh: the reference matches where
    // the buggy matcher does not (the bug only ever demands more repetitions).
    let reference = &d.engines[0];
    assert_eq!(reference.0, "reference");
    assert_eq!(reference.1, Some(Answer::Matches(vec![true])));
    assert_eq!(d.external, Answer::Matches(vec![false]));
    // The finding carries what replays it (lpe-check writes the command line from
    // it): asked again as a given case, the set and path disagree in the same way.
    let again = run(
        naive("--plant-bug"),
        &Cases::Given {
            exprs: d.exprs(),
            paths: vec![d.path.clone()],
        },
        5000,
    );
    assert_eq!(again.disagreements(), 1, "{:?}", again.findings);
}

#[test]
fn unsupported_constructs_are_counted_not_disagreements() {
    lpe_testkit::host::require_python3();
    let r = run(
        naive(""),
        &Cases::Given {
            exprs: vec!["directDiffuse".into()],
            paths: vec!["C RD L".into()],
        },
        5000,
    );
    assert!(r.findings.is_empty(), "{:?}", r.findings);
    assert_eq!(r.unsupported.0, 1);
}

#[test]
fn rejections_are_compared_both_ways() {
    lpe_testkit::host::require_python3();
    // Both reject: agreement.
    let r = run(
        naive(""),
        &Cases::Given {
            exprs: vec!["C.L".into(), "C(L".into()],
            paths: vec!["C RD L".into()],
        },
        5000,
    );
    assert!(r.findings.is_empty(), "{:?}", r.findings);
    // The external rejects what every engine accepts: a disagreement, minimized to one
    // small expression (the path does not matter to a rejection).
    let broken = format!(
        "python3 {} reject",
        shell_quote(&repo("engines/tests/adapters/broken_matcher.py"))
    );
    let r = run(broken, &generated(3, 2), 5000);
    let Some(Finding::Disagreement(d)) = r.findings.first() else {
        panic!("{:?}", r.findings);
    };
    assert!(
        matches!(
            d.external,
            Answer::Rejected {
                aov: Some(0),
                position: Some(0),
                ..
            }
        ),
        "{:?}",
        d.external
    );
    assert_eq!(d.aovs.len(), 1);
    assert!(d.aovs[0].expr.len() <= 3, "{}", d.aovs[0].expr);
}

#[test]
fn broken_adapters_become_findings_and_the_run_finishes() {
    lpe_testkit::host::require_python3();
    let script = shell_quote(&repo("engines/tests/adapters/broken_matcher.py"));
    let cases = generated(3, 5);
    for (mode, label) in [
        ("crash", "crash"),
        ("hang", "timeout"),
        ("garbage", "malformed reply"),
        ("count", "wrong answer count"),
        // Requests are pipelined: the second compile reply arrives where the match
        // reply should.
        ("extra", "reply to another request"),
        ("wrongid", "reply to another request"),
    ] {
        let r = run(format!("python3 {script} {mode}"), &cases, 1000);
        assert_eq!(r.cases, 3, "{mode}: the run did not finish");
        assert_eq!(r.findings.len(), 3, "{mode}: {:?}", r.findings);
        for f in &r.findings {
            let Finding::Fault { case, fault } = f else {
                panic!("{mode}: {f}");
            };
            assert!(case.is_some());
            assert_eq!(fault.kind.label(), label, "{mode}: {f}");
            // The report names the request that caused it (`extra` is noticed on the
            // request after the double reply: the match).
            assert!(fault.request.contains(r#""op":"match""#), "{mode}: {f}");
        }
        // Each fault killed the process; each next case started a fresh one.
        assert_eq!(r.restarts, 2, "{mode}");
        let Finding::Fault { fault, .. } = &r.findings[0] else {
            unreachable!()
        };
        match &fault.kind {
            FaultKind::Crash { status, stderr } => {
                assert!(status.contains('3'), "{status}");
                assert_eq!(stderr, &["boom: mode crash"]);
            }
            // A timeout shows what the process said before it was killed, as a crash does.
            FaultKind::Timeout { stderr, .. } => {
                assert_eq!(stderr, &["waiting: mode hang"]);
                assert!(
                    fault.to_string().contains("stderr: waiting: mode hang"),
                    "{fault}"
                );
            }
            _ => {}
        }
    }
}

#[test]
fn a_command_that_cannot_start_is_bad_input() {
    let err = external::run(
        &setup("/nonexistent/matcher --flag".into(), 500),
        &generated(1, 0),
        &lpe_engines::all(),
    )
    .expect_err("cannot start");
    assert!(err.to_string().contains("/nonexistent/matcher"), "{err}");
    let err = external::run(&setup("'unclosed".into(), 500), &generated(1, 0), &[])
        .expect_err("bad quoting");
    assert!(err.to_string().contains("bad --external command"), "{err}");
}

/// `max_restarts` N means at most N restarts: an adapter that crashes on every case runs
/// N + 1 cases (the first process and N restarted ones), reports one fault each, and
/// stops with the count said; N = 0 never restarts.
#[test]
fn the_restart_budget_is_exact() {
    lpe_testkit::host::require_python3();
    let script = shell_quote(&repo("engines/tests/adapters/broken_matcher.py"));
    for n in [0u64, 1, 5] {
        let setup = Setup {
            max_restarts: n,
            ..setup(format!("python3 {script} crash"), 1000)
        };
        let r = external::run(&setup, &generated(20, 5), &lpe_engines::all::<RenderMan>())
            .expect("starts");
        assert_eq!(r.restarts, n, "N = {n}: {:?}", r.stopped);
        assert_eq!(r.cases, n + 1, "N = {n}");
        assert_eq!(r.findings.len() as u64, n + 1, "N = {n}");
        let stopped = r.stopped.as_deref().unwrap_or_default();
        assert!(
            stopped.contains(&format!("after {n} restart(s)")),
            "N = {n}: {stopped}"
        );
    }
}

/// After a crash mid-batch, the unanswered cases are asked again before the cases behind
/// them: with more cases than one pipelined batch holds (64) and an adapter that crashes
/// on every case, the faults are reported in case order, each with its case number.
#[test]
fn findings_keep_case_order_across_crashes() {
    lpe_testkit::host::require_python3();
    let script = shell_quote(&repo("engines/tests/adapters/broken_matcher.py"));
    let setup = Setup {
        max_restarts: 200,
        ..setup(format!("python3 {script} crash"), 1000)
    };
    let r =
        external::run(&setup, &generated(70, 5), &lpe_engines::all::<RenderMan>()).expect("starts");
    let cases: Vec<Option<u64>> = r
        .findings
        .iter()
        .map(|f| match f {
            Finding::Fault { case, .. } => *case,
            other => panic!("{other}"),
        })
        .collect();
    let want: Vec<Option<u64>> = (0..70).map(Some).collect();
    assert_eq!(cases, want);
}
