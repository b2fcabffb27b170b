//! OSL's own LPE unit test (liboslexec's accum test, 130 verdicts produced by running
//! OSL's code, `osl/accum_test.toml`) and the hand-written rows of `osl/extra.toml` and
//! `osl/algebra.toml`, one verdict at a time on `AovSet` compiled from the OSL dialect,
//! in both stepping modes: the DFA, and the bitset NFA (a zero DFA budget).

use lpe::osl::{self, Registered};
use lpe::{AovSet, Options};
use lpe_testkit::suite::{distinct_rules, Row};

/// The verdicts of `testdata/<file>`, one per (expression, path).
fn load_rows(file: &str) -> Vec<Row> {
    lpe_tests::suite_rows(file)
}

fn path(r: &Row) -> osl::Path {
    lpe_tests::row_path(r)
}

fn modes() -> [(&'static str, Options); 2] {
    [
        ("dfa", Options::default()),
        (
            "nfa",
            Options {
                dfa_budget: 0,
                ..Options::default()
            },
        ),
    ]
}

/// The rows whose answer differs from OSL's, as `file: case mode: ...` lines.
fn failures(rows: &[Row]) -> Vec<String> {
    let mut out = Vec::new();
    for (mode, opts) in modes() {
        for r in rows {
            let lpe = match osl::parse(&r.expr, &r.registered) {
                Ok(l) => l,
                Err(e) => {
                    out.push(format!(
                        "{}: `{}` {mode}: `{}`: {e}",
                        r.file, r.case, r.expr
                    ));
                    continue;
                }
            };
            let set = AovSet::compile_under(&[("rule".into(), lpe)], &r.registered, &opts)
                .unwrap_or_else(|e| panic!("{}: `{}`: {e}", r.file, r.case));
            assert_eq!(set.uses_dfa(), mode == "dfa", "{}: `{}`", r.file, r.case);
            let got = set.match_path(&path(r)).contains(0);
            if got != r.matches {
                out.push(format!(
                    "{}: `{}` {mode}: `{}` [{}] on `{}`: got {got}, OSL says {}",
                    r.file, r.case, r.expr, r.registered, r.path, r.matches
                ));
            }
        }
    }
    out
}

#[test]
fn accum_test_answers_130_of_130_in_both_modes() {
    let rows = load_rows("osl/accum_test.toml");
    assert_eq!(rows.len(), 130);
    let fails = failures(&rows);
    assert!(fails.is_empty(), "{}", fails.join("\n"));
}

#[test]
fn extra_rows_in_both_modes() {
    let rows = load_rows("osl/extra.toml");
    assert!(rows.len() >= 30, "{}", rows.len());
    let fails = failures(&rows);
    assert!(fails.is_empty(), "{}", fails.join("\n"));
}

#[test]
fn algebra_rows_in_both_modes() {
    let rows = load_rows("osl/algebra.toml");
    let fails = failures(&rows);
    assert!(fails.is_empty(), "{}", fails.join("\n"));
}

#[test]
fn one_set_of_all_accum_rules_answers_each_rule() {
    // All rules in one set (as OSL compiles them, sharing one automaton): each AOV's bit
    // still gives that rule's verdict.
    let rows = load_rows("osl/accum_test.toml");
    let reg: Registered = "events=U;scatters=Y".parse().unwrap();
    assert!(rows.iter().all(|r| r.registered == reg));
    let rules = distinct_rules(&rows);
    let aovs: Vec<(String, osl::Lpe)> = rules
        .iter()
        .map(|e| (e.clone(), osl::parse(e, &reg).unwrap()))
        .collect();
    for (mode, opts) in modes() {
        let set = AovSet::compile_under(&aovs, &reg, &opts).unwrap();
        for r in &rows {
            let i = rules.iter().position(|e| *e == r.expr).unwrap();
            let got = set.match_path(&path(r)).contains(i);
            assert_eq!(
                got, r.matches,
                "{mode}: case `{}` `{}` on `{}`",
                r.case, r.expr, r.path
            );
        }
    }
}
