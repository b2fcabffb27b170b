//! Every subcommand whose output goes into a pipe that nobody reads any more stops
//! quietly, as Unix tools do: no panic, no "internal failure", exit 141 (128 + SIGPIPE).
//!
//! The pipe's read end is closed before `lpe-check` starts, so its first write fails
//! with `BrokenPipe` every time (with a live reader that closes "early", a short output
//! could fit in the pipe's buffer and the test would pass without testing anything).
//! Checked against planted faults: without the panic hook (`pipe::quiet_on_closed_pipe`
//! not installed) every row fails with exit 101 and the panic on stderr; with the hook
//! matching only stdout's failure, none fails here but the unit test in `cli/src/pipe.rs`
//! does.

use std::io::Write;
use std::process::{Command, Stdio};

/// Runs `lpe-check args` with `stdin` on its standard input and a pipe whose reader is
/// already gone as its standard output; returns the exit code and standard error.
fn into_closed_pipe(args: &[&str], stdin: &str) -> (Option<i32>, String) {
    // `std::io::pipe` is newer than the workspace's `rust-version`; tests are built only
    // with the workspace's own toolchain.
    #[allow(clippy::incompatible_msrv)]
    let (reader, writer) = std::io::pipe().expect("a pipe");
    drop(reader);
    let mut child = Command::new(env!("CARGO_BIN_EXE_lpe-check"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(writer)
        .stderr(Stdio::piped())
        .spawn()
        .expect("lpe-check runs");
    // The command may exit before reading its input: a failed write here is fine.
    let _ = child.stdin.take().unwrap().write_all(stdin.as_bytes());
    let out = child.wait_with_output().unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn every_subcommand_stops_quietly_on_a_closed_pipe() {
    let usd = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../tests/testdata/usd/clean_basic.usda"
    );
    let runs: &[(&[&str], &str)] = &[
        (&["parse", "C<RD>.+[<L.>O]"], ""),
        (&["match", "C.*L", "C RD L"], ""),
        (&["match", "--batch"], "C.*L\tC RD L\nCDL\tC RS L\n"),
        (&["equiv", "C.*L", "C.*[LO]"], ""),
        (&["partition", "directDiffuse", "indirectDiffuse"], ""),
        (&["lint", "--format", "json", usd], ""),
        (&["lint", usd], ""),
        (&["explain", "C RD L", "--aov", "a=C.*L"], ""),
        (
            &[
                "translate",
                "--from",
                "renderman",
                "--to",
                "osl",
                "indirectDiffuse",
            ],
            "",
        ),
        (&["diff", "--cases", "30"], ""),
    ];
    let mut failures = Vec::new();
    for (args, stdin) in runs {
        let (code, err) = into_closed_pipe(args, stdin);
        if code != Some(141) || err.contains("panicked") || err.contains("internal failure") {
            failures.push(format!(
                "lpe-check {}: exit {code:?}, stderr: {err}",
                args.join(" ")
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
