//! One checked property and its outcome: what verification produces, and what the console
//! and the report print (a leaf both import).

use serde::Serialize;

/// One checked property and its measured error.
#[derive(Clone, Debug, Serialize)]
pub struct Invariant {
    pub name: String,
    /// The measured error (its meaning is in `detail`).
    pub measured: f64,
    pub tolerance: f64,
    /// `None`: not checked, or informational (e.g. a formal check of a set that need
    /// not partition every path).
    pub passed: Option<bool>,
    pub detail: String,
    /// Decided on the automata for every possible path (no measurement: `measured` and
    /// `tolerance` mean nothing; `detail` says what was decided, with a witness path).
    pub formal: bool,
}

impl Invariant {
    /// A measured property: it passes when `measured <= tolerance` (NaN fails).
    pub fn new(
        name: impl Into<String>,
        measured: f64,
        tolerance: f64,
        detail: impl Into<String>,
    ) -> Self {
        Invariant {
            name: name.into(),
            measured,
            tolerance,
            passed: Some(measured <= tolerance),
            detail: detail.into(),
            formal: false,
        }
    }

    /// The measurement as printed (`-` for a formal check).
    pub fn measured_text(&self) -> String {
        if self.formal {
            "-".into()
        } else {
            format!("{:.3e}", self.measured)
        }
    }

    /// The tolerance as printed (`-` for a formal check).
    pub fn tolerance_text(&self) -> String {
        if self.formal {
            "-".into()
        } else {
            format!("{:.3e}", self.tolerance)
        }
    }

    /// One console line: the outcome and name, then what was measured against what,
    /// or for a formal check what was decided and its witness.
    pub fn line(&self) -> String {
        let tag = match self.passed {
            Some(true) => "pass",
            Some(false) => "FAIL",
            None => "skip",
        };
        if self.formal {
            format!("[{tag}] {} — {}", self.name, self.detail)
        } else {
            format!(
                "[{tag}] {} — measured {:.3e} (tolerance {:.3e})",
                self.name, self.measured, self.tolerance
            )
        }
    }

    pub fn failed(&self) -> bool {
        self.passed == Some(false)
    }
}
