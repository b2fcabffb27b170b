#!/usr/bin/env bash
# Builds the C examples against the static library of lpe-capi into examples/c/build/,
# checks the header as C++ too, and runs render_loop against its expected output.
# Usage: examples/c/build.sh   (from anywhere; needs cc and c++)
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release -q -p lpe-capi
mkdir -p examples/c/build
LIB=target/release/liblpe_capi.a
FLAGS=(-std=c99 -O2 -Wall -Wextra -Werror -pedantic -Icapi/include)
cc "${FLAGS[@]}" examples/c/render_loop.c "$LIB" -lpthread -ldl -lm -o examples/c/build/render_loop
cc "${FLAGS[@]}" examples/c/adapter.c "$LIB" -lpthread -ldl -lm -o examples/c/build/adapter
c++ -x c++ -std=c++11 -Wall -Wextra -Werror -fsyntax-only capi/include/lpe.h
examples/c/build/render_loop | diff -u examples/c/render_loop.expected -
echo "examples/c: render_loop output as expected; adapter built"
