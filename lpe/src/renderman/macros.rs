//! Named expressions: RenderMan's built-in LPE macros and user macros from a
//! `rendermn.ini`-style file (docs/language.md §6.1).
//!
//! Names are case-insensitive. A user macro with a built-in's name replaces it (the last
//! definition wins), as a later `rendermn.ini` line would.

use std::sync::Arc;

/// The seven basic AOVs. Every light-transport path `C.*[<L.>O]` matches exactly one.
pub const BASIC: [(&str, &str); 7] = [
    ("directDiffuse", "C<RD>[<L.>O]"),
    ("indirectDiffuse", "C<RD>.+[<L.>O]"),
    ("subsurface", "C<TD>.*[<L.>O]"),
    ("directSpecular", "C<RS>[<L.>O]"),
    ("indirectSpecular", "C<RS>.+[<L.>O]"),
    ("transmissive", "C<TS>.*[<L.>O]"),
    ("emissive", "C[<L.>O]"),
];

/// RenderMan's per-lobe AOVs (without `emissive`, which [`BASIC`] has).
pub const PER_LOBE: [(&str, &str); 16] = [
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
];

/// The remaining built-ins: per-lobe glass transmission, legacy names, caustics and the
/// shadow collector.
pub const OTHER: [(&str, &str); 6] = [
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

/// A table of macros: the built-ins plus user definitions. Shared on clone, copied on
/// the first definition after it: a parser (and every set compiled under it) carries
/// its table, and `match --batch` clones the parser per distinct expression, where
/// copying 29 built-ins (58 strings) cost a quarter of a line's compile.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MacroTable {
    entries: Arc<Vec<(String, String)>>,
}

impl Default for MacroTable {
    fn default() -> Self {
        MacroTable::builtin()
    }
}

impl MacroTable {
    /// RenderMan's built-in macros (docs/language.md §6.1).
    pub fn builtin() -> MacroTable {
        MacroTable {
            entries: Arc::new(
                BASIC
                    .iter()
                    .chain(&PER_LOBE)
                    .chain(&OTHER)
                    .map(|(n, s)| (n.to_string(), s.to_string()))
                    .collect(),
            ),
        }
    }

    /// A table with no macros at all.
    pub fn empty() -> MacroTable {
        MacroTable {
            entries: Arc::new(Vec::new()),
        }
    }

    /// Defines (or redefines) a macro. The source is parsed when the macro is used.
    pub fn define(&mut self, name: &str, source: &str) {
        let entries = Arc::make_mut(&mut self.entries);
        entries.retain(|(n, _)| !n.eq_ignore_ascii_case(name));
        entries.push((name.to_string(), source.to_string()));
    }

    /// The source of a macro, looked up ignoring case.
    pub fn get(&self, name: &str) -> Option<&str> {
        self.entries
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(name))
            .map(|(_, s)| s.as_str())
    }

    /// Every name, in definition order.
    pub fn names(&self) -> impl Iterator<Item = &str> {
        self.entries.iter().map(|(n, _)| n.as_str())
    }

    /// Every `(name, source)`, in definition order.
    pub fn iter(&self) -> impl Iterator<Item = (&str, &str)> {
        self.entries.iter().map(|(n, s)| (n.as_str(), s.as_str()))
    }
}
