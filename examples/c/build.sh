#!/usr/bin/env bash
# Builds the C examples against the static library of lpe-capi into examples/c/build/,
# checks the header (its inline step included) as C++ too, runs render_loop against its
# expected output, step_view_test (the inline step against lpe_step) and a short
# step_bench (whose rows must reach the same states; its times mean little at this size).
# Usage: examples/c/build.sh   (from anywhere; needs cc and c++)
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release -q -p lpe-capi
mkdir -p examples/c/build
LIB=target/release/liblpe_capi.a
FLAGS=(-std=c99 -O2 -Wall -Wextra -Werror -pedantic -Icapi/include)
cc "${FLAGS[@]}" examples/c/render_loop.c "$LIB" -lpthread -ldl -lm -o examples/c/build/render_loop
cc "${FLAGS[@]}" examples/c/adapter.c "$LIB" -lpthread -ldl -lm -o examples/c/build/adapter
for prog in step_view_test step_bench; do
    cc "${FLAGS[@]}" "examples/c/$prog.c" "$LIB" -lpthread -ldl -lm -o "examples/c/build/$prog"
done
c++ -x c++ -std=c++11 -Wall -Wextra -Werror -fsyntax-only capi/include/lpe.h
examples/c/build/render_loop | diff -u examples/c/render_loop.expected -
examples/c/build/step_view_test
examples/c/build/step_bench 2000 1 > /dev/null
echo "examples/c: render_loop output as expected, inline step agrees with lpe_step; adapter and step_bench built"
