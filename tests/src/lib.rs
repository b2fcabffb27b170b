//! Cross-crate property tests and conformance vectors live in `tests/`.
