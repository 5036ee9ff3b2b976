#!/usr/bin/env bash
# npm test: the gates (formatting, lints), native tests, the wasm suites in headless Node, the type
# check, the TypeScript unit tests (the features without a browser, on the page's wasm module), then
# the browser end-to-end tests in headless Chromium against a fresh build. The formatting gates come
# first, the quickest first: they fail on what a review would. Clippy lints the crates as the test
# builds compile them (it is the compiler's wrapper there, as `cargo clippy` makes it for a check),
# so the code is analysed once, not once to lint and again to test. On two cores the rest overlaps:
# the page builds while the native tests build and run, and most browser files run while the wasm
# suites and the reproduction report are checked.
set -euo pipefail
cd "$(dirname "$0")/.."
# Each step's header says how long the test has run so far and the CPU seconds its steps have
# used (the finished commands' user and system time, from /proc: no command is started for it),
# so the slow steps show even on a machine whose load makes wall time say little. A step run in the
# background counts its own shell's (cpu_of).
cpu_seconds() {
  local stat
  read -r -a stat < "/proc/${cpu_of:-$$}/stat"
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

# The page (the release wasm: link-time optimisation on one code unit, most of it on one core; then
# the site and the type check) builds in the background from here, while the lints and the native
# tests use the other core. Its output is shown when it is waited for, before the browser tests.
page_log=$(mktemp)
(
  set -e
  cpu_of=$BASHPID
  step "page: the release wasm (scripts/build-wasm.sh)"
  bash scripts/build-wasm.sh
  step "page: vite build, sizes, type check"
  npx --no-install vite build --logLevel warn
  node scripts/sizes.mjs
  npx --no-install tsc --noEmit -p .
  step "page: built"
) >"$page_log" 2>&1 &
page_build=$!
browser_log=$(mktemp)
browser_tests=
trap 'kill $page_build $browser_tests 2>/dev/null || true; rm -f "$page_log" "$browser_log"' EXIT

# `cargo clippy -- -D warnings` runs clippy-driver as the workspace crates' compiler with these
# arguments; the test builds below do the same, so every target clippy would check (--all-targets)
# is linted while it is built, and the run after builds nothing again.
lint=(env RUSTC_WORKSPACE_WRAPPER=clippy-driver CLIPPY_ARGS=-D__CLIPPY_HACKERY__warnings__CLIPPY_HACKERY__)

step "native tests, clippy -D warnings as they build (cargo test)"
"${lint[@]}" cargo test --workspace --all-targets --no-run --quiet
"${lint[@]}" cargo test --workspace --quiet

# The command line in the quick profile (the release build without link-time optimisation: the
# same results, built in a fraction of the time); the browser tests call it too.
step "the JSON Schemas in docs/schema are current (kumiki schema --check)"
cargo run --profile quick --quiet -p kumiki-cli -- schema --check

step "the Python package and the docs' notebook (scripts/test-python.sh)"
bash scripts/test-python.sh

step "the page (waiting for its build)"
if ! wait "$page_build"; then
  cat "$page_log" >&2
  echo "the page's build failed" >&2
  exit 1
fi
cat "$page_log"

# The features' unit tests run the page's wasm module (web/pkg), built with the page.
step "TypeScript unit tests (vitest, tests/unit/)"
npx --no-install vitest run

# The browser files that measure time or the browser's memory (the main thread's stalls, the time
# to answer a hostile link, every Chromium process's memory) run alone, at the end; the others,
# each with its own server and browser, start now and run three at a time while the wasm suites and
# the reproduction report are checked: most of their time is waiting for frames and the worker.
alone=(tests/e2e/opening.test.mjs tests/e2e/page.test.mjs tests/e2e/safety.test.mjs)
together=()
for f in tests/e2e/*.test.mjs; do
  [[ " ${alone[*]} " == *" $f "* ]] || together+=("$f")
done
step "browser tests (headless Chromium), in the background: ${#together[@]} files"
node --test --test-concurrency=3 "${together[@]}" >"$browser_log" 2>&1 &
browser_tests=$!

step "wasm tests (wasm-bindgen-test in headless Node), clippy -D warnings (wasm32) as they build"
"${lint[@]}" cargo test -p kumiki-wasm -p kumiki-lab --target wasm32-unknown-unknown --all-targets --no-run --quiet
# Not --quiet: cargo would pass it on to wasm-bindgen-test-runner, which refuses it.
"${lint[@]}" CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUNNER=wasm-bindgen-test-runner \
  cargo test -p kumiki-wasm -p kumiki-lab --target wasm32-unknown-unknown

step "the reproduction report is current (kumiki reproduce --check)"
cargo run --profile quick --quiet -p kumiki-cli -- reproduce --check

step "browser tests (waiting for the background files)"
if ! wait "$browser_tests"; then
  cat "$browser_log"
  echo "browser tests failed" >&2
  exit 1
fi
cat "$browser_log"

step "browser tests that measure time or memory, alone"
node --test --test-concurrency=1 "${alone[@]}"
printf '\nnpm test: passed in %d s (%s CPU s)\n' "$SECONDS" "$(cpu_seconds)"
