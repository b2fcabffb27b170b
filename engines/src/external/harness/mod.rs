//! `lpe-check diff --external`: generated (or given) cases asked of an external matcher
//! and of the registered engines, disagreements minimized by re-asking the external
//! process, protocol faults reported with their request.
//!
//! Per case: `compile` the AOV set, then one batched `match` of all its paths. An
//! external `unsupported` reply (to `compile` or `match`) makes the case *unsupported*:
//! counted and reported in the summary, never a disagreement, and the minimizer never
//! steps onto an unsupported input. Whether an expression is an error is compared too:
//! the external rejecting a set every engine accepts, or accepting one lpe rejects, is a
//! disagreement (byte positions are shown, not compared: they legitimately differ).
//!
//! The report, then the run:
//!
//! - [`report`]: what a run found ([`Report`], [`Finding`], [`Disagreement`],
//!   [`Answer`]) and how it prints, as structured data: the set, path and registration
//!   of a finding are there for a caller to replay it (`lpe-check` prints its own
//!   command line);
//! - [`run`](mod@run): driving the cases in pipelined batches ([`run()`], [`Setup`],
//!   [`Cases`]);
//! - [`answers`]: each side's answers on one set, the external process's over the
//!   protocol and the engines';
//! - [`judge`](mod@judge): one case's answers compared, a disagreement minimized, asked
//!   again and recorded;
//! - [`minimize`](mod@minimize): the minimizer's failure test that re-asks the external
//!   process.

pub mod answers;
pub mod judge;
pub mod minimize;
pub mod report;
pub mod run;

pub use report::{Answer, Disagreement, Finding, Report};
pub use run::{run, Cases, Setup};
