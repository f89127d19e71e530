#!/usr/bin/env bash
# `mpirun -np 3 demcal reproduce` gives the local run's numbers (docs/scale.md): a workflow of
# seconds per run (tiny_reproduce/: two species, one coating level, a few-gram segregation heap
# in 3 scenarios x 2 replicates, a 2-replicate fidelity check), run with --threads 2 and under
# `mpirun --oversubscribe -np 3`; summary.json, the stage journal and every stage's result must be
# equal apart from wall times, hosts, ranks and the output folder's name; a run resumed under
# mpirun after a kill in the segregation stage reads the finished heaps back. The two species'
# calibrations run together (their batches share the farm's batches, seen in their journals);
# a local run with --calibrations-in-sequence must give the same numbers.
# Usage: mpi_reproduce_test.sh DEMCAL REPO_ROOT
set -euo pipefail
demcal=$1 root=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [[ $(id -u) == 0 ]]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
workflow=$root/tests/objectives/farm/tiny_reproduce/workflow.json
args=("$workflow" --quick --quiet)

start=$(date +%s%N)
local_rc=0
"$demcal" reproduce "${args[@]}" --out "$work/local" --threads 2 2> "$work/local.log" || local_rc=$?
local_ms=$((($(date +%s%N) - start) / 1000000))
sequence_rc=0
"$demcal" reproduce "${args[@]}" --out "$work/sequence" --threads 2 --calibrations-in-sequence \
  2> "$work/sequence.log" || sequence_rc=$?
start=$(date +%s%N)
mpi_rc=0
mpirun --oversubscribe -np 3 "$demcal" reproduce "${args[@]}" --out "$work/mpi" 2> "$work/mpi.log" ||
  mpi_rc=$?
mpi_ms=$((($(date +%s%N) - start) / 1000000))
echo "wall time (ms): local --threads 2: $local_ms, mpirun --oversubscribe -np 3: $mpi_ms"
if [[ $local_rc != 0 || $mpi_rc != 0 || $sequence_rc != 0 ]]; then
  echo "exit codes: local $local_rc, mpirun $mpi_rc, in sequence $sequence_rc"
  cat "$work/local.log" "$work/mpi.log" "$work/sequence.log"; exit 1
fi

for b in mpi sequence; do
python3 - "$work/local" "$work/$b" <<'PY'
import glob, json, os, sys
a, b = sys.argv[1], sys.argv[2]
# Where and when each run went, and how long it took, differ by design; nothing else may.
timing = {"wall_time_s", "run", "host", "rank", "start_unix_s", "end_unix_s", "batch_unix_s",
          "stage_wall_time_s", "total_wall_time_s_this_run"}
def clean(v):
    if isinstance(v, dict):
        return {k: clean(x) for k, x in v.items() if k not in timing}
    if isinstance(v, list):
        return [clean(x) for x in v]
    return v
def load(path, root):  # the output folder's own name is the one other difference
    return clean(json.loads(open(path).read().replace(root, "OUT")))
def stages(root):
    lines = open(f"{root}/stages.jsonl").read().splitlines()[1:]
    return sorted(json.dumps(load_text(l, root), sort_keys=True) for l in lines)
def load_text(text, root):
    return clean(json.loads(text.replace(root, "OUT")))
sa, sb = load(f"{a}/summary.json", a), load(f"{b}/summary.json", b)
assert sa == sb, f"summary.json differs:\n{json.dumps(sa)}\n{json.dumps(sb)}"
ja, jb = stages(a), stages(b)
assert ja == jb, "stages.jsonl records differ:\n" + "\n".join(set(ja) ^ set(jb))
results = sorted(os.path.relpath(p, a) for p in glob.glob(f"{a}/*/stage_result.json"))
for r in results:
    assert load(f"{a}/{r}", a) == load(f"{b}/{r}", b), f"{r} differs"
segregation = [k for k in jb if '"key": "segregation/' in k]
assert len(segregation) == 6, f"{len(segregation)} segregation runs in the journal, not 6"
for f in ("report.html", "segregation/uncoated/r1/result.json", "fidelity_check/result.json"):
    assert os.path.isfile(f"{b}/{f}"), f"{f} missing from the farmed run's folder"
# Together, the species' batches went out as the farm's batches (one batch start for both
# journals); in sequence, never.
def batches(root, species):
    lines = open(f"{root}/species/{species}/journal.jsonl").read().splitlines()[1:]
    return {json.loads(l)["batch_unix_s"] for l in lines}
for root, together in ((a, True), (b, not b.endswith("sequence"))):
    shared = batches(root, "EP") & batches(root, "BP")
    assert bool(shared) == together, f"{root}: shared batch starts {shared}"
print(f"{os.path.basename(b)} the same as the local run: summary.json ({len(sa['rows'])} rows), "
      f"{len(jb)} stage records, {len(results)} stage results")
PY
done
# The segregation replicates and the calibrations' heaps ran on both workers.
stats=$("$demcal" journal-stats "$work/mpi")
for rank in 1 2; do
  grep -q "^rank $rank on " <<< "$stats" || { echo "journal-stats: no runs of rank $rank"; exit 1; }
done

# Resumed under mpirun as a kill during the segregation stage leaves it (the excessive scenario's
# runs, the last two stages' records gone, a last line cut short): every rank reads the same 4
# finished heaps back, only the 2 missing run, and the summary is the same.
python3 - "$work/mpi/stages.jsonl" <<'PY'
import sys
lines = open(sys.argv[1]).read().splitlines(True)
keep = [l for l in lines if not any(k in l for k in
        ('"key":"segregation"', '"key":"fidelity_check"', '"key":"segregation/excessive'))]
open(sys.argv[1], "w").write("".join(keep) + '{"key":"segregation/exc')
PY
mpirun --oversubscribe -np 3 "$demcal" reproduce "$workflow" --quick --out "$work/mpi" \
  2> "$work/resume.log" || { echo "resumed run failed:"; cat "$work/resume.log"; exit 1; }
grep -q "3 scenarios x 2 replicates, 4 from the journal" "$work/resume.log" || {
  echo "the resumed run did not read the journal:"; cat "$work/resume.log"; exit 1; }
python3 - "$work/local" "$work/mpi" <<'PY'
import json, sys
def summary(root):
    s = json.loads(open(f"{root}/summary.json").read().replace(root, "OUT"))
    for k in ("stage_wall_time_s", "total_wall_time_s_this_run"):
        s.pop(k)
    return s
assert summary(sys.argv[1]) == summary(sys.argv[2]), "resumed summary.json differs"
print("resumed under mpirun: 4 heaps from the journal, summary.json the local run's")
PY
