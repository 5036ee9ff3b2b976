#!/usr/bin/env bash
# npm test: the gates (formatting, lints), the TypeScript unit tests, native tests, the wasm suites
# in headless Node, the type check, then the browser end-to-end tests in headless Chromium against
# a fresh build. The gates come first: they take seconds and fail on what a review would.
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

step "gate: cargo clippy -D warnings (native)"
cargo clippy --workspace --all-targets --quiet -- -D warnings

step "setup"
bash scripts/setup.sh --browser

step "gate: cargo clippy -D warnings (wasm32)"
cargo clippy -p kumiki-wasm -p kumiki-lab --target wasm32-unknown-unknown --all-targets --quiet -- -D warnings

step "gate: biome lint (web/, tests/, scripts/)"
npx --no-install biome lint --error-on-warnings

step "gate: biome format --check (web/, tests/, scripts/)"
npx --no-install biome format .

step "TypeScript unit tests (vitest, tests/unit/)"
npx --no-install vitest run

step "native tests (cargo test)"
cargo test --workspace --quiet

step "wasm tests (wasm-bindgen-test in headless Node)"
# Not --quiet: cargo would pass it on to wasm-bindgen-test-runner, which refuses it.
CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUNNER=wasm-bindgen-test-runner \
  cargo test -p kumiki-wasm -p kumiki-lab --target wasm32-unknown-unknown

step "the JSON Schemas in docs/schema are current (kumiki schema --check)"
cargo run --release --quiet -p kumiki-cli -- schema --check

step "the reproduction report is current (kumiki reproduce --check)"
cargo run --release --quiet -p kumiki-cli -- reproduce --check

step "build and type check"
bash scripts/build.sh
npx --no-install tsc --noEmit -p .

step "browser tests (headless Chromium)"
# The files that measure time or the browser's memory (the main thread's stalls, the time to
# answer a hostile link, every Chromium process's memory) run alone, after the rest; the others,
# each with its own server and browser, run two at a time.
alone=(tests/e2e/opening.test.mjs tests/e2e/page.test.mjs tests/e2e/safety.test.mjs)
together=()
for f in tests/e2e/*.test.mjs; do
  [[ " ${alone[*]} " == *" $f "* ]] || together+=("$f")
done
node --test --test-concurrency=2 "${together[@]}"
node --test --test-concurrency=1 "${alone[@]}"
printf '\nnpm test: passed in %d s (%s CPU s)\n' "$SECONDS" "$(cpu_seconds)"
