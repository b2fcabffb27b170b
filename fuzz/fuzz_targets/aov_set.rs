//! Fuzz target `aov_set`: the property is `lpe_engines::fuzzing::aov_set` (see its docs), which
//! `cargo test` also runs on every committed corpus and regression file.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| lpe_engines::fuzzing::aov_set(data));
