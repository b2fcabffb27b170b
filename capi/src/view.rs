//! The step view: a set's DFA table exported read-only, so that a C caller steps inline.
//!
//! A Rust step is one table load (1-2 ns), cheaper than any out-of-line call, so a
//! renderer that calls `lpe_step` per vertex pays for the call, not the step. The view
//! hands out what the step reads (the transition table, its length, the class count) and
//! the header's `static inline` `lpe_view_step` does the load itself, falling back to
//! `lpe_step` for whatever the table does not answer (a lazy set, a class or state out
//! of range), so that every answer is `lpe_step`'s.

use crate::set::lpe_set;
use crate::status::{guard, lpe_status};
use crate::step::lpe_state;

/// What stepping a set reads, for the header's inline `lpe_view_step` and
/// `lpe_view_is_dead`: fill it once per set with `lpe_set_step_view`, keep it beside the
/// set (a local copy in the loop is best), and step with it where you would call
/// `lpe_step`. Read-only: it points into the set, stays valid until `lpe_set_free`, and
/// never changes, so threads share it as they share the set. Only states of this set
/// (from `start`, `lpe_start` or a step of it) and its classes mean anything; anything
/// else gets `lpe_step`'s answer, never a crash.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct lpe_step_view {
    /// The set; the inline functions call `lpe_step` on it for what the table does not
    /// answer.
    pub set: *const lpe_set,
    /// The DFA's transitions: for a class `c` below `class_count` and a state `s`, when
    /// `i = (uint32_t)(s.opaque + c.id)` is below `table_len`, `table[i]` is the state
    /// `lpe_step` steps `s` to. NULL for a lazy set (over `lpe_options.dfa_budget`).
    pub table: *const u32,
    /// Entries in `table` (0 for a lazy set: every step falls back to `lpe_step`).
    pub table_len: usize,
    /// `lpe_set_class_count`: a class at or above it is `lpe_step`'s `LPE_ERR_RANGE`.
    pub class_count: usize,
    /// `lpe_start`'s state.
    pub start: lpe_state,
    /// Whether state 0 is dead: `lpe_is_dead` answers `opaque == 0 && zero_is_dead`.
    pub zero_is_dead: bool,
}

/// Fills `*view` with `set`'s step view (see `lpe_step_view`); `LPE_ERR_NULL` if either
/// is NULL.
#[no_mangle]
pub extern "C" fn lpe_set_step_view(set: *const lpe_set, view: *mut lpe_step_view) -> lpe_status {
    // SAFETY: NULL or valid pointers from the caller.
    let (Some(s), Some(out)) = (unsafe { set.as_ref() }, unsafe { view.as_mut() }) else {
        return lpe_status::LPE_ERR_NULL;
    };
    guard(lpe_status::LPE_ERR_PANIC, || {
        let table = s.set.automaton().step_table();
        *out = lpe_step_view {
            set,
            table: if table.is_empty() {
                std::ptr::null()
            } else {
                table.as_ptr()
            },
            table_len: table.len(),
            class_count: s.class_count,
            start: lpe_state {
                opaque: s.set.automaton().start().to_u32(),
            },
            zero_is_dead: s.set.automaton().is_dead(lpe::State::from_u32(0)),
        };
        lpe_status::LPE_OK
    })
}
