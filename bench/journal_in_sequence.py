#!/usr/bin/env python3
"""The wall-time model (docs/scale.md) of a reproduce folder's calibration runs had its
calibrations run one after another (`demcal reproduce --calibrations-in-sequence`): the same
journal records, each calibration's batches on their own (grouped per journal and batch_unix_s
instead of per batch_unix_s alone), list-scheduled on N - 1 slots, summed. The time between
batches is left out. Usage: journal_in_sequence.py DIR [8,64,512]"""
import glob
import heapq
import json
import sys


def makespan(times, slots):
    free, end = [0.0] * slots, 0.0
    for t in times:
        start = heapq.heappop(free)
        heapq.heappush(free, start + t)
        end = max(end, start + t)
    return end


def main():
    root = sys.argv[1]
    ranks = [int(x) for x in (sys.argv[2] if len(sys.argv) > 2 else "1,8,64,512").split(",")]
    batches = {}
    for path in glob.glob(f"{root}/**/journal.jsonl", recursive=True):
        for line in open(path).read().splitlines()[1:]:
            r = json.loads(line)
            if "start_unix_s" in r and "batch_unix_s" in r:
                batches.setdefault((path, r["batch_unix_s"]), []).append(
                    (r["start_unix_s"], r["end_unix_s"] - r["start_unix_s"]))
    print(f"in sequence: {sum(map(len, batches.values()))} timed runs in {len(batches)} batches")
    for n in ranks:
        span = sum(makespan([t for _, t in sorted(b)], max(1, n - 1)) for b in batches.values())
        print(f"predicted wall span at {n} ranks, in sequence, without the time between "
              f"batches (s): {span:.1f}")


if __name__ == "__main__":
    main()
