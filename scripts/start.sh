#!/usr/bin/env bash
# npm start: installs what is missing, builds the wasm (release) and the page, and serves it on
# http://localhost:8080.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
echo
echo "Kumiki is running at http://localhost:8080/  (Ctrl+C to stop)"
exec npx --no-install vite preview --port 8080 --strictPort --host localhost --logLevel warn
