#!/usr/bin/env bash
# Builds the test suite with clang, AddressSanitizer and UndefinedBehaviorSanitizer into
# ${SANITIZE_BUILD_DIR:-build-asan} and runs the fast tests (Catch2 tag [unit] by default, or the
# filter given) and the hostile-input corpus through the sanitized demcal. Any sanitizer report
# fails the run (UBSan without recovery, ASan aborting on the first error).
#   bash scripts/sanitize.sh              # [unit] tests + bad_inputs
#   bash scripts/sanitize.sh "[unit]~[slow]"
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SANITIZE_BUILD_DIR:-build-asan}
filter=${1:-[unit]}
command -v clang++-14 >/dev/null || bash scripts/install_deps.sh --fuzz
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
CXX=clang++-14 cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build "$build" --parallel "${BUILD_JOBS:-2}" --target demcal demcal_tests
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1
"$build/tests/demcal_tests" "$filter"
(cd "$build" && ctest -L bad_inputs -j "${BUILD_JOBS:-2}" --output-on-failure)
