#!/usr/bin/env bash
# Installs what is missing, builds Release and runs every test through ctest, then the
# sanitizer and fuzzing stage (ASan+UBSan unit tests, a short bounded run of every libFuzzer
# harness: scripts/ci_sanitize_fuzz.sh; SKIP_SANITIZE=1 leaves it out for a quick local run).
set -euo pipefail
cd "$(dirname "$0")/.."
started=$(date +%s)
bash scripts/install_deps.sh --fuzz
bash scripts/build.sh
(cd "${BUILD_DIR:-build}" && ctest --output-on-failure --parallel "$(nproc)" --timeout 900)
# Every fuzz harness runs CI_FUZZ_SECONDS (default 10) seconds from its seed corpus: enough to
# replay the corpus and catch a regression on the paths it covers; long runs are scripts/fuzz.sh's
# job. CI must finish within 25 min on 2 cores and the builds already take most of it (24.7 min
# without fuzzing at the last landing), so fuzzing gets only what is left of CI_BUDGET_S (default
# 1440 s = 24 min, one minute of margin) after the sanitized tests, and is skipped, saying so, when
# that is under 2 s per harness.
if [[ "${SKIP_SANITIZE:-0}" != 1 ]]; then
  CI_FUZZ_DEADLINE=$((started + ${CI_BUDGET_S:-1440})) CI_FUZZ_SECONDS=${CI_FUZZ_SECONDS:-10} \
    bash scripts/ci_sanitize_fuzz.sh
fi
