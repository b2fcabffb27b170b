//! Empty: a build script makes cargo build the build-dependencies this crate unifies.
fn main() {}
