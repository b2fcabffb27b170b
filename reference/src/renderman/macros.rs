//! Macros as plain data (docs/language.md §6, §8): the built-in table of §6.1 written
//! out from the document, and [`Registration`], what a `rendermn.ini` adds (name to
//! source text) with the limits, so this front end takes no type of lpe's parser.

use std::collections::BTreeMap;

use crate::error::Limits;

/// The built-in macros of docs/language.md §6.1, name and source.
pub const BUILTIN: [(&str, &str); 29] = [
    ("directDiffuse", "C<RD>[<L.>O]"),
    ("indirectDiffuse", "C<RD>.+[<L.>O]"),
    ("subsurface", "C<TD>.*[<L.>O]"),
    ("directSpecular", "C<RS>[<L.>O]"),
    ("indirectSpecular", "C<RS>.+[<L.>O]"),
    ("transmissive", "C<TS>.*[<L.>O]"),
    ("emissive", "C[<L.>O]"),
    ("directDiffuseLobe", "CD2[<L.>O]"),
    ("indirectDiffuseLobe", "CD2.+[<L.>O]"),
    ("subsurfaceLobe", "CD3.*[<L.>O]"),
    ("directSpecularPrimaryLobe", "CS2[<L.>O]"),
    ("indirectSpecularPrimaryLobe", "CS2.+[<L.>O]"),
    ("directSpecularRoughLobe", "CS3[<L.>O]"),
    ("indirectSpecularRoughLobe", "CS3.+[<L.>O]"),
    ("directSpecularClearcoatLobe", "CS4[<L.>O]"),
    ("indirectSpecularClearcoatLobe", "CS4.+[<L.>O]"),
    ("directSpecularIridescenceLobe", "CS5[<L.>O]"),
    ("indirectSpecularIridescenceLobe", "CS5.+[<L.>O]"),
    ("directSpecularFuzzLobe", "CS6[<L.>O]"),
    ("indirectSpecularFuzzLobe", "CS6.+[<L.>O]"),
    ("transmissiveSingleScatterLobe", "CS7.*[<L.>O]"),
    ("directSpecularGlassLobe", "C<RS8>[<L.>O]"),
    ("indirectSpecularGlassLobe", "C<RS8>.+[<L.>O]"),
    ("transmissiveGlassLobe", "C<TS8>.*[<L.>O]"),
    ("diffuse", "CD<L.>"),
    ("specular", "CS<L.>"),
    ("emission", "CO"),
    ("caustics", "CDS+[<L.>O]"),
    (
        "shadowcollector",
        "shadows;C[<.D'collector'><.S'collector'>]<L.>",
    ),
];

/// What a RenderMan parse is registered with: user macros (`/prman/lpe/macro/NAME EXPR`
/// of a `rendermn.ini`, name to source text; one with a built-in's name replaces it) and
/// the limits.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Registration {
    /// User macros, name to source.
    pub macros: BTreeMap<String, String>,
    /// The parse limits.
    pub limits: Limits,
}

impl Registration {
    /// The source of the macro called `name` (ignoring case), user macros first.
    pub fn macro_source(&self, name: &str) -> Option<&str> {
        if name.is_empty() {
            return None;
        }
        self.macros
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(name))
            .map(|(_, s)| s.as_str())
            .or_else(|| {
                BUILTIN
                    .iter()
                    .find(|(n, _)| n.eq_ignore_ascii_case(name))
                    .map(|(_, s)| *s)
            })
    }
}
