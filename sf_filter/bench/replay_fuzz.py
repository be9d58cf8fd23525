#!/usr/bin/python3
"""Random damage to a bag, replayed offline (doc/reliability.md, "Faults tried"): each round
copies BAG with one random fault (a flipped bit, 1 B to 4 KiB of random bytes or zeros, or
truncation at a random offset), runs `NODE --replay copy --csv o.csv --bag o.bag` and checks
that the replay either succeeds or ends with exit status 1 and its error as the last line of
stderr, never by a signal or a hang, and leaves neither an output nor a `.partial` file after
a failure. Prints the outcomes by count; exits 1 if any round broke the rules.

  sf_filter/bench/replay_fuzz.py NODE BAG [--rounds 100] [--seed 1] [--keep DIR]

Use an uncompressed bag (`rosbag decompress`) to damage record headers and indexes rather
than bz2 blocks. --keep DIR keeps the copies that broke a rule.
"""

import argparse
import collections
import os
import random
import shutil
import subprocess
import sys
import tempfile


def damage(data, rng):
    d = bytearray(data)
    mode = rng.choice(["overwrite", "zero", "flip", "truncate"])
    offset = rng.randrange(len(d))
    if mode == "overwrite":
        n = rng.choice([1, 4, 16, 256, 4096])
        d[offset:offset + n] = bytes(rng.randrange(256) for _ in range(min(n, len(d) - offset)))
    elif mode == "zero":
        n = rng.choice([4, 64, 1024])
        d[offset:offset + n] = bytes(min(n, len(d) - offset))
    elif mode == "flip":
        d[offset] ^= 1 << rng.randrange(8)
    else:
        del d[offset:]
    return bytes(d), "%s at %d" % (mode, offset)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("node")
    parser.add_argument("bag")
    parser.add_argument("--rounds", type=int, default=100)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--keep")
    args = parser.parse_args()
    data = open(args.bag, "rb").read()
    rng = random.Random(args.seed)
    outcomes = collections.Counter()
    broken = 0
    with tempfile.TemporaryDirectory(prefix="sf_replay_fuzz_") as tmp:
        copy, csv, out = (os.path.join(tmp, n) for n in ("f.bag", "o.csv", "o.bag"))
        for k in range(args.rounds):
            damaged, what = damage(data, rng)
            open(copy, "wb").write(damaged)
            for p in (csv, out):
                if os.path.exists(p):
                    os.remove(p)
            try:
                proc = subprocess.run([args.node, "--replay", copy, "--csv", csv, "--bag", out],
                                      stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                      universal_newlines=True, errors="replace", timeout=120)
            except subprocess.TimeoutExpired:
                outcomes["hang"] += 1
                broken += 1
                continue
            left = [n for n in os.listdir(tmp) if n.startswith("o.")]
            last = proc.stderr.strip().splitlines()[-1:] or [""]
            if proc.returncode == 0:
                outcomes["replayed (exit 0)"] += 1
                continue
            reason = last[0].split(": ", 1)[-1].replace(copy, "BAG")[:100]
            outcomes["exit %d: %s" % (proc.returncode, reason)] += 1
            if proc.returncode != 1 or left or not last[0].startswith(args.node + ": "):
                broken += 1
                print("round %d (%s): exit %d, left %s, stderr: %s" % (
                    k, what, proc.returncode, left, proc.stderr[-300:]))
                if args.keep:
                    os.makedirs(args.keep, exist_ok=True)
                    shutil.copy(copy, os.path.join(args.keep, "round%d.bag" % k))
    for outcome, count in outcomes.most_common():
        print("%5d  %s" % (count, outcome))
    print("%d rounds, %d broke the rules" % (args.rounds, broken))
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
