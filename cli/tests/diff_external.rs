//! `lpe-check diff --external` end to end: exit codes, the printed replay command and
//! that it replays. Needs python3 for the example matcher (skipped with the reason
//! printed when it is absent); the harness itself is tested in lpe-engines.

use std::process::Command;

fn lpe_check(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_lpe-check"))
        .args(args)
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
        .output()
        .expect("lpe-check runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

fn python() -> bool {
    let ok = Command::new("python3")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    if !ok {
        eprintln!("skipped: python3 is not installed, so the example matcher cannot run");
    }
    ok
}

#[test]
fn bad_input_exits_2() {
    for args in [
        &["diff", "--external", "/nonexistent/adapter"][..],
        &["diff", "--external", "'unclosed"],
        &["diff", "--external", "true", "--dialect", "osl"],
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
    if !python() {
        return;
    }
    let clean = "python3 examples/python/naive_matcher.py";
    let (code, out, err) = lpe_check(&["diff", "--external", clean, "--cases", "60"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("agrees with every engine"), "{out}");
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
