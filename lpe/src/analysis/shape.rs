//! Path shapes: small DFAs over vertex groups (camera, scatter, emitter) that the
//! searches run in product with, so that they only visit sequences of the wanted shape.

pub(super) const NONE: u8 = u8::MAX;

/// `next[state][group]` and which states accept; state 0 is the start.
pub(super) struct Shape {
    pub(super) next: [[u8; 3]; 3],
    pub(super) accept: [bool; 3],
}

/// Any non-empty sequence.
pub(super) const ANY: Shape = Shape {
    next: [[1, 1, 1], [1, 1, 1], [NONE; 3]],
    accept: [false, true, false],
};
/// Starts with the camera.
pub(super) const FROM_CAMERA: Shape = Shape {
    next: [[1, NONE, NONE], [1, 1, 1], [NONE; 3]],
    accept: [false, true, false],
};
/// Starts with the camera, ends with an emitter, anything between.
pub(super) const CAMERA_TO_EMITTER: Shape = Shape {
    next: [[1, NONE, NONE], [1, 1, 2], [1, 1, 2]],
    accept: [false, false, true],
};
/// A path: `C`, `R`/`T` vertices, one emitter.
pub(super) const PATH: Shape = Shape {
    next: [[1, NONE, NONE], [NONE, 1, 2], [NONE; 3]],
    accept: [false, false, true],
};
