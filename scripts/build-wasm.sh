#!/usr/bin/env bash
# Builds the three wasm packages into web/pkg/: the page's module, kumiki_wasm{.js,_bg.wasm} (what
# the page needs to open: runs, the view, the scenario in view, links; without the built-in
# scenarios and lessons, which scripts/catalog.mjs writes as JSON for the page to fetch when it
# needs them: --no-default-features leaves out crate/wasm's `catalog`); the same module with the
# built-in scenarios and the rule scripts' engine, kumiki_wasm_rules{.js,_bg.wasm}, which the page loads only
# for a scenario that carries rules (docs/rules.md); and the lab module, kumiki_lab{.js,_bg.wasm}
# (experiments, the report's claims, grading, with the engine), which the page loads only when it
# needs it. Two cargo builds: the page's module alone, without the engine, then the rules module
# and the lab together, so the crates they both use compile once with it; release mode, then
# wasm-bindgen --target web, then wasm-opt when npm's binaryen is installed.
set -euo pipefail
cd "$(dirname "$0")/.."

# wasm-bindgen, then wasm-opt, of target/.../$1.wasm into web/pkg/$2{.js,_bg.wasm}.
package() {
  wasm-bindgen --target web --out-dir web/pkg --out-name "$2" "target/wasm32-unknown-unknown/release/$1.wasm"
  if [ -x node_modules/.bin/wasm-opt ]; then
    node_modules/.bin/wasm-opt -O3 --enable-bulk-memory --enable-nontrapping-float-to-int \
      --enable-sign-ext --enable-mutable-globals --enable-reference-types --enable-multivalue --enable-simd \
      "web/pkg/$2_bg.wasm" -o "web/pkg/$2_bg.wasm"
  fi
  echo "wasm: web/pkg/$2_bg.wasm ($(wc -c < "web/pkg/$2_bg.wasm") bytes)"
}

cargo build -p kumiki-wasm --no-default-features --target wasm32-unknown-unknown --release --quiet
package kumiki_wasm kumiki_wasm
cargo build -p kumiki-wasm -p kumiki-lab --features kumiki-wasm/rules --target wasm32-unknown-unknown --release --quiet
package kumiki_wasm kumiki_wasm_rules
package kumiki_lab kumiki_lab
node scripts/catalog.mjs
