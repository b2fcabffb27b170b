//! Classification by interned label ids: a RenderMan set's hot path at scene load and
//! in the C ABI. A renderer interns each label of its scene once
//! ([`AovSet::label_id`]); classifying a vertex is then index arithmetic and table
//! loads, no hashing ([`AovSet::classify_interned`]).

use super::path::{Event, VertexType};
use super::RenderMan;
use crate::aov::AovSet;
use crate::automata::mask::{Class, LabelId};

impl AovSet<RenderMan> {
    /// The id of a vertex label (or of no label) for [`AovSet::classify_interned`]:
    /// intern each label of a scene once, at load. Labels no expression mentions all
    /// get one id.
    pub fn label_id(&self, label: Option<&str>) -> LabelId {
        self.classes().label_id(label)
    }

    /// The class of a vertex given by its parts and an interned label: index arithmetic
    /// and table loads, no hashing. Same answer as [`AovSet::classify`] on the vertex. An
    /// event on `C`, `L` or `O` is ignored; `R`/`T` without an event or a label id of
    /// another set give some class, never a panic.
    #[inline]
    pub fn classify_interned(&self, ty: VertexType, event: Option<Event>, label: LabelId) -> Class {
        self.classes().classify_interned(ty, event, label)
    }
}
