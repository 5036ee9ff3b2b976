#!/usr/bin/env bash
# Builds the wasm package the page and the wasm benchmark load: web/pkg/kumiki_wasm{.js,_bg.wasm}.
# Release mode, then wasm-bindgen --target web, then wasm-opt when npm's binaryen is installed.
set -euo pipefail
cd "$(dirname "$0")/.."

cargo build -p kumiki-wasm --target wasm32-unknown-unknown --release --quiet
wasm-bindgen --target web --out-dir web/pkg \
  target/wasm32-unknown-unknown/release/kumiki_wasm.wasm
if [ -x node_modules/.bin/wasm-opt ]; then
  node_modules/.bin/wasm-opt -O3 --enable-bulk-memory --enable-nontrapping-float-to-int \
    --enable-sign-ext --enable-mutable-globals --enable-reference-types --enable-multivalue --enable-simd \
    web/pkg/kumiki_wasm_bg.wasm -o web/pkg/kumiki_wasm_bg.wasm
fi
echo "wasm: web/pkg/kumiki_wasm_bg.wasm ($(wc -c < web/pkg/kumiki_wasm_bg.wasm) bytes)"
