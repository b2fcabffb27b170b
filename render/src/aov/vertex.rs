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

impl SceneVertex<'_> {
    /// The vertex as the RenderMan dialect sees it.
    pub fn renderman(&self) -> lpe::renderman::Vertex {
        match *self {
            SceneVertex::Camera => lpe::renderman::Vertex::camera(),
            SceneVertex::Scatter {
                side, event, group, ..
            } => lpe::renderman::Vertex::scatter(side, event, group),
            SceneVertex::Light { group } => lpe::renderman::Vertex::light(group),
            SceneVertex::Emissive { group } => lpe::renderman::Vertex::emissive(group),
        }
    }

    /// The vertex as the OSL dialect sees it (see the module docs for the mapping).
    pub fn osl(&self) -> osl::Vertex {
        let (event, scattering, group) = match *self {
            SceneVertex::Camera => ("C", None, None),
            SceneVertex::Scatter {
                side,
                scattering,
                group,
                ..
            } => {
                let event = if side == VertexType::T { "T" } else { "R" };
                (event, Some(scattering.osl_label()), group)
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

/// How a dialect sees the renderer's vertices: the one thing the renderer needs per
/// dialect.
pub trait SceneDialect: Dialect {
    /// The vertex `v` as this dialect sees it.
    fn scene_vertex(v: &SceneVertex) -> Self::Vertex;
}

impl SceneDialect for RenderMan {
    fn scene_vertex(v: &SceneVertex) -> lpe::renderman::Vertex {
        v.renderman()
    }
}

impl SceneDialect for Osl {
    fn scene_vertex(v: &SceneVertex) -> osl::Vertex {
        v.osl()
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
    fn osl_vertices_are_the_documented_ones() {
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
            assert_eq!(v.osl().to_string(), want, "{v:?}");
        }
    }

    #[test]
    fn renderman_vertices_keep_the_lobe_event_and_label() {
        let v = scatter(VertexType::T, Scattering::Delta, Some("glass"));
        assert_eq!(v.renderman().to_string(), "TS4'glass'");
        assert_eq!(
            SceneVertex::Emissive { group: Some("key") }
                .renderman()
                .to_string(),
            "O'key'"
        );
        assert_eq!(SceneVertex::Camera.renderman().to_string(), "C");
    }
}
