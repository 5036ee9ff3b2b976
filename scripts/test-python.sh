#!/usr/bin/env bash
# npm test's Python step: the package built from this checkout (pip install ./python, in the quick
# profile, so it shares the CLI's build of the core in target/quick) into the project's .venv, its
# tests against the CLI, then the docs' notebook executed headless. Needs target/quick/kumiki.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --python
# The build backend's maturin is found on the PATH.
export PATH="$PWD/.venv/bin:$PATH"
.venv/bin/python -m pip install --quiet --disable-pip-version-check --no-deps --no-build-isolation \
  --force-reinstall ./python
export KUMIKI_CLI="$PWD/target/quick/kumiki"
.venv/bin/python -m pytest -q python/tests
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
.venv/bin/jupyter nbconvert --to notebook --execute docs/reproduce-a-figure.ipynb --output-dir "$out"
