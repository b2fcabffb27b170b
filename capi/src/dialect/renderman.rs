//! RenderMan's dialect in the C ABI: sets compiled under a `rendermn.ini` text, and
//! vertices from their fields (`lpe_classify`) or their path text
//! (`lpe_classify_text`).

use std::ffi::c_char;

use lpe::renderman::{
    Config, Error, Event, EventKind, Parser, Path, RenderMan, Vertex, VertexType,
};
use lpe::AovSet;

use super::{CDialect, DialectSet};
use crate::args::text;
use crate::error::lpe_error;
use crate::status::lpe_status;

/// Expressions in RenderMan's LPE dialect (docs/language.md).
pub const LPE_DIALECT_RENDERMAN: u32 = 0;

impl CDialect for RenderMan {
    const ID: u32 = LPE_DIALECT_RENDERMAN;

    fn registration(
        ini_text: *const c_char,
        registered: *const c_char,
    ) -> Result<Parser, lpe_error> {
        if !registered.is_null() {
            return Err(lpe_error::plain(
                lpe_status::LPE_ERR_UNSUPPORTED,
                "`osl_registered` applies to LPE_DIALECT_OSL only",
                None,
            ));
        }
        if ini_text.is_null() {
            return Ok(Config::default().parser());
        }
        let ini = text(ini_text)
            .map_err(|s| lpe_error::plain(s, "the rendermn.ini text is not UTF-8", None))?;
        let config = Config::from_ini(ini).map_err(|e| {
            lpe_error::new(
                lpe_status::LPE_ERR_INI,
                format!("rendermn.ini: {e}"),
                None,
                Some(e.line),
            )
        })?;
        Ok(config.parser())
    }

    fn parse_error(e: &Error) -> (String, usize) {
        (e.one_line(), e.span().start)
    }

    fn wrap(set: AovSet<RenderMan>) -> DialectSet {
        DialectSet::RenderMan(set)
    }

    fn set_of(set: &DialectSet) -> Option<&AovSet<RenderMan>> {
        match set {
            DialectSet::RenderMan(s) => Some(s),
            _ => None,
        }
    }
}

/// The vertex of `lpe_vertex`'s fields (the label read already).
pub(crate) fn vertex_of(
    vertex_type: u8,
    event: u8,
    lobe: u8,
    label: Option<&str>,
) -> Result<Vertex, lpe_status> {
    let ty = VertexType::from_letter(char::from(vertex_type)).ok_or(lpe_status::LPE_ERR_RANGE)?;
    let no_event = event == 0 && lobe == 0;
    match ty {
        VertexType::C if no_event && label.is_none() => Ok(Vertex::camera()),
        VertexType::L if no_event => Ok(Vertex::light(label)),
        VertexType::O if no_event => Ok(Vertex::emissive(label)),
        VertexType::R | VertexType::T => {
            let kind =
                EventKind::from_letter(char::from(event)).ok_or(lpe_status::LPE_ERR_RANGE)?;
            let event = Event::new(kind, lobe).ok_or(lpe_status::LPE_ERR_RANGE)?;
            Ok(Vertex::scatter(ty, event, label))
        }
        _ => Err(lpe_status::LPE_ERR_RANGE),
    }
}

/// One vertex in path text: parsed inside the shortest path that can hold it (a camera
/// before an emitter, an emitter after a camera, both around a scattering vertex).
pub(crate) fn vertex_from_text(src: &str) -> Option<Vertex> {
    let first = src.trim_start().chars().next()?.to_ascii_uppercase();
    let (text, at) = match first {
        'C' => (format!("{src} L"), 0),
        'L' | 'O' => (format!("C {src}"), 1),
        _ => (format!("C {src} L"), 1),
    };
    let path: Path = text.parse().ok()?;
    let expected = if at == 1 && !matches!(first, 'L' | 'O') {
        3
    } else {
        2
    };
    (path.len() == expected).then(|| path.vertices()[at].clone())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_vertex_of_text_and_nothing_else() {
        let v = vertex_from_text("RD2'a b'").unwrap();
        assert_eq!(v.to_string(), "RD2'a b'");
        assert_eq!(vertex_from_text("C").unwrap(), Vertex::camera());
        assert_eq!(
            vertex_from_text("l'key'").unwrap(),
            Vertex::light(Some("key"))
        );
        assert_eq!(vertex_from_text("O").unwrap(), Vertex::emissive(None));
        for bad in ["", "RD RS", "C L", "RX", "L O", "RD9", "C'x'"] {
            assert!(vertex_from_text(bad).is_none(), "{bad}");
        }
    }
}
