//! What a file declares: AOVs, partitions, the dialect of its expressions, the groups its
//! scene carries, lobe mappings.

use std::collections::BTreeSet;
use std::fmt;
use std::path::PathBuf;

use lpe::DialectName;

/// Which reader a file went through.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// A USD stage (`.usda`, `.usdc`, `.usd`, `.usdz`).
    Usd,
    /// A RIB stream (`.rib`).
    Rib,
    /// A `rendermn.ini`-style file (`.ini`).
    Ini,
}

impl Format {
    /// Lower-case name, as in the JSON output.
    pub fn name(self) -> &'static str {
        match self {
            Format::Usd => "usd",
            Format::Rib => "rib",
            Format::Ini => "ini",
        }
    }

    /// The dialect a file of this format is written in whatever it says: RIB and
    /// `rendermn.ini` are RenderMan's own formats; a USD stage is read by every render
    /// delegate, so only an `lpe:dialect` attribute can say.
    pub fn dialect(self) -> Option<DialectName> {
        match self {
            Format::Usd => None,
            Format::Rib | Format::Ini => Some(DialectName::RenderMan),
        }
    }
}

/// Where a declaration sits in its file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Location {
    /// A text line (1-based) and the byte column (1-based) where the expression starts.
    Line {
        /// 1-based line.
        line: usize,
        /// 1-based byte column of the first byte of the expression.
        column: usize,
    },
    /// A USD prim and the property holding the value: USD text gives no stable line once
    /// layers compose, so the prim path is the address users search for.
    Prim {
        /// The prim path, e.g. `/Render/Vars/diffuse`.
        prim: String,
        /// The attribute, e.g. `sourceName`.
        attribute: String,
    },
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Location::Line { line, column } => write!(f, "{line}:{column}"),
            Location::Prim { prim, attribute } => write!(f, "<{prim}>.{attribute}"),
        }
    }
}

/// One LPE AOV as declared.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AovDecl {
    /// The AOV (USD: the RenderVar prim name; RIB: the channel name).
    pub name: String,
    /// The expression as written (`sourceName`, or the RIB source after its type),
    /// `lpe:` prefix included when present.
    pub source: String,
    /// Where it is.
    pub location: Location,
    /// USD `sourceType` as authored (`lpe`); `None` outside USD.
    pub source_type: Option<String>,
}

/// A declared partition: AOVs meant to sum to beauty.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PartitionDecl {
    /// Its name (`beauty` for a bare `lpe:partition`).
    pub name: String,
    /// Member AOV names, in declaration order.
    pub members: Vec<String>,
    /// Where it is declared.
    pub location: Location,
}

/// Which dialect a file says its expressions are written in.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DialectDecl {
    /// The dialect.
    pub dialect: DialectName,
    /// Where it is declared (USD: the `lpe:dialect` attribute); `None` when the file's
    /// format says it ([`Format::dialect`]).
    pub location: Option<Location>,
}

/// Everything one file declares.
#[derive(Clone, Debug)]
pub struct Document {
    /// The file as given.
    pub file: PathBuf,
    /// The reader it went through.
    pub format: Format,
    /// LPE AOVs in file (traversal) order.
    pub aovs: Vec<AovDecl>,
    /// Declared partitions.
    pub partitions: Vec<PartitionDecl>,
    /// The dialect of the file's expressions, when the file says (`None`: a USD stage
    /// without `lpe:dialect`, whose expressions every delegate reads in its own dialect).
    pub dialect: Option<DialectDecl>,
    /// The renderer profile the stage names in an `lpe:renderer` attribute, with where.
    pub renderer: Option<(String, Location)>,
    /// The namespaces of the attributes authored on the stage's `RenderSettings` prims
    /// (`karma` for `karma:global:...`), with the first prim holding each: a stage set up
    /// for one renderer holds that renderer's settings.
    pub settings_namespaces: std::collections::BTreeMap<String, String>,
    /// Light-group labels the stage's lights carry; `None` when the file holds no light
    /// at all (a settings-only layer, a RIB display file): then nothing can be checked.
    pub light_groups: Option<BTreeSet<String>>,
    /// Object-group labels the stage's geometry carries; `None` when it holds none.
    pub object_groups: Option<BTreeSet<String>>,
    /// The first RenderProduct's `orderedVars`, as AOV (prim) names, in order.
    pub ordered_vars: Option<Vec<String>>,
    /// Macros and lobe mappings (ini files only).
    pub config: Option<lpe::renderman::Config>,
}

impl Document {
    /// An empty document for `file`.
    pub fn new(file: impl Into<PathBuf>, format: Format) -> Document {
        Document {
            file: file.into(),
            format,
            aovs: Vec::new(),
            partitions: Vec::new(),
            dialect: format.dialect().map(|dialect| DialectDecl {
                dialect,
                location: None,
            }),
            renderer: None,
            settings_namespaces: Default::default(),
            light_groups: None,
            object_groups: None,
            ordered_vars: None,
            config: None,
        }
    }
}

/// Splits a partition member list: names separated by commas and/or white space.
pub fn split_members(list: &str) -> Vec<String> {
    list.split(|c: char| c == ',' || c.is_whitespace())
        .filter(|s| !s.is_empty())
        .map(str::to_string)
        .collect()
}
