//! OSL's dialect in the C ABI: sets compiled under the labels `osl_registered` names,
//! and vertices from their symbols (`lpe_classify_symbols`).

use std::ffi::c_char;

use lpe::osl::{Error, Osl, Registered, RegisteredError, Symbol, Vertex};
use lpe::AovSet;

use super::{CDialect, DialectSet};
use crate::args::text;
use crate::error::lpe_error;
use crate::status::lpe_status;

/// Expressions in OSL's LPE dialect (docs/language.md §18), parsed under the labels
/// `lpe_options.osl_registered` names; classify vertices with `lpe_classify_symbols`.
pub const LPE_DIALECT_OSL: u32 = 1;

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
