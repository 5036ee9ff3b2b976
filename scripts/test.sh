#!/usr/bin/env bash
# npm test: the gates (formatting, lints), the TypeScript unit tests, native tests, the wasm suites
# in headless Node, the type check, then the browser end-to-end tests in headless Chromium against
# a fresh build. The gates come first, the quickest first: they fail on what a review would.
set -euo pipefail
cd "$(dirname "$0")/.."
# Each step's header says how long the test has run so far and the CPU seconds its steps have
# used (the finished commands' user and system time, from /proc: no command is started for it),
# so the slow steps show even on a machine whose load makes wall time say little.
cpu_seconds() {
  local stat
  read -r -a stat < /proc/$$/stat
  echo $(((stat[15] + stat[16]) / $(getconf CLK_TCK)))
}
step() { printf '\n\033[1m== %s ==\033[0m (at %d s, %s CPU s)\n' "$*" "$SECONDS" "$(cpu_seconds)"; }

step "gate: no merge-conflict markers in tracked files"
if git grep -nE '^(<{7}|>{7})( |$)' -- . ':!package-lock.json'; then
  echo "merge-conflict markers above" >&2
  exit 1
fi

step "gate: cargo fmt --check"
cargo fmt --all -- --check

step "setup"
bash scripts/setup.sh --browser

step "gate: biome lint (web/, tests/, scripts/)"
npx --no-install biome lint --error-on-warnings

step "gate: biome format --check (web/, tests/, scripts/)"
npx --no-install biome format .

step "gate: cargo clippy -D warnings (native)"
cargo clippy --workspace --all-targets --quiet -- -D warnings

step "gate: cargo clippy -D warnings (wasm32)"
cargo clippy -p kumiki-wasm -p kumiki-lab --target wasm32-unknown-unknown --all-targets --quiet -- -D warnings

# The page's wasm (release: link-time optimisation on one code unit, most of it on one core) builds
# in the background while the tests below compile and run, and is waited for before the page is
# built. Its output is shown then.
wasm_log=$(mktemp)
bash scripts/build-wasm.sh >"$wasm_log" 2>&1 &
wasm_build=$!
trap 'kill "$wasm_build" 2>/dev/null || true; rm -f "$wasm_log"' EXIT

step "TypeScript unit tests (vitest, tests/unit/)"
npx --no-install vitest run

step "native tests (cargo test)"
cargo test --workspace --quiet

step "wasm tests (wasm-bindgen-test in headless Node)"
# Not --quiet: cargo would pass it on to wasm-bindgen-test-runner, which refuses it.
CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUNNER=wasm-bindgen-test-runner \
  cargo test -p kumiki-wasm -p kumiki-lab --target wasm32-unknown-unknown

# The command line in the quick profile (the release build without link-time optimisation: the
# same results, built in a fraction of the time); the browser tests call it too.
step "the JSON Schemas in docs/schema are current (kumiki schema --check)"
cargo run --profile quick --quiet -p kumiki-cli -- schema --check

step "the reproduction report is current (kumiki reproduce --check)"
cargo run --profile quick --quiet -p kumiki-cli -- reproduce --check

step "build and type check"
if ! wait "$wasm_build"; then
  cat "$wasm_log" >&2
  echo "the wasm build failed" >&2
  exit 1
fi
cat "$wasm_log"
npx --no-install vite build --logLevel warn
node scripts/sizes.mjs
npx --no-install tsc --noEmit -p .

step "browser tests (headless Chromium)"
# The files that measure time or the browser's memory (the main thread's stalls, the time to
# answer a hostile link, every Chromium process's memory) run alone, after the rest; the others,
# each with its own server and browser, run three at a time: most of their time is waiting for
# frames and the worker, not computing.
alone=(tests/e2e/opening.test.mjs tests/e2e/page.test.mjs tests/e2e/safety.test.mjs)
together=()
for f in tests/e2e/*.test.mjs; do
  [[ " ${alone[*]} " == *" $f "* ]] || together+=("$f")
done
node --test --test-concurrency=3 "${together[@]}"
node --test --test-concurrency=1 "${alone[@]}"
printf '\nnpm test: passed in %d s (%s CPU s)\n' "$SECONDS" "$(cpu_seconds)"
