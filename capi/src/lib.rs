//! The C ABI of lpe: compile an AOV set once, classify each kind of scene vertex once,
//! then per path `lpe_start`, one `lpe_step` per vertex, `lpe_matches` at an emitter and
//! `lpe_is_dead` to stop early; or, with the set's step view (`lpe_set_step_view`), the
//! header's inline `lpe_view_step` and `lpe_view_is_dead`, which load from the set's DFA
//! table in the caller's loop and give the calls' answers. The header is `capi/include/lpe.h`, generated from
//! these items by cbindgen (a test fails when the checked-in header is stale).
//!
//! Conventions every function keeps:
//! - the return value is an [`lpe_status`] (or a size, a string or a pointer that is
//!   `NULL`/0 on bad arguments, as documented per function);
//! - null pointers and out-of-range indices or classes are errors, never crashes;
//! - no Rust panic crosses the boundary: each body runs under `catch_unwind`, a panic
//!   becomes `LPE_ERR_PANIC`;
//! - a compiled `lpe_set` is immutable: share it across threads freely; `lpe_state`
//!   (a 32-bit id) and `lpe_class` are plain values the caller copies; an `lpe_cache`
//!   (optional, for sets stepped as a lazy DFA) belongs to one thread at a time.
//!
//! Both dialects: `LPE_DIALECT_RENDERMAN` sets classify vertices by type, event, lobe
//! and label (`lpe_classify`, `lpe_classify_text`); `LPE_DIALECT_OSL` sets, compiled
//! under the registration in `lpe_options.osl_registered`, classify a vertex from its
//! symbols (`lpe_classify_symbols`). Stepping is the same for both.
//!
//! Modules: [`status`] (codes and the panic guard), `args` (C string arguments as
//! text), [`error`] (the error object of a failed compile), `dialect` (what the ABI asks
//! of each dialect beyond `lpe::Dialect`: `CDialect` on `lpe`'s RenderMan and OSL
//! markers with its `LPE_DIALECT_*` number, one file each; the set of any dialect),
//! [`set`] (compile, names, warnings, free), [`classify`] (vertices to classes: the
//! entry points whose C vertex types are a dialect's), [`step`] (states: start, step,
//! matches, is_dead; caches), [`view`] (the step view the header's inline
//! `lpe_view_step` reads), [`bench`] (a benchmark-only export, not in the header, for
//! `examples/c/step_bench.c`; the criterion step bench is `lpe-bench`'s,
//! `cargo bench -p lpe-bench --bench step`). Each imports only modules listed before it.

#![allow(non_camel_case_types)]
// Every pointer argument is checked for null and documented in the header; marking the
// functions `unsafe` would add nothing for C callers.
#![allow(clippy::not_unsafe_ptr_arg_deref)]

mod args;
pub mod bench;
pub mod classify;
mod dialect;
pub mod error;
pub mod set;
pub mod status;
pub mod step;
pub mod view;

pub use classify::{lpe_class, lpe_vertex};
pub use error::lpe_error;
pub use set::{lpe_options, lpe_set};
pub use status::lpe_status;
pub use step::{lpe_cache, lpe_state};
pub use view::lpe_step_view;
