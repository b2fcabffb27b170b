//! Per-path states: start, step, matches, is_dead.
//!
//! `lpe_state` is a fixed-size opaque value (32 bytes, 8-aligned) holding lpe's `State`
//! by copy. lpe's state representation may change (a register-sized DFA id, a wide NFA
//! state); C callers never look inside, so only the compile-time size check below has
//! to hold, and the step stays one call with no allocation.

use lpe::State;

use crate::classify::lpe_class;
use crate::set::lpe_set;
use crate::status::{guard, lpe_status};

/// Where one path is. Opaque, plain data: copy it freely (to branch a path), keep one
/// per path, only pass states this library returned for the same set.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct lpe_state {
    /// Do not read or write: the library's representation.
    pub opaque: [u64; 4],
}

const _: () = assert!(std::mem::size_of::<State>() <= std::mem::size_of::<lpe_state>());
const _: () = assert!(std::mem::align_of::<State>() <= std::mem::align_of::<lpe_state>());

impl lpe_state {
    #[inline(always)]
    fn from_state(s: State) -> lpe_state {
        let mut out = lpe_state { opaque: [0; 4] };
        // SAFETY: `State` is plain `Copy` data that fits (size and alignment asserted
        // above); the bytes past it stay zero.
        unsafe { std::ptr::write(out.opaque.as_mut_ptr().cast::<State>(), s) };
        out
    }

    #[inline(always)]
    fn to_state(self) -> State {
        // SAFETY: the bytes were written by `from_state` (callers pass only states this
        // library returned); size and alignment asserted above.
        unsafe { std::ptr::read(self.opaque.as_ptr().cast::<State>()) }
    }
}

/// The state before any vertex (step the camera first), into `*out`.
#[no_mangle]
pub extern "C" fn lpe_start(set: *const lpe_set, out: *mut lpe_state) -> lpe_status {
    // SAFETY: NULL or valid pointers from the caller.
    let (Some(set), Some(out)) = (unsafe { set.as_ref() }, unsafe { out.as_mut() }) else {
        return lpe_status::LPE_ERR_NULL;
    };
    guard(lpe_status::LPE_ERR_PANIC, || {
        *out = lpe_state::from_state(set.set.start());
        lpe_status::LPE_OK
    })
}

/// Steps `*state` over one vertex of class `cls`, in place. `LPE_ERR_RANGE` if `cls` is
/// not a class of `set` (the state is then unchanged). No allocation, no lock.
#[no_mangle]
pub extern "C" fn lpe_step(
    set: *const lpe_set,
    state: *mut lpe_state,
    cls: lpe_class,
) -> lpe_status {
    // SAFETY: NULL or valid pointers from the caller.
    let (Some(set), Some(state)) = (unsafe { set.as_ref() }, unsafe { state.as_mut() }) else {
        return lpe_status::LPE_ERR_NULL;
    };
    let Some(c) = cls.to_class(set) else {
        return lpe_status::LPE_ERR_RANGE;
    };
    guard(lpe_status::LPE_ERR_PANIC, || {
        *state = lpe_state::from_state(set.set.step_class(state.to_state(), c));
        lpe_status::LPE_OK
    })
}

/// Steps `*state` over `count` vertices of the given classes, in place: the same as
/// `count` calls of `lpe_step`, one call for a whole path segment (the per-call overhead
/// paid once). `LPE_ERR_RANGE` if any class is not one of `set`'s: then no step is
/// taken. `classes` may be NULL when `count` is 0.
#[no_mangle]
pub extern "C" fn lpe_step_n(
    set: *const lpe_set,
    state: *mut lpe_state,
    classes: *const lpe_class,
    count: usize,
) -> lpe_status {
    // SAFETY: NULL or valid pointers from the caller.
    let (Some(set), Some(state)) = (unsafe { set.as_ref() }, unsafe { state.as_mut() }) else {
        return lpe_status::LPE_ERR_NULL;
    };
    if count == 0 {
        return lpe_status::LPE_OK;
    }
    if classes.is_null() {
        return lpe_status::LPE_ERR_NULL;
    }
    // SAFETY: the caller passes `count` readable classes (checked non-null).
    let classes = unsafe { std::slice::from_raw_parts(classes, count) };
    if classes.iter().any(|c| c.to_class(set).is_none()) {
        return lpe_status::LPE_ERR_RANGE;
    }
    guard(lpe_status::LPE_ERR_PANIC, || {
        let mut s = state.to_state();
        for c in classes {
            if let Some(c) = c.to_class(set) {
                s = set.set.step_class(s, c);
            }
        }
        *state = lpe_state::from_state(s);
        lpe_status::LPE_OK
    })
}

/// Which AOVs match a path ending in `*state`: bit `i % 64` of `words[i / 64]` is AOV
/// `i`. `word_count` must be at least `lpe_set_mask_words(set)` (else `LPE_ERR_RANGE`);
/// extra words are zeroed. `words` may be NULL when `word_count` is 0 (only the count is
/// wanted). `*match_count` (if not NULL) receives the number of matching AOVs.
#[no_mangle]
pub extern "C" fn lpe_matches(
    set: *const lpe_set,
    state: *const lpe_state,
    words: *mut u64,
    word_count: usize,
    match_count: *mut usize,
) -> lpe_status {
    // SAFETY: NULL or valid pointers from the caller.
    let (Some(set), Some(state)) = (unsafe { set.as_ref() }, unsafe { state.as_ref() }) else {
        return lpe_status::LPE_ERR_NULL;
    };
    if words.is_null() && word_count > 0 {
        return lpe_status::LPE_ERR_NULL;
    }
    let need = set.set.len().div_ceil(64).max(1);
    if word_count > 0 && word_count < need {
        return lpe_status::LPE_ERR_RANGE;
    }
    guard(lpe_status::LPE_ERR_PANIC, || {
        let mask = set.set.matches(state.to_state());
        if word_count > 0 {
            // SAFETY: the caller passes `word_count` writable words (checked non-null).
            let out = unsafe { std::slice::from_raw_parts_mut(words, word_count) };
            out.fill(0);
            for i in mask.iter() {
                out[i / 64] |= 1 << (i % 64);
            }
        }
        if !match_count.is_null() {
            // SAFETY: checked non-null; the caller passes a writable `size_t`.
            unsafe { *match_count = mask.count() };
        }
        lpe_status::LPE_OK
    })
}

/// Whether no continuation of the path can match any AOV, into `*dead`: stop tracking
/// the path once it is.
#[no_mangle]
pub extern "C" fn lpe_is_dead(
    set: *const lpe_set,
    state: *const lpe_state,
    dead: *mut bool,
) -> lpe_status {
    // SAFETY: NULL or valid pointers from the caller.
    let (Some(set), Some(state), Some(dead)) =
        (unsafe { set.as_ref() }, unsafe { state.as_ref() }, unsafe {
            dead.as_mut()
        })
    else {
        return lpe_status::LPE_ERR_NULL;
    };
    guard(lpe_status::LPE_ERR_PANIC, || {
        *dead = set.set.is_dead(state.to_state());
        lpe_status::LPE_OK
    })
}
