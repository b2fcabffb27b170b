//! Fuzz target `differential`: the property is the body `lpe_engines::fuzzing::target("differential")`
//! names (see `lpe_engines::fuzzing`), which `cargo test` also runs on every committed
//! corpus and regression file.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| lpe_engines::fuzzing::run("differential", data));
