//! Compiling a set, and what a compiled set tells: names, warnings, sizes.

use std::ffi::{c_char, CStr, CString};

use lpe::{AovSet, Config, Lpe, Options};

use crate::error::lpe_error;
use crate::status::{guard, lpe_status};

/// Expressions in RenderMan's LPE dialect (docs/language.md).
pub const LPE_DIALECT_RENDERMAN: u32 = 0;
/// Expressions in OSL's LPE dialect. Not in this build yet: compiling answers
/// `LPE_ERR_UNSUPPORTED`.
pub const LPE_DIALECT_OSL: u32 = 1;

/// Compile-time knobs; start from `lpe_options_default()`.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct lpe_options {
    /// Most bytes the DFA may take; over it the set steps the bitset NFA. 0 forces the NFA.
    pub dfa_budget: usize,
    /// Most bytes the NFA may take; over it compiling fails with `LPE_ERR_COMPILE`.
    pub nfa_budget: usize,
    /// The longest path (in vertices) the caller will ever step, or 0 for no bound.
    /// With a bound, `e{n,m}` with `m >= max_path_len` compiles as `e{n,}`.
    pub max_path_len: u32,
}

/// A compiled AOV set: immutable, safe to share between threads. Release it with
/// `lpe_set_free`.
pub struct lpe_set {
    pub(crate) set: AovSet,
    pub(crate) class_count: usize,
    names: Vec<CString>,
    warnings: Vec<CString>,
}

/// The defaults: 16 MiB DFA and NFA budgets, no path length bound.
#[no_mangle]
pub extern "C" fn lpe_options_default() -> lpe_options {
    let o = Options::default();
    lpe_options {
        dfa_budget: o.dfa_budget,
        nfa_budget: o.nfa_budget,
        max_path_len: o.max_path_len.unwrap_or(0),
    }
}

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

/// Compiles `count` AOVs into one set.
///
/// - `names[i]`, `exprs[i]`: NUL-terminated UTF-8, the AOV's name and expression (bit `i`
///   of every match mask is AOV `i`). Both arrays may be NULL only when `count` is 0.
/// - `dialect`: `LPE_DIALECT_RENDERMAN` (`LPE_DIALECT_OSL` answers
///   `LPE_ERR_UNSUPPORTED` in this build).
/// - `ini_text`: the contents of a rendermn.ini (user macros), or NULL.
/// - `options`: NULL for the defaults.
/// - `out`: receives the set, or NULL on failure.
/// - `error`: if not NULL, receives an error object on failure (free it with
///   `lpe_error_free`); NULL on success.
///
/// Returns `LPE_OK`, or `LPE_ERR_NULL`, `LPE_ERR_UTF8`, `LPE_ERR_PARSE`, `LPE_ERR_INI`,
/// `LPE_ERR_COMPILE`, `LPE_ERR_RANGE` (unknown dialect), `LPE_ERR_UNSUPPORTED`.
#[no_mangle]
pub extern "C" fn lpe_set_compile(
    names: *const *const c_char,
    exprs: *const *const c_char,
    count: usize,
    dialect: u32,
    ini_text: *const c_char,
    options: *const lpe_options,
    out: *mut *mut lpe_set,
    error: *mut *mut lpe_error,
) -> lpe_status {
    if !error.is_null() {
        // SAFETY: checked non-null; the caller passes a writable `lpe_error *`.
        unsafe { *error = std::ptr::null_mut() };
    }
    if out.is_null() {
        let e = lpe_error::new(lpe_status::LPE_ERR_NULL, "`out` is NULL".into(), None, None);
        return e.report(error);
    }
    // SAFETY: checked non-null; the caller passes a writable `lpe_set *`.
    unsafe { *out = std::ptr::null_mut() };
    let result = guard(
        Err(lpe_error::new(
            lpe_status::LPE_ERR_PANIC,
            "internal failure while compiling (please report it with the input)".into(),
            None,
            None,
        )),
        || compile(names, exprs, count, dialect, ini_text, options),
    );
    match result {
        Ok(set) => {
            // SAFETY: checked non-null above.
            unsafe { *out = Box::into_raw(Box::new(set)) };
            lpe_status::LPE_OK
        }
        Err(e) => e.report(error),
    }
}

fn compile(
    names: *const *const c_char,
    exprs: *const *const c_char,
    count: usize,
    dialect: u32,
    ini_text: *const c_char,
    options: *const lpe_options,
) -> Result<lpe_set, lpe_error> {
    let err = |status, message: &str, aov| lpe_error::new(status, message.into(), aov, None);
    let fail = |status, message: &str, aov| Err(err(status, message, aov));
    match dialect {
        LPE_DIALECT_RENDERMAN => {}
        LPE_DIALECT_OSL => {
            return fail(
                lpe_status::LPE_ERR_UNSUPPORTED,
                "the OSL dialect is not in this build",
                None,
            )
        }
        _ => return fail(lpe_status::LPE_ERR_RANGE, "unknown dialect", None),
    }
    if count > 0 && (names.is_null() || exprs.is_null()) {
        return fail(lpe_status::LPE_ERR_NULL, "`names` or `exprs` is NULL", None);
    }
    let config = if ini_text.is_null() {
        Config::default()
    } else {
        let ini = text(ini_text).map_err(|s| err(s, "the rendermn.ini text is not UTF-8", None))?;
        Config::from_ini(ini).map_err(|e| {
            lpe_error::new(
                lpe_status::LPE_ERR_INI,
                format!("rendermn.ini: {e}"),
                None,
                Some(e.line),
            )
        })?
    };
    let parser = config.parser();
    let mut aovs: Vec<(String, Lpe)> = Vec::with_capacity(count.min(1024));
    let mut c_names = Vec::with_capacity(count.min(1024));
    for i in 0..count {
        // SAFETY: the caller passes arrays of `count` pointers (checked non-null above).
        let (name_p, expr_p) = unsafe { (*names.add(i), *exprs.add(i)) };
        let name = text(name_p).map_err(|s| err(s, "an AOV name is NULL or not UTF-8", Some(i)))?;
        let src =
            text(expr_p).map_err(|s| err(s, "an expression is NULL or not UTF-8", Some(i)))?;
        let lpe = parser.parse(src).map_err(|e| {
            lpe_error::new(
                lpe_status::LPE_ERR_PARSE,
                format!("AOV `{name}`: {}", e.one_line()),
                Some(i),
                Some(e.span().start),
            )
        })?;
        // SAFETY: `name_p` is a valid C string (read above).
        c_names.push(unsafe { CStr::from_ptr(name_p) }.to_owned());
        aovs.push((name.to_string(), lpe));
    }
    // SAFETY: NULL or a readable `lpe_options`.
    let opts = match unsafe { options.as_ref() } {
        None => Options::default(),
        Some(o) => Options {
            dfa_budget: o.dfa_budget,
            nfa_budget: o.nfa_budget,
            max_path_len: (o.max_path_len > 0).then_some(o.max_path_len),
            ..Options::default()
        },
    };
    let set = AovSet::compile_with(&aovs, &opts)
        .map_err(|e| lpe_error::new(lpe_status::LPE_ERR_COMPILE, e.to_string(), None, None))?;
    let warnings = set
        .warnings()
        .iter()
        .map(|w| CString::new(w.to_string()).unwrap_or_default())
        .collect();
    Ok(lpe_set {
        class_count: set.class_count(),
        names: c_names,
        warnings,
        set,
    })
}

/// Releases a set. NULL is ignored. No state or class of it may be used after.
#[no_mangle]
pub extern "C" fn lpe_set_free(set: *mut lpe_set) {
    if !set.is_null() {
        guard((), || {
            // SAFETY: a set this library returned, freed once.
            drop(unsafe { Box::from_raw(set) });
        });
    }
}

/// What `f` reads from the set, or `none` when `set` is NULL (or `f` finds nothing).
fn read<T>(set: *const lpe_set, none: T, f: impl FnOnce(&lpe_set) -> Option<T>) -> T {
    // SAFETY: NULL or a set this library returned.
    unsafe { set.as_ref() }.and_then(f).unwrap_or(none)
}

/// Number of AOVs (0 if `set` is NULL).
#[no_mangle]
pub extern "C" fn lpe_set_len(set: *const lpe_set) -> usize {
    read(set, 0, |s| Some(s.names.len()))
}

/// Name of AOV `i`, NUL-terminated, valid until `lpe_set_free`; NULL if `set` is NULL
/// or `i` is out of range.
#[no_mangle]
pub extern "C" fn lpe_set_name(set: *const lpe_set, i: usize) -> *const c_char {
    read(set, std::ptr::null(), |s| {
        s.names.get(i).map(|n| n.as_ptr())
    })
}

/// 64-bit words a match mask of this set needs: `(len + 63) / 64`, at least 1 (0 if
/// `set` is NULL).
#[no_mangle]
pub extern "C" fn lpe_set_mask_words(set: *const lpe_set) -> usize {
    read(set, 0, |s| Some(s.names.len().div_ceil(64).max(1)))
}

/// Number of vertex classes: every `lpe_class` of this set has an index below it (0 if
/// `set` is NULL).
#[no_mangle]
pub extern "C" fn lpe_set_class_count(set: *const lpe_set) -> usize {
    read(set, 0, |s| Some(s.class_count))
}

/// Number of compile warnings: AOVs that can match no path (0 if `set` is NULL).
#[no_mangle]
pub extern "C" fn lpe_set_warning_count(set: *const lpe_set) -> usize {
    read(set, 0, |s| Some(s.warnings.len()))
}

/// Warning `i` as text (naming the AOV and why it can match nothing), valid until
/// `lpe_set_free`; NULL if out of range.
#[no_mangle]
pub extern "C" fn lpe_set_warning(set: *const lpe_set, i: usize) -> *const c_char {
    read(set, std::ptr::null(), |s| {
        s.warnings.get(i).map(|w| w.as_ptr())
    })
}

/// Index of the AOV warning `i` is about, or -1 if out of range.
#[no_mangle]
pub extern "C" fn lpe_set_warning_aov(set: *const lpe_set, i: usize) -> i64 {
    read(set, -1, |s| s.set.warnings().get(i).map(|w| w.aov as i64))
}
