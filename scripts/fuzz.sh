#!/usr/bin/env bash
# npm run fuzz: the no-panic properties at length. Every preset's link, edited at random, must
# open and run or be refused with a message; prints how many cases ran and the slowest.
# KUMIKI_FUZZ_CASES sets the count (default 20000; npm test runs 300).
set -euo pipefail
cd "$(dirname "$0")/.."
KUMIKI_FUZZ_CASES="${KUMIKI_FUZZ_CASES:-20000}" \
  cargo test --release -p kumiki-core --test no_panic -- --nocapture
