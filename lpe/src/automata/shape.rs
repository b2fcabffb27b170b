//! Path shapes: small DFAs over vertex places (camera, scatter, emitter) that the
//! searches run in product with, so that they only visit sequences of the wanted shape.

pub(crate) const NONE: u8 = u8::MAX;

/// `next[state][group]` and which states accept; state 0 is the start.
pub(crate) struct Shape {
    pub(crate) next: [[u8; 3]; 3],
    pub(crate) accept: [bool; 3],
}

/// Any non-empty sequence.
pub(crate) const ANY: Shape = Shape {
    next: [[1, 1, 1], [1, 1, 1], [NONE; 3]],
    accept: [false, true, false],
};
/// Starts with the camera.
pub(crate) const FROM_CAMERA: Shape = Shape {
    next: [[1, NONE, NONE], [1, 1, 1], [NONE; 3]],
    accept: [false, true, false],
};
/// Starts with the camera, ends with an emitter, anything between.
pub(crate) const CAMERA_TO_EMITTER: Shape = Shape {
    next: [[1, NONE, NONE], [1, 1, 2], [1, 1, 2]],
    accept: [false, false, true],
};
/// A path: `C`, `R`/`T` vertices, one emitter.
pub(crate) const PATH: Shape = Shape {
    next: [[1, NONE, NONE], [NONE, 1, 2], [NONE; 3]],
    accept: [false, false, true],
};

impl crate::automata::ir::PathShape {
    /// The shape's automaton over places.
    pub(crate) fn automaton(self) -> &'static Shape {
        match self {
            crate::automata::ir::PathShape::CameraScattersEmitter => &PATH,
            crate::automata::ir::PathShape::Any => &ANY,
        }
    }
}
