//! Test support shared by the workspace's test suites, runners and tools.
//!
//! - [`suite`]: the conformance suite's loader: the case format of
//!   `tests/testdata/**/*.toml` (both dialects, `tests/testdata/README.md`), file
//!   discovery, validation with errors naming the file and the case, and the flat views
//!   every runner checks ([`suite::Plan`], [`suite::Row`]). The runners themselves live
//!   with what they run: the engines and `AovSet` in `lpe-tests`, the C ABI in
//!   `lpe-capi`'s tests, the renderer's matcher in `lpe-render`'s, external matchers in
//!   `lpe-check diff --external CMD --suite DIR`.
//! - [`generate`]: random expressions, AOV sets and paths aimed at them, from any
//!   source of choices (lpe's `SplitMix64`, or fuzz input through `arbitrary`), one
//!   file per dialect ([`generate::renderman`], [`generate::osl`]); the differential
//!   harness (`lpe-check diff`) and the fuzz bodies (`lpe_engines::fuzzing`) draw their
//!   cases here.
//! - [`grammar`]: expression *text* from each dialect's documented grammar, with a
//!   count of the productions written (`lpe-check diff --coverage`).
//! - [`host`]: what tests need of the host (`python3`), a failure naming it when missing.
//! - [`labels`]: labels one byte apart at every position and length, UTF-8 included.
//! - `strategy` (feature `proptest`): proptest strategies for the same shapes.

#![forbid(unsafe_code)]

pub mod generate;
pub mod grammar;
pub mod host;
pub mod labels;
#[cfg(feature = "proptest")]
pub mod strategy;
pub mod suite;
