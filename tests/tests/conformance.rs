//! The conformance suite (`tests/testdata/*.toml`) against every registered engine and
//! every `Options` configuration, plus the checks that keep the suite honest: it loads
//! at least as many cases as were folded into it, it compares answers on every subject,
//! and a wrong vector makes it fail.

use std::sync::OnceLock;

use lpe_tests::conformance::{self, load_str, run, subjects, Loaded, Report, Subject};

/// Cases in the suite when it was built from the earlier vector tables (design.tsv,
/// reference/tests/design.rs, the AOV set's hand table, the parser's error table) plus
/// the first new ones. Cases may be added; the count must never drop below this.
const FOLDED_CASES: usize = 193;

/// Distinct vectors those tables held: 325 expression/path answers, 62 parse errors,
/// 3 malformed paths.
const FOLDED_VECTORS: usize = 390;

fn suite() -> &'static [Loaded] {
    static SUITE: OnceLock<Vec<Loaded>> = OnceLock::new();
    SUITE.get_or_init(|| {
        conformance::load_dir(&conformance::testdata_dir()).unwrap_or_else(|e| panic!("{e}"))
    })
}

#[test]
fn every_case_passes_on_every_engine_and_configuration() {
    let subjects = subjects();
    let report = run(suite(), &subjects);
    assert!(
        report.failures.is_empty(),
        "{} of {} checks failed:\n{}",
        report.failures.len(),
        report.checks,
        report.failures_text()
    );
    for (file, case, engine, config) in &report.allowed_refusals {
        eprintln!("refused, as the case allows: {file}: `{case}` by {engine} ({config})");
    }
    let vectors: usize = suite().iter().map(|c| c.case.vectors()).sum();
    eprintln!(
        "{} cases ({vectors} vectors), {} checks on {} subjects, {} answers skipped as longer than max_path_len",
        report.cases,
        report.checks,
        subjects.len(),
        report.too_long
    );
}

#[test]
fn the_suite_is_loaded_whole_and_runs_on_every_registered_engine() {
    let cases = suite();
    assert!(
        cases.len() >= FOLDED_CASES,
        "{} cases loaded, {FOLDED_CASES} were folded in",
        cases.len()
    );
    let vectors: usize = cases.iter().map(|c| c.case.vectors()).sum();
    assert!(
        vectors >= FOLDED_VECTORS,
        "{vectors} vectors loaded, {FOLDED_VECTORS} were folded in"
    );
    for topic in [
        "atoms",
        "triples",
        "negation",
        "quantifiers",
        "precedence",
        "macros",
        "prefixes",
        "errors",
        "limits",
        "aov-sets",
        "algebra",
    ] {
        let file = format!("{topic}.toml");
        assert!(
            cases.iter().any(|c| c.file == file),
            "no case loaded from {file}"
        );
    }
    // The OSL dialect's files, converted from 228 TSV rows (130 + 66 + 32), and the 55
    // rows probed on OSL's own matcher; cases may be added, never dropped.
    for (file, rows) in [
        ("osl/accum_test.toml", 130),
        ("osl/extra.toml", 66),
        ("osl/algebra.toml", 32),
        ("osl/probed.toml", 55),
    ] {
        let of_file: Vec<Loaded> = cases.iter().filter(|c| c.file == file).cloned().collect();
        assert!(
            of_file.iter().all(|c| c.dialect == lpe::DialectName::Osl),
            "{file}"
        );
        let loaded = lpe_testkit::suite::rows(&of_file).len();
        assert!(
            loaded >= rows,
            "{file}: {loaded} rows, {rows} were converted"
        );
    }
    let subjects = subjects();
    let engines: Vec<&str> = subjects.iter().map(Subject::engine).collect();
    for name in ["reference", "oracle", "fast", "nfa", "aovset"] {
        assert!(engines.contains(&name), "{name} is not run: {engines:?}");
    }
    let configs: Vec<&str> = subjects.iter().map(Subject::config).collect();
    for config in conformance::configs() {
        assert!(configs.contains(&config.name), "{} is not run", config.name);
    }
}

/// A case with wrong expectations, in memory: the runner must report each wrong answer,
/// naming the file, case, engine, configuration, path, expected and got.
const FLIPPED: &str = r#"
[[case]]
name = "flipped"
expr = "C<RD>L"
match = ["C RS L"]
no_match = ["C RD L"]

[[case]]
name = "wrong landing"
aovs = [{ name = "d", expr = "C<RD>L" }, { name = "s", expr = "C<RS>L" }]
lands = [{ path = "C RD L", in = ["s"] }]

[[case]]
name = "wrong error"
expr = "C[]L"
error = { kind = "Syntax", at = 1 }

[[case]]
name = "wrong error position"
expr = "C[]L"
error = { kind = "Empty", at = 2 }

[[case]]
name = "not an error"
expr = "CL"
error = { kind = "Empty", at = 0 }

[[case]]
name = "wrong blame"
bad_path = [{ path = "C RD5 L", vertex = 2, at = 2 }]

[[case]]
name = "valid path"
bad_path = [{ path = "C RD L", vertex = 1 }]
"#;

/// Asserts that every subject fails case `flipped` of `file` on each of `flips` (a path,
/// the answer the case expects, the answer the subject gives) with a report line naming
/// the file, case, engine, configuration and path, and fails case `wrong landing` (which
/// expects the path in AOV `s` while it lands in `d`).
fn assert_flipped_on_every_subject(report: &Report, file: &str, flips: &[(&str, &str, &str)]) {
    let text = report.failures_text();
    for s in &subjects() {
        let (engine, config) = (s.engine(), s.config());
        for &(path, want, got) in flips {
            let f = report
                .failures
                .iter()
                .find(|f| {
                    f.case == "flipped"
                        && f.engine == engine
                        && f.config == config
                        && f.path.as_deref() == Some(path)
                })
                .unwrap_or_else(|| panic!("{engine} ({config}) on {path}:\n{text}"));
            assert_eq!(f.file, file);
            assert_eq!((f.expected.as_str(), f.got.as_str()), (want, got));
            let line = f.to_string();
            for part in [file, "`flipped`", engine, config, path] {
                assert!(line.contains(part), "{part} missing from {line}");
            }
        }
        assert!(
            report.failures.iter().any(|f| f.case == "wrong landing"
                && f.engine == engine
                && f.config == config
                && f.expected == "[s]"
                && f.got == "[d]"),
            "{engine} ({config}):\n{text}"
        );
    }
}

#[test]
fn a_wrong_vector_fails_on_every_subject() {
    let cases = load_str("flipped.toml", FLIPPED).unwrap();
    let subjects = subjects();
    let report = run(&cases, &subjects);
    let text = report.failures_text();
    assert_flipped_on_every_subject(
        &report,
        "flipped.toml",
        &[
            ("C RS L", "match", "no-match"),
            ("C RD L", "no-match", "match"),
        ],
    );
    for case in [
        "wrong error",
        "wrong error position",
        "not an error",
        "wrong blame",
        "valid path",
    ] {
        assert!(
            report
                .failures
                .iter()
                .any(|f| f.case == case && f.engine == "parser"),
            "{case} passed:\n{text}"
        );
    }
    // Two flipped answers and one wrong landing per subject, five parser failures.
    assert_eq!(report.failures.len(), 3 * subjects.len() + 5, "{text}");
}

/// The same in the OSL dialect: the runner dispatches on the case's dialect, and a wrong
/// OSL verdict fails on every subject too.
const FLIPPED_OSL: &str = r#"
dialect = "osl"

[[case]]
name = "flipped"
expr = "CDY+U"
registered = { events = ["U"], scatters = ["Y"] }
match = ["C,_ R,D U,_"]
no_match = ["C,_ R,D R,Y U,_"]

[[case]]
name = "wrong landing"
aovs = [{ name = "d", expr = "C<R.>L" }, { name = "s", expr = "C<T.>L" }]
lands = [{ path = "C,_ R,D L,_", in = ["s"] }]
"#;

#[test]
fn a_wrong_vector_fails_on_every_subject_in_the_osl_dialect() {
    let cases = load_str("flipped-osl.toml", FLIPPED_OSL).unwrap();
    let subjects = subjects();
    let report = run(&cases, &subjects);
    assert_flipped_on_every_subject(
        &report,
        "flipped-osl.toml",
        &[
            ("C,_ R,D U,_", "match", "no-match"),
            ("C,_ R,D R,Y U,_", "no-match", "match"),
        ],
    );
    assert_eq!(
        report.failures.len(),
        3 * subjects.len(),
        "{}",
        report.failures_text()
    );
}

#[test]
fn a_refusal_fails_unless_the_case_allows_it() {
    // More operands than a set holds (each `A - B` is two hidden AOVs): the engines
    // built on lpe's AOV set refuse it; the reference and the oracle, which answer per
    // expression (129 of them, within an `AovMask`), do not.
    let aovs: Vec<String> = (0..=lpe::MAX_AOVS / 2)
        .map(|i| format!("{{ name = \"a{i}\", expr = \"CL - CO\" }}"))
        .collect();
    let case = |refused_by: &str| {
        let text = format!(
            "[[case]]\nname = \"too many\"\naovs = [{}]\nlands = [{{ path = \"C O\", in = [] }}]\n{refused_by}",
            aovs.join(", ")
        );
        load_str("t.toml", &text).unwrap()
    };
    let all = subjects();
    let on_sets = ["fast", "nfa", "aovset"];
    let strict = run(&case(""), &all);
    let refusing = all.iter().filter(|s| on_sets.contains(&s.engine())).count();
    assert_eq!(
        strict.failures.len(),
        refusing,
        "{}",
        strict.failures_text()
    );
    assert!(strict
        .failures
        .iter()
        .all(|f| f.got.starts_with("a refusal")));
    let lenient = run(&case("refused_by = [\"fast\", \"nfa\", \"aovset\"]"), &all);
    assert!(lenient.failures.is_empty(), "{}", lenient.failures_text());
    assert_eq!(lenient.allowed_refusals.len(), refusing);
    // Allowed refusals from every subject leave nothing checked: that fails too.
    let sets: Vec<Subject> = subjects()
        .into_iter()
        .filter(|s| s.engine() == "aovset")
        .collect();
    let nobody = run(&case("refused_by = [\"aovset\"]"), &sets);
    assert_eq!(nobody.failures.len(), 1, "{}", nobody.failures_text());
    assert!(nobody.failures[0].got.contains("every engine"));
}

#[test]
fn malformed_cases_are_load_errors() {
    let bad = [
        ("name = \"x\"\nexpr = \"CL\"", "no expectation"),
        (
            "name = \"x\"\nexpr = \"CL\"\naovs = [{ name = \"a\", expr = \"CL\" }]\nmatch = [\"C L\"]",
            "not both",
        ),
        (
            "name = \"x\"\nexpr = \"CL\"\nmatch = [\"C L\"]\nno_match = [\"C L\"]",
            "both `match` and `no_match`",
        ),
        (
            "name = \"x\"\nexpr = \"C[]L\"\nerror = { kind = \"Nope\", at = 1 }",
            "not an error kind",
        ),
        (
            "name = \"x\"\naovs = [{ name = \"a\", expr = \"CL\" }]\nlands = [{ path = \"C L\", in = [\"b\"] }]",
            "not in `aovs`",
        ),
        ("name = \"x\"\nexpr = \"CL\"\nmatchs = [\"C L\"]", "unknown field"),
    ];
    for (body, needle) in bad {
        let err = load_str("bad.toml", &format!("[[case]]\n{body}\n"))
            .expect_err(body)
            .to_string();
        assert!(err.contains(needle), "{body}: {err}");
        assert!(err.starts_with("bad.toml"), "{err}");
    }
    let twice = "[[case]]\nname = \"x\"\nexpr = \"CL\"\nmatch = [\"C L\"]\n";
    let err = load_str("bad.toml", &format!("{twice}{twice}")).unwrap_err();
    assert!(err.to_string().contains("used twice"), "{err}");
}

#[test]
fn the_readme_examples_load_and_pass() {
    let readme = std::fs::read_to_string(conformance::testdata_dir().join("README.md")).unwrap();
    let blocks: Vec<&str> = readme
        .split("```toml\n")
        .skip(1)
        .map(|b| b.split("```").next().unwrap())
        .collect();
    assert_eq!(blocks.len(), 4);
    for block in blocks {
        let cases = load_str("README.md", block).unwrap_or_else(|e| panic!("{e}"));
        let report = run(&cases, &subjects());
        assert!(report.failures.is_empty(), "{}", report.failures_text());
    }
}
