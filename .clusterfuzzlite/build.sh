#!/bin/bash -eu
# Builds every cargo-fuzz target and ships it with its seed corpus and dictionary.
# Coverage is scoped to this repository's crates, without comparison tracing
# (fuzz/sancov-scope); the sanitizer covers every crate.
cd "$SRC/lpe"
export RUSTC_WRAPPER="$SRC/lpe/fuzz/sancov-scope"
export RUSTFLAGS="${RUSTFLAGS:-} --cfg=sancov_scope_edges"
cargo fuzz build -O --debug-assertions
for target in parse path_text differential aov_set osl_parse osl_differential; do
  cp "fuzz/target/x86_64-unknown-linux-gnu/release/$target" "$OUT/"
  (cd "fuzz/corpus/$target" && zip -q -r "$OUT/${target}_seed_corpus.zip" .)
  cp fuzz/lpe.dict "$OUT/$target.dict"
done
