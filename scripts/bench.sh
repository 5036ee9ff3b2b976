#!/usr/bin/env bash
# npm run bench: every workload of tests/bench natively and in wasm (Node), the page in headless
# Chromium (the first load, cold, on loopback and on the classroom profile, from npm start's server;
# in-page run rates), and the gzipped wasm size. Medians; one run.
# Then a short soak (40 000 steps of each model's largest preset, past the page's timeline's
# warm-up, see scripts/soak.mjs; npm run soak runs 10^6).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --browser
cargo build --release -p kumiki-cli --quiet
bash scripts/build.sh >/dev/null
# The bench fails when the first load is over its budget (scripts/budget.mjs); the soak still runs first.
status=0
node scripts/bench.mjs "$@" || status=$?
node scripts/soak.mjs --steps 40000
exit "$status"
