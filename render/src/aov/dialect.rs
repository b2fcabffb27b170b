//! What the renderer needs of a dialect ([`SceneDialect`]): how it shows the renderer's
//! vertices, how it reads an AOV, its default AOVs and what it refuses in a scene; and the
//! matchers that show a dialect's vertices ([`SceneClassifier`]). The renderer takes the
//! dialect from the command line once and is generic over this trait from there on; each
//! dialect implements it in a file of its own (`renderman.rs`, `osl.rs`).

use lpe::renderman::LobeMap;
use lpe::{AovSet, Dialect, PathMatcher};
use lpe_reference::lpe_tree::ReferenceMatch;

use super::declare::Declared;
use super::flags::AovFlags;
use super::vertex::SceneVertex;
use crate::scene::Scene;

/// One AOV source as a dialect reads it.
#[derive(Clone, Debug)]
pub struct ParsedAov<L> {
    pub lpe: L,
    /// How the AOV accumulates (a dialect without prefixes: the default).
    pub flags: AovFlags,
    /// Warnings about the expression (the list keeps them as notes).
    pub warnings: Vec<String>,
}

/// Why a dialect did not take a `rendermn.ini`.
#[derive(Debug, thiserror::Error)]
pub enum IniRefusal {
    /// The file does not read.
    #[error("{0}")]
    Unreadable(Box<dyn std::error::Error + Send + Sync>),
    /// The dialect has no use for one: why.
    #[error("{0}")]
    NotTaken(&'static str),
}

/// What the renderer needs per dialect. The reference matcher (the renderer's fallback
/// when the fast matcher refuses a set) must read the dialect's trees.
pub trait SceneDialect:
    Dialect<Lpe: ReferenceMatch<Path = Self::Path>> + lpe_profile::ProfileDialect
{
    /// What the renderer's report calls the basic set's partition.
    const BASIC_PARTITION: &'static str;
    /// How error messages name the dialect after an AOV's name (`AOV `x` (OSL
    /// dialect): ...`); empty for the default dialect.
    const MESSAGE_TAG: &'static str;
    /// Whether the dialect sees user lobes: the pseudo paths `C <R Un> L` that carry a
    /// material's albedo, position and normal to AOVs that ask for them.
    const USER_LOBES: bool;
    /// Whether this is the renderer's own dialect, the one its scenes' lobe events are
    /// written in: `check` runs the estimator, prefix and determinism checks in it, and
    /// checks every other dialect's basic set against it.
    const NATIVE: bool;
    /// Any emitter, as one item of an expression.
    const EMITTER: &'static str;
    /// Distinct, plausible AOVs beyond the defaults, `(name, source)`: what `lpe-render
    /// bench` pads its list with.
    const BENCH_EXTRA: &'static [(&'static str, &'static str)];

    /// The vertex `v` as this dialect sees it.
    fn scene_vertex(v: &SceneVertex) -> Self::Vertex;

    /// The basic AOVs, `(name, source)`: a partition of beauty.
    fn basic_aovs() -> Vec<(&'static str, String)>;

    /// The basic AOVs, declared as the partition they are.
    fn basic() -> Declared {
        let mut d = Declared::default();
        let aovs = Self::basic_aovs().into_iter().map(|(n, s)| (n.into(), s));
        d.push_partition(Self::BASIC_PARTITION, aovs, true);
        d
    }

    /// The default AOVs of a render of `scene`, with the partitions they form.
    fn defaults(scene: &Scene) -> Declared;

    /// The AOV of the furnace's paths of exactly `k` diffuse bounces.
    fn furnace_bounce(k: u32) -> String;

    /// Reads one AOV source under `registration`; the error is the message.
    fn parse_aov(
        source: &str,
        registration: &Self::Registration,
    ) -> Result<ParsedAov<Self::Lpe>, String>;

    /// Whether the expression can tell vertices apart by their labels (else the
    /// integrator classifies them without).
    fn names_labels(lpe: &Self::Lpe) -> bool;

    /// Why a scene label (an object's `lpegroup`, a light's group) cannot be shown in
    /// this dialect, if it cannot.
    fn refused_label(label: &str) -> Option<&'static str> {
        let _ = label;
        None
    }

    /// The registration and lobe map a `rendermn.ini` gives, or why the dialect does not
    /// take one.
    fn from_ini(text: &str) -> Result<(Self::Registration, LobeMap), IniRefusal>;

    /// The path of `vertices` as the integrator stepped them, if they form one (the
    /// whole-path engines judge it).
    fn whole_path(vertices: Vec<Self::Vertex>) -> Option<Self::Path>;
}

/// A matcher the integrator can hand the renderer's vertices: it shows each one in its
/// dialect.
pub trait SceneClassifier: PathMatcher<Vertex = <Self::Dialect as Dialect>::Vertex> {
    /// The dialect the matcher's expressions are written in.
    type Dialect: SceneDialect;

    /// The class of a scene vertex (called once per kind of vertex, before rendering).
    fn classify_scene(&self, v: &SceneVertex) -> Self::Class {
        self.classify(&Self::Dialect::scene_vertex(v))
    }
}

impl<D: SceneDialect> SceneClassifier for AovSet<D> {
    type Dialect = D;
}
