//! Vertices to classes: once per material lobe, light and camera at scene load. One
//! entry point per shape of C vertex, each a dialect's (`lpe_classify` and
//! `lpe_classify_text` for RenderMan, `lpe_classify_symbols` for OSL; the reading of the
//! C types is in that dialect's file of `dialect`), all through one generic
//! `classify_into`.

use std::ffi::c_char;

use lpe::osl::Osl;
use lpe::renderman::{RenderMan, Vertex};
use lpe::Class;

use crate::args::text;
use crate::dialect::{osl, renderman, CDialect};
use crate::set::lpe_set;
use crate::status::{guard, lpe_status};

/// A vertex after classification. Plain data, only meaningful for the set that made it;
/// `id` is below `lpe_set_class_count` (classes are lpe's 32-bit class numbers).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct lpe_class {
    /// The class number.
    pub id: u32,
}

// The C side carries lpe's class number; converting back is a plain copy of it.
const _: () = assert!(std::mem::size_of::<Class>() == std::mem::size_of::<u32>());
const _: () = assert!(std::mem::align_of::<Class>() <= std::mem::align_of::<u32>());

impl lpe_class {
    pub(crate) fn from_class(c: Class) -> lpe_class {
        lpe_class {
            // Class numbers are u32 inside lpe (asserted above).
            id: c.index() as u32,
        }
    }

    /// lpe's class, if `id` is one of `set`'s.
    #[inline(always)]
    pub(crate) fn to_class(self, set: &lpe_set) -> Option<Class> {
        if (self.id as usize) < set.class_count {
            // SAFETY: `Class` is a u32 class number (size asserted above), and any
            // number below the set's class count is one of its classes.
            Some(unsafe { std::mem::transmute::<u32, Class>(self.id) })
        } else {
            None
        }
    }
}

/// One vertex of a path, by fields (docs/language.md §2.1).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct lpe_vertex {
    /// `'C'` camera, `'R'` reflection, `'T'` transmission, `'L'` light, `'O'` emissive
    /// object (lower case accepted).
    pub vertex_type: u8,
    /// On `R`/`T` only: `'D'` diffuse, `'S'` specular, `'U'` user lobe; 0 on `C`/`L`/`O`.
    pub event: u8,
    /// On `R`/`T` only: the lobe number, D 1-4, S 1-8, U 1-12; 0 on `C`/`L`/`O`.
    pub lobe: u8,
    /// The label (`lpegroup`, or the light's group), NUL-terminated UTF-8, or NULL for
    /// none. Never on `C`.
    pub label: *const c_char,
}

/// The vertex of `v`'s fields.
fn vertex_of(v: &lpe_vertex) -> Result<Vertex, lpe_status> {
    let label = if v.label.is_null() {
        None
    } else {
        Some(text(v.label)?)
    };
    renderman::vertex_of(v.vertex_type, v.event, v.lobe, label)
}

/// Classifies the vertex `vertex` gives in `set`, which must be of dialect `D`, into
/// `*out`.
pub(crate) fn classify_into<D: CDialect>(
    set: &lpe_set,
    out: &mut lpe_class,
    vertex: impl FnOnce() -> Result<D::Vertex, lpe_status>,
) -> lpe_status {
    let Some(set) = D::set_of(&set.set) else {
        return lpe_status::LPE_ERR_UNSUPPORTED;
    };
    guard(lpe_status::LPE_ERR_PANIC, || match vertex() {
        Ok(v) => {
            *out = lpe_class::from_class(set.classify(&v));
            lpe_status::LPE_OK
        }
        Err(s) => s,
    })
}

/// The class of a vertex, into `*out`. Classify every kind of scene vertex once, at
/// load, and step with classes. `LPE_ERR_RANGE`: an unknown letter, a lobe out of
/// range, an event on `C`/`L`/`O`, a label on `C`; `LPE_ERR_UTF8`: a label that is not
/// UTF-8; `LPE_ERR_UNSUPPORTED`: an OSL set (use `lpe_classify_symbols`).
#[no_mangle]
pub extern "C" fn lpe_classify(
    set: *const lpe_set,
    vertex: *const lpe_vertex,
    out: *mut lpe_class,
) -> lpe_status {
    // SAFETY: NULL or valid pointers from the caller.
    let (Some(set), Some(vertex), Some(out)) = (
        unsafe { set.as_ref() },
        unsafe { vertex.as_ref() },
        unsafe { out.as_mut() },
    ) else {
        return lpe_status::LPE_ERR_NULL;
    };
    classify_into::<RenderMan>(set, out, || vertex_of(vertex))
}

/// The class of one vertex written in path text form (docs/language.md §2.3), such as
/// `RD2'floor'`, `L'key'` or `C`, into `*out`. `LPE_ERR_PARSE` if it is not exactly one
/// vertex; `LPE_ERR_UNSUPPORTED` on an OSL set (use `lpe_classify_symbols`).
#[no_mangle]
pub extern "C" fn lpe_classify_text(
    set: *const lpe_set,
    vertex: *const c_char,
    out: *mut lpe_class,
) -> lpe_status {
    // SAFETY: NULL or valid pointers from the caller.
    let (Some(set), Some(out)) = (unsafe { set.as_ref() }, unsafe { out.as_mut() }) else {
        return lpe_status::LPE_ERR_NULL;
    };
    if RenderMan::set_of(&set.set).is_none() {
        return lpe_status::LPE_ERR_UNSUPPORTED;
    }
    let src = match text(vertex) {
        Ok(s) => s,
        Err(e) => return e,
    };
    classify_into::<RenderMan>(set, out, || {
        renderman::vertex_from_text(src).ok_or(lpe_status::LPE_ERR_PARSE)
    })
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
    classify_into::<Osl>(set, out, || osl::vertex_of(symbols))
}
