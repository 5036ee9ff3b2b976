#!/usr/bin/env bash
# npm run quick: the inner loop, in a few minutes. The gates (rustfmt, Biome, the type check), the
# TypeScript unit tests (the features without a browser), and clippy and the tests of the crates
# changed since the branch left main (committed or not), with the crates that depend on them where
# a change reaches the contract or the core. npm test runs all of it and the browser tests.
#
# KUMIKI_QUICK_BASE names another commit to compare with. The unit tests need the page's wasm
# module (web/pkg, with the catalogue it writes): a checkout without them builds them once
# (scripts/build-wasm.sh, minutes).
set -euo pipefail
cd "$(dirname "$0")/.."
step() { printf '\n\033[1m== %s ==\033[0m (at %d s)\n' "$*" "$SECONDS"; }

base=${KUMIKI_QUICK_BASE:-$(git merge-base HEAD main 2>/dev/null || git rev-parse HEAD)}
changed=$( (git diff --name-only "$base"; git ls-files --others --exclude-standard) | sort -u)

# The packages whose sources changed: a crate's own folder, or the test files it names.
packages=()
add() { [[ " ${packages[*]-} " == *" $1 "* ]] || packages+=("$1"); }
while read -r path; do
  case "$path" in
    crate/models/*/*) add "kumiki-$(cut -d/ -f3 <<<"$path")" ;;
    crate/*/*) add "$(sed -n 's/^name = "\(.*\)"/\1/p' "crate/$(cut -d/ -f2 <<<"$path")/Cargo.toml" | head -1)" ;;
    tests/native/*|tests/fixtures/*) add kumiki-core ;;
    tests/wasm/*) add kumiki-wasm ;;
  esac
done <<<"$changed"
# A change of the contract or the core is checked where it is used: the core's own tests read every
# model, and the view reads the contract.
if [[ " ${packages[*]-} " == *" kumiki-model "* ]]; then add kumiki-core; add kumiki-view; fi
native=()
for p in "${packages[@]-}"; do
  [ -n "$p" ] && [ "$p" != kumiki-wasm ] && [ "$p" != kumiki-lab ] && native+=(-p "$p")
done

step "gates: cargo fmt --check, biome (lint and format), tsc"
cargo fmt --all -- --check
npx --no-install biome check --error-on-warnings .
# The type check keeps what it learnt between runs (npm test checks from nothing).
npx --no-install tsc --noEmit -p . --incremental --tsBuildInfoFile node_modules/.cache/kumiki-quick.tsbuildinfo

if [ ! -f web/pkg/kumiki_wasm_bg.wasm ] || [ ! -f web/pkg/catalog.json ]; then
  step "the page's wasm module, once (scripts/build-wasm.sh)"
  bash scripts/build-wasm.sh
fi
step "TypeScript unit tests (vitest)"
npx --no-install vitest run

if [ ${#native[@]} -gt 0 ]; then
  step "clippy and tests of the changed crates:${native[*]//-p/}"
  cargo clippy "${native[@]}" --all-targets --quiet -- -D warnings
  cargo test "${native[@]}" --quiet
else
  step "no crate changed since $(git rev-parse --short "$base")"
fi
if [[ " ${packages[*]-} " == *" kumiki-wasm "* || " ${packages[*]-} " == *" kumiki-lab "* ]]; then
  step "clippy of the wasm glue (wasm32); its wasm tests are npm test's"
  cargo clippy -p kumiki-wasm -p kumiki-lab --target wasm32-unknown-unknown --all-targets --quiet -- -D warnings
fi
printf '\nnpm run quick: passed in %d s\n' "$SECONDS"
