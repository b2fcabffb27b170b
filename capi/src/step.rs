//! Per-path states: start, step, matches, is_dead; and caller-owned lazy-DFA caches.
//!
//! `lpe_state` is lpe's `State`, a 32-bit id, by value: stepping is one call with no
//! allocation, and a state fits a register. A set over its DFA budget is a lazy DFA,
//! determinized into a cache while stepping: `lpe_step` and `lpe_matches` use a cache
//! per thread (kept by the library), `lpe_step_with` and `lpe_matches_with` one the
//! caller owns (`lpe_cache_new`), which saves the thread-local lookup per step.

use lpe::{AovMask, Cache, Class, State};

use crate::classify::lpe_class;
use crate::set::lpe_set;
use crate::status::{guard, lpe_status};

/// Where one path is. Opaque, plain data: copy it freely (to branch a path), keep one
/// per path, only pass states this library returned for the same set.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct lpe_state {
    /// Do not read or write: the library's representation.
    pub opaque: u32,
}

impl lpe_state {
    #[inline(always)]
    fn from_state(s: State) -> lpe_state {
        lpe_state { opaque: s.to_u32() }
    }

    #[inline(always)]
    fn to_state(self) -> State {
        State::from_u32(self.opaque)
    }
}

/// A lazy-DFA cache of one set, for one thread at a time: `lpe_step_with` and
/// `lpe_matches_with` step through it. Holds nothing for a set with a DFA. Release it
/// with `lpe_cache_free`, before its set.
pub struct lpe_cache {
    cache: Cache,
}

/// A cache for stepping `set` (sized by `lpe_options.lazy_cache`), or NULL if `set` is
/// NULL. One per thread: a cache is not thread-safe, the set is.
#[no_mangle]
pub extern "C" fn lpe_cache_new(set: *const lpe_set) -> *mut lpe_cache {
    // SAFETY: NULL or a set this library returned.
    let Some(set) = (unsafe { set.as_ref() }) else {
        return std::ptr::null_mut();
    };
    guard(std::ptr::null_mut(), || {
        Box::into_raw(Box::new(lpe_cache {
            cache: set.set.automaton().cache(),
        }))
    })
}

/// Releases a cache. NULL is ignored.
#[no_mangle]
pub extern "C" fn lpe_cache_free(cache: *mut lpe_cache) {
    if !cache.is_null() {
        guard((), || {
            // SAFETY: a cache this library returned, freed once.
            drop(unsafe { Box::from_raw(cache) });
        });
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
        *out = lpe_state::from_state(set.set.automaton().start());
        lpe_status::LPE_OK
    })
}

/// Steps `*state` over one vertex of class `cls`, in place. `LPE_ERR_RANGE` if `cls` is
/// not a class of `set` (the state is then unchanged). No allocation, no lock; a lazy
/// set steps through this thread's cache.
#[no_mangle]
pub extern "C" fn lpe_step(
    set: *const lpe_set,
    state: *mut lpe_state,
    cls: lpe_class,
) -> lpe_status {
    step_one(set, state, cls, |set, s, c| {
        set.set.automaton().step_class(s, c)
    })
}

/// `lpe_step` through the caller's cache (from `lpe_cache_new` for this set; a cache of
/// another set is reset for this one). `LPE_ERR_NULL` if `cache` is NULL.
#[no_mangle]
pub extern "C" fn lpe_step_with(
    set: *const lpe_set,
    cache: *mut lpe_cache,
    state: *mut lpe_state,
    cls: lpe_class,
) -> lpe_status {
    // SAFETY: NULL or a cache this library returned, used by one thread at a time.
    let Some(cache) = (unsafe { cache.as_mut() }) else {
        return lpe_status::LPE_ERR_NULL;
    };
    step_one(set, state, cls, |set, s, c| {
        set.set.automaton().step_with(&mut cache.cache, s, c)
    })
}

/// One checked step of `*state` by `step`.
#[inline(always)]
fn step_one(
    set: *const lpe_set,
    state: *mut lpe_state,
    cls: lpe_class,
    step: impl FnOnce(&lpe_set, State, Class) -> State,
) -> lpe_status {
    // SAFETY: NULL or valid pointers from the caller.
    let (Some(set), Some(state)) = (unsafe { set.as_ref() }, unsafe { state.as_mut() }) else {
        return lpe_status::LPE_ERR_NULL;
    };
    let Some(c) = cls.to_class(set) else {
        return lpe_status::LPE_ERR_RANGE;
    };
    guard(lpe_status::LPE_ERR_PANIC, || {
        *state = lpe_state::from_state(step(set, state.to_state(), c));
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
    guard(lpe_status::LPE_ERR_PANIC, || {
        // One pass: the steps go to a local, written back only if every class is valid.
        let mut s = state.to_state();
        for c in classes {
            let Some(c) = c.to_class(set) else {
                return lpe_status::LPE_ERR_RANGE;
            };
            s = set.set.automaton().step_class(s, c);
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
    matches_by(set, state, words, word_count, match_count, |set, s| {
        set.set.automaton().matches(s)
    })
}

/// `lpe_matches` through the caller's cache (see `lpe_step_with`). `LPE_ERR_NULL` if
/// `cache` is NULL.
#[no_mangle]
pub extern "C" fn lpe_matches_with(
    set: *const lpe_set,
    cache: *mut lpe_cache,
    state: *const lpe_state,
    words: *mut u64,
    word_count: usize,
    match_count: *mut usize,
) -> lpe_status {
    // SAFETY: NULL or a cache this library returned, used by one thread at a time.
    let Some(cache) = (unsafe { cache.as_mut() }) else {
        return lpe_status::LPE_ERR_NULL;
    };
    matches_by(set, state, words, word_count, match_count, |set, s| {
        set.set.automaton().matches_with(&mut cache.cache, s)
    })
}

/// The checked arguments of a matches call, the mask from `mask` written out.
fn matches_by(
    set: *const lpe_set,
    state: *const lpe_state,
    words: *mut u64,
    word_count: usize,
    match_count: *mut usize,
    mask: impl FnOnce(&lpe_set, State) -> AovMask,
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
        let mask = mask(set, state.to_state());
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
        *dead = set.set.automaton().is_dead(state.to_state());
        lpe_status::LPE_OK
    })
}
