//! The error object of a failed compile: status, message, which AOV, which byte.

use std::ffi::{c_char, CString};

use crate::status::{guard, lpe_status};

/// Why `lpe_set_compile` failed. Opaque: read it with the `lpe_error_*` functions and
/// release it with `lpe_error_free`.
pub struct lpe_error {
    pub(crate) status: lpe_status,
    pub(crate) message: CString,
    pub(crate) aov: i64,
    pub(crate) position: i64,
}

impl lpe_error {
    /// An error with no byte position.
    pub(crate) fn plain(status: lpe_status, message: &str, aov: Option<usize>) -> lpe_error {
        lpe_error::new(status, message.into(), aov, None)
    }

    pub(crate) fn new(
        status: lpe_status,
        message: String,
        aov: Option<usize>,
        position: Option<usize>,
    ) -> lpe_error {
        // Messages never hold NUL; if one did, cut it there rather than fail.
        let message = CString::new(message).unwrap_or_else(|e| {
            let end = e.nul_position();
            CString::new(&e.into_vec()[..end]).expect("no NUL before the first")
        });
        let to_i64 = |x: Option<usize>| x.map_or(-1, |v| i64::try_from(v).unwrap_or(i64::MAX));
        lpe_error {
            status,
            message,
            aov: to_i64(aov),
            position: to_i64(position),
        }
    }

    /// Hands the error to the caller through `out` (if not NULL) and returns its status.
    pub(crate) fn report(self, out: *mut *mut lpe_error) -> lpe_status {
        let status = self.status;
        if !out.is_null() {
            // SAFETY: checked non-null; the caller passes a writable `lpe_error *`.
            unsafe { *out = Box::into_raw(Box::new(self)) };
        }
        status
    }
}

/// The status this error stands for (`LPE_ERR_NULL` if `error` is NULL).
#[no_mangle]
pub extern "C" fn lpe_error_status(error: *const lpe_error) -> lpe_status {
    // SAFETY: NULL or an error this library returned.
    unsafe { error.as_ref() }.map_or(lpe_status::LPE_ERR_NULL, |e| e.status)
}

/// The message, NUL-terminated UTF-8, valid until `lpe_error_free` (NULL if `error` is
/// NULL). For a parse error it reads like `lpe-check parse` reports it, without the
/// caret lines.
#[no_mangle]
pub extern "C" fn lpe_error_message(error: *const lpe_error) -> *const c_char {
    // SAFETY: NULL or an error this library returned.
    unsafe { error.as_ref() }.map_or(std::ptr::null(), |e| e.message.as_ptr())
}

/// Index of the AOV whose expression failed, or -1 when the error is about the whole
/// set (or `error` is NULL).
#[no_mangle]
pub extern "C" fn lpe_error_aov(error: *const lpe_error) -> i64 {
    // SAFETY: NULL or an error this library returned.
    unsafe { error.as_ref() }.map_or(-1, |e| e.aov)
}

/// Byte offset of the error in that AOV's expression (or the one-based line of the
/// rendermn.ini text for `LPE_ERR_INI`), or -1 when there is none.
#[no_mangle]
pub extern "C" fn lpe_error_position(error: *const lpe_error) -> i64 {
    // SAFETY: NULL or an error this library returned.
    unsafe { error.as_ref() }.map_or(-1, |e| e.position)
}

/// Releases an error. NULL is ignored.
#[no_mangle]
pub extern "C" fn lpe_error_free(error: *mut lpe_error) {
    if !error.is_null() {
        guard((), || {
            // SAFETY: an error this library returned, freed once.
            drop(unsafe { Box::from_raw(error) });
        });
    }
}
