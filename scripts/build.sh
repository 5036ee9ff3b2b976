#!/usr/bin/env bash
# Builds the static site into dist/ (relative URLs: it works from any sub-path) and prints the
# gzipped sizes of the two wasm modules (the page's against its budget, and the lab's) and the JavaScript.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build-wasm.sh
npx --no-install vite build --logLevel warn
node scripts/sizes.mjs
