//! The vertices `lpe-render` produces, described in the renderer's own terms, and how
//! each dialect sees them: a RenderMan [`lpe::renderman::Vertex`] (type, event with its lobe number,
//! one label) or an OSL [`osl::Vertex`] (event, scattering, custom labels).
//!
//! The integrator classifies every vertex its scene can produce once, before rendering,
//! through [`SceneClassifier::classify_scene`]; the dialect only decides what the
//! matcher is shown, never what the integrator traces.
//!
//! The OSL mapping (docs/language.md §18.12):
//!
//! | renderer vertex | OSL vertex |
//! |---|---|
//! | camera | `C,~` |
//! | scattering off a lobe, reflected / transmitted | `R` / `T`, then `D` (Lambert, diffuse transmission), `G` (GGX) or `S` (dielectric: a delta lobe), then the object's `lpegroup` |
//! | light reached by a bounce or a light sample | `L,~`, then the light's group |
//! | area light seen straight from the camera, glowing object | `O,~`, then the light's group / the object's `lpegroup` |
//!
//! A vertex carries at most one custom label: light objects have no `lpegroup`, and no
//! other vertex has a light group. Emitters and the camera scatter NONE (`~`).

use lpe::osl::{self, Osl, Symbol};
use lpe::renderman::macros::BASIC;
use lpe::renderman::RenderMan;
use lpe::renderman::{Event, VertexType};
use lpe::{AovSet, Dialect, DialectName, PathMatcher};

use crate::material::Scattering;

/// One kind of vertex the renderer produces.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneVertex<'a> {
    /// The camera, every path's first vertex.
    Camera,
    /// Scattering off one lobe of an object's material.
    Scatter {
        /// `R` or `T`.
        side: VertexType,
        /// The event the lobe map gives the lobe (RenderMan).
        event: Event,
        /// How the lobe scatters (OSL).
        scattering: Scattering,
        /// The object's `lpegroup`.
        group: Option<&'a str>,
    },
    /// A light reached by a bounce or by a light sample.
    Light { group: Option<&'a str> },
    /// An emitting surface seen as an object: an area light straight from the camera
    /// (labelled with its light group) or a glowing material (with its `lpegroup`).
    Emissive { group: Option<&'a str> },
}

/// A matcher the integrator can hand the renderer's vertices: it shows each one in its
/// own dialect.
pub trait SceneClassifier: PathMatcher {
    /// The class of a scene vertex (called once per kind of vertex, before rendering).
    fn classify_scene(&self, v: &SceneVertex) -> Self::Class;

    /// The dialect the matcher's expressions are written in. Only RenderMan has user
    /// lobes (the pseudo paths `C <R Un> L`).
    fn dialect(&self) -> DialectName;
}

/// What the renderer needs per dialect: how the dialect sees the renderer's vertices,
/// and its basic AOV set (the default AOVs, a partition of beauty).
pub trait SceneDialect: Dialect {
    /// What the renderer's report calls the basic set's partition.
    const BASIC_PARTITION: &'static str;

    /// The vertex `v` as this dialect sees it.
    fn scene_vertex(v: &SceneVertex) -> Self::Vertex;

    /// The basic AOVs, `(name, source)`.
    fn basic_aovs() -> Vec<(&'static str, String)>;
}

impl SceneDialect for RenderMan {
    const BASIC_PARTITION: &'static str = "basic AOVs";

    /// Type, the event the lobe map gives the lobe (with its number), one label.
    fn scene_vertex(v: &SceneVertex) -> lpe::renderman::Vertex {
        match *v {
            SceneVertex::Camera => lpe::renderman::Vertex::camera(),
            SceneVertex::Scatter {
                side, event, group, ..
            } => lpe::renderman::Vertex::scatter(side, event, group),
            SceneVertex::Light { group } => lpe::renderman::Vertex::light(group),
            SceneVertex::Emissive { group } => lpe::renderman::Vertex::emissive(group),
        }
    }

    /// The basic macros, by name.
    fn basic_aovs() -> Vec<(&'static str, String)> {
        BASIC
            .iter()
            .map(|(n, _)| (*n, format!("lpe:{n}")))
            .collect()
    }
}

impl SceneDialect for Osl {
    const BASIC_PARTITION: &'static str = "OSL basic AOVs";

    /// See the module docs for the mapping.
    fn scene_vertex(v: &SceneVertex) -> osl::Vertex {
        let (event, scattering, group) = match *v {
            SceneVertex::Camera => ("C", None, None),
            SceneVertex::Scatter {
                side,
                scattering,
                group,
                ..
            } => {
                let event = if side == VertexType::T { "T" } else { "R" };
                (event, Some(scattering_label(scattering)), group)
            }
            SceneVertex::Light { group } => ("L", None, group),
            SceneVertex::Emissive { group } => ("O", None, group),
        };
        let mut symbols = vec![
            Symbol::label(event),
            scattering.map_or(Symbol::None, Symbol::label),
        ];
        symbols.extend(group.map(Symbol::label));
        osl::Vertex::new(symbols)
    }

    /// `lpe::osl::BASIC`, under RenderMan's basic names.
    fn basic_aovs() -> Vec<(&'static str, String)> {
        osl::BASIC
            .iter()
            .map(|(n, s)| (*n, s.to_string()))
            .collect()
    }
}

/// OSL's scattering label of a lobe.
fn scattering_label(s: Scattering) -> &'static str {
    match s {
        Scattering::Diffuse => "D",
        Scattering::Glossy => "G",
        Scattering::Delta => "S",
    }
}

impl<D: SceneDialect> SceneClassifier for AovSet<D> {
    #[inline]
    fn classify_scene(&self, v: &SceneVertex) -> lpe::Class {
        self.classify(&D::scene_vertex(v))
    }

    fn dialect(&self) -> DialectName {
        DialectName::of::<D>().expect("the renderer's dialects are lpe's")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use lpe::renderman::EventKind;

    fn scatter(side: VertexType, scattering: Scattering, group: Option<&str>) -> SceneVertex<'_> {
        SceneVertex::Scatter {
            side,
            event: Event::new(EventKind::S, 4).unwrap(),
            scattering,
            group,
        }
    }

    /// Hand-written OSL path text of each kind of vertex (§18.1's notation).
    #[test]
    fn vertices_are_the_documented_ones_in_the_osl_dialect() {
        let cases = [
            (SceneVertex::Camera, "C,~"),
            (
                scatter(VertexType::R, Scattering::Diffuse, Some("floor")),
                "R,D,floor",
            ),
            (scatter(VertexType::R, Scattering::Glossy, None), "R,G"),
            (
                scatter(VertexType::T, Scattering::Delta, Some("glass")),
                "T,S,glass",
            ),
            (scatter(VertexType::R, Scattering::Delta, None), "R,S"),
            (SceneVertex::Light { group: Some("key") }, "L,~,key"),
            (SceneVertex::Light { group: None }, "L,~"),
            (
                SceneVertex::Emissive {
                    group: Some("ember"),
                },
                "O,~,ember",
            ),
            (SceneVertex::Emissive { group: None }, "O,~"),
        ];
        for (v, want) in cases {
            assert_eq!(Osl::scene_vertex(&v).to_string(), want, "{v:?}");
        }
    }

    #[test]
    fn renderman_vertices_keep_the_lobe_event_and_label() {
        let v = scatter(VertexType::T, Scattering::Delta, Some("glass"));
        let rm = |v: &SceneVertex| RenderMan::scene_vertex(v).to_string();
        assert_eq!(rm(&v), "TS4'glass'");
        assert_eq!(rm(&SceneVertex::Emissive { group: Some("key") }), "O'key'");
        assert_eq!(rm(&SceneVertex::Camera), "C");
    }
}
