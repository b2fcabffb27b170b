//! Status codes, and the guard that keeps panics on the Rust side.

use std::ffi::c_char;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// What a call did. `LPE_OK` is 0; every error is non-zero.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum lpe_status {
    /// Success.
    LPE_OK = 0,
    /// A required pointer argument was NULL.
    LPE_ERR_NULL = 1,
    /// An index, class, letter, lobe number or buffer size out of range.
    LPE_ERR_RANGE = 2,
    /// A string that is not UTF-8.
    LPE_ERR_UTF8 = 3,
    /// An expression or a vertex text does not parse (see the `lpe_error`).
    LPE_ERR_PARSE = 4,
    /// The rendermn.ini text has a bad line (see the `lpe_error`).
    LPE_ERR_INI = 5,
    /// The set does not compile: too many AOVs, an automaton over budget.
    LPE_ERR_COMPILE = 6,
    /// The dialect or operation is not available in this build.
    LPE_ERR_UNSUPPORTED = 7,
    /// An internal failure (a caught panic): please report it with the input.
    LPE_ERR_PANIC = 8,
}

/// A static, NUL-terminated description of a status code (an `lpe_status` value; any
/// other number gives "unknown status"). Never NULL.
#[no_mangle]
pub extern "C" fn lpe_status_message(status: u32) -> *const c_char {
    // A number rather than the enum: C may pass any int, and an out-of-range Rust enum
    // would be undefined behaviour.
    let s: &'static [u8] = match status {
        0 => b"ok\0",
        1 => b"a required pointer argument is NULL\0",
        2 => b"an argument is out of range\0",
        3 => b"a string is not UTF-8\0",
        4 => b"an expression or vertex does not parse\0",
        5 => b"the rendermn.ini text has a bad line\0",
        6 => b"the AOV set does not compile\0",
        7 => b"not available in this build\0",
        8 => b"internal failure\0",
        _ => b"unknown status\0",
    };
    s.as_ptr().cast()
}

/// Runs `f`, turning a panic into `fallback`.
#[inline(always)]
pub(crate) fn guard<T>(fallback: T, f: impl FnOnce() -> T) -> T {
    catch_unwind(AssertUnwindSafe(f)).unwrap_or(fallback)
}
