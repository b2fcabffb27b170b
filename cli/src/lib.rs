//! `lpe-check`, the command line over the engines of `lpe-engines`, as a library so the
//! criterion bench (`cargo bench -p lpe-cli`) and the tests share its code.
//!
//! - [`cmd`]: one module per subcommand (`parse`, `match`, `equiv`, `partition`,
//!   `bench`, `diff`), each with its clap `Args` and a `run` giving the exit code; the
//!   binary (`src/main.rs`) only dispatches.
//! - [`input`]: what the subcommands share to read their input (`--engine`, `--ini`)
//!   and the typed [`input::InputError`] they report (exit 2).
//! - [`lint`]: the checks of `lpe-check lint` on what `lpe-lint` reads, and their text
//!   and JSON reports.
//! - [`witness`]: analysis witnesses re-checked with the reference matcher before
//!   `equiv` and `partition` print them.
//! - [`bench`](mod@bench): the matcher benchmark, workloads, path sampler, the
//!   regex-automata baseline and the timed loops, shared with the criterion bench.

pub mod bench;
pub mod cmd;
pub mod input;
pub mod lint;
pub mod witness;
