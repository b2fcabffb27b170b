//! `lpe-check`, the command line over the engines of `lpe-engines`, the checks of
//! `lpe-lint` and the benchmark of `lpe-bench`, as a library so the tests share its code.
//! The capabilities are those libraries'; this crate parses arguments, calls them,
//! prints and gives exit codes.
//!
//! - [`cmd`]: one module per subcommand (`parse`, `match`, `equiv`, `partition`,
//!   `bench`, `diff`, `lint`, `explain`, `translate`, `serve`, `report`), each with its clap `Args` and a `run` giving
//!   the exit code; the binary (`src/main.rs`) only dispatches.
//! - [`dialect`]: what the subcommands ask of an expression language
//!   ([`dialect::CliDialect`], on `lpe`'s RenderMan and OSL markers): registration from
//!   `--ini` or `--register`, how its errors print.
//! - [`error`]: [`error::InputError`], what the subcommands report as bad input
//!   (exit 2).
//! - [`input`]: what the subcommands share to read their input (`--engine`,
//!   `--dialect` with `--ini` or `--register`).
//! - [`pipe`]: output into a closed pipe ends the run quietly (exit 141), as Unix tools
//!   do, instead of a panic.
//! - [`witness`]: the exit code and printing of reports whose witnesses
//!   [`lpe_lint::witness`] re-checked with the reference matcher (`equiv`, `partition`,
//!   `lint`).

pub mod cmd;
pub mod dialect;
pub mod error;
pub mod input;
pub mod pipe;
pub mod witness;
