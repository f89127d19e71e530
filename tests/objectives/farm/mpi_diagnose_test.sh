#!/usr/bin/env bash
# `mpirun -np 3 demcal diagnose` gives the local run's diagnosis (docs/scale.md): the control
# example (no hidden effect) at its quick fidelity, one candidate effect, a base calibration of 2
# candidates: 16 simulations. Too long for CI on 2 cores (about 2 min each run on the shared
# development VM); scripts/run_long_tests.sh runs it when mpirun is installed.
# Usage: mpi_diagnose_test.sh DEMCAL REPO_ROOT
set -euo pipefail
demcal=$1 root=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [[ $(id -u) == 0 ]]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
args=("$root/examples/diagnose/diagnose_none.json" --quick --max-evaluations 2 --quiet
      --effects rolling_resistance --refits 1 --max-effects 1 --extra-refits 0)
"$demcal" diagnose "${args[@]}" --out "$work/local" --threads 2
mpirun --oversubscribe -np 3 "$demcal" diagnose "${args[@]}" --out "$work/mpi"
python3 - "$work/local" "$work/mpi" <<'PY'
import glob, json, os, sys
a, b = sys.argv[1], sys.argv[2]
def strip(o):
    if isinstance(o, dict): return {k: strip(v) for k, v in o.items() if "wall_time" not in k}
    if isinstance(o, list): return [strip(v) for v in o]
    return o
assert strip(json.load(open(f"{a}/diagnosis.json"))) == strip(json.load(open(f"{b}/diagnosis.json"))), \
    "diagnosis.json differs (apart from wall times)"
for name in ("diagnosed_params.json", "residuals.csv", "ranking.csv", "signatures.csv"):
    assert open(f"{a}/{name}").read() == open(f"{b}/{name}").read(), f"{name} differs"
drop = ("host", "rank", "start_unix_s", "end_unix_s", "batch_unix_s", "wall_time_s")
def records(d):
    return sorted((os.path.basename(p), json.dumps({k: v for k, v in json.loads(l).items()
                                                    if k not in drop}, sort_keys=True))
                  for p in glob.glob(f"{d}/journal/*.jsonl")
                  for l in open(p).read().splitlines()[1:])
ra, rb = records(a), records(b)
assert ra == rb, "journal records differ"
print(f"same as the local run: diagnosis.json, the CSVs, {len(rb)} journal records")
PY
