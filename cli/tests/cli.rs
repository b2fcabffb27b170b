//! `lpe-check` end to end: a few vectors through `match --batch`, exit codes, and errors
//! with carets. The conformance vectors themselves run in-process on every engine in
//! `tests/testdata/`; here only the CLI's plumbing is under test.

use std::io::Write;
use std::process::{Command, Stdio};

/// `EXPR <TAB> PATH <TAB> expected batch answer` (`error` for a malformed expression or
/// path); comment and blank lines are echoed.
const VECTORS: &str = "# a comment is echoed
C.*L\tC RD2'floor' TS8 RS1 L'key'\tmatch
CD|(SD)L\tC RS RD L\tmatch
C<RD'floor'>[LO]\tC RD'wall' L\tno-match
lpe:directDiffuse\tC RD L\tmatch

C.{3,2}L\tC L\terror
C.*L\tC RD5 L\terror
unoccluded;shadows;C.*L\tC RD L\tmatch
";

fn lpe_check(args: &[&str], stdin: &str) -> (i32, String, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_lpe-check"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("lpe-check runs");
    child
        .stdin
        .take()
        .unwrap()
        .write_all(stdin.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn batch_answers_one_line_per_input_line() {
    let mut input = String::new();
    let mut expected = Vec::new();
    for line in VECTORS.lines() {
        if line.trim().is_empty() || line.starts_with('#') {
            input.push_str(line);
            input.push('\n');
            expected.push(line.to_string());
            continue;
        }
        let (case, want) = line.rsplit_once('\t').expect("three columns");
        input.push_str(case);
        input.push('\n');
        expected.push(want.to_string());
    }
    let (code, out, err) = lpe_check(&["match", "--batch"], &input);
    assert_eq!(code, 0, "stderr: {err}");
    let got: Vec<&str> = out.lines().collect();
    assert_eq!(got.len(), expected.len(), "one output line per input line");
    for ((got, want), line) in got.iter().zip(&expected).zip(VECTORS.lines()) {
        if want == "error" {
            assert!(got.starts_with("error: "), "{line:?} gave {got:?}");
        } else {
            assert_eq!(got, want, "{line:?}");
        }
    }
}

#[test]
fn match_with_arguments_prints_one_answer_per_path() {
    let (code, out, _) = lpe_check(&["match", "CD|(SD)L", "C RD L", "C RS RD L", "C RS L"], "");
    assert_eq!(code, 0);
    assert_eq!(out, "match\nmatch\nno-match\n");
}

#[test]
fn parse_prints_canonical_form_or_caret_error() {
    let (code, out, _) = lpe_check(&["parse", "lpe: c <rd> .+ [<l.> o]"], "");
    assert_eq!((code, out.as_str()), (0, "C<RD>.+[<L.>O]\n"));
    let (code, out, err) = lpe_check(&["parse", "C<L'key'>"], "");
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert!(err.contains("  | C<L'key'>\n  |    ^^^^^\n"), "{err}");
    assert!(err.contains("write `<L.'key'>`"), "{err}");
}

#[test]
fn bad_arguments_are_errors_not_panics() {
    let (code, _, err) = lpe_check(&["match", "--engine", "nope", "CL", "C L"], "");
    assert_eq!(code, 2);
    assert!(err.contains("unknown engine `nope`"), "{err}");
    let (code, _, err) = lpe_check(&["match", "CL", "C X L"], "");
    assert_eq!(code, 2);
    assert!(err.contains("not a vertex type"), "{err}");
    let (code, _, _) = lpe_check(&["match", "CL"], "");
    assert_eq!(code, 2);
    let (code, _, err) = lpe_check(&["parse", "x", "--ini", "/nonexistent/rendermn.ini"], "");
    assert_eq!(code, 2);
    assert!(err.contains("cannot read"), "{err}");
}

#[test]
fn ini_macros_are_usable() {
    let dir = std::env::temp_dir().join(format!("lpe-check-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let ini = dir.join("rendermn.ini");
    std::fs::write(&ini, "/prman/lpe/macro/keyDiffuse C<RD>.*<L.'key'>\n").unwrap();
    let ini = ini.to_str().unwrap();
    let (code, out, err) = lpe_check(
        &[
            "match",
            "--ini",
            ini,
            "keyDiffuse",
            "C RD RS L'key'",
            "C RD L",
        ],
        "",
    );
    assert_eq!(code, 0, "{err}");
    assert_eq!(out, "match\nno-match\n");
}

#[test]
fn diff_reports_rate_and_agreement_and_is_deterministic() {
    let args = ["diff", "--cases", "300", "--seed", "11"];
    let (code, out, err) = lpe_check(&args, "");
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("300 cases"), "{out}");
    assert!(out.contains("match rate: "), "{out}");
    assert!(out.contains("all engines agree"), "{out}");
    // Agreement counts only if engines were compared: every case had two or more, and
    // only the engines with a position limit (`fast`, `nfa`) ever refuse a set.
    assert!(!out.contains("uncompared"), "{out}");
    for engine in ["reference", "oracle"] {
        assert!(!out.contains(&format!("skips: {engine} ")), "{out}");
    }
    // Same seed, same cases: the counts line (minus timing) repeats exactly.
    let counts = |o: &str| {
        o.lines()
            .find(|l| l.starts_with("match rate"))
            .unwrap()
            .to_string()
    };
    let (_, again, _) = lpe_check(&args, "");
    assert_eq!(counts(&out), counts(&again));
}

#[test]
fn diff_needs_two_engines() {
    let (code, _, err) = lpe_check(&["diff", "--engine", "reference", "--cases", "1"], "");
    assert_eq!(code, 2);
    assert!(err.contains("at least two engines"), "{err}");
}

#[test]
fn set_algebra_matches_on_every_engine_and_remainders_round_trip() {
    let (code, out, err) = lpe_check(&["match", "C.*L - C.*DL", "C RS L", "C RD L"], "");
    assert_eq!((code, out.as_str()), (0, "match\nno-match\n"), "{err}");
    let (code, out, _) = lpe_check(&["partition", "directDiffuse", "indirectDiffuse"], "");
    assert_eq!(code, 1, "{out}");
    let rest = out
        .lines()
        .find_map(|l| l.strip_prefix("remainder: "))
        .unwrap_or_else(|| panic!("{out}"));
    let rest = format!("rest={rest}");
    let (code, out, err) = lpe_check(
        &["partition", "directDiffuse", "indirectDiffuse", &rest],
        "",
    );
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.ends_with("clean partition\n"), "{out}");
}
