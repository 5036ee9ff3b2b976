#!/usr/bin/env bash
# Installs whatever is missing, and nothing that is already there:
#   - the wasm32-unknown-unknown Rust target (rustup),
#   - the wasm-bindgen CLI at exactly the version Cargo.toml pins,
#   - the npm packages (npm ci, when node_modules is missing or older than package-lock.json),
#   - with --browser: Debian's chromium for the browser tests (installed when running as root);
#   - with --python: the project's virtual environment .venv with python/requirements-dev.txt
#     from PyPI (the Python package's build backend, pandas, pytest, SciPy, nbconvert).
set -euo pipefail
cd "$(dirname "$0")/.."

say() { printf '\033[1msetup:\033[0m %s\n' "$*"; }
fail() { printf '\033[1;31msetup:\033[0m %s\n' "$*" >&2; exit 1; }

want_browser=0
[ "${1:-}" = "--browser" ] && want_browser=1
want_python=0
[ "${1:-}" = "--python" ] && want_python=1

command -v cargo >/dev/null || fail "Rust is not installed. Install it from https://rustup.rs and run this again."
command -v node >/dev/null || fail "Node.js 20 or newer is needed (https://nodejs.org)."
node_major=$(node -p 'process.versions.node.split(".")[0]')
[ "$node_major" -ge 20 ] || fail "Node.js 20 or newer is needed; this is $(node --version)."

if command -v rustup >/dev/null; then
  if ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
    say "adding the wasm32-unknown-unknown target"
    rustup target add wasm32-unknown-unknown
  fi
else
  rustc --print target-list | grep -qx wasm32-unknown-unknown \
    || fail "the wasm32-unknown-unknown target is missing and rustup is not available to add it."
fi

pinned=$(sed -n 's/^wasm-bindgen = "=\([0-9.]*\)".*/\1/p' Cargo.toml)
[ -n "$pinned" ] || fail "could not read the pinned wasm-bindgen version from Cargo.toml"
installed=$(wasm-bindgen --version 2>/dev/null | awk '{print $2}' || true)
if [ "$installed" != "$pinned" ]; then
  say "installing wasm-bindgen-cli $pinned (a few minutes, once)"
  # Not --locked: the registry copy of the CLI names a lock file version that is not published.
  cargo install wasm-bindgen-cli --version "$pinned" --quiet
fi

if [ ! -d node_modules ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
  say "installing npm packages"
  npm ci --no-audit --no-fund --loglevel=error
fi

if [ "$want_browser" = 1 ]; then
  chromium_bin="${KUMIKI_CHROMIUM:-/usr/bin/chromium}"
  if [ ! -x "$chromium_bin" ]; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
      say "installing Debian's chromium for the browser tests"
      apt-get update -qq
      DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium >/dev/null
    else
      fail "the browser tests need Chromium at $chromium_bin. Install it (Debian/Ubuntu: 'sudo apt-get install chromium') or point KUMIKI_CHROMIUM at a Chromium binary, then run 'npm test' again."
    fi
  fi
fi

if [ "$want_python" = 1 ]; then
  command -v python3 >/dev/null || fail "Python 3.9 or newer is needed for the Python package (https://www.python.org)."
  if [ ! -x .venv/bin/python ]; then
    say "creating the virtual environment .venv"
    python3 -m venv .venv || fail "python3 -m venv failed; on Debian/Ubuntu install python3-venv."
  fi
  # Installed once, again when the list is newer than the last install.
  if [ ! -f .venv/.requirements-dev ] || [ python/requirements-dev.txt -nt .venv/.requirements-dev ]; then
    say "installing python/requirements-dev.txt into .venv"
    .venv/bin/python -m pip install --quiet --disable-pip-version-check -r python/requirements-dev.txt
    touch .venv/.requirements-dev
  fi
fi
