#!/usr/bin/env bash
# Installs what is missing, builds Release and runs every test through ctest, then the
# sanitizer and fuzzing stage (ASan+UBSan unit tests, a short bounded run of every libFuzzer
# harness: scripts/ci_sanitize_fuzz.sh; SKIP_SANITIZE=1 leaves it out for a quick local run).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh --fuzz
bash scripts/build.sh
(cd "${BUILD_DIR:-build}" && ctest --output-on-failure --parallel "$(nproc)" --timeout 900)
# Fuzzing in CI is off by default (CI_FUZZ_SECONDS=0) until a whole stage with it has run green
# on a fresh clone: the first run found UB in fuzz_checkpoint that a detection bug in fuzz.sh hid
# (both fixed, the fuzz stage not yet re-run). The sanitized unit tests run.
if [[ "${SKIP_SANITIZE:-0}" != 1 ]]; then
  CI_FUZZ_SECONDS=${CI_FUZZ_SECONDS:-0} bash scripts/ci_sanitize_fuzz.sh
fi
