#!/usr/bin/env bash
# npm start: installs what is missing, builds the wasm (release) and the page, and serves dist/ on
# http://localhost:8080 with scripts/serve.mjs: the build's precompressed files (.br, .gz) and the
# headers of dist/_headers, as a static host would.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
echo
exec node scripts/serve.mjs --port 8080 --host localhost
