//! C string arguments read as Rust text: NULL and invalid UTF-8 become the status a
//! caller returns.

use std::ffi::{c_char, CStr};

use crate::status::lpe_status;

/// A C string argument, or the status saying why not.
pub(crate) fn text<'a>(p: *const c_char) -> Result<&'a str, lpe_status> {
    if p.is_null() {
        return Err(lpe_status::LPE_ERR_NULL);
    }
    // SAFETY: checked non-null; the caller passes a NUL-terminated string.
    unsafe { CStr::from_ptr(p) }
        .to_str()
        .map_err(|_| lpe_status::LPE_ERR_UTF8)
}
