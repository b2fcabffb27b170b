//! The exit code and printing of re-checked reports (`equiv`, `partition`, `lint`). The
//! re-check itself, re-exported here, is [`lpe_lint::witness`]: the analysis in `lpe`
//! builds witnesses from its own automata, and every witness goes through
//! [`recheck`] before it is printed.

use std::process::ExitCode;

pub use lpe_lint::witness::{recheck, Checked, Disagreement, Expect, PathOf};

/// Exit code for a witness that failed its re-check.
pub const DISAGREE: u8 = 3;

/// Prints a re-checked report and gives the exit code shared by `equiv` and
/// `partition`: 0 when `clean`, 1 when not, [`DISAGREE`] when a witness failed its
/// re-check (then only the disagreement is printed, on stderr).
pub fn exit_with(report: Result<String, Disagreement>, clean: bool) -> ExitCode {
    match report {
        Ok(text) => {
            print!("{text}");
            ExitCode::from(u8::from(!clean))
        }
        Err(e) => {
            eprintln!("{e}");
            ExitCode::from(DISAGREE)
        }
    }
}
