#!/usr/bin/env bash
# npm run reproduce: runs every model's paper experiments on every core and writes the
# reproduction report, docs/reproduction.md and docs/reproduction.json. Commit both.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo run --release --quiet -p kumiki-cli -- reproduce "$@"
