#!/usr/bin/python3
"""SHA-256 of the replay CSV of every shipped configuration on its shipped bag: a record of
what the nodes compute, so that a change that must not move any estimate (a refactoring, a
build option, a new feature of other headers) is checked to the bit, and one that should is
seen node by node.

  replay_digests.py [--lib-dir DIR] --write test/robots/replay_digests.txt
  replay_digests.py [--lib-dir DIR] --check test/robots/replay_digests.txt [--only NODE...]
  replay_digests.py [--lib-dir DIR] --compare OTHER_LIB_DIR

--write replays each node and writes `node bag sha256` lines; --check replays and lists the
nodes whose CSV differs from the file (exit 1 if any); --compare replays with two builds (for
example main's and a branch's devel spaces) and lists which nodes' CSVs differ. A node that is
not built is reported and left out. The CSV of a replay depends only on the node and the bag
(the replay is deterministic, the particle filters seeded), but it is the compiler's floating
point: the file holds for the package's own build (Debian 12, g++ 12, Release, no -march).
"""

import argparse
import hashlib
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pioneer_nodes  # noqa: E402  (devel-space lookup)

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# Each shipped configuration on the shipped bag it is made for (doc/bags.md). The soccer CWA
# nodes read the filters' outputs, not a shipped bag, and the train and tuning-example nodes
# have no shipped bag: they are left out.
PIONEER = ["nav1", "nav1ctrl", "nav2", "nav2ctrl", "nav3", "nav3ctrl", "nav3red"]
PAIRS = ([("sf_%s_%s" % (model, method), "bags/pioneer_seed1.bag")
          for model in PIONEER for method in ("ekf", "ukf", "pf", "kf", "moving_average")
          if os.path.exists(os.path.join(REPO, "config", "%s_%s.h" % (model, method)))] +
         [("sf_soccer_%s" % name, "bags/soccer_seed1.bag")
          for name in ("kf", "vision_kf", "encoder_kf")] +
         [("sf_pioneer_skid_steer_ekf", "bags/pioneer_seed1.bag"),
          ("sf_diff_drive_odom_imu", "bags/diff_drive_seed1.bag"),
          ("sf_skid_steer_odom_imu", "bags/diff_drive_seed1.bag")] +
         [("sf_husky_%s" % name, "bags/husky_gps.bag")
          for name in ("diff_drive_ekf", "diff_drive_ukf", "diff_drive_pf", "skid_steer_ekf",
                       "skid_steer_ukf", "skid_steer_pf", "skid_steer_gps")] +
         # The IMU-only attitude header (QUATERNION_STATES) on the real BROAD trial; the 3D
         # IMU + odometry header needs --allow-missing-topics there (no odometry) and is not
         # recorded.
         [("sf_imu_attitude", "bags/broad_21_fast_combined.bag")] +
         # Armesto et al.'s inertial+vision headers read the trial's IMU and vision pose.
         [("sf_armesto_inertial_vision_%s" % method, "bags/broad_21_fast_combined.bag")
          for method in ("ekf", "ukf")])


def digest(lib_dir, node, bag):
    """SHA-256 of `node --replay bag --csv`'s CSV, or None when the node is not built."""
    exe = os.path.join(lib_dir, node)
    if not os.access(exe, os.X_OK):
        return None
    with tempfile.TemporaryDirectory(prefix="sf_digest_") as tmp:
        out = os.path.join(tmp, "out.csv")
        proc = subprocess.run([exe, "--replay", os.path.join(REPO, bag), "--csv", out],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              universal_newlines=True, timeout=300)
        if proc.returncode != 0:
            raise RuntimeError("%s --replay %s failed (%d): %s" %
                               (node, bag, proc.returncode, proc.stderr))
        with open(out, "rb") as f:
            return hashlib.sha256(f.read()).hexdigest()


def read_table(path):
    table = {}
    with open(path) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                node, bag, sha = line.split()
                table[(node, bag)] = sha
    return table


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lib-dir", help="where the sf_* executables are (default: the "
                        "sourced devel space's)")
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument("--write", metavar="FILE")
    mode.add_argument("--check", metavar="FILE")
    mode.add_argument("--compare", metavar="OTHER_LIB_DIR")
    parser.add_argument("--only", nargs="+", metavar="NODE", help="these nodes only")
    args = parser.parse_args(argv)
    lib_dir = args.lib_dir or pioneer_nodes.find_lib_dir(PAIRS[0][0])
    if not lib_dir:
        parser.error("no --lib-dir and no sourced devel space with the nodes")
    pairs = [p for p in PAIRS if not args.only or p[0] in args.only]
    expected = read_table(args.check) if args.check else {}
    lines, differ = [], []
    for node, bag in pairs:
        sha = digest(lib_dir, node, bag)
        if sha is None:
            print("note: %s not built, left out" % node, file=sys.stderr)
            continue
        if args.write:
            lines.append("%s %s %s" % (node, bag, sha))
        elif args.check:
            if expected.get((node, bag)) != sha:
                differ.append("%s on %s: %s, the file says %s" %
                              (node, bag, sha[:16], (expected.get((node, bag)) or "none")[:16]))
        else:
            other = digest(args.compare, node, bag)
            if other is not None and other != sha:
                differ.append("%s on %s" % (node, bag))
    if args.write:
        with open(args.write, "w") as f:
            f.write("# node bag sha256-of-the-replay-CSV: tools/eval/replay_digests.py --write "
                    "(doc/evaluation.md)\n")
            f.write("\n".join(lines) + "\n")
        print("wrote %d digests to %s" % (len(lines), args.write))
        return 0
    for line in differ:
        print("differs: " + line)
    print("%d of %d replays differ" % (len(differ), len(pairs)))
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
