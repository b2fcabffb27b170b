//! Compiling a set, and what a compiled set tells: names, warnings, sizes.

use std::ffi::{c_char, CStr, CString};

use lpe::{with_dialect, AovSet, Options};

use crate::args::text;
use crate::dialect::{self, CDialect, DialectSet};
use crate::error::lpe_error;
use crate::status::{guard, lpe_status};

// Each dialect's `LPE_DIALECT_*` number is defined beside its `CDialect` impl.
pub use crate::dialect::osl::LPE_DIALECT_OSL;
pub use crate::dialect::renderman::LPE_DIALECT_RENDERMAN;

/// Compile-time knobs; start from `lpe_options_default()`.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct lpe_options {
    /// Most bytes the DFA may take; over it the set is a lazy DFA (determinized while
    /// stepping, into caches). 0 forces the lazy DFA.
    pub dfa_budget: usize,
    /// Bytes of transitions one lazy-DFA cache may hold (a set over `dfa_budget` only),
    /// cleared whole when full: per `lpe_cache`, and per thread for the thread-local
    /// cache `lpe_step` uses. 0 turns caching off (every step runs the bitset NFA).
    pub lazy_cache: usize,
    /// Most bytes the NFA may take; over it compiling fails with `LPE_ERR_COMPILE`.
    pub nfa_budget: usize,
    /// The longest path (in vertices) the caller will ever step, or 0 for no bound.
    /// With a bound, `e{n,m}` with `m >= max_path_len` compiles as `e{n,}`.
    pub max_path_len: u32,
    /// `LPE_DIALECT_OSL` only: the labels the renderer registers before parsing (OSL's
    /// `AccumAutomata::addEventType` / `addScatteringType`), as NUL-terminated text
    /// `events=U,V;scatters=Y` (either part optional, in any order; `-` or NULL for
    /// none). Registration changes how expressions parse and match. Read during
    /// `lpe_set_compile` only. Must be NULL for `LPE_DIALECT_RENDERMAN`.
    pub osl_registered: *const c_char,
    /// A renderer profile by name (`karma`, `arnold`, `hdprman`, ...; docs/profiles.md),
    /// as NUL-terminated text, or NULL for none: its letters, prefixes and built-in AOV
    /// names are registered on top of `osl_registered`, so expressions read as that
    /// renderer reads them. A profile of the other dialect, or an unknown name, is
    /// `LPE_ERR_UNSUPPORTED`. Read during `lpe_set_compile` only.
    pub renderer: *const c_char,
}

/// A compiled AOV set: immutable, safe to share between threads. Release it with
/// `lpe_set_free`.
pub struct lpe_set {
    pub(crate) set: DialectSet,
    pub(crate) class_count: usize,
    names: Vec<CString>,
    warnings: Vec<CString>,
}

/// The defaults: 16 MiB DFA and NFA budgets, a 2 MiB lazy-DFA cache, no path length
/// bound, nothing registered.
#[no_mangle]
pub extern "C" fn lpe_options_default() -> lpe_options {
    let o = Options::default();
    lpe_options {
        dfa_budget: o.dfa_budget,
        lazy_cache: o.lazy_cache,
        nfa_budget: o.nfa_budget,
        max_path_len: o.max_path_len.unwrap_or(0),
        osl_registered: std::ptr::null(),
        renderer: std::ptr::null(),
    }
}

/// Compiles `count` AOVs into one set.
///
/// - `names[i]`, `exprs[i]`: NUL-terminated UTF-8, the AOV's name and expression (bit `i`
///   of every match mask is AOV `i`). Both arrays may be NULL only when `count` is 0.
/// - `dialect`: `LPE_DIALECT_RENDERMAN` or `LPE_DIALECT_OSL`.
/// - `ini_text`: RenderMan only: the contents of a rendermn.ini (user macros, lobe
///   mappings), or NULL. Must be NULL for OSL.
/// - `options`: NULL for the defaults. For OSL, `options->osl_registered` names the
///   registered labels; `options->renderer` names a renderer profile to read under.
/// - `out`: receives the set, or NULL on failure.
/// - `error`: if not NULL, receives an error object on failure (free it with
///   `lpe_error_free`); NULL on success.
///
/// Returns `LPE_OK`, or `LPE_ERR_NULL`, `LPE_ERR_UTF8`, `LPE_ERR_PARSE` (an expression,
/// or the `osl_registered` text: then `lpe_error_aov` is -1 and `lpe_error_position` the
/// byte in that text), `LPE_ERR_INI`, `LPE_ERR_COMPILE`, `LPE_ERR_RANGE` (unknown
/// dialect), `LPE_ERR_UNSUPPORTED` (a rendermn.ini with OSL, a registration with
/// RenderMan).
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
    let Some(dialect) = dialect::by_id(dialect) else {
        return Err(lpe_error::plain(
            lpe_status::LPE_ERR_RANGE,
            "unknown dialect",
            None,
        ));
    };
    if count > 0 && (names.is_null() || exprs.is_null()) {
        return Err(lpe_error::plain(
            lpe_status::LPE_ERR_NULL,
            "`names` or `exprs` is NULL",
            None,
        ));
    }
    // SAFETY: NULL or a readable `lpe_options`.
    let given = unsafe { options.as_ref() }.copied();
    let opts = given.map_or_else(Options::default, |o| Options {
        dfa_budget: o.dfa_budget,
        lazy_cache: o.lazy_cache,
        nfa_budget: o.nfa_budget,
        max_path_len: (o.max_path_len > 0).then_some(o.max_path_len),
        // A C caller steps a set for a whole render: never only a few paths.
        ..Options::default()
    });
    let registered = given.map_or(std::ptr::null(), |o| o.osl_registered);
    let profile = renderer_profile(given.map_or(std::ptr::null(), |o| o.renderer), dialect)?;
    let sources = read_sources(names, exprs, count)?;
    let set = with_dialect!(dialect, D => compile_in::<D>(&sources, ini_text, registered, profile, &opts)?);
    let warnings = set
        .warnings()
        .iter()
        .map(|w| CString::new(w.to_string()).unwrap_or_default())
        .collect();
    Ok(lpe_set {
        class_count: set.class_count(),
        names: sources.into_iter().map(|s| s.c_name).collect(),
        warnings,
        set,
    })
}

/// One AOV as the caller passed it.
struct Source<'a> {
    c_name: CString,
    name: &'a str,
    expr: &'a str,
}

/// The `count` names and expressions, checked for NULL and UTF-8.
fn read_sources<'a>(
    names: *const *const c_char,
    exprs: *const *const c_char,
    count: usize,
) -> Result<Vec<Source<'a>>, lpe_error> {
    let mut out = Vec::with_capacity(count.min(1024));
    for i in 0..count {
        // SAFETY: the caller passes arrays of `count` pointers (checked non-null).
        let (name_p, expr_p) = unsafe { (*names.add(i), *exprs.add(i)) };
        let name = text(name_p)
            .map_err(|s| lpe_error::plain(s, "an AOV name is NULL or not UTF-8", Some(i)))?;
        let expr = text(expr_p)
            .map_err(|s| lpe_error::plain(s, "an expression is NULL or not UTF-8", Some(i)))?;
        out.push(Source {
            // SAFETY: `name_p` is a valid C string (read above).
            c_name: unsafe { CStr::from_ptr(name_p) }.to_owned(),
            name,
            expr,
        });
    }
    Ok(out)
}

/// A parse error of AOV `i`, at byte `position` of its expression.
fn parse_error(
    i: usize,
    name: &str,
    message: impl std::fmt::Display,
    position: usize,
) -> lpe_error {
    lpe_error::new(
        lpe_status::LPE_ERR_PARSE,
        format!("AOV `{name}`: {message}"),
        Some(i),
        Some(position),
    )
}

fn compile_error(e: lpe::CompileError) -> lpe_error {
    lpe_error::new(lpe_status::LPE_ERR_COMPILE, e.to_string(), None, None)
}

/// The profile `options->renderer` names (NULL: none), which must read `dialect`.
fn renderer_profile(
    renderer: *const c_char,
    dialect: lpe::DialectName,
) -> Result<Option<&'static lpe_profile::Profile>, lpe_error> {
    if renderer.is_null() {
        return Ok(None);
    }
    let unsupported = |m: String| lpe_error::new(lpe_status::LPE_ERR_UNSUPPORTED, m, None, None);
    let name = text(renderer)
        .map_err(|s| lpe_error::plain(s, "the `renderer` text is not UTF-8", None))?;
    let profile = lpe_profile::by_name(name).map_err(|e| unsupported(e.to_string()))?;
    if profile.dialect() != dialect {
        return Err(unsupported(format!(
            "renderer `{name}` reads {}'s dialect, not {dialect}'s",
            profile.dialect()
        )));
    }
    Ok(Some(profile))
}

/// The set of `sources` in dialect `D`, under the registration of `ini_text` or
/// `registered`, with `profile`'s on top.
fn compile_in<D: CDialect>(
    sources: &[Source],
    ini_text: *const c_char,
    registered: *const c_char,
    profile: Option<&lpe_profile::Profile>,
    opts: &Options,
) -> Result<DialectSet, lpe_error> {
    let mut registration = D::registration(ini_text, registered)?;
    if let Some(p) = profile {
        registration = D::with_profile(p, registration);
    }
    let mut aovs: Vec<(String, D::Lpe)> = Vec::with_capacity(sources.len());
    for (i, s) in sources.iter().enumerate() {
        let lpe = D::parse(s.expr, &registration).map_err(|e| {
            let (message, position) = D::parse_error(&e);
            parse_error(i, s.name, message, position)
        })?;
        aovs.push((s.name.to_string(), lpe));
    }
    AovSet::<D>::compile_under(&aovs, &registration, opts)
        .map(D::wrap)
        .map_err(compile_error)
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
