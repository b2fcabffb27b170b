//! Fuzz target `differential`: the property is `oracle::fuzzing::differential` (see its docs), which
//! `cargo test` also runs on every committed corpus and regression file.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| oracle::fuzzing::differential(data));
