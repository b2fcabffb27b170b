//! A profile file's format (docs/profiles.md, "The file"), read with serde: unknown keys
//! are errors, so a typo cannot drop a rule. Values the checks may refuse keep their
//! place in the file (`toml::Spanned`) so a refusal names its line.

use serde::Deserialize;
use toml::Spanned;

use lpe::translate::Correspondence;
use lpe::DialectName;

/// One renderer's reading of LPEs.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Profile {
    /// The name it is selected by (`--renderer karma`): lowercase, the file's stem.
    pub name: String,
    /// The renderer's name as people write it.
    pub title: String,
    /// `"renderman"` or `"osl"`: the syntax and matching the renderer starts from.
    pub base: Spanned<String>,
    /// What differs from the base dialect, in a sentence or two.
    #[serde(default)]
    pub summary: String,
    /// The documents and sources the rules cite, by id.
    #[serde(default)]
    pub sources: Vec<Source>,
    /// Event letters the renderer adds to its base (OSL base only).
    #[serde(default)]
    pub events: Vec<Rule>,
    /// Scattering letters the renderer adds to its base (OSL base only).
    #[serde(default)]
    pub scatterings: Vec<Rule>,
    /// Vertices the renderer never produces.
    #[serde(default)]
    pub never: Vec<Never>,
    /// Prefixes the renderer reads before an expression (`unoccluded;`); OSL base only,
    /// RenderMan's own are part of its dialect.
    #[serde(default)]
    pub prefixes: Vec<Prefix>,
    /// AOVs the renderer defines by name.
    #[serde(default)]
    pub builtins: Vec<Builtin>,
    /// Where light and object groups come from.
    #[serde(default)]
    pub groups: Option<Groups>,
    /// How a RenderVar's `sourceName` reaches the renderer.
    #[serde(default)]
    pub source_name: Option<SourceName>,
    /// How a stage says it is rendered by this renderer.
    #[serde(default)]
    pub detect: Option<Detect>,
    /// How RenderMan's lobes and labels become this renderer's letters.
    #[serde(default)]
    pub translate: Option<Translate>,
}

impl Profile {
    /// The base dialect (checked when the profile loads).
    pub fn dialect(&self) -> DialectName {
        match self.base.get_ref().as_str() {
            "osl" => DialectName::Osl,
            _ => DialectName::RenderMan,
        }
    }

    /// The source cited by `id`.
    pub fn source(&self, id: &str) -> Option<&Source> {
        self.sources.iter().find(|s| s.id == id)
    }

    /// Whether the renderer prepends `lpe:` to a `sourceName` itself.
    pub fn prepends_lpe_mark(&self) -> bool {
        matches!(
            self.source_name.as_ref().map(|s| s.lpe_mark),
            Some(LpeMark::Prepended)
        )
    }

    /// The attribute namespace of the renderer's RenderSettings attributes (`karma`).
    pub fn settings_namespace(&self) -> Option<&str> {
        self.detect.as_ref().map(|d| d.settings_namespace.as_str())
    }

    /// How RenderMan's lobes and labels become this renderer's letters: its `[translate]`
    /// declaration applied to the default, or the default when it has none.
    pub fn correspondence(&self) -> Correspondence {
        let declared = self
            .translate
            .as_ref()
            .map_or("", |t| t.correspondence.get_ref());
        // The declaration parsed when the profile loaded (`check`): a failure here is a
        // profile built past the loader.
        Correspondence::parse(declared)
            .expect("a profile's correspondence is checked when it loads")
    }
}

/// A document or source file the rules cite.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Source {
    /// How rules name it.
    pub id: String,
    /// Its title.
    pub title: String,
    /// A URL, or `repository:path`.
    #[serde(rename = "where")]
    pub location: String,
}

/// A letter the renderer adds, with what it means.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Rule {
    /// The letter (or word) as expressions write it.
    pub letter: Spanned<String>,
    /// What it stands for.
    pub meaning: String,
    /// The id of the source that says so.
    pub source: Spanned<String>,
}

/// A vertex the renderer never produces.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Never {
    /// A one-vertex pattern in the base dialect (`<[RT]S>`).
    pub vertex: Spanned<String>,
    /// Why it never appears.
    pub why: String,
    /// The id of the source that says so.
    pub source: Spanned<String>,
}

/// A prefix the renderer reads before an expression.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Prefix {
    /// Its name, without the `;`.
    pub name: Spanned<String>,
    /// What it changes.
    pub meaning: String,
    /// The id of the source that says so.
    pub source: Spanned<String>,
}

/// An AOV the renderer defines by name.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Builtin {
    /// The name a RenderVar writes as its whole source.
    pub name: Spanned<String>,
    /// Its expression, in the profile's own syntax.
    pub expr: Spanned<String>,
    /// The id of the source that says so.
    pub source: Spanned<String>,
}

/// The USD attributes light and object groups come from.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Groups {
    /// Attributes on lights whose value labels the light's vertex.
    #[serde(default)]
    pub light: Vec<String>,
    /// Attributes on geometry whose value labels the object's vertices.
    #[serde(default)]
    pub object: Vec<String>,
    /// The id of the source that says so.
    pub source: Spanned<String>,
}

/// How a RenderVar's `sourceName` reaches the renderer.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SourceName {
    /// What happens to an `lpe:` mark.
    pub lpe_mark: LpeMark,
    /// The id of the source that says so.
    pub source: Spanned<String>,
}

/// What a renderer does with the `lpe:` mark of a `sourceName`.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum LpeMark {
    /// It reads the `sourceName` as written (a leading `lpe:` is optional).
    AsAuthored,
    /// It prepends `lpe:` itself, so an authored one is doubled (hdPrman).
    Prepended,
}

/// How a stage names the renderer.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Detect {
    /// The namespace of its RenderSettings attributes (`karma` for `karma:...`).
    pub settings_namespace: String,
}

/// Translation to and from the renderer.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Translate {
    /// RenderMan lobes and labels as this renderer's letters, in
    /// `lpe::translate::Correspondence::parse`'s syntax (`S1-S7=G, S8=S`).
    pub correspondence: Spanned<String>,
    /// The id of the source that says so.
    pub source: Spanned<String>,
}
