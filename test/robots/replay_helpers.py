"""Helpers of the robot replay tests: run a generated node's offline replay, read its CSV."""

import csv
import math
import os
import subprocess
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "tools", "eval"))
import pioneer_nodes  # noqa: E402  (devel-space lookup)

# The real Clearpath Husky recording with GPS (doc/bags.md).
HUSKY_BAG = os.path.join(REPO, "bags", "husky_gps.bag")


def built_lib_dir(*exe_names):
    """The folder of the built executables `exe_names`: $SF_LIB_DIR (set by the CMake test
    registration) or the sourced devel space's. Skips the test when one is not built."""
    lib_dir = os.environ.get("SF_LIB_DIR") or pioneer_nodes.find_lib_dir(exe_names[0])
    for exe_name in exe_names:
        if not os.access(os.path.join(lib_dir or "", exe_name), os.X_OK):
            raise unittest.SkipTest("%s not built (set SF_LIB_DIR or source the devel space)"
                                    % exe_name)
    return lib_dir


def built_exe(exe_name):
    """The path of the built executable `exe_name` (built_lib_dir(): skips when not built)."""
    return os.path.join(built_lib_dir(exe_name), exe_name)


def replay_exe(exe_name, bag, csv_path, *extra):
    """Runs `<exe> --replay BAG --csv CSV [extra]` from built_lib_dir(); the finished process.
    Skips the test when the executable is not built, fails it when the replay fails."""
    exe = built_exe(exe_name)
    proc = subprocess.run([exe, "--replay", bag, "--csv", csv_path] + list(extra),
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True, timeout=120)
    if proc.returncode != 0:
        raise AssertionError("replay failed (%d): %s%s" % (proc.returncode, proc.stdout, proc.stderr))
    return proc


def assert_smoothed_csv_extends_plain(test, plain_path, smoothed_path, proc):
    """A smoothing replay's CSV (`smoothed_path`, its process `proc`) is the plain replay's
    (`plain_path`) line for line, followed by the smoothed columns, over one segment."""
    with open(plain_path) as a, open(smoothed_path) as b:
        plain, smoothed = a.read().splitlines(), b.read().splitlines()
    test.assertEqual(len(plain), len(smoothed))
    columns = plain[0].count(",") + 1
    test.assertEqual(smoothed[0].split(",")[columns], "smoothed_x0")
    for p, s in zip(plain, smoothed):
        test.assertEqual(",".join(s.split(",")[:columns]), p)
    test.assertIn("smoothed %d periods (1 segments)" % (len(plain) - 1), proc.stdout)


def read_rows(csv_path):
    """The replay CSV as a list of {column: float}."""
    with open(csv_path, newline="") as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def correction(row, prefix, angle_states):
    """(mean square, its expectation) of the smoothing correction of a CSV row: over the states
    with a filtered variance, mean of (x_s - x_f)^2 / var_f and of 1 - var_s / var_f, the
    smoothed columns named `prefix` + the filtered ones, the differences of `angle_states`
    wrapped (doc/smoothing.md); None for a row without a smoothed belief or without a filtered
    variance."""
    squares, expected = [], []
    for i in range(sum(1 for k in row if k.startswith("var"))):
        var = row["var%d" % i]
        smoothed = row["%sx%d" % (prefix, i)]
        if math.isnan(smoothed):
            return None
        if not var > 0.0:
            continue
        d = smoothed - row["x%d" % i]
        if i in angle_states:
            d = math.atan2(math.sin(d), math.cos(d))
        squares.append(d * d / var)
        expected.append(1.0 - row["%svar%d" % (prefix, i)] / var)
    if not squares:
        return None
    return sum(squares) / len(squares), sum(expected) / len(expected)
