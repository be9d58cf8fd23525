"""Faulty GPS fixes on the real Husky recording through config/husky_skid_steer_gps.h (issue 38
D2, D3): a copy of bags/husky_gps.bag whose first fix has latitude 91, whose 20th has
longitude 500, whose 40th has altitude 1e30 and whose 60th jumps 1000 km north-east (latitude and
longitude + 9 degrees: both its east and north innovations far beyond the gate). The three positions not on the Earth are dropped before the filter (counted with
their reason), the next fix after the first becomes the datum, and the jump fails the
header's gate (counted as gated). Reference: the same recording with those four fixes
removed, which must give the same estimates (a dropped or gated fix is a missing one). Before
the checks the first fix became the datum and every later fix was dropped as not finite;
without the gate the jump left 289 m of error at the end.

The executable comes from $SF_LIB_DIR or the sourced devel space (skipped when not built).
"""

import os
import subprocess
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from replay_helpers import HUSKY_BAG, built_lib_dir, read_rows  # noqa: E402

NODE = "sf_husky_skid_steer_gps"
FAULTS = {0: ("latitude", 91.0), 19: ("longitude", 500.0), 39: ("altitude", 1e30),
          59: (("latitude", "longitude"), None)}  # None: 9 degrees more (about 1000 km)


def write_bags(faulty_path, removed_path, faults=FAULTS):
    """The recording with the fixes of `faults` changed, and with them left out. `faults`:
    {fix index: (field, value)}, or ((fields), (values)) for several fields of one fix."""
    import rosbag

    fix = -1
    with rosbag.Bag(HUSKY_BAG) as src, rosbag.Bag(faulty_path, "w") as faulty, \
            rosbag.Bag(removed_path, "w") as removed:
        for topic, msg, t in src.read_messages():
            if topic == "/fix":
                fix += 1
                if fix in faults:
                    field, value = faults[fix]
                    if value is None:
                        msg.latitude += 9.0
                        msg.longitude += 9.0
                    elif isinstance(field, tuple):
                        for name, v in zip(field, value):
                            setattr(msg, name, v)
                    else:
                        setattr(msg, field, value)
                    faulty.write(topic, msg, t)
                    continue
            faulty.write(topic, msg, t)
            removed.write(topic, msg, t)


class GpsFaultsOnHusky(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        exe = os.path.join(built_lib_dir(NODE), NODE)
        cls.tmp = tempfile.TemporaryDirectory()
        faulty, removed = (os.path.join(cls.tmp.name, n + ".bag") for n in ("faulty", "removed"))
        write_bags(faulty, removed)
        cls.runs = {}
        for name, bag, extra in (("faulty", faulty, []), ("removed", removed, []),
                                 ("strict", faulty, ["--strict"])):
            csv_path = os.path.join(cls.tmp.name, name + ".csv")
            proc = subprocess.run([exe, "--replay", bag, "--csv", csv_path] + extra,
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                  universal_newlines=True, timeout=120)
            rows = read_rows(csv_path) if proc.returncode == 0 else None
            cls.runs[name] = (proc, rows)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_faults_dropped_or_gated_and_counted(self):
        proc, _ = self.runs["faulty"]
        self.assertEqual(proc.returncode, 0, proc.stderr)
        # 95 fixes: 3 not on the Earth never reach the filter, the jump is gated.
        for i in (3, 4):
            self.assertIn("input %d (GPS): 0 fixes dropped without a fix (status < STATUS_FIX), "
                          "3 dropped as not on the Earth (newest: altitude 1e+30 outside "
                          "[-1e4, 1e5] m)" % i, proc.stdout)
            self.assertIn("input %d: 92 received, 91 used, dropped: none, 1 gated," % i,
                          proc.stdout)

    def test_strict_counts_the_fixes_dropped_before_the_filter(self):
        # Issue 38 D3: "0 dropped values", exit 0. The 3 fixes of 2 inputs each are 6 values.
        proc, _ = self.runs["strict"]
        self.assertEqual(proc.returncode, 1, proc.stdout + proc.stderr)
        self.assertIn("--strict: 0 failed steps, 0 filter resets, 6 dropped values", proc.stderr)

    def test_estimates_as_without_the_faulty_fixes(self):
        (proc, faulty), (ref_proc, removed) = self.runs["faulty"], self.runs["removed"]
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(ref_proc.returncode, 0, ref_proc.stderr)
        self.assertEqual(len(faulty), len(removed))
        for a, b in zip(faulty, removed):
            for key in ("time", "x0", "x1", "x2", "var0", "var1"):
                self.assertAlmostEqual(a[key], b[key], places=9, msg=(key, a["time"]))


if __name__ == "__main__":
    unittest.main()
