#!/usr/bin/env bash
# Builds the libFuzzer harnesses (fuzz/, clang + ASan + UBSan) into ${FUZZ_BUILD_DIR:-build-fuzz}
# and runs each for FUZZ_SECONDS (default 600) seconds, starting from the corpus in
# fuzz/corpus/NAME (seeded from examples/, tests/bad_inputs/ and tests/data/). A crash leaves
# crash-* in build-fuzz/ and fails the script. Usage:
#   bash scripts/fuzz.sh                       # every harness, 10 minutes each
#   FUZZ_SECONDS=30 bash scripts/fuzz.sh fuzz_stl fuzz_json_document
#   FUZZ_RUNS=1000000 FUZZ_SECONDS=3600 bash scripts/fuzz.sh   # 10^6 inputs each (at most 1 h)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${FUZZ_BUILD_DIR:-build-fuzz}
seconds=${FUZZ_SECONDS:-600}
jobs=${FUZZ_JOBS:-1}
runs=()      # FUZZ_RUNS: stop each harness after this many inputs (or at FUZZ_SECONDS)
[[ -n "${FUZZ_RUNS:-}" ]] && runs=(-runs="$FUZZ_RUNS")
parallel=()  # one job runs in this process (its statistics printed here)
((jobs > 1)) && parallel=(-jobs="$jobs" -workers="$jobs")
harnesses=("$@")
((${#harnesses[@]})) ||
  harnesses=(fuzz_stl fuzz_json_document fuzz_scene_json fuzz_experiment_json fuzz_measurement_table
             fuzz_study fuzz_journal fuzz_workflow fuzz_checkpoint)
command -v clang++-14 >/dev/null || bash scripts/install_deps.sh --fuzz
CXX=clang++-14 cmake -S fuzz -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" --parallel "${BUILD_JOBS:-2}" --target "${harnesses[@]}"

seed() {  # seed corpus per harness: the bundled inputs of that kind
  local dir=$1; shift
  mkdir -p "$dir"
  for f in "$@"; do [[ -f "$f" && $(stat -c %s "$f") -lt 100000 ]] && cp -n "$f" "$dir/" || true; done
}
for h in "${harnesses[@]}"; do
  corpus=fuzz/corpus/$h
  case $h in
    fuzz_stl) seed "$corpus" tests/data/*.stl tests/bad_inputs/files/*.stl ;;
    fuzz_measurement_table) seed "$corpus" datasets/*/*.csv tests/bad_inputs/files/*.csv ;;
    fuzz_study) seed "$corpus" examples/calibrate_*.json tests/bad_inputs/files/study_*.json ;;
    fuzz_workflow) seed "$corpus" datasets/*/workflow.json tests/bad_inputs/files/workflow_*.json ;;
    fuzz_journal) seed "$corpus" tests/bad_inputs/files/*.jsonl tests/data/*.jsonl ;;
    fuzz_checkpoint)  # a valid checkpoint of the harness's scene, in both modes
      mkdir -p "$corpus"
      ls "$corpus"/seed_mode1 >/dev/null 2>&1 ||
        DEMCAL_FUZZ_WRITE_SEED="$PWD/$corpus" "$build/fuzz_checkpoint" ;;
    *) seed "$corpus" examples/*.json examples/invalid/*.json tests/bad_inputs/files/*.json ;;
  esac
  echo "== $h: $seconds s"
  (cd "$build" && ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 \
     "./$h" -max_total_time="$seconds" -max_len="${FUZZ_MAX_LEN:-65536}" -timeout=10 -rss_limit_mb=2048 \
     ${parallel[@]+"${parallel[@]}"} ${runs[@]+"${runs[@]}"} -print_final_stats=1 "../$corpus" 2>&1 |
     grep -E "stat::number_of_executed_units|Done|ERROR|SUMMARY|crash-|timeout-|oom-" || true)
done
# Any one kind of finding fails (ls of the three globs failed unless all three kinds existed).
shopt -s nullglob
findings=("$build"/crash-* "$build"/timeout-* "$build"/oom-*)
if ((${#findings[@]})); then
  echo "fuzz: findings in $build (crash-*, timeout-*, oom-*)" >&2
  exit 1
fi
