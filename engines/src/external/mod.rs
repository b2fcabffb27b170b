//! External matchers: any program that speaks the JSON Lines protocol of
//! docs/protocol.md, differential-tested against the registered engines.
//!
//! - [`protocol`]: the request and reply types, and the check of a reply against its
//!   request ([`protocol::Violation`]: malformed, another request's id, unknown, wrong
//!   answer count).
//! - [`process`]: the child process, its stdout read on a thread so every wait has a
//!   deadline.
//! - [`client`]: typed requests; any [`Fault`] (crash, timeout, bad reply) kills the
//!   process and the next request starts a fresh one.
//! - [`harness`]: `lpe-check diff --external`, generated cases compared with every
//!   engine, disagreements minimized by re-asking the external process (the moves of
//!   [`crate::differential::shrink`]); its report is structured data, each finding with
//!   the set, path and registration that replay it.

pub mod client;
pub mod harness;
pub mod process;
pub mod protocol;

pub use client::{Client, Fault, FaultKind, StartError};
pub use harness::{run, Answer, Cases, Disagreement, Finding, Report, Setup};
pub use process::MAX_LINE;
pub use protocol::{AovSource, Reply, PROTOCOL_MINOR, PROTOCOL_VERSION};
