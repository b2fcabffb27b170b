//! The exit code and printing of re-checked reports (`equiv`, `partition`, `lint`). The
//! re-check itself, re-exported here, is [`lpe_lint::witness`]: the analysis in `lpe`
//! builds witnesses from its own automata, and every witness goes through
//! [`recheck`] before it is printed.

use std::process::ExitCode;

pub use lpe_lint::witness::{recheck, Checked, Disagreement, Expect, PathOf};

/// Exit code for a witness that failed its re-check.
pub const DISAGREE: u8 = 3;

/// Exit code of `equiv` and `partition` when the analysis ran out of its budget
/// (`--max-steps`, `--max-seconds`) before deciding: nothing was wrong with the input.
pub const UNDECIDED: u8 = 4;

/// The analysis budget of `equiv` and `partition`.
#[derive(clap::Args, Debug, Clone)]
pub struct BudgetArgs {
    /// Most search steps the analysis may take before answering `undecided` (exit 4).
    #[arg(long, default_value_t = lpe::analysis::DEFAULT_STEPS)]
    pub max_steps: usize,
    /// Most seconds the analysis may take before answering `undecided` (exit 4).
    #[arg(long)]
    pub max_seconds: Option<f64>,
}

impl BudgetArgs {
    /// The budget these arguments give.
    pub fn budget(&self) -> lpe::analysis::AnalysisBudget {
        lpe::analysis::AnalysisBudget {
            steps: self.max_steps,
            time: self
                .max_seconds
                .and_then(|s| std::time::Duration::try_from_secs_f64(s).ok()),
        }
    }
}

/// Prints `undecided: …` and gives [`UNDECIDED`].
pub fn exit_undecided(u: &lpe::analysis::Undecided) -> ExitCode {
    println!("undecided: {u}");
    ExitCode::from(UNDECIDED)
}

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
