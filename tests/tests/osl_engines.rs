//! The OSL dialect on every registered engine (and the eager form of `oracle`): OSL's
//! own accum test (130 verdicts) and the hand-written `extra.toml` rows, one set of all
//! accum rules compiled at once, and the differential property on generated OSL cases.

use lpe::osl::{self, Osl, Registered};
use lpe::rng::SplitMix64;
use lpe_engines::differential::{self, Outcome};
use lpe_engines::engine::bits;
use lpe_engines::Engine;
use lpe_testkit::suite::{distinct_rules, Row};
use lpe_tests::cases;
use proptest::prelude::*;

/// The registry plus the eager (dense DFA) oracle.
fn engines() -> Vec<&'static dyn Engine<Osl>> {
    let mut all = lpe_engines::all::<Osl>();
    all.push(&lpe_engines::regex::EAGER);
    all
}

/// The verdicts of `testdata/<file>`, one per (expression, path).
fn load_rows(file: &str) -> Vec<Row> {
    lpe_tests::suite_rows(file)
}

fn path(r: &Row) -> osl::Path {
    lpe_tests::row_path(r)
}

/// Each engine's wrong answers on `rows`, as `file: case engine: ...` lines, and the
/// number of answers checked.
fn failures(rows: &[Row]) -> (Vec<String>, usize) {
    let mut out = Vec::new();
    let mut checked = 0;
    for e in engines() {
        for r in rows {
            let lpe = osl::parse(&r.expr, &r.registered)
                .unwrap_or_else(|err| panic!("{}: `{}`: {err}", r.file, r.case));
            let m = e
                .compile(std::slice::from_ref(&lpe), &r.registered)
                .unwrap_or_else(|err| panic!("{}: `{}` {}: {err}", r.file, r.case, e.name()));
            let got = bits(m.which(&path(r)), 1);
            checked += 1;
            if got != [r.matches] {
                out.push(format!(
                    "{}: `{}` {}: `{}` [{}] on `{}`: got {got:?}, OSL says {}",
                    r.file,
                    r.case,
                    e.name(),
                    r.expr,
                    r.registered,
                    r.path,
                    r.matches
                ));
            }
        }
    }
    (out, checked)
}

#[test]
fn accum_test_answers_130_of_130_on_every_engine() {
    let rows = load_rows("osl/accum_test.toml");
    assert_eq!(rows.len(), 130);
    let (fails, checked) = failures(&rows);
    assert!(fails.is_empty(), "{}", fails.join("\n"));
    assert_eq!(checked, 130 * engines().len());
    // Both verdicts occur, so an engine answering a constant could not pass.
    assert!(rows.iter().any(|r| r.matches) && rows.iter().any(|r| !r.matches));
}

#[test]
fn extra_rows_on_every_engine() {
    let rows = load_rows("osl/extra.toml");
    let (fails, _) = failures(&rows);
    assert!(fails.is_empty(), "{}", fails.join("\n"));
}

#[test]
fn algebra_rows_on_every_engine() {
    let rows = load_rows("osl/algebra.toml");
    assert!(rows.len() >= 30, "{}", rows.len());
    let (fails, _) = failures(&rows);
    assert!(fails.is_empty(), "{}", fails.join("\n"));
}

#[test]
fn the_algebra_rules_as_one_set_per_registration_on_every_engine() {
    // Many set-algebra AOVs in one set: each AOV's answer combines its own operands
    // only, wherever they sit among the set's hidden AOVs.
    let rows = load_rows("osl/algebra.toml");
    let mut regs: Vec<Registered> = Vec::new();
    for r in &rows {
        if !regs.contains(&r.registered) {
            regs.push(r.registered.clone());
        }
    }
    assert_eq!(regs.len(), 2);
    for reg in regs {
        let rows: Vec<Row> = rows
            .iter()
            .filter(|r| r.registered == reg)
            .cloned()
            .collect();
        rows_as_one_set_on_every_engine(&rows, &reg);
    }
}

#[test]
fn all_accum_rules_as_one_set_on_every_engine() {
    let rows = load_rows("osl/accum_test.toml");
    let reg: Registered = "events=U;scatters=Y".parse().unwrap();
    assert!(rows.iter().all(|r| r.registered == reg));
    rows_as_one_set_on_every_engine(&rows, &reg);
}

/// Every distinct rule of `rows` compiled into one set on every engine; each row's rule
/// answers as the row says (the other rules in the set must not disturb it).
fn rows_as_one_set_on_every_engine(rows: &[Row], reg: &Registered) {
    let rules = distinct_rules(rows);
    let lpes: Vec<osl::Lpe> = rules.iter().map(|e| osl::parse(e, reg).unwrap()).collect();
    for e in engines() {
        let m = e.compile(&lpes, reg).unwrap();
        for r in rows {
            let i = rules.iter().position(|x| *x == r.expr).unwrap();
            let got = bits(m.which(&path(r)), rules.len());
            assert_eq!(got.len(), rules.len());
            assert_eq!(
                got[i],
                r.matches,
                "{} case `{}`: {}",
                e.name(),
                r.case,
                r.expr
            );
        }
    }
}

#[test]
fn the_redos_expression_builds_and_matches_on_every_engine() {
    // OSL's subset construction takes minutes on this one (90 192 DFA states).
    let src = "C(R('a'+|G[^S]{2}[^OC]){2,}|(L|T*[sBO]{2,})+)";
    let reg = Registered::none();
    let lpe = osl::parse(src, &reg).unwrap();
    // `|` ORs its two neighbouring items only: C R ((…){2,} | ((L|T*) [sBO]{2,})+), so
    // C R L followed by two of B, O or a straight scattering matches, and C R L L does not.
    let yes: osl::Path = "C,_ R,D L,_ B,_ O,_".parse().unwrap();
    let no: osl::Path = "C,_ R,D L,_ L,_".parse().unwrap();
    for e in engines() {
        let m = e.compile(std::slice::from_ref(&lpe), &reg).unwrap();
        assert_eq!(bits(m.which(&yes), 1), [true], "{}", e.name());
        assert_eq!(bits(m.which(&no), 1), [false], "{}", e.name());
    }
}

fn assert_agree(seed: u64) -> Result<(), TestCaseError> {
    let cfg = lpe_testkit::generate::osl::Config::default();
    let case = differential::generate_case::<Osl>(seed, 0, &cfg, 6);
    match differential::check_in(&engines(), &case.registration, &case.exprs, &case.paths) {
        Outcome::Agree(a) => {
            prop_assert!(a.skipped.is_empty(), "skipped: {:?}", a.skipped);
            prop_assert_eq!(a.engines, engines().len());
            Ok(())
        }
        Outcome::Disagree(c) => Err(TestCaseError::fail(c.to_string())),
    }
}

proptest! {
    #![proptest_config(cases(256))]

    /// Every engine agrees on generated OSL cases (a registration, one expression or a
    /// set, paths aimed at them).
    #[test]
    fn engines_agree_in_the_osl_dialect(seed in any::<u64>()) {
        assert_agree(seed)?;
    }

    /// A generated expression prints to text that parses back to the same tree.
    #[test]
    fn generated_expressions_print_and_parse_back_in_the_osl_dialect(seed in any::<u64>()) {
        let mut rng = SplitMix64::new(seed);
        let reg = lpe_testkit::generate::osl::registered(&mut rng);
        let cfg = lpe_testkit::generate::osl::Config::default();
        let e = lpe_testkit::generate::osl::lpe(&mut rng, &reg, &cfg);
        let text = e.to_string();
        let back = osl::parse(&text, &reg)
            .map_err(|err| TestCaseError::fail(format!("`{text}` [{reg}]: {err}")))?;
        prop_assert_eq!((back.expr, back.algebra), (e.expr, e.algebra), "{}", text);
    }
}
