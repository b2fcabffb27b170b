//! Fuzz target `osl_parse`: the property is `lpe_engines::fuzzing::osl_parse` (see its docs), which
//! `cargo test` also runs on every committed corpus and regression file.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| lpe_engines::fuzzing::osl_parse(data));
