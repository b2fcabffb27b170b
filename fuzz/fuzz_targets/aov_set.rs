//! Fuzz target `aov_set`: the property is `engines::fuzzing::aov_set` (see its docs), which
//! `cargo test` also runs on every committed corpus and regression file.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| engines::fuzzing::aov_set(data));
