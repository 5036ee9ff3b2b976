#!/usr/bin/env bash
# npm run soak: each model's largest preset for 10^6 steps natively and in wasm (Node), with the
# memory sampled and checked flat (see scripts/soak.mjs). Arguments go to soak.mjs, for example
# `npm run soak -- --model fracta --wasm-steps 100000`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cargo build --release -p kumiki-cli --quiet
bash scripts/build-wasm.sh >/dev/null
node scripts/soak.mjs "$@"
