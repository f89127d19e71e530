#!/usr/bin/env python3
"""Damages a demcal checkpoint for the hostile-input tests (checkpoint_test.sh).
    ckpt_edit.py IN OUT time VALUE [--reframe]     the simulated time (a double)
    ckpt_edit.py IN OUT steps VALUE [--reframe]    the step count (an int64)
    ckpt_edit.py IN OUT budget VALUE [--reframe]   the energy budget (a double, J)
    ckpt_edit.py IN OUT mass FACTOR [--reframe]    slot 0's mass times FACTOR (radius kept)
    ckpt_edit.py IN OUT flip COUNT SEED [--reframe] COUNT random bytes XORed with 1..255
    ckpt_edit.py IN OUT old-format                 the start of a format-4 file
--reframe recomputes the payload length and FNV-1a checksum of the header (core/checkpoint/checkpoint_file.h),
so the edit reaches the state checks behind the checksum."""
import random, struct, sys

HEADER = 32


def fnv1a64(data):
    h = 14695981039346656037
    for b in data:
        h = ((h ^ b) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    return h


def time_offset(payload):
    """Payload offset of the time: after the fingerprint parts and the time step."""
    count, = struct.unpack_from("<Q", payload, 0)
    o = 8
    for _ in range(count):
        length, = struct.unpack_from("<Q", payload, o)
        o += 8 + length + 8
    return o + 8


def mass_offset(payload):
    """Payload offset of slot 0's mass: after time, steps, rebuilds, energy budget and scale,
    the five Vec3 arrays (x, v, omega, F, T) and the radii."""
    o = time_offset(payload) + 5 * 8
    for element in (24, 24, 24, 24, 24, 8):
        count, = struct.unpack_from("<Q", payload, o)
        o += 8 + count * element
    return o + 8


def main():
    src, dst, what = sys.argv[1:4]
    rest = [a for a in sys.argv[4:] if a != "--reframe"]
    data = bytearray(open(src, "rb").read())
    payload = data[HEADER:]
    if what == "time":
        struct.pack_into("<d", payload, time_offset(payload), float(rest[0]))
    elif what == "steps":
        struct.pack_into("<q", payload, time_offset(payload) + 8, int(rest[0]))
    elif what == "budget":
        struct.pack_into("<d", payload, time_offset(payload) + 3 * 8, float(rest[0]))
    elif what == "mass":
        o = mass_offset(payload)
        mass, = struct.unpack_from("<d", payload, o)
        struct.pack_into("<d", payload, o, mass * float(rest[0]))
    elif what == "flip":
        rng = random.Random(int(rest[1]))
        target = payload if "--reframe" in sys.argv else data
        for _ in range(int(rest[0])):
            target[rng.randrange(len(target))] ^= rng.randrange(1, 256)
        if target is data:
            open(dst, "wb").write(data)
            return
    elif what == "old-format":
        data[0:27] = struct.pack("<Q", 19) + b"demcal-checkpoint/4"
        open(dst, "wb").write(data)
        return
    if "--reframe" in sys.argv:
        data[16:32] = struct.pack("<QQ", len(payload), fnv1a64(payload))
    open(dst, "wb").write(data[:HEADER] + payload)


if __name__ == "__main__":
    main()
