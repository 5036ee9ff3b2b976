#!/usr/bin/env bash
# Builds the two wasm packages into web/pkg/: the page's module, kumiki_wasm{.js,_bg.wasm} (what
# the page needs to open: runs, the view, the scenario in view, links, presets, lessons), and the
# lab module, kumiki_lab{.js,_bg.wasm} (experiments, the report's claims, grading), which the page
# loads only when it needs it. One cargo build, so the crates both use compile once; release
# mode, then wasm-bindgen --target web, then wasm-opt when npm's binaryen is installed.
set -euo pipefail
cd "$(dirname "$0")/.."

cargo build -p kumiki-wasm -p kumiki-lab --target wasm32-unknown-unknown --release --quiet
for name in kumiki_wasm kumiki_lab; do
  wasm-bindgen --target web --out-dir web/pkg "target/wasm32-unknown-unknown/release/$name.wasm"
  if [ -x node_modules/.bin/wasm-opt ]; then
    node_modules/.bin/wasm-opt -O3 --enable-bulk-memory --enable-nontrapping-float-to-int \
      --enable-sign-ext --enable-mutable-globals --enable-reference-types --enable-multivalue --enable-simd \
      "web/pkg/${name}_bg.wasm" -o "web/pkg/${name}_bg.wasm"
  fi
  echo "wasm: web/pkg/${name}_bg.wasm ($(wc -c < "web/pkg/${name}_bg.wasm") bytes)"
done
