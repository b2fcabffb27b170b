//! Test support shared by the workspace's test suites, runners and tools.
//!
//! - [`suite`]: the conformance suite's loader: the case format of
//!   `tests/testdata/**/*.toml` (both dialects, `tests/testdata/README.md`), file
//!   discovery, validation with errors naming the file and the case, and the flat views
//!   every runner checks ([`suite::Plan`], [`suite::Row`]). The runners themselves live
//!   with what they run: the engines and `AovSet` in `lpe-tests`, the C ABI in
//!   `lpe-capi`'s tests, the renderer's matcher in `lpe-render`'s, external matchers in
//!   `lpe-check diff --external CMD --suite DIR`.

#![forbid(unsafe_code)]

pub mod suite;
