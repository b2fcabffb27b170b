//! include/lpe.h is what cbindgen generates from the crate today: a stale header fails
//! here. `LPE_BLESS=1 cargo test -p lpe-capi --test header` rewrites it.

use std::path::PathBuf;

#[test]
fn the_checked_in_header_is_current() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(dir.join("cbindgen.toml")).expect("cbindgen.toml");
    let mut generated = Vec::new();
    cbindgen::Builder::new()
        .with_crate(&dir)
        .with_config(config)
        .generate()
        .expect("cbindgen understands the crate")
        .write(&mut generated);
    let generated = String::from_utf8(generated).expect("UTF-8 header");
    let path = dir.join("include/lpe.h");
    if std::env::var_os("LPE_BLESS").is_some() {
        std::fs::write(&path, &generated).expect("write the header");
    }
    let checked_in = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        checked_in == generated,
        "capi/include/lpe.h is stale: run `LPE_BLESS=1 cargo test -p lpe-capi --test header` \
         and commit it"
    );
    // What C and C++ callers rely on.
    for needle in [
        "#ifdef __cplusplus",
        "extern \"C\" {",
        "lpe_step(",
        "#include <stdint.h>",
        // A state is one register-sized value.
        "uint32_t opaque;\n} lpe_state;",
        "lpe_classify_symbols(",
        "const char *osl_registered;",
        // The inline step, under a guard of its own (it follows LPE_H's #endif).
        "#ifndef LPE_H_INLINE",
        "static inline lpe_status lpe_view_step(",
        "static inline lpe_status lpe_view_is_dead(",
    ] {
        assert!(generated.contains(needle), "{needle}");
    }
}
