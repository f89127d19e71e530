#!/usr/bin/env bash
# Installs what is missing, builds Release and runs every test through ctest, then the
# sanitizer and fuzzing stage (ASan+UBSan unit tests, a short bounded run of every libFuzzer
# harness: scripts/ci_sanitize_fuzz.sh; SKIP_SANITIZE=1 leaves it out for a quick local run).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh --fuzz
bash scripts/build.sh
(cd "${BUILD_DIR:-build}" && ctest --output-on-failure --parallel "$(nproc)" --timeout 900)
# Every fuzz harness runs CI_FUZZ_SECONDS (default 10) seconds from its seed corpus: enough to
# replay the corpus and catch a regression on the paths it covers, small enough for CI's 25 min
# (the sanitized build dominates the stage); long runs are scripts/fuzz.sh's job.
if [[ "${SKIP_SANITIZE:-0}" != 1 ]]; then
  CI_FUZZ_SECONDS=${CI_FUZZ_SECONDS:-10} bash scripts/ci_sanitize_fuzz.sh
fi
