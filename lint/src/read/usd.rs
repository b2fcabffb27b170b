//! USD stages, through the `openusd` crate: `RenderVar`s with `sourceType = "lpe"`,
//! `RenderProduct.orderedVars`, the group attributes of lights and objects, declared
//! partitions and the declared dialect.
//!
//! `sourceType` and `sourceName` are read whether authored `uniform` or not and as
//! `token` or `string` (the schema says `uniform token` / `uniform string`; Solaris,
//! hdPrman and hdArnold users write all four spellings). A RenderVar without
//! `sourceType` is `raw` (the schema fallback) and skipped, as are inactive prims.
//!
//! Group attributes (a label in `<L.'key'>` or `<R.'floor'>` must be carried by one):
//!
//! | attribute | on | delegate |
//! |---|---|---|
//! | `ri:light:lightGroup` (or `inputs:ri:light:lightGroup`) | lights | hdPrman (RenderMan) |
//! | `primvars:arnold:aov` | lights | hdArnold (Arnold) |
//! | `inputs:karma:light:lpetag` | lights | Karma (Houdini) |
//! | `primvars:karma:object:lpetag` | objects | Karma (Houdini) |
//! | `primvars:ri:attributes:identifier:lpegroup` | objects | hdPrman (RenderMan) |
//!
//! A partition is declared as `custom string lpe:partition = "a,b,c"` (named `beauty`)
//! or `custom string lpe:partition:NAME = "a,b,c"` on any prim, usually the
//! `RenderSettings`.
//!
//! The dialect of the stage's expressions is declared as `custom string lpe:dialect =
//! "renderman"` (or `"osl"`; a `token` is read too) on any prim, usually the
//! `RenderSettings`: a RenderVar says `sourceType = "lpe"` for hdPrman and for Karma or
//! hdArnold alike, and most expressions parse in both dialects. Any other value, a value
//! that is no string, or two prims naming different dialects is a [`ReadError::Dialect`]
//! at the attribute: reading on would check the expressions in a dialect the stage does
//! not mean.
//!
//! The renderer is named by `custom string lpe:renderer = "karma"` (a shipped profile's
//! name, docs/profiles.md); a name that is no profile, or two prims naming different
//! ones, is a [`ReadError::Renderer`]. The namespaces of the attributes authored on
//! `RenderSettings` prims (`karma:`, `arnold:`, `ri:`) are recorded too: lint takes the
//! renderer from them when exactly one renderer's are there.
//!
//! A `.usda` layer (the root and every layer it composes) is skimmed before the USD
//! library parses it ([`super::skim`]): values of attributes lint never reads
//! ([`lint_reads`]: all but `sourceType`, `sourceName`, the group attributes and
//! `lpe:...`) are dropped unparsed, so reading a shot costs what its declarations cost,
//! not what its point arrays do. Binary layers (`.usdc`, `.usdz`) are read whole.
//!
//! This module is the composed reading, and the conventions every reading follows: a
//! `.usda` file that composes nothing is read without `openusd` by the flat reader
//! (`read/flat.rs`, which `lpe_lint::read::read_usd` tries first), through the same
//! [`DocumentBuilder`] and [`lint_reads`]; the tests hold it to [`read`].

use std::collections::BTreeSet;
use std::io;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use openusd::{ar, sdf, usd};

use lpe::{DialectName, UnknownDialect};

use crate::decl::{split_members, AovDecl, DialectDecl, Document, Format, Location, PartitionDecl};
use crate::error::{DialectProblem, ReadError};
use crate::read::common::{as_text, read_bounded, Limits};
use crate::read::skim::{skim, SkimError};

/// Light attributes holding the light's group, per delegate (see the module docs).
pub const LIGHT_GROUP_ATTRIBUTES: [&str; 4] = [
    "ri:light:lightGroup",
    "inputs:ri:light:lightGroup",
    "primvars:arnold:aov",
    "inputs:karma:light:lpetag",
];

/// Object attributes holding the object's LPE group, per delegate.
pub const OBJECT_GROUP_ATTRIBUTES: [&str; 2] = [
    "primvars:karma:object:lpetag",
    "primvars:ri:attributes:identifier:lpegroup",
];

/// The attribute declaring the dialect of the stage's expressions.
pub const DIALECT_ATTRIBUTE: &str = "lpe:dialect";

/// The attribute naming the renderer profile the stage is rendered with
/// (docs/profiles.md): its dialect and its rules.
pub const RENDERER_ATTRIBUTE: &str = "lpe:renderer";

/// Whether lint reads the value of the attribute `name` (on any prim): the RenderVar
/// attributes, the group attributes and every `lpe:` attribute. The `.usda` skim drops
/// every other value, and `lpe.lint(stage)` queries only these.
pub fn lint_reads(name: &str) -> bool {
    PrimReading::of_property(name) != PrimReading::Nothing
}

/// How much of a prim lint reads, known from its type name and property names before
/// any value is fetched: `lpe.lint(stage)` asks pxr for no more. A prim's reading is the
/// most that its type or any of its properties asks ([`PrimReading::of_type`],
/// [`PrimReading::of_property`]). [`document`] uses nothing else of a prim: a test
/// checks it on every fixture.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum PrimReading {
    /// Nothing but its type name (in [`StageFacts::types`]).
    Nothing,
    /// Its type name and the values of the attributes [`lint_reads`]: a group attribute
    /// only adds its group, wherever the prim is.
    Values,
    /// Also its path, every property name and, a RenderProduct, its [`ORDERED_VARS`]:
    /// the prims that declare AOVs, partitions, the dialect or the renderer.
    Declarations,
}

impl PrimReading {
    /// What a prim's type asks: [`READ_PRIM_TYPES`] are read whatever they hold.
    pub fn of_type(type_name: &str) -> Self {
        if READ_PRIM_TYPES.contains(&type_name) {
            Self::Declarations
        } else {
            Self::Nothing
        }
    }

    /// What one property of a prim asks: an `lpe:` attribute declares, the other
    /// [`READ_ATTRIBUTES`] are read for their values.
    pub fn of_property(name: &str) -> Self {
        if name.starts_with(READ_PREFIX) {
            Self::Declarations
        } else if READ_ATTRIBUTES.contains(&name) {
            Self::Values
        } else {
            Self::Nothing
        }
    }
}

/// Every attribute lint reads by its whole name: the RenderVar attributes and the group
/// attributes ([`lint_reads`]).
pub const READ_ATTRIBUTES: [&str; 8] = [
    "sourceType",
    "sourceName",
    LIGHT_GROUP_ATTRIBUTES[0],
    LIGHT_GROUP_ATTRIBUTES[1],
    LIGHT_GROUP_ATTRIBUTES[2],
    LIGHT_GROUP_ATTRIBUTES[3],
    OBJECT_GROUP_ATTRIBUTES[0],
    OBJECT_GROUP_ATTRIBUTES[1],
];

/// The namespace of the attributes lint reads on any prim (`lpe:dialect`,
/// `lpe:renderer`, `lpe:partition...`).
pub const READ_PREFIX: &str = "lpe:";

/// Prim types that are geometry: a stage holding one can be checked for object groups.
const GEOMETRY_TYPES: [&str; 13] = [
    "Mesh",
    "Sphere",
    "Cube",
    "Cylinder",
    "Cone",
    "Capsule",
    "Plane",
    "Points",
    "BasisCurves",
    "NurbsCurves",
    "NurbsPatch",
    "PointInstancer",
    "TetMesh",
];

/// Reads the declarations of a USD stage composed through `openusd`, every `.usda`
/// layer skimmed first (`lpe_lint::read::read_usd` reads a `.usda` that composes nothing
/// without composing it, to the same document).
pub fn read(path: &Path, limits: &Limits) -> Result<Document, ReadError> {
    read_as(path, limits, true)
}

/// [`read`], with `.usda` layers skimmed or (`skimming` false, for tests that check the
/// skim changes no finding) parsed whole.
fn read_as(path: &Path, limits: &Limits, skimming: bool) -> Result<Document, ReadError> {
    document(path, &facts_of(path, limits, skimming)?)
}

/// The facts of every prim of the stage at `path` (every property name, every value
/// [`lint_reads`]), read by `openusd`.
fn facts_of(path: &Path, limits: &Limits, skimming: bool) -> Result<StageFacts, ReadError> {
    let usd_err = |message: String| ReadError::Usd {
        path: path.to_path_buf(),
        message,
    };
    let name = path
        .to_str()
        .ok_or_else(|| usd_err("the path is not UTF-8".into()))?;
    let mut resolver = Skimming {
        inner: ar::DefaultResolver::new(),
        root: Mutex::new(None),
        limit: limits.usd_bytes,
    };
    if skimming && is_usda(path) {
        // The root is skimmed here, so that its errors keep their kinds and positions.
        let io_err = |source| ReadError::Io {
            path: path.to_path_buf(),
            source,
        };
        let file = std::fs::File::open(path).map_err(io_err)?;
        let text = skim(io::BufReader::new(file), lint_reads, limits.usd_bytes)
            .map_err(|e| skim_error(path, e))?;
        let canonical = path.canonicalize().map_err(io_err)?;
        resolver.root = Mutex::new(Some((canonical, text.into_bytes())));
    } else {
        let bytes = read_bounded(path, limits.usd_bytes, "USD")?;
        // Text layers must be text; usdc (`PXR-USDC`) and usdz (a zip) are binary.
        if !bytes.starts_with(b"PXR-USDC") && !bytes.starts_with(b"PK\x03\x04") {
            as_text(&bytes, path, 0)?;
        }
    }
    let stage = if skimming {
        usd::Stage::builder().resolver(resolver).open(name)
    } else {
        usd::Stage::open(name)
    }
    .map_err(|e| usd_err(format!("{e:#}")))?;
    let mut paths = Vec::new();
    stage
        .traverse(usd::PrimPredicate::DEFAULT, |p| paths.push(p.clone()))
        .map_err(|e| usd_err(format!("{e:#}")))?;
    let mut facts = StageFacts::default();
    for p in &paths {
        let prim = stage.prim(p.clone());
        let type_name = prim
            .type_name()
            .map_err(|e| usd_err(format!("<{p}>: {e:#}")))?
            .map(|t| t.as_str().to_string())
            .unwrap_or_default();
        let properties: Vec<String> = prim
            .property_names()
            .map_err(|e| usd_err(format!("<{p}>: {e:#}")))?
            .iter()
            .map(|t| t.as_str().to_string())
            .collect();
        let mut values = Vec::new();
        for attr in properties.iter().filter(|a| lint_reads(a)) {
            let value = prim
                .attribute(attr)
                .get::<sdf::Value>()
                .map_err(|e| usd_err(format!("<{p}>.{attr}: {e:#}")))?;
            values.push((
                attr.clone(),
                value.and_then(|v| v.as_str().map(str::to_string)),
            ));
        }
        let ordered_vars = if type_name == "RenderProduct" {
            prim.relationship(ORDERED_VARS)
                .targets()
                .map_err(|e| usd_err(format!("<{p}>.orderedVars: {e:#}")))?
                .iter()
                .map(|t| t.name().unwrap_or_default().to_string())
                .collect()
        } else {
            Vec::new()
        };
        facts.types.insert(type_name.clone());
        facts.prims.push(PrimFacts {
            path: p.to_string(),
            name: p.name().unwrap_or_default().to_string(),
            type_name,
            properties,
            values,
            ordered_vars,
        });
    }
    Ok(facts)
}

/// The read error of a skim of the root layer `path`, with its kind and position.
pub(crate) fn skim_error(path: &Path, e: SkimError) -> ReadError {
    match e {
        SkimError::Io(source) => ReadError::Io {
            path: path.to_path_buf(),
            source,
        },
        SkimError::NotText { offset } => ReadError::NotText {
            path: path.to_path_buf(),
            offset,
        },
        SkimError::TooLarge { limit } => ReadError::TooLarge {
            path: path.to_path_buf(),
            bytes: std::fs::metadata(path).map_or(0, |m| m.len()),
            limit,
            what: "USD text (besides skipped values)",
        },
        e @ SkimError::Syntax { .. } => ReadError::Usd {
            path: path.to_path_buf(),
            message: e.to_string(),
        },
    }
}

/// The relationship of a RenderProduct listing its RenderVars in order.
pub const ORDERED_VARS: &str = "orderedVars";

/// The prim types whose prims lint reads whatever attributes they hold: RenderVars (the
/// AOVs), RenderProducts (`orderedVars`), RenderSettings (their namespaces).
pub const READ_PRIM_TYPES: [&str; 3] = ["RenderVar", "RenderProduct", "RenderSettings"];

/// What lint reads of a composed stage, however it was traversed: by [`read`] through
/// `openusd`, or by `lpe.lint(stage)` through Pixar's USD. [`document`] makes the
/// [`Document`] from it, so both readers follow one definition of the conventions.
#[derive(Clone, Debug, Default)]
pub struct StageFacts {
    /// The prims to read, in traversal order: at least every prim whose
    /// [`PrimReading`] is more than nothing (others change nothing).
    pub prims: Vec<PrimFacts>,
    /// The type names of every prim traversed (`""` for a typeless one): lights and
    /// geometry make groups checkable.
    pub types: BTreeSet<String>,
}

/// One prim of [`StageFacts`]. Of a prim whose [`PrimReading`] is
/// [`PrimReading::Values`], the path, the name and the property names may be left
/// empty: [`document`] does not read them.
#[derive(Clone, Debug, Default)]
pub struct PrimFacts {
    /// Its path, `/Render/Vars/diffuse`.
    pub path: String,
    /// Its name, `diffuse`.
    pub name: String,
    /// Its type name (`""` for none).
    pub type_name: String,
    /// Its property names (at least the authored ones), in the library's order.
    pub properties: Vec<String>,
    /// Each attribute [`lint_reads`] it holds, with its value as text (a string, token
    /// or asset path; `None` for any other value or none).
    pub values: Vec<(String, Option<String>)>,
    /// A RenderProduct's `orderedVars`: the targets' prim names, in order.
    pub ordered_vars: Vec<String>,
}

/// The declarations of a stage `file` whose prims are `facts` (module docs).
pub fn document(file: &Path, facts: &StageFacts) -> Result<Document, ReadError> {
    let mut builder = DocumentBuilder::new(file);
    for t in &facts.types {
        builder.prim_type(t);
    }
    for prim in &facts.prims {
        builder.prim(prim)?;
    }
    Ok(builder.finish())
}

/// [`document`] one prim at a time, for readers that stream a stage instead of holding
/// its [`StageFacts`] (the flat reader, `read/flat.rs`): the prims must come in
/// traversal order, and every type traversed must be named through
/// [`DocumentBuilder::prim_type`].
pub struct DocumentBuilder {
    doc: Document,
    lights: BTreeSet<String>,
    objects: BTreeSet<String>,
    has_lights: bool,
    has_objects: bool,
    declared: Option<(DialectName, Location)>,
}

impl DocumentBuilder {
    /// A builder for the stage `file`, with no prim yet.
    pub fn new(file: &Path) -> DocumentBuilder {
        DocumentBuilder {
            doc: Document::new(file, Format::Usd),
            lights: BTreeSet::new(),
            objects: BTreeSet::new(),
            has_lights: false,
            has_objects: false,
            declared: None,
        }
    }

    /// Records that a prim of type `type_name` (`""` for none) was traversed: lights and
    /// geometry make groups checkable.
    pub fn prim_type(&mut self, type_name: &str) {
        self.has_lights |= type_name.ends_with("Light");
        self.has_objects |= GEOMETRY_TYPES.contains(&type_name);
    }

    /// Reads one prim (its type is not recorded: see [`DocumentBuilder::prim_type`]).
    pub fn prim(&mut self, prim: &PrimFacts) -> Result<(), ReadError> {
        let file = self.doc.file.clone();
        let doc = &mut self.doc;
        let p = &prim.path;
        let text = |attr: &str| -> Option<String> {
            prim.values
                .iter()
                .find(|(name, _)| name == attr)
                .and_then(|(_, v)| v.clone())
        };
        let at = |attribute: &str| Location::Prim {
            prim: p.clone(),
            attribute: attribute.to_string(),
        };
        match prim.type_name.as_str() {
            "RenderVar" => {
                let source_type = text("sourceType").unwrap_or_else(|| "raw".into());
                if source_type == "lpe" {
                    doc.aovs.push(AovDecl {
                        name: prim.name.clone(),
                        source: text("sourceName").unwrap_or_default(),
                        location: at("sourceName"),
                        source_type: Some(source_type),
                    });
                }
            }
            "RenderProduct" if doc.ordered_vars.is_none() && !prim.ordered_vars.is_empty() => {
                doc.ordered_vars = Some(prim.ordered_vars.clone());
            }
            _ => {}
        }
        for attr in LIGHT_GROUP_ATTRIBUTES {
            if let Some(g) = text(attr) {
                self.has_lights = true;
                self.lights.insert(g);
            }
        }
        for attr in OBJECT_GROUP_ATTRIBUTES {
            if let Some(g) = text(attr) {
                self.has_objects = true;
                self.objects.insert(g);
            }
        }
        for prop in &prim.properties {
            let prop = prop.as_str();
            if prim.type_name == "RenderSettings" {
                if let Some((namespace, _)) = prop.split_once(':') {
                    doc.settings_namespaces
                        .entry(namespace.to_string())
                        .or_insert_with(|| p.clone());
                }
            }
            if prop == RENDERER_ATTRIBUTE {
                declare_renderer(&mut doc.renderer, &file, text(prop), at(prop))?;
                continue;
            }
            if prop == DIALECT_ATTRIBUTE {
                declare_dialect(&mut self.declared, &file, text(prop).as_deref(), at(prop))?;
                continue;
            }
            let name = match prop.strip_prefix("lpe:partition") {
                Some("") => "beauty",
                Some(rest) => match rest.strip_prefix(':') {
                    Some(n) if !n.is_empty() => n,
                    _ => continue,
                },
                None => continue,
            };
            doc.partitions.push(PartitionDecl {
                name: name.to_string(),
                members: split_members(&text(prop).unwrap_or_default()),
                location: at(prop),
            });
        }
        Ok(())
    }

    /// The document of the prims read.
    pub fn finish(self) -> Document {
        let mut doc = self.doc;
        doc.dialect = self.declared.map(|(dialect, at)| DialectDecl {
            dialect,
            location: Some(at),
        });
        doc.light_groups = self.has_lights.then_some(self.lights);
        doc.object_groups = self.has_objects.then_some(self.objects);
        doc
    }
}

/// Whether `path` names a text layer by its extension: the layers the skim reads.
pub(crate) fn is_usda(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("usda"))
}

/// The default resolver, but every `.usda` layer it opens is skimmed first; the root
/// layer, skimmed by [`read`] already, is handed over once.
struct Skimming {
    inner: ar::DefaultResolver,
    root: Mutex<Option<(PathBuf, Vec<u8>)>>,
    limit: u64,
}

impl ar::Resolver for Skimming {
    fn create_identifier(&self, asset_path: &str, anchor: Option<&ar::ResolvedPath>) -> String {
        self.inner.create_identifier(asset_path, anchor)
    }

    fn resolve(&self, asset_path: &str) -> Option<ar::ResolvedPath> {
        self.inner.resolve(asset_path)
    }

    fn resolve_for_new_asset(&self, asset_path: &str) -> Option<ar::ResolvedPath> {
        self.inner.resolve_for_new_asset(asset_path)
    }

    fn open_asset(&self, resolved: &ar::ResolvedPath) -> io::Result<Box<dyn ar::Asset>> {
        if !is_usda(resolved) {
            return self.inner.open_asset(resolved);
        }
        let mut root = self.root.lock().unwrap_or_else(|e| e.into_inner());
        if root
            .as_ref()
            .is_some_and(|(p, _)| p.as_path() == &**resolved)
        {
            if let Some((_, text)) = root.take() {
                return Ok(Box::new(io::Cursor::new(text)));
            }
        }
        drop(root);
        let file = self.inner.open_asset(resolved)?;
        let text = skim(file, lint_reads, self.limit).map_err(|e| match e {
            SkimError::Io(e) => e,
            e => io::Error::new(
                io::ErrorKind::InvalidData,
                format!("{}: {e}", resolved.display()),
            ),
        })?;
        Ok(Box::new(io::Cursor::new(text.into_bytes())))
    }

    fn get_asset_info(&self, asset_path: &str, resolved: &ar::ResolvedPath) -> ar::AssetInfo {
        self.inner.get_asset_info(asset_path, resolved)
    }

    fn get_modification_timestamp(
        &self,
        asset_path: &str,
        resolved: &ar::ResolvedPath,
    ) -> Option<std::time::SystemTime> {
        self.inner.get_modification_timestamp(asset_path, resolved)
    }

    fn identity(&self) -> String {
        self.inner.identity()
    }
}

/// Records in `declared` the renderer an `lpe:renderer` attribute at `at` names.
fn declare_renderer(
    declared: &mut Option<(String, Location)>,
    path: &Path,
    named: Option<String>,
    at: Location,
) -> Result<(), ReadError> {
    let error = |at: Location, message: String| ReadError::Renderer {
        path: path.to_path_buf(),
        at: Box::new(at),
        message,
    };
    let Some(name) = named else {
        return Err(error(
            at,
            "expected a string or token naming a renderer profile".into(),
        ));
    };
    lpe_profile::by_name(&name).map_err(|e| error(at.clone(), e.to_string()))?;
    match declared {
        Some((earlier, first)) if *earlier != name => Err(error(
            at,
            format!("names `{name}`, but {first} names `{earlier}`"),
        )),
        Some(_) => Ok(()),
        None => {
            *declared = Some((name, at));
            Ok(())
        }
    }
}

/// Records in `declared` the dialect an `lpe:dialect` attribute at `at` names (`named`
/// `None`: the attribute holds no string or token).
fn declare_dialect(
    declared: &mut Option<(DialectName, Location)>,
    path: &Path,
    named: Option<&str>,
    at: Location,
) -> Result<(), ReadError> {
    let problem = match (named.map(str::parse::<DialectName>), &*declared) {
        (Some(Ok(d)), None) => {
            *declared = Some((d, at));
            return Ok(());
        }
        (Some(Ok(d)), Some((earlier, _))) if *earlier == d => return Ok(()),
        (Some(Ok(d)), Some((earlier, first))) => DialectProblem::Conflict {
            dialect: d,
            earlier: *earlier,
            first: first.clone(),
        },
        (Some(Err(unknown)), _) => DialectProblem::Unknown {
            suggestion: likely_dialect(&unknown),
            unknown,
        },
        (None, _) => DialectProblem::NotAName,
    };
    Err(ReadError::Dialect {
        path: path.to_path_buf(),
        at: Box::new(at),
        problem: Box::new(problem),
    })
}

/// The dialect an unknown name most likely means: a dialect's name in other case, or a
/// renderer (or its Hydra delegate) that reads one.
fn likely_dialect(unknown: &UnknownDialect) -> Option<DialectName> {
    let name = unknown.0.trim().to_ascii_lowercase();
    if let Ok(d) = name.parse() {
        return Some(d);
    }
    match name.as_str() {
        "prman" | "hdprman" | "ri" => Some(DialectName::RenderMan),
        "arnold" | "hdarnold" | "karma" | "moonray" => Some(DialectName::Osl),
        _ => None,
    }
}

#[cfg(test)]
mod profile_tests {
    use super::{LIGHT_GROUP_ATTRIBUTES, OBJECT_GROUP_ATTRIBUTES};

    /// Every group attribute a shipped renderer profile cites is one this reader reads,
    /// on the carrier the profile names: a profile citing an attribute lint never reads
    /// would promise group checks that do not happen. Checked by hand: dropping
    /// `primvars:arnold:aov` from `LIGHT_GROUP_ATTRIBUTES` fails it, naming Arnold.
    #[test]
    fn every_group_attribute_a_profile_cites_is_read() {
        let mut cited = 0;
        for p in lpe_profile::shipped() {
            let Some(g) = &p.groups else { continue };
            for a in &g.light {
                assert!(
                    LIGHT_GROUP_ATTRIBUTES.contains(&a.as_str()),
                    "{}: light `{a}`",
                    p.name
                );
                cited += 1;
            }
            for a in &g.object {
                assert!(
                    OBJECT_GROUP_ATTRIBUTES.contains(&a.as_str()),
                    "{}: object `{a}`",
                    p.name
                );
                cited += 1;
            }
        }
        assert!(cited >= 5, "{cited}");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every fixture (and every layer it composes) reads the same skimmed as whole.
    #[test]
    fn the_skim_changes_nothing_lint_reads() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/testdata");
        let mut seen = 0;
        for dir in ["usd", "lint"] {
            for entry in std::fs::read_dir(root.join(dir)).unwrap() {
                let path = entry.unwrap().path();
                if !is_usda(&path) {
                    continue;
                }
                let limits = Limits::default();
                let skimmed = format!("{:?}", read_as(&path, &limits, true));
                let whole = format!("{:?}", read_as(&path, &limits, false));
                assert_eq!(skimmed, whole, "{}", path.display());
                seen += 1;
            }
        }
        assert_eq!(seen, 11, "fixtures");
    }

    /// `facts` as `lpe.lint(stage)` collects them: the prims whose [`PrimReading`] is
    /// `Declarations` whole, in order; then, of those read for their values only, each
    /// distinct attribute and text once, with nothing else.
    fn as_collected(facts: &StageFacts) -> StageFacts {
        let mut prims = Vec::new();
        let mut texts = BTreeSet::new();
        for p in &facts.prims {
            let reading = p
                .properties
                .iter()
                .map(|n| PrimReading::of_property(n))
                .fold(PrimReading::of_type(&p.type_name), Ord::max);
            match reading {
                PrimReading::Nothing => {}
                PrimReading::Values => {
                    texts.extend(p.values.iter().filter(|(_, t)| t.is_some()).cloned())
                }
                PrimReading::Declarations => prims.push(p.clone()),
            }
        }
        prims.extend(texts.into_iter().map(|value| PrimFacts {
            values: vec![value],
            ..PrimFacts::default()
        }));
        StageFacts {
            prims,
            types: facts.types.clone(),
        }
    }

    /// Every fixture's declarations are the same made from every prim's facts as from
    /// only what [`PrimReading`] says lint reads: `lpe.lint(stage)` may skip the rest.
    /// Planted faults, seen failing: `RenderSettings` dropped from [`READ_PRIM_TYPES`]
    /// (karma_settings.usda's namespaces are lost); [`PrimReading::of_type`] answering
    /// `Values` for the typed prims (their paths are lost).
    #[test]
    fn what_lint_collects_of_each_fixture_makes_the_same_document() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/testdata/usd");
        let mut seen = 0;
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if !is_usda(&path) {
                continue;
            }
            let facts = facts_of(&path, &Limits::default(), true).unwrap();
            let whole = format!("{:?}", document(&path, &facts));
            let collected = format!("{:?}", document(&path, &as_collected(&facts)));
            assert_eq!(whole, collected, "{}", path.display());
            seen += 1;
        }
        assert!(seen >= 10, "{seen} fixtures");
    }

    /// Each kind of prim read as lint needs it, worked by hand: what every reading keeps
    /// and what the document makes of it. Planted faults, seen failing: an `lpe:`
    /// attribute read as `Values` (which would lose the typeless prim's path and
    /// property names, so its partition and dialect; the fixtures keep theirs on
    /// RenderSettings and do not see it); the group attributes read as `Nothing`;
    /// `of_property` comparing the prefix without its colon (`lpedata` declares);
    /// `RenderSettings` dropped from [`READ_PRIM_TYPES`].
    #[test]
    fn each_kind_of_prim_is_read_as_much_as_the_document_needs() {
        use PrimReading::{Declarations, Nothing, Values};
        assert_eq!(PrimReading::of_type("RenderVar"), Declarations);
        assert_eq!(PrimReading::of_type("RenderProduct"), Declarations);
        assert_eq!(PrimReading::of_type("RenderSettings"), Declarations);
        assert_eq!(PrimReading::of_type("Mesh"), Nothing);
        assert_eq!(PrimReading::of_type("RectLight"), Nothing);
        assert_eq!(PrimReading::of_type(""), Nothing);
        assert_eq!(
            PrimReading::of_property("lpe:partition:groups"),
            Declarations
        );
        assert_eq!(PrimReading::of_property("lpe:dialect"), Declarations);
        assert_eq!(PrimReading::of_property("lpedata"), Nothing);
        for group in LIGHT_GROUP_ATTRIBUTES
            .iter()
            .chain(&OBJECT_GROUP_ATTRIBUTES)
        {
            assert_eq!(PrimReading::of_property(group), Values, "{group}");
        }
        assert_eq!(PrimReading::of_property("sourceName"), Values);
        assert_eq!(PrimReading::of_property("points"), Nothing);
        assert_eq!(PrimReading::of_property("primvars:karma:object"), Nothing);

        let prim = |path: &str, type_name: &str, values: &[(&str, &str)]| PrimFacts {
            path: path.to_string(),
            name: path.rsplit('/').next().unwrap().to_string(),
            type_name: type_name.to_string(),
            properties: values.iter().map(|(n, _)| n.to_string()).collect(),
            values: values
                .iter()
                .map(|(n, v)| (n.to_string(), Some(v.to_string())))
                .collect(),
            ordered_vars: Vec::new(),
        };
        let facts = StageFacts {
            prims: vec![
                prim(
                    "/World/floor",
                    "Mesh",
                    &[("primvars:karma:object:lpetag", "floor")],
                ),
                prim(
                    "/World/key",
                    "RectLight",
                    &[("inputs:karma:light:lpetag", "key")],
                ),
                prim("/World/plain", "Xform", &[("points", "")]),
                prim(
                    "/World/wall",
                    "Mesh",
                    &[("primvars:karma:object:lpetag", "floor")],
                ),
                prim(
                    "/World/notes",
                    "",
                    &[("lpe:dialect", "osl"), ("lpe:partition:groups", "a,b")],
                ),
            ],
            types: ["Mesh", "RectLight", "Xform", ""].map(String::from).into(),
        };
        let collected = as_collected(&facts);
        // The declaring prim whole; the two meshes' group once, the light's.
        let kept: Vec<_> = collected
            .prims
            .iter()
            .map(|p| {
                (
                    p.path.as_str(),
                    p.type_name.as_str(),
                    p.properties.len(),
                    p.values[0].0.as_str(),
                )
            })
            .collect();
        assert_eq!(
            kept,
            [
                ("/World/notes", "", 2, "lpe:dialect"),
                ("", "", 0, "inputs:karma:light:lpetag"),
                ("", "", 0, "primvars:karma:object:lpetag"),
            ]
        );
        let file = Path::new("stage.usda");
        let doc = document(file, &collected).unwrap();
        let set = |v: &[&str]| Some(v.iter().map(|s| s.to_string()).collect::<BTreeSet<_>>());
        assert_eq!(doc.object_groups, set(&["floor"]));
        assert_eq!(doc.light_groups, set(&["key"]));
        assert_eq!(doc.dialect.map(|d| d.dialect), Some(DialectName::Osl));
        let partitions: Vec<_> = doc
            .partitions
            .iter()
            .map(|p| (p.name.as_str(), p.members.join(","), p.location.to_string()))
            .collect();
        assert_eq!(
            partitions,
            [(
                "groups",
                "a,b".to_string(),
                "</World/notes>.lpe:partition:groups".to_string()
            )]
        );
    }

    /// Lights and geometry make a stage's groups checkable when no prim carries a group:
    /// a `SphereLight` gives an empty set of light groups, a `TetMesh` one of object
    /// groups, typeless, `Xform`, `Scope` and `Material` prims neither (`None`: nothing
    /// to check against). Planted faults (cargo-mutants), each seen failing:
    /// [`DocumentBuilder::prim_type`] doing nothing; its `has_objects |=` as `&=`.
    #[test]
    fn lights_and_geometry_make_groups_checkable_without_a_group() {
        let groups = |types: &[&str]| {
            let facts = StageFacts {
                prims: Vec::new(),
                types: types.iter().map(|t| t.to_string()).collect(),
            };
            let doc = document(Path::new("stage.usda"), &facts).unwrap();
            (doc.light_groups, doc.object_groups)
        };
        let empty = Some(BTreeSet::new());
        assert_eq!(
            groups(&["", "Material", "SphereLight", "TetMesh", "Xform"]),
            (empty.clone(), empty.clone())
        );
        assert_eq!(groups(&["SphereLight", "Xform"]), (empty.clone(), None));
        assert_eq!(groups(&["Scope", "TetMesh"]), (None, empty));
        assert_eq!(groups(&["", "Material", "Scope", "Xform"]), (None, None));
    }

    /// A prim whose group attribute follows heavy values with brackets and quotes in
    /// strings is still read, with its value.
    #[test]
    fn heavy_and_adversarial_values_keep_the_groups() {
        let dir = std::env::temp_dir().join(format!("lpe-skim-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("adversarial.usda");
        let points = "(0.5, -1e3, 2), ".repeat(2000);
        let text = format!(
            "#usda 1.0\ndef Mesh \"m\"\n{{\n    point3f[] points = [{points}]\n    string[] primvars:notes = [\"}}]\\\" def Mesh\", '\"', \"\"\"\n]\"\"\"]\n    string primvars:karma:object:lpetag = \"floor\"\n}}\ndef RectLight \"l\"\n{{\n    string primvars:arnold:aov = 'key'\n    float karma:x = 1\n}}\n"
        );
        std::fs::write(&path, text).unwrap();
        let doc = read(&path, &Limits::default()).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        let set = |v: &[&str]| Some(v.iter().map(|s| s.to_string()).collect::<BTreeSet<_>>());
        assert_eq!(doc.object_groups, set(&["floor"]));
        assert_eq!(doc.light_groups, set(&["key"]));
    }
}
