#!/usr/bin/env bash
# npm run bench: every workload of tests/bench natively and in wasm (Node), the page in headless
# Chromium (load to interactive, in-page run rates), and the gzipped wasm size. Medians; one run.
# Then a short soak (40 000 steps of each model's largest preset, past the page's timeline's
# warm-up, see scripts/soak.mjs; npm run soak runs 10^6).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --browser
cargo build --release -p kumiki-cli --quiet
bash scripts/build.sh >/dev/null
# The bench fails when the wasm is over its budget; the soak still runs first.
status=0
node scripts/bench.mjs "$@" || status=$?
node scripts/soak.mjs --steps 40000
exit "$status"
