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
    // Every line is answered; the vectors hold malformed lines, so the exit is 2.
    assert!(VECTORS.lines().any(|l| l.ends_with("\terror")));
    assert_eq!(code, 2, "stderr: {err}");
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
    let (_, again, _) = lpe_check(&args, "");
    assert_eq!(match_rate(&out), match_rate(&again));
}

/// The `match rate` line of a `diff` report (the counts, without timing).
fn match_rate(out: &str) -> &str {
    out.lines().find(|l| l.starts_with("match rate")).unwrap()
}

/// A default run (10 000 cases) writes every production of each dialect's grammar and
/// every boundary value of one (docs/fuzzing.md); `--coverage` lists them with their
/// counts, each written at least once.
///
/// Fault planted in `testkit/src/grammar/renderman.rs`, seen to fail this test and
/// reverted (the production counts alone passed it): lobes drawn as
/// `1 + c.below(max - 1)`, never the largest of a kind.
#[test]
fn a_default_diff_run_covers_every_grammar_production() {
    // The boundary values, listed by hand from docs/language.md: the lobe ranges of §2.4
    // (RenderMan only), the count limit of §10, the empty label and the longest written.
    let both = [
        "value.count.0",
        "value.count.1",
        "value.count.256",
        "label.empty",
        "label.longest",
    ];
    let lobes = [
        "value.lobe.D1",
        "value.lobe.D4",
        "value.lobe.S1",
        "value.lobe.S8",
        "value.lobe.U1",
        "value.lobe.U12",
    ];
    for (dialect, total, values) in [
        ("renderman", 77, [&both[..], &lobes[..]].concat()),
        ("osl", 66, both.to_vec()),
    ] {
        let (code, out, err) = lpe_check(&["diff", "--dialect", dialect, "--coverage"], "");
        assert_eq!(code, 0, "{out}{err}");
        let line =
            format!("grammar coverage: {total} of {total} productions ({dialect} dialect)\n");
        assert!(out.contains(&line), "{out}");
        // The production lines follow the coverage line.
        let listed: Vec<&str> = out
            .lines()
            .skip_while(|l| !l.starts_with("grammar coverage: "))
            .skip(1)
            .take_while(|l| l.starts_with("  ") && !l.starts_with("  both reject"))
            .collect();
        assert_eq!(listed.len(), total, "{out}");
        for l in &listed {
            let n: u64 = l.split_whitespace().last().unwrap().parse().unwrap();
            assert!(n > 0, "{l}");
        }
        for v in values {
            assert!(
                listed
                    .iter()
                    .any(|l| l.split_whitespace().next() == Some(v)),
                "{dialect}: {v} not listed\n{out}"
            );
        }
    }
}

#[test]
fn diff_needs_two_engines() {
    let (code, _, err) = lpe_check(&["diff", "--engine", "reference", "--cases", "1"], "");
    assert_eq!(code, 2);
    assert!(err.contains("at least two engines"), "{err}");
}

/// OSL's accum test (`tests/testdata/osl/accum_test.toml`) as `--batch` input: a
/// comment line, then one `EXPR<TAB>REGISTERED<TAB>PATH<TAB>MATCH|NOMATCH` line per verdict.
fn accum_test() -> String {
    let cases = lpe_testkit::suite::load_file("osl/accum_test.toml").unwrap();
    let mut text = String::from("# OSL's accum test, one line per (rule, path)\n");
    for r in lpe_testkit::suite::rows(&cases) {
        let verdict = if r.matches { "MATCH" } else { "NOMATCH" };
        text += &format!("{}\t{}\t{}\t{verdict}\n", r.expr, r.registered, r.path);
    }
    text
}

#[test]
fn batch_answers_accum_test_and_checks_its_fourth_column_in_the_osl_dialect() {
    let text = accum_test();
    let (code, out, err) = lpe_check(&["match", "--dialect", "osl", "--batch"], &text);
    assert_eq!(code, 0, "{err}");
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(
        lines.len(),
        text.lines().count(),
        "one output line per input line"
    );
    let mut answered = 0;
    for (input, got) in text.lines().zip(&lines) {
        if input.starts_with('#') || input.trim().is_empty() {
            assert_eq!(input, *got);
            continue;
        }
        let want = match input.rsplit('\t').next().unwrap() {
            "MATCH" => "match",
            _ => "no-match",
        };
        assert_eq!(*got, want, "{input}");
        answered += 1;
    }
    assert_eq!(answered, 130);
    // The same rows with the expected answer of one flipped: that line disagrees (exit 3).
    let first = text.lines().find(|l| l.ends_with("\tMATCH")).unwrap();
    let flipped = first.replace("\tMATCH", "\tNOMATCH");
    let (code, out, _) = lpe_check(&["match", "--dialect", "osl", "--batch"], &flipped);
    assert_eq!(code, 3);
    assert!(
        out.starts_with("disagree: expected=no-match reference=match oracle=match"),
        "{out}"
    );
    // Three columns, as the scripts write them: no expectation to check.
    let three: String = text
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| l.rsplit_once('\t').unwrap().0.to_string() + "\n")
        .collect();
    let (code, out, _) = lpe_check(&["match", "--dialect", "osl", "--batch"], &three);
    assert_eq!(code, 0);
    assert_eq!(
        out.lines().filter(|l| *l == "match").count(),
        rows_with(&text, "\tMATCH")
    );
}

fn rows_with(text: &str, end: &str) -> usize {
    text.lines().filter(|l| l.ends_with(end)).count()
}

#[test]
fn batch_reports_bad_lines_in_place_in_the_osl_dialect() {
    let input = "C<RD\t-\tC,_ R,D\n\
                 CRL\tevents\tC,_ R,D L,_\n\
                 CRL\t-\tC,_ R,'D\n\
                 CRL\t-\n\
                 CRL\t-\tC,_ R,D L,_\tMAYBE\n\
                 CRL\tevents=U\tC,_ R,D,U L,_\n\
                 CRL\t-\tC,_ R,D,U L,_\n";
    let (code, out, _) = lpe_check(&["match", "--dialect", "osl", "--batch"], input);
    // Every line is answered; the bad ones make the exit 2.
    assert_eq!(code, 2);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 7);
    assert_eq!(
        lines[0],
        "error: expression: Reached end of line looking for > to end a group at char 4"
    );
    assert!(lines[1].starts_with("error: registered: "), "{}", lines[1]);
    assert!(
        lines[2].starts_with("error: path: at byte 6"),
        "{}",
        lines[2]
    );
    assert!(lines[3].contains("found 2 column(s)"), "{}", lines[3]);
    assert!(lines[4].contains("MAYBE"), "{}", lines[4]);
    // Registering U makes it basic: the eater no longer skips it.
    assert_eq!(lines[5], "no-match");
    assert_eq!(lines[6], "match");
}

#[test]
fn diff_help_says_register_is_for_a_given_case() {
    let (code, out, _) = lpe_check(&["diff", "--help"], "");
    assert_eq!(code, 0);
    let line = out.lines().find(|l| l.contains("--register")).unwrap();
    assert!(line.contains("with --external and --expr only"), "{line}");
}

#[test]
fn sources_may_carry_the_pipelines_lpe_mark_in_the_osl_dialect() {
    let osl = |args: &[&str]| lpe_check(args, "");
    // Read as OSL, `lpe:` would be the custom labels l, p, e and a syntax error at `:`.
    let (code, out, err) = osl(&["parse", "--dialect", "osl", "lpe:C[^RD]L"]);
    assert_eq!((code, out.as_str()), (0, "<C.><.[^'R''D']><L.>\n"));
    assert!(
        err.contains("mixing labels of different type in [...] at char 5"),
        "{err}"
    );
    let (code, _, err) = osl(&["match", "--dialect", "osl", "lpe:C<RD", "C,_"]);
    assert_eq!(code, 2);
    assert!(err.contains("at char 8\n  lpe:C<RD\n          ^"), "{err}");
    let (code, out, _) = osl(&["match", "--dialect", "osl", "lpe:C<RD>L", "C,_ R,D L,_"]);
    assert_eq!((code, out.as_str()), (0, "match\n"));
    let (code, out, _) = osl(&["equiv", "--dialect", "osl", "lpe:C<RD>L", "C<RD>L"]);
    assert_eq!((code, out.as_str()), (0, "equivalent\n"));
}

#[test]
fn match_parse_equiv_and_partition_with_arguments_in_the_osl_dialect() {
    let osl = |args: &[&str]| lpe_check(args, "");
    let (code, out, _) = osl(&[
        "match",
        "--dialect",
        "osl",
        "--register",
        "events=U;scatters=Y",
        "CDY+U",
        "C,_ R,D R,Y U,_",
        "C,_ R,D U,_",
    ]);
    assert_eq!((code, out.as_str()), (0, "match\nno-match\n"));
    let (code, _, err) = osl(&["match", "--dialect", "osl", "C<RD", "C,_"]);
    assert_eq!(code, 2);
    assert!(err.contains("at char 4\n  C<RD\n      ^"), "{err}");
    let (code, _, err) = osl(&["match", "--dialect", "osl", "CL", "C,'x"]);
    assert_eq!(code, 2);
    assert!(err.contains("path `C,'x`"), "{err}");
    let (code, _, err) = osl(&["match", "--register", "events=U", "CL", "C L"]);
    assert_eq!(code, 2, "--register without --dialect osl");
    assert!(err.contains("--dialect osl"), "{err}");

    let (code, out, err) = osl(&["parse", "--dialect", "osl", "C[^RD]L"]);
    assert_eq!((code, out.as_str()), (0, "<C.><.[^'R''D']><L.>\n"));
    assert!(err.contains("mixing labels"), "{err}");
    let (code, _, err) = osl(&["parse", "--dialect", "osl", "C x"]);
    assert_eq!(code, 2);
    assert!(err.contains("at char 1"), "{err}");

    let (code, out, _) = osl(&[
        "equiv",
        "--dialect",
        "osl",
        "C<RD>[LO]",
        "(C<RD>L)|(C<RD>O)",
    ]);
    assert_eq!((code, out.as_str()), (0, "equivalent\n"));
    let (code, out, _) = osl(&["equiv", "--dialect", "osl", "C.+L", "C.*L"]);
    assert_eq!(code, 1);
    assert!(out.contains("A is strictly included in B"), "{out}");

    let basic = [
        "C<RD>[LO]",
        "C<RD>.+[LO]",
        "C<TD>.*[LO]",
        "C<R[GS]>[LO]",
        "C<R[GS]>.+[LO]",
        "C<T[GS]>.*[LO]",
        "C[LO]",
    ];
    let mut args = vec!["partition", "--dialect", "osl"];
    args.extend(basic);
    let (code, out, _) = osl(&args);
    assert_eq!(code, 0, "{out}");
    assert!(out.ends_with("clean partition\n"), "{out}");
    // Without the direct glossy AOV the set has a gap: a camera, one R glossy, a light
    // (the shortest witness uses NONE for the slots any symbol fills).
    args.retain(|a| *a != "C<R[GS]>[LO]");
    let (code, out, _) = osl(&args);
    assert_eq!(code, 1);
    assert!(out.contains("gap: C,~ R,G L,~\n"), "{out}");
    // With the remainder that closes it: the OSL universe minus every AOV, which parses
    // back, is exactly the AOV left out (within the universe), and closes the gap.
    let rest = out
        .lines()
        .find_map(|l| l.strip_prefix("remainder: "))
        .unwrap_or_else(|| panic!("{out}"));
    assert!(rest.starts_with("<C.><[RT][DGS]>*<L.>|<O.> - (("), "{rest}");
    let within = "C<R[GS]>[LO] & C<[RT][DGS]>*[LO]";
    let (code, out, _) = osl(&["equiv", "--dialect", "osl", rest, within]);
    assert_eq!((code, out.as_str()), (0, "equivalent\n"), "{rest}");
    args.push(rest);
    let (code, out, _) = osl(&args);
    assert_eq!(code, 0, "{out}");
    assert!(out.ends_with("clean partition\n"), "{out}");
    // Set algebra in the OSL dialect: the AOVs may use it too.
    let (code, out, _) = osl(&[
        "match",
        "--dialect",
        "osl",
        "C.*L - C.*DL",
        "C,_ R,G L,_",
        "C,_ R,D L,_",
    ]);
    assert_eq!((code, out.as_str()), (0, "match\nno-match\n"));
    let (code, out, _) = osl(&["equiv", "--dialect", "osl", "C.*L - C.*DL", "C.*L & ^C.*DL"]);
    assert_eq!((code, out.as_str()), (0, "equivalent\n"));
}

#[test]
fn diff_agrees_and_is_deterministic_in_the_osl_dialect() {
    let args = ["diff", "--dialect", "osl", "--cases", "300", "--seed", "5"];
    let (code, out, err) = lpe_check(&args, "");
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.starts_with("osl dialect, engines: reference, oracle, fast, nfa"),
        "{out}"
    );
    assert!(out.contains("300 cases"), "{out}");
    assert!(out.contains("skips: none"), "{out}");
    assert!(out.contains("all engines agree"), "{out}");
    let (_, again, _) = lpe_check(&args, "");
    assert_eq!(match_rate(&out), match_rate(&again));
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

/// An expression no selected engine can build (over the NFA budget) is an error: exit 2,
/// with the reason, from arguments and from a batch line (the batch still answers every
/// line, and a disagreement elsewhere would still exit 3).
#[test]
fn match_exits_2_when_no_engine_can_build_the_expression() {
    let huge = "C(.{256}){200}L";
    let (code, out, _) = lpe_check(&["match", "--engine", "fast", huge, "C L"], "");
    assert_eq!(code, 2, "{out}");
    assert!(
        out.contains("no engine could build") && out.contains("NFA budget"),
        "{out}"
    );
    let (code, out, _) = lpe_check(
        &["match", "--engine", "fast", "--batch"],
        &format!("{huge}\tC L\nCL\tC L\n"),
    );
    assert_eq!(code, 2, "{out}");
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 2, "{out}");
    assert!(
        lines[0].starts_with("error: no engine could build"),
        "{out}"
    );
    assert_eq!(lines[1], "match");
    // A malformed batch line is an error too; well-formed lines alone exit 0.
    let (code, out, _) = lpe_check(&["match", "--batch"], "CL\tC L\nC(\tC L\n");
    assert_eq!(code, 2, "{out}");
    let (code, out, _) = lpe_check(&["match", "--batch"], "CL\tC L\n# note\n\n");
    assert_eq!(code, 0, "{out}");
}

#[test]
fn translate_reports_verdicts_with_exit_codes() {
    let (code, out, err) = lpe_check(
        &[
            "translate",
            "--from",
            "renderman",
            "--to",
            "osl",
            "directDiffuse",
        ],
        "",
    );
    assert_eq!(
        (code, out.as_str()),
        (0, "directDiffuse  ->  <C.><RD><[LO].>  (exact)\n"),
        "{err}"
    );
    let (code, out, _) = lpe_check(
        &["translate", "--from", "renderman", "--to", "osl", "C<RD2>L"],
        "",
    );
    assert_eq!(code, 1);
    assert!(
        out.contains("from above: <C.><RD><L.>  (adds `C RD1 L`"),
        "{out}"
    );
    let (code, out, _) = lpe_check(
        &[
            "translate",
            "--from",
            "osl",
            "--to",
            "renderman",
            "C<RD>.+[LO]",
        ],
        "",
    );
    assert_eq!(
        (code, out.as_str()),
        (0, "C<RD>.+[LO]  ->  C<RD>.+[LO]  (exact)\n")
    );
    // Bad input: exit 2 with the position or the part.
    for (args, needle) in [
        (
            &["translate", "--from", "osl", "--to", "osl", "C"][..],
            "both read osl's dialect",
        ),
        (
            &["translate", "--from", "karma", "--to", "arnold", "C"][..],
            "both read osl's dialect",
        ),
        (
            &["translate", "--from", "renderman", "--to", "karm", "C"][..],
            "--to: unknown renderer `karm` (did you mean `karma`?)",
        ),
        (
            &["translate", "--from", "renderman", "--to", "osl", "C<L'k'>"],
            "byte 3",
        ),
        (
            &[
                "translate",
                "--from",
                "renderman",
                "--to",
                "osl",
                "--correspondence",
                "S1=G U2=G",
                "CL",
            ],
            "byte 5",
        ),
    ] {
        let (code, _, err) = lpe_check(args, "");
        assert_eq!(code, 2, "{args:?}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}

#[test]
fn translated_usda_is_a_stage_lint_reads_back() {
    let dir = std::env::temp_dir().join(format!("lpe-translate-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (code, usda, err) = lpe_check(
        &[
            "translate",
            "--from",
            "osl",
            "--to",
            "renderman",
            "--format",
            "usda",
            "C<RD>[LO]",
            "C<RD[^'a']>L",
        ],
        "",
    );
    assert_eq!(code, 1, "{err}");
    let file = dir.join("vars.usda");
    std::fs::write(&file, &usda).unwrap();
    let doc = lpe_lint::read::read_file(&file, &lpe_lint::read::Limits::default()).unwrap();
    let sources: Vec<&str> = doc.aovs.iter().map(|a| a.source.as_str()).collect();
    assert_eq!(sources, ["lpe:C<RD>[LO]", "lpe:C<RD[^'a']>L"]);
    let (code, json, _) = lpe_check(
        &[
            "translate",
            "--from",
            "renderman",
            "--to",
            "osl",
            "--format",
            "json",
            "--from-file",
            file.to_str().unwrap(),
        ],
        "",
    );
    assert_eq!(code, 1);
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(v["correspondence"], "S1-S7=G S8=S");
    assert_eq!(v["aovs"][0]["translation"], "<C.><RD><[LO].>");
    assert_eq!(v["aovs"][0]["exact"], true);
    assert_eq!(v["aovs"][1]["exact"], false);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn equiv_across_dialects_prints_both_views() {
    let (code, out, _) = lpe_check(
        &[
            "equiv",
            "--dialect-a",
            "renderman",
            "--dialect-b",
            "osl",
            "C<RS>L",
            "C<RS>L",
        ],
        "",
    );
    assert_eq!(
        (code, out.as_str()),
        (1, "not equivalent\nonly A: C RS1 L (OSL C,~ R,G L,~)\n")
    );
    let (code, out, _) = lpe_check(
        &[
            "equiv",
            "--dialect-a",
            "osl",
            "--dialect-b",
            "renderman",
            "C<RG>L",
            "C<R[S1 S2 S3 S4 S5 S6 S7]>L",
        ],
        "",
    );
    assert_eq!((code, out.as_str()), (0, "equivalent\n"));
}

#[test]
fn translate_reads_rib_and_ini_sets_and_reports_what_does_not_parse() {
    let data = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/testdata/lint/");
    let (rib, ini) = (format!("{data}display.rib"), format!("{data}rendermn.ini"));
    let args = [
        "translate",
        "--from",
        "renderman",
        "--to",
        "osl",
        "--from-file",
        &rib,
        "--ini",
        &ini,
    ];
    let (code, out, err) = lpe_check(&args, "");
    // `broken` (`<L'key'>`) does not parse: reported, the others still translated.
    assert_eq!(code, 2, "{out}");
    assert!(
        err.contains("broken: error in `lpe:C<RD>.*<L'key'>`"),
        "{err}"
    );
    assert!(
        out.contains("diffuse: lpe:C<.D>.*[<L.>O]  ->  <C.><[RT]D><[RT].>*<[LO].>  (exact)"),
        "{out}"
    );
    assert!(
        out.contains("wetness: lpe:C<.U5>L  ->  not expressible"),
        "{out}"
    );
    assert!(
        out.contains("keyDiffuse: lpe:keyDiffuse  ->  <C.><RD><[RT].>*<L.'key'>  (exact)"),
        "{out}"
    );
    // The ini file alone: its user macros are the set.
    let (code, out, _) = lpe_check(
        &[
            "translate",
            "--from",
            "renderman",
            "--to",
            "osl",
            "--from-file",
            &ini,
        ],
        "",
    );
    assert_eq!(
        (code, out.as_str()),
        (
            0,
            "keyDiffuse: C<RD>.*<L.'key'>  ->  <C.><RD><[RT].>*<L.'key'>  (exact)\n"
        )
    );
}

/// The `rendermn.ini` of the translate tests below: a user macro, a built-in redefined
/// (`emissive`: lights only), a built-in defined again as it is (`directSpecular`) and a
/// glass macro.
const TRANSLATE_INI: &str = "\
# user macros next to built-ins
/prman/lpe/macro/keyDiffuse      C<RD>.*<L.'key'>
/prman/lpe/macro/emissive        C<L.>
/prman/lpe/macro/directSpecular  C<RS>[<L.>O]
/prman/lpe/macro/glassDirect     C<RS8>[<L.>O]
";

/// `translate`'s whole output, text and JSON, for a `rendermn.ini` alone and for
/// arguments mixing built-ins, its macros and plain expressions. Worked by hand from
/// docs/language.md §19 (default correspondence: D lobes are `D`, S1-S7 `G`, S8 `S`):
/// `C` is `<C.>`, `[<L.>O]` is `<[LO].>`, a middle `.` is `<[RT].>`, RenderMan's `S` is
/// `[GS]` and `S8` alone `S`, a label on `L` is the custom label; `<RD2>` collides with
/// `<RD1>` (one view `R,D`), so from above it takes the whole `<RD>` (adding `C RD1 L`)
/// and from below nothing (`[]`, missing `C RD2 L`); on the right of `-` it rounds the
/// other way, so the whole from above subtracts nothing (adding `C RD2 L`) and from below
/// subtracts every `R,D` vertex (missing `C RD1 L`).
///
/// From the file the set is the user macros, in the file's order, but not one defined as
/// its built-in already is (`directSpecular`), while a redefined built-in (`emissive`)
/// is one; as arguments each name reads as the ini defines it.
///
/// Faults planted in `cli/src/cmd/translate.rs`, each seen to fail this test and
/// reverted: user macros filtered by name (`builtin.get(n).is_none()`: the redefined
/// `emissive` dropped), which the test of the shipped ini above passes; the filter
/// dropped (every built-in printed); `--ini` not read for arguments.
#[test]
fn translate_prints_user_macros_beside_builtins_and_plain_expressions() {
    let dir = std::env::temp_dir().join(format!("lpe-translate-ini-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let ini = dir.join("rendermn.ini");
    std::fs::write(&ini, TRANSLATE_INI).unwrap();
    let ini = ini.to_str().unwrap();
    let head = ["translate", "--from", "renderman", "--to", "osl"];
    let run = |rest: &[&str]| lpe_check(&[&head[..], rest].concat(), "");

    let (code, out, err) = run(&["--from-file", ini]);
    assert_eq!(
        (code, out.as_str()),
        (
            0,
            "keyDiffuse: C<RD>.*<L.'key'>  ->  <C.><RD><[RT].>*<L.'key'>  (exact)\n\
             emissive: C<L.>  ->  <C.><L.>  (exact)\n\
             glassDirect: C<RS8>[<L.>O]  ->  <C.><RS><[LO].>  (exact)\n"
        ),
        "{err}"
    );

    let args = [
        "--ini",
        ini,
        "directDiffuse",
        "keyDiffuse",
        "emissive",
        "directSpecular",
        "C<RD2>L",
        "C.*L - C<RD2>L",
    ];
    let (code, out, err) = run(&args);
    let want = "\
directDiffuse  ->  <C.><RD><[LO].>  (exact)
keyDiffuse  ->  <C.><RD><[RT].>*<L.'key'>  (exact)
emissive  ->  <C.><L.>  (exact)
directSpecular  ->  <C.><R[GS]><[LO].>  (exact)
C<RD2>L  ->  not expressible
  why: `C RD2 L` and `C RD1 L` have one OSL view `C,~ R,D L,~` and only the first matches
  from above: <C.><RD><L.>  (adds `C RD1 L` (OSL `C,~ R,D L,~`))
  from below: <C.>[]<L.>  (misses `C RD2 L` (OSL `C,~ R,D L,~`))
C.*L - C<RD2>L  ->  not expressible
  why: `C RD1 L` and `C RD2 L` have one OSL view `C,~ R,D L,~` and only the first matches
  from above: <C.><[RT].>*<L.> - <C.>[]<L.>  (adds `C RD2 L` (OSL `C,~ R,D L,~`))
  from below: <C.><[RT].>*<L.> - <C.><RD><L.>  (misses `C RD1 L` (OSL `C,~ R,D L,~`))
";
    assert_eq!((code, out.as_str()), (1, want), "{err}");

    let (code, json, err) = run(&[&["--format", "json"][..], &args].concat());
    assert_eq!(code, 1, "{err}");
    let got: serde_json::Value = serde_json::from_str(&json).unwrap();
    let exact = |source: &str, translation: &str| {
        serde_json::json!({
            "name": "", "source": source, "translation": translation, "exact": true,
            "reasons": [], "lower": translation, "adds": null, "misses": null, "notes": [],
        })
    };
    let view = "(OSL `C,~ R,D L,~`)";
    let why = |matched: &str, unmatched: &str| {
        format!(
            "`{matched}` and `{unmatched}` have one OSL view `C,~ R,D L,~` and only the \
             first matches"
        )
    };
    let want = serde_json::json!({
        "from": "renderman",
        "to": "osl",
        "correspondence": "S1-S7=G S8=S",
        "aovs": [
            exact("directDiffuse", "<C.><RD><[LO].>"),
            exact("keyDiffuse", "<C.><RD><[RT].>*<L.'key'>"),
            exact("emissive", "<C.><L.>"),
            exact("directSpecular", "<C.><R[GS]><[LO].>"),
            {
                "name": "", "source": "C<RD2>L", "translation": "<C.><RD><L.>",
                "exact": false, "reasons": [why("C RD2 L", "C RD1 L")],
                "lower": "<C.>[]<L.>",
                "adds": format!("`C RD1 L` {view}"), "misses": format!("`C RD2 L` {view}"),
                "notes": [],
            },
            {
                "name": "", "source": "C.*L - C<RD2>L",
                "translation": "<C.><[RT].>*<L.> - <C.>[]<L.>",
                "exact": false, "reasons": [why("C RD1 L", "C RD2 L")],
                "lower": "<C.><[RT].>*<L.> - <C.><RD><L.>",
                "adds": format!("`C RD2 L` {view}"), "misses": format!("`C RD1 L` {view}"),
                "notes": [],
            },
        ],
    });
    assert_eq!(got, want, "{json}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `--to` a renderer translates with its profile's correspondence: every RenderMan
/// specular lobe is Karma's `G` and Arnold's `S` (docs/profiles.md), so `C<RS>L` is exact
/// in both, with the letter each renderer writes; the default correspondence (plain OSL)
/// splits the same lobes between `G` and `S`. `--from` a renderer reads its built-in names.
#[test]
fn translate_to_a_renderer_uses_its_profiles_correspondence() {
    for (to, want) in [
        ("karma", "C<RS>L  ->  <C.><RG><L.>  (exact)\n"),
        ("arnold", "C<RS>L  ->  <C.><RS><L.>  (exact)\n"),
    ] {
        let (code, out, err) = lpe_check(
            &["translate", "--from", "renderman", "--to", to, "C<RS>L"],
            "",
        );
        assert_eq!((code, out.as_str()), (0, want), "{to}: {err}");
    }
    let (_, osl, _) = lpe_check(
        &["translate", "--from", "renderman", "--to", "osl", "C<RS>L"],
        "",
    );
    assert!(osl.contains("[GS]"), "{osl}");
    let (code, out, err) = lpe_check(
        &[
            "translate",
            "--from",
            "arnold",
            "--to",
            "renderman",
            "diffuse_direct",
        ],
        "",
    );
    assert_eq!(
        (code, out.as_str()),
        (0, "diffuse_direct  ->  C<RD>L  (exact)\n"),
        "{err}"
    );
}

/// `--renderer` reaches every subcommand that reads expressions: Arnold's built-in name
/// in `match` (arguments and `--batch` lines, whose own labels add to the profile's) and
/// `equiv`, Karma's `A` in `explain`; without the profile each is an error.
#[test]
fn every_subcommand_reads_expressions_under_the_renderers_profile() {
    let (code, out, err) = lpe_check(
        &[
            "match",
            "--renderer",
            "arnold",
            "diffuse_direct",
            "C,~ R,D L,~",
            "C,~ R,G L,~",
        ],
        "",
    );
    assert_eq!((code, out.as_str()), (0, "match\nno-match\n"), "{err}");
    let (code, out, err) = lpe_check(
        &["match", "--batch", "--renderer", "arnold"],
        "diffuse_direct\t-\tC,~ R,D L,~\nC<RD>AU\tevents=U\tC,~ R,D A,~ U,~\n",
    );
    assert_eq!((code, out.as_str()), (0, "match\nmatch\n"), "{err}");
    let (code, out, _) = lpe_check(
        &["match", "--batch", "--dialect", "osl"],
        "diffuse_direct\t-\tC,~ R,D L,~\n",
    );
    // A batch line in error makes the run's exit status 2.
    assert_eq!(code, 2);
    assert!(out.starts_with("error: expression:"), "{out}");
    let (code, out, err) = lpe_check(
        &["equiv", "--renderer", "arnold", "diffuse_direct", "C<RD>L"],
        "",
    );
    assert_eq!((code, out.trim()), (0, "equivalent"), "{err}");
    let (code, out, err) = lpe_check(
        &[
            "explain",
            "--renderer",
            "karma",
            "--aov",
            "alb=C<RD>A",
            "C,~ R,D A,~",
        ],
        "",
    );
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("lands in: alb"), "{out}");
    let (code, _, err) = lpe_check(
        &[
            "explain",
            "--dialect",
            "osl",
            "--aov",
            "alb=C<RD>A",
            "C,~ R,D A,~",
        ],
        "",
    );
    assert_eq!(code, 2, "{err}");
}

/// `translate --to karma --format usda` names the renderer in the layer
/// (`lpe:renderer`), so lint reads it back with Karma's rules: Karma's `G` for
/// RenderMan's specular lobes passes, where a Karma-read `S` would be `never_produced`.
#[test]
fn a_layer_translated_for_a_renderer_names_it_and_lints_under_its_rules() {
    let dir = std::env::temp_dir().join(format!("lpe-translate-karma-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (code, usda, err) = lpe_check(
        &[
            "translate",
            "--from",
            "renderman",
            "--to",
            "karma",
            "--format",
            "usda",
            "C<RS>L",
        ],
        "",
    );
    assert_eq!(code, 0, "{err}");
    assert!(
        usda.contains("custom string lpe:dialect = \"osl\"\n"),
        "{usda}"
    );
    assert!(
        usda.contains("custom string lpe:renderer = \"karma\"\n"),
        "{usda}"
    );
    let file = dir.join("karma.usda");
    std::fs::write(&file, &usda).unwrap();
    let (code, out, err) = lpe_check(&["lint", file.to_str().unwrap()], "");
    assert_eq!(code, 0, "{out}{err}");
    assert!(err.contains("reading as Karma"), "{err}");
    let (_, osl, _) = lpe_check(
        &[
            "translate",
            "--from",
            "renderman",
            "--to",
            "osl",
            "--format",
            "usda",
            "C<RS>L",
        ],
        "",
    );
    assert!(!osl.contains("lpe:renderer"), "{osl}");
    std::fs::remove_dir_all(&dir).unwrap();
}
