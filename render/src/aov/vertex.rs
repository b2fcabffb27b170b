//! The vertices `lpe-render` produces, described in the renderer's own terms. Each
//! dialect shows them to its matcher in its own way
//! ([`SceneDialect::scene_vertex`](super::SceneDialect::scene_vertex)); the dialect only
//! decides what the matcher is shown, never what the integrator traces.

use lpe::renderman::{Event, VertexType};

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
        /// The event the lobe map gives the lobe (its lobe number included).
        event: Event,
        /// How the lobe scatters (diffuse, glossy or delta).
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
