#!/bin/bash -eu
# Builds every cargo-fuzz target and ships it with its seed corpus and dictionary.
cd "$SRC/lpe"
cargo fuzz build -O --debug-assertions
for target in parse path_text differential aov_set; do
  cp "fuzz/target/x86_64-unknown-linux-gnu/release/$target" "$OUT/"
  (cd "fuzz/corpus/$target" && zip -q -r "$OUT/${target}_seed_corpus.zip" .)
  cp fuzz/lpe.dict "$OUT/$target.dict"
done
