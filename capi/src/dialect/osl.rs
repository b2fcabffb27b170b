//! OSL's dialect in the C ABI: sets compiled under the labels `osl_registered` names,
//! and vertices from their symbols (`lpe_classify_symbols`).

use std::ffi::c_char;

use lpe::osl::{Error, Osl, Registered, RegisteredError, Symbol, Vertex};
use lpe::AovSet;

use super::{CDialect, DialectSet};
use crate::classify::{classify_into, lpe_class};
use crate::error::lpe_error;
use crate::set::{lpe_set, text, LPE_DIALECT_OSL};
use crate::status::lpe_status;

impl CDialect for Osl {
    const ID: u32 = LPE_DIALECT_OSL;

    fn registration(
        ini_text: *const c_char,
        registered: *const c_char,
    ) -> Result<Registered, lpe_error> {
        if !ini_text.is_null() {
            return Err(lpe_error::plain(
                lpe_status::LPE_ERR_UNSUPPORTED,
                "a rendermn.ini applies to LPE_DIALECT_RENDERMAN only",
                None,
            ));
        }
        if registered.is_null() {
            return Ok(Registered::none());
        }
        let t = text(registered)
            .map_err(|s| lpe_error::plain(s, "the `osl_registered` text is not UTF-8", None))?;
        t.parse().map_err(|e: RegisteredError| {
            lpe_error::new(
                lpe_status::LPE_ERR_PARSE,
                format!("osl_registered: {e}"),
                None,
                Some(e.pos),
            )
        })
    }

    fn parse_error(e: &Error) -> (String, usize) {
        (e.to_string(), e.pos)
    }

    fn wrap(set: AovSet<Osl>) -> DialectSet {
        DialectSet::Osl(set)
    }

    fn set_of(set: &DialectSet) -> Option<&AovSet<Osl>> {
        match set {
            DialectSet::Osl(s) => Some(s),
            _ => None,
        }
    }
}

/// The vertex of C symbols, NULL being OSL's NONE.
pub(crate) fn vertex_of(symbols: &[*const c_char]) -> Result<Vertex, lpe_status> {
    symbols
        .iter()
        .map(|&p| {
            if p.is_null() {
                Ok(Symbol::None)
            } else {
                text(p).map(Symbol::label)
            }
        })
        .collect::<Result<_, _>>()
        .map(Vertex::new)
}

/// The class of an OSL vertex, into `*out`: `count` symbols, in OSL's order: the event
/// (`"C"`, `"R"`, `"T"`, `"L"`, `"O"`, `"B"`, `"V"` or a registered one), the scattering
/// (`"D"`, `"G"`, `"S"`, `"s"` or a registered one), then the custom labels. Each is
/// NUL-terminated UTF-8; a NULL entry is OSL's NONE, so an OSL renderer passes its
/// ustrings' `c_str()` as they are. Classify every kind of scene vertex once, at load,
/// and step with classes; a vertex of fewer than two symbols matches nothing, as in OSL.
/// `LPE_ERR_RANGE`: `count` is 0; `LPE_ERR_UTF8`: a symbol that is not UTF-8;
/// `LPE_ERR_UNSUPPORTED`: a RenderMan set (use `lpe_classify`).
#[no_mangle]
pub extern "C" fn lpe_classify_symbols(
    set: *const lpe_set,
    symbols: *const *const c_char,
    count: usize,
    out: *mut lpe_class,
) -> lpe_status {
    // SAFETY: NULL or valid pointers from the caller.
    let (Some(set), Some(out)) = (unsafe { set.as_ref() }, unsafe { out.as_mut() }) else {
        return lpe_status::LPE_ERR_NULL;
    };
    if symbols.is_null() {
        return lpe_status::LPE_ERR_NULL;
    }
    if count == 0 {
        return lpe_status::LPE_ERR_RANGE;
    }
    if Osl::set_of(&set.set).is_none() {
        return lpe_status::LPE_ERR_UNSUPPORTED;
    }
    // SAFETY: the caller passes `count` readable pointers (checked non-null).
    let symbols = unsafe { std::slice::from_raw_parts(symbols, count) };
    classify_into::<Osl>(set, out, || vertex_of(symbols))
}
