//! `lpe-check diff --external` end to end: exit codes, the printed replay command and
//! that it replays. Needs python3 for the example matcher: a test that runs it fails,
//! naming what to install, when python3 is absent (a skip would read as a pass); the
//! harness itself is tested in lpe-engines.

mod common;
use common::lpe_check;

#[test]
fn bad_input_exits_2() {
    for args in [
        &["diff", "--external", "/nonexistent/adapter"][..],
        &["diff", "--external", "'unclosed"],
        &["diff", "--external", "true", "--dialect", "osl"],
        // A registration is OSL's, and only for a given case.
        &[
            "diff",
            "--external",
            "true",
            "--register",
            "events=U",
            "--expr",
            "C.L",
        ],
        &[
            "diff",
            "--external",
            "true",
            "--dialect",
            "osl",
            "--register",
            "events=U",
        ],
        &[
            "diff",
            "--external",
            "true",
            "--dialect",
            "osl",
            "--expr",
            "CDL",
            "--path",
            "C,",
        ],
        &[
            "diff",
            "--external",
            "true",
            "--expr",
            "C.L",
            "--path",
            "C X L",
        ],
    ] {
        let (code, _, err) = lpe_check(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.starts_with("error"), "{args:?}: {err}");
    }
}

#[test]
fn agreement_exits_0_and_the_planted_bug_3_with_a_replay_that_replays() {
    lpe_testkit::host::require_python3();
    let clean = "python3 examples/python/naive_matcher.py";
    let (code, out, err) = lpe_check(&["diff", "--external", clean, "--cases", "60"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("agrees with every engine"), "{out}");
    // The header names the matcher as its `hello` reply does.
    assert!(out.contains("(naive-python, renderman dialect)"), "{out}");
    let buggy = "python3 examples/python/naive_matcher.py --plant-bug";
    let (code, out, _) = lpe_check(&[
        "diff",
        "--external",
        buggy,
        "--cases",
        "300",
        "--max-failures",
        "1",
    ]);
    assert_eq!(code, 3, "{out}");
    assert!(
        out.contains("summary: 1 finding(s), 1 disagreement(s)"),
        "{out}"
    );
    let replay = out
        .lines()
        .find_map(|l| l.trim().strip_prefix("replay: lpe-check "))
        .expect("a replay line");
    let words = shell_words::split(replay).unwrap();
    let words: Vec<&str> = words.iter().map(|s| s.as_str()).collect();
    let (code, again, _) = lpe_check(&words);
    assert_eq!(code, 3, "{again}");
    assert!(
        again.contains("external: no AOV") && again.contains("reference: a0"),
        "{again}"
    );
}

/// The OSL test adapter (cli/tests/adapters/osl_proxy.py) over this build's lpe-check.
fn proxy_in_the_osl_dialect(flags: &str) -> String {
    format!(
        "python3 cli/tests/adapters/osl_proxy.py {} {flags}",
        env!("CARGO_BIN_EXE_lpe-check")
    )
}

#[test]
fn runs_send_each_registration_and_replay_it_in_the_osl_dialect() {
    lpe_testkit::host::require_python3();
    let clean = proxy_in_the_osl_dialect("");
    let (code, out, err) = lpe_check(&[
        "diff",
        "--external",
        &clean,
        "--dialect",
        "osl",
        "--cases",
        "40",
    ]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("osl dialect") && out.contains("agrees with every engine"));
    // An adapter that drops `registered` from `compile` parses and matches as if nothing
    // were registered: found, minimized, and replayed with the case's registration.
    let forgetful = proxy_in_the_osl_dialect("--forget-registration");
    let (code, out, _) = lpe_check(&[
        "diff",
        "--external",
        &forgetful,
        "--dialect",
        "osl",
        "--cases",
        "300",
        "--max-failures",
        "1",
    ]);
    assert_eq!(code, 3, "{out}");
    let registered = out
        .lines()
        .find_map(|l| l.trim().strip_prefix("registered: "))
        .expect("the disagreement names its registration");
    assert_ne!(registered, "-", "{out}");
    let replay = out
        .lines()
        .find_map(|l| l.trim().strip_prefix("replay: lpe-check "))
        .expect("a replay line");
    let words = shell_words::split(replay).unwrap();
    let at = words
        .iter()
        .position(|w| w == "--register")
        .expect("{replay}");
    assert_eq!(words[at + 1], registered);
    assert!(
        words.windows(2).any(|w| w == ["--dialect", "osl"]),
        "{replay}"
    );
    let words: Vec<&str> = words.iter().map(|s| s.as_str()).collect();
    let (code, again, _) = lpe_check(&words);
    assert_eq!(code, 3, "{again}");
    assert!(again.contains("1 disagreement(s)"), "{again}");
    // The same case, asked of the clean adapter, agrees: the registration made the
    // difference.
    let mut fixed = words.clone();
    let cmd = fixed.iter().position(|w| *w == forgetful).unwrap();
    fixed[cmd] = &clean;
    let (code, out, _) = lpe_check(&fixed);
    assert_eq!(code, 0, "{out}");
}

#[test]
fn a_renderman_only_matcher_refuses_an_osl_run_with_exit_2() {
    lpe_testkit::host::require_python3();
    let (code, _, err) = lpe_check(&[
        "diff",
        "--external",
        "python3 examples/python/naive_matcher.py",
        "--dialect",
        "osl",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("refused the hello"), "{err}");
}

/// A suite directory of its own under the system's temp dir, with these files.
fn suite_dir(tag: &str, files: &[(&str, &str)]) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("lpe-suite-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    for (name, text) in files {
        let path = dir.join(name);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, text).unwrap();
    }
    dir
}

#[test]
fn the_osl_suite_replays_clean_through_the_osl_proxy() {
    lpe_testkit::host::require_python3();
    let proxy = proxy_in_the_osl_dialect("");
    let (code, out, err) = lpe_check(&[
        "diff",
        "--external",
        &proxy,
        "--suite",
        "tests/testdata/osl",
    ]);
    assert_eq!(code, 0, "{out}{err}");
    // 79 cases, 307 verdicts: 228 (130 + 66 + 32 rows of the former TSV files), the 21
    // of the groups-inside-`<…>` cases and the 58 of `probed.toml` (17 cases).
    assert!(
        out.contains("suite: 79 cases run (307 answers checked), 0 failed"),
        "{out}"
    );
    // The proxy that forgets registrations fails the cases that register labels, each
    // named with its file and case.
    let forgetful = proxy_in_the_osl_dialect("--forget-registration");
    let (code, out, _) = lpe_check(&[
        "diff",
        "--external",
        &forgetful,
        "--suite",
        "tests/testdata/osl",
    ]);
    assert_eq!(code, 3, "{out}");
    assert!(
        out.lines()
            .any(|l| l.starts_with("accum_test.toml: case `CDY+U [events=U;scatters=Y]`")),
        "{out}"
    );
}

/// The renderer profiles' cases replay through the external protocol: each `compile`
/// names the case's renderer (`renderer`), and the proxy reads the set under it. The
/// proxy that drops the field rejects Arnold's built-in names (`RGBA`, `direct`, …),
/// each failure named with its file and case.
#[test]
fn renderer_profile_cases_replay_with_the_renderer_named_in_each_compile() {
    lpe_testkit::host::require_python3();
    let (code, out, err) = lpe_check(&[
        "diff",
        "--external",
        &proxy_in_the_osl_dialect(""),
        "--suite",
        "tests/testdata/profiles",
    ]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains(" 0 failed"), "{out}");
    let (code, out, _) = lpe_check(&[
        "diff",
        "--external",
        &proxy_in_the_osl_dialect("--forget-renderer"),
        "--suite",
        "tests/testdata/profiles",
    ]);
    assert_eq!(code, 3, "{out}");
    assert!(
        out.lines()
            .any(|l| l.starts_with("arnold.toml: case `direct`")),
        "{out}"
    );
}

#[test]
fn a_planted_wrong_verdict_is_reported_with_its_file_and_case() {
    lpe_testkit::host::require_python3();
    let dir = suite_dir(
        "planted",
        &[
            (
                "planted.toml",
                "[[case]]\nname = \"right\"\nexpr = \"C<RD>L\"\nmatch = [\"C RD L\"]\n\
                 no_match = [\"C RS L\"]\n\n\
                 [[case]]\nname = \"wrong verdict\"\nexpr = \"C<RD>L\"\nno_match = [\"C RD L\"]\n\n\
                 [[case]]\nname = \"a rejection\"\nexpr = \"C[]L\"\nerror = { kind = \"Empty\", at = 1 }\n",
            ),
            (
                "sub/aovs.toml",
                "[[case]]\nname = \"set\"\naovs = [{ name = \"d\", expr = \"C<RD>L\" }, \
                 { name = \"s\", expr = \"C<RS>L\" }]\nlands = [{ path = \"C RD L\", in = [\"s\"] }]\n",
            ),
            // The naive matcher speaks RenderMan only: its OSL cases are not run.
            (
                "osl/one.toml",
                "dialect = \"osl\"\n[[case]]\nname = \"o\"\nexpr = \"C.L\"\nmatch = [\"C,_ R,D L,_\"]\n",
            ),
        ],
    );
    let (code, out, err) = lpe_check(&[
        "diff",
        "--external",
        "python3 examples/python/naive_matcher.py",
        "--suite",
        dir.to_str().unwrap(),
    ]);
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(code, 3, "{out}{err}");
    let failures: Vec<&str> = out
        .lines()
        .filter(|l| l.contains(".toml: case `"))
        .collect();
    assert_eq!(
        failures,
        [
            "planted.toml: case `wrong verdict`: `C<RD>L` on `C RD L`: expected no-match, got match",
            "sub/aovs.toml: case `set`: `d=C<RD>L` on `C RD L`: expected no-match, got match",
            "sub/aovs.toml: case `set`: `s=C<RS>L` on `C RD L`: expected match, got no-match",
        ],
        "{out}"
    );
    assert!(
        out.contains("osl: 1 cases not run: the matcher refused the hello"),
        "{out}"
    );
    assert!(
        out.contains("suite: 4 cases run (6 answers checked), 3 failed"),
        "{out}"
    );
    // A suite that does not load is bad input.
    let bad = suite_dir(
        "bad",
        &[("x.toml", "[[case]]\nname = \"x\"\nexpr = \"CL\"\n")],
    );
    let (code, _, err) = lpe_check(&[
        "diff",
        "--external",
        "python3 examples/python/naive_matcher.py",
        "--suite",
        bad.to_str().unwrap(),
    ]);
    std::fs::remove_dir_all(&bad).unwrap();
    assert_eq!(code, 2);
    assert!(err.contains("x.toml: case `x`: no expectation"), "{err}");
}

/// `lpe-check diff --external PROXY --dialect osl` with `flags` for the test adapter,
/// on generated cases (`--cases 300` and `extra`).
fn planted_adapter_run(flags: &str, extra: &[&str]) -> (i32, String, String) {
    let proxy = proxy_in_the_osl_dialect(flags);
    let mut args = vec![
        "diff",
        "--external",
        &proxy,
        "--dialect",
        "osl",
        "--cases",
        "300",
    ];
    args.extend_from_slice(extra);
    lpe_check(&args)
}

/// Every `replay:` line of a report, run: the exit code and output of each.
fn replays(out: &str) -> Vec<(i32, String)> {
    out.lines()
        .filter_map(|l| l.trim().strip_prefix("replay: lpe-check "))
        .map(|replay| {
            let words = shell_words::split(replay).unwrap();
            let words: Vec<&str> = words.iter().map(|s| s.as_str()).collect();
            let (code, again, _) = lpe_check(&words);
            (code, again)
        })
        .collect()
}

/// The minimizer judges what the external process is sent. The planted adapter answers
/// "no AOV" on any set with a counted repetition, so minimizing walks the counts down
/// towards `{0}`, which OSL reads only among leading items: a candidate whose text lpe
/// rejects is rejected on both sides, not a disagreement. Every minimized case still
/// disagrees when replayed, and the header's case range ends at the last case asked.
#[test]
fn minimized_cases_still_disagree_when_replayed() {
    lpe_testkit::host::require_python3();
    let mut findings = 0;
    for seed in ["3", "4", "5"] {
        let (code, out, err) = planted_adapter_run("--miss-counted", &["--seed", seed]);
        assert_eq!(code, 3, "{out}{err}");
        let last = out
            .lines()
            .filter_map(|l| l.strip_prefix("case "))
            .filter_map(|l| l.split(':').next()?.parse::<u64>().ok())
            .max()
            .expect("a finding with its case");
        assert!(
            out.contains(&format!("cases 0..{}, ", last + 1)),
            "the header's range: {out}"
        );
        // The adapter is deterministic: no minimized case fell back to the original.
        assert!(!out.contains("note: "), "{out}");
        for (code, again) in replays(&out) {
            assert_eq!(
                code, 3,
                "a minimized case agrees on replay:\n{again}\nfrom\n{out}"
            );
            findings += 1;
        }
    }
    assert!(findings >= 6, "{findings}");
}

/// A candidate that crashed the external process is never sent again: with the planted
/// crash on `{0}` counts, no two crash findings carry the same request.
#[test]
fn a_candidate_that_crashed_is_not_sent_again() {
    lpe_testkit::host::require_python3();
    let (code, out, err) = planted_adapter_run(
        "--miss-counted --crash-on-zero",
        &["--seed", "4", "--max-restarts", "100"],
    );
    assert_eq!(code, 3, "{out}{err}");
    let requests: Vec<&str> = out
        .lines()
        .filter(|l| l.trim_start().starts_with("request:"))
        .collect();
    assert!(
        !requests.is_empty(),
        "no crash was planted on the way:\n{out}"
    );
    let mut distinct = requests.clone();
    distinct.sort();
    distinct.dedup();
    assert_eq!(distinct.len(), requests.len(), "{out}");
}

/// A flaky matcher (its bug shows only the first time it compiles a set) makes the
/// minimized case agree when asked again: the report says so and shows the original
/// case instead of one that does not disagree.
#[test]
fn a_minimized_case_that_agrees_on_replay_falls_back_to_the_original() {
    lpe_testkit::host::require_python3();
    let (code, out, err) = planted_adapter_run("--miss-counted --flaky", &["--seed", "3"]);
    assert_eq!(code, 3, "{out}{err}");
    assert!(
        out.contains(
            "note: the minimized case agreed when asked again; the original case is shown"
        ),
        "{out}"
    );
    // The finding shows the original set: its `aov` lines equal those under "from the
    // original case".
    let finding = out.split("\ncase ").nth(1).expect("a finding");
    let shown: Vec<&str> = finding
        .lines()
        .filter(|l| l.starts_with("  aov "))
        .map(str::trim)
        .collect();
    let original: Vec<&str> = finding
        .lines()
        .filter(|l| l.starts_with("    aov "))
        .map(str::trim)
        .collect();
    assert_eq!(shown, original, "{finding}");
}

/// The restart budget holds during minimization: an adapter that answers one `compile`
/// per process and crashes on the next, on a given case it disagrees on. Minimizing
/// crashes it on every second candidate; with `--max-restarts N` the run makes exactly N
/// restarts, reports N + 1 crashes and the one disagreement, and never restarts the
/// process past the budget to ask about the minimized case again.
#[test]
fn the_restart_budget_holds_during_minimization() {
    lpe_testkit::host::require_python3();
    let proxy = proxy_in_the_osl_dialect("--miss-counted --crash-after 1");
    for n in [0u64, 1, 5] {
        let budget = n.to_string();
        let (code, out, err) = lpe_check(&[
            "diff",
            "--external",
            &proxy,
            "--dialect",
            "osl",
            "--expr",
            "C<.D>{1,2}<.G>*<.S>+<L.>",
            "--path",
            "C,_ R,D R,G R,G R,S L,_",
            "--max-restarts",
            &budget,
        ]);
        assert_eq!(code, 3, "{out}{err}");
        let summary = format!(
            "summary: {} finding(s), 1 disagreement(s), {n} restart(s) of the external process",
            n + 2
        );
        assert!(out.contains(&summary), "N = {n}:\n{out}");
        let crashes = out
            .lines()
            .filter(|l| {
                l.trim_start().starts_with(|c: char| c.is_ascii_digit()) && l.ends_with(". crash")
            })
            .count();
        assert_eq!(crashes as u64, n + 1, "N = {n}:\n{out}");
    }
}
