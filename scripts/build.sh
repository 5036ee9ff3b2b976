#!/usr/bin/env bash
# Builds the static site into dist/ (relative URLs: it works from any sub-path) and prints the
# gzipped sizes of its wasm modules and JavaScript (scripts/sizes.mjs). The first load's budget is
# one number of bytes on the wire before interactive (scripts/budget.mjs), which `npm run bench`
# measures in a browser (scripts/bench-load.mjs).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build-wasm.sh
npx --no-install vite build --logLevel warn
node scripts/sizes.mjs
