#!/usr/bin/env bash
# `mpirun -np 3 demcal calibrate` gives the local run's results, and a job whose manager or a
# worker was killed resumes from the journal with nothing lost or repeated (docs/scale.md). The smallest study: the BP
# rolling-friction heap at its quick fidelity, 2 replicates, 2 candidates (4 heaps).
# Usage: mpi_calibrate_test.sh DEMCAL REPO_ROOT
set -euo pipefail
demcal=$1 root=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [[ $(id -u) == 0 ]]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
mpi=(mpirun --oversubscribe -np 3)
python3 - "$root" "$work/study.json" <<'PY'
import json, sys
root, out = sys.argv[1], sys.argv[2]
s = json.load(open(f"{root}/examples/calibrate_bp_rolling.json"))
s["experiment_file"] = f"{root}/examples/aor_bp.json"
s["measurement"]["dataset"] = f"{root}/datasets/alizadeh2018/measurements.csv"
s["replicates"] = 2
json.dump(s, open(out, "w"))
PY
args=("$work/study.json" --quick --max-evaluations 2)

# Same inputs: the journals' records, minus where and when each ran, and the outputs.
same() {
  python3 - "$1" "$2" <<'PY'
import json, sys
def records(d):
    lines = open(f"{d}/journal.jsonl").read().splitlines()[1:]
    keep = lambda r: {k: v for k, v in r.items()
                      if k not in ("host", "rank", "start_unix_s", "end_unix_s", "batch_unix_s",
                                   "wall_time_s")}
    return sorted(json.dumps(keep(json.loads(l)), sort_keys=True) for l in lines)
a, b = sys.argv[1], sys.argv[2]
ra, rb = records(a), records(b)
assert ra == rb, f"journal records differ:\n{ra}\n{rb}"
assert len(set(rb)) == len(rb), f"a run is in {b}/journal.jsonl twice"
for name in ("calibrated_params.json", "evaluations.csv"):
    assert open(f"{a}/{name}").read() == open(f"{b}/{name}").read(), f"{name} differs"
ja, jb = (json.load(open(f"{d}/result.json")) for d in (a, b))
for j in (ja, jb):
    j.pop("wall_time_s", None)
assert ja == jb, "result.json differs (apart from wall_time_s)"
print(f"same as the local run: {len(rb)} journal records, calibrated_params.json, "
      f"evaluations.csv, result.json")
PY
}

# Exit code 0 (matched) or 3 (not matched within the 2-candidate budget): the same for both.
start=$(date +%s%N)
local_rc=0
"$demcal" calibrate "${args[@]}" --quiet --out "$work/local" --threads 2 || local_rc=$?
local_ms=$((($(date +%s%N) - start) / 1000000))
start=$(date +%s%N)
mpi_rc=0
"${mpi[@]}" "$demcal" calibrate "${args[@]}" --quiet --out "$work/mpi" || mpi_rc=$?
mpi_ms=$((($(date +%s%N) - start) / 1000000))
echo "wall time (ms): local --threads 2: $local_ms, mpirun --oversubscribe -np 3: $mpi_ms"
if [[ $local_rc != 0 && $local_rc != 3 ]] || [[ $mpi_rc != "$local_rc" ]]; then
  echo "exit codes: local $local_rc, mpirun $mpi_rc"; exit 1
fi
same "$work/local" "$work/mpi"
"$demcal" journal-stats "$work/mpi" | grep -q "^rank 2 on " || {
  echo "journal-stats: no runs of rank 2"; exit 1; }

# A rank killed (kill -9) once the first heap is in the journal: Open MPI ends the job, and the
# same command resumes with every finished run read back and none repeated.
kill_and_resume() {
  local rank=$1 out=$work/killed_$1 victim="" launcher lines kept resume_rc=0
  "${mpi[@]}" "$demcal" calibrate "${args[@]}" --quiet --out "$out" > "$out.log" 2>&1 &
  launcher=$!
  for _ in $(seq 600); do
    if [[ -z $victim ]]; then
      for p in $(pgrep -P "$launcher" || true); do
        tr '\0' '\n' < "/proc/$p/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$rank" &&
          victim=$p
      done
    fi
    lines=$(wc -l 2>/dev/null < "$out/journal.jsonl" || echo 0)
    [[ -n $victim && $lines -ge 2 ]] && break
    sleep 0.1
  done
  [[ -n $victim ]] || { echo "rank $rank not found"; exit 1; }
  kill -9 "$victim"
  if wait "$launcher"; then echo "the job went on after rank $rank was killed"; exit 1; fi
  kept=$(($(wc -l < "$out/journal.jsonl") - 1))
  echo "rank $rank killed with $kept heap(s) in the journal"
  "${mpi[@]}" "$demcal" calibrate "${args[@]}" --out "$out" 2> "$out.resume.log" || resume_rc=$?
  [[ $resume_rc == "$local_rc" ]] || { echo "resumed run: exit code $resume_rc"; exit 1; }
  grep -q "resuming: $kept replicate runs" "$out.resume.log" || {
    echo "the resumed run did not read the journal:"; cat "$out.resume.log"; exit 1; }
  # result.json's replicates_reused differs after a resume: compare the records and parameters.
  python3 - "$work/local" "$out" <<'PY'
import json, sys
a, b = sys.argv[1], sys.argv[2]
rec = lambda d: sorted(json.dumps({k: v for k, v in json.loads(l).items() if k in
                      ("group", "parameters", "replicate", "seed", "status", "values")},
                      sort_keys=True) for l in open(f"{d}/journal.jsonl").read().splitlines()[1:])
ra, rb = rec(a), rec(b)
assert ra == rb, f"resumed journal differs from the local run's (lost or repeated runs):\n{ra}\n{rb}"
assert open(f"{a}/calibrated_params.json").read() == open(f"{b}/calibrated_params.json").read()
print(f"resumed: {len(rb)} journal records, none lost or repeated; calibrated_params.json same")
PY
}
kill_and_resume 0  # the manager
kill_and_resume 1  # a worker
