#!/usr/bin/env bash
# CI's sanitizer and fuzzing stage (called by scripts/run_tests.sh after ctest): one clang build
# with AddressSanitizer + UndefinedBehaviorSanitizer (fuzz/CMakeLists.txt) gives
#   1. demcal_sanitized_tests: the fast parser, checkpoint and core unit tests ([unit], not
#      [slow]) under the sanitizers; any report fails (UBSan without recovery, ASan aborts);
#   2. every libFuzzer harness, run for CI_FUZZ_SECONDS (default 20) seconds each from its seed
#      corpus; a crash, leak, timeout or out-of-memory fails (scripts/fuzz.sh).
# Budget (measured on a fresh clone, 2 cores; README "Reliability"): the build dominates.
#   CI_FUZZ_SECONDS=0 bash scripts/ci_sanitize_fuzz.sh   # sanitized tests only
set -euo pipefail
cd "$(dirname "$0")/.."
build=${FUZZ_BUILD_DIR:-build-fuzz}
seconds=${CI_FUZZ_SECONDS:-20}
bash scripts/install_deps.sh --fuzz
start=$(date +%s)
CXX=clang++-14 cmake -S fuzz -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
harnesses=(fuzz_stl fuzz_json_document fuzz_scene_json fuzz_experiment_json fuzz_measurement_table
           fuzz_study fuzz_journal fuzz_workflow fuzz_checkpoint)
cmake --build "$build" --parallel "${BUILD_JOBS:-$(nproc)}" --target demcal_sanitized_tests \
  "${harnesses[@]}"
echo "sanitize: build $(($(date +%s) - start)) s"
start=$(date +%s)
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  "$build/demcal_sanitized_tests" "[unit]~[slow]" --durations no
echo "sanitize: tests $(($(date +%s) - start)) s"
if [[ -n "${CI_FUZZ_DEADLINE:-}" ]]; then
  # ~2 s per harness besides its fuzzing time (8 x 20 s took 171 s on 2 cores).
  fit=$(( (CI_FUZZ_DEADLINE - $(date +%s)) / ${#harnesses[@]} - 2 ))
  if ((fit < seconds)); then
    echo "fuzz: ${fit} s per harness left of the CI budget (asked ${seconds} s)"
    seconds=$fit
  fi
  if ((seconds < 2)); then
    echo "fuzz: skipped: the CI budget is used up (run scripts/fuzz.sh for a fuzzing run)"
    seconds=0
  fi
fi
if ((seconds > 0)); then
  start=$(date +%s)
  FUZZ_SECONDS=$seconds FUZZ_BUILD_DIR=$build bash scripts/fuzz.sh "${harnesses[@]}"
  echo "fuzz: ${#harnesses[@]} harnesses x $seconds s in $(($(date +%s) - start)) s"
fi
