"""The GPS input on the real Husky recording (config/husky_skid_steer_gps.h, issue 14 item 4,
issue 37 item 5): with every 5th fix fused (tools/eval/gps_holdout.py), on the 76 fixes it did
not fuse the fix the GPS node predicts beats holding the last fused fix by at least 20 % RMSE
with no fitted yaw offset, and is closer to the GPS than the same robot's odometry + IMU track
without GPS in the fitted frame (by at least a third of its RMSE) and than that track after its
best batch alignment onto the fused fixes; the replay leaves out exactly the held-out fixes
and uses every fused one; the wheel speed scale state ends positive (the wheels over-report
the distance) and within 3 of the filter's standard deviations of the path ratio the
recording shows (27.6 m of wheel path against 24.0 m of GPS path: k = 0.15).

The executables come from $SF_LIB_DIR or the sourced devel space (skipped when not built).
"""

import math
import os
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from replay_helpers import HUSKY_BAG, built_lib_dir, read_rows  # noqa: E402  (and tools/eval)
import gps_holdout as gh  # noqa: E402


class GpsHoldoutOnHusky(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        lib_dir = built_lib_dir(gh.GPS_NODE, gh.BASELINE_NODE)
        cls.tmp = tempfile.TemporaryDirectory()
        cls.result = gh.evaluate_holdout(HUSKY_BAG, lib_dir, cls.tmp.name, every=5)
        cls.rows = {r["label"].split(" (")[0]: r for r in cls.result["rows"]}
        cls.state = read_rows(os.path.join(cls.tmp.name, gh.GPS_NODE + ".csv"))

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_fuses_every_fifth_fix_only(self):
        self.assertEqual(self.result["fixes"], 95)
        self.assertEqual(len(self.result["fused"]), 19)
        self.assertEqual(self.result["left_out"], 76)
        self.assertIn("input 3: 19 received, 19 used", self.result["summary"])
        self.assertIn("input 3 (GPS): 0 fixes dropped without a fix", self.result["summary"])

    def test_gps_node_beats_the_held_fix_by_a_fifth_without_a_fitted_yaw(self):
        # Issue 37: the fix the GPS node predicts (its pose turned into ENU by its yaw state,
        # plus the fixes' offset states) is at least 20 % closer to the held-out fixes than
        # the last fused fix held (0.36 against 0.69 m; before the yaw and error states 0.69
        # against 0.69 m with the yaw offset fitted by this tool). Nothing was fitted for it:
        # the replay got no ~gps_yaw_offset.
        gps = self.rows["GPS node, predicted fix"]
        self.assertLessEqual(gps["rmse"], 0.8 * self.rows["fused fixes held"]["rmse"])
        self.assertFalse(os.path.exists(os.path.join(self.tmp.name, "gps.yaml")))
        self.assertIsNotNone(self.result["yaw_state"])

    def test_gps_node_beats_dead_reckoning_on_held_out_fixes(self):
        gps = self.rows["GPS node, predicted fix"]
        self.assertEqual(gps["n"], 76)
        self.assertLess(gps["rmse"], 2.0 / 3.0 * self.rows["no GPS, same frame"]["rmse"])
        self.assertLess(gps["rmse"], self.rows["no GPS, best fit on the fused fixes"]["rmse"])
        self.assertLess(gps["max"], 2.0)

    def test_wheel_scale_learned_from_the_gps(self):
        end = self.state[-1]
        k, sigma = end["x7"], math.sqrt(end["var7"])
        self.assertGreater(k, 0.0)
        self.assertLess(abs(k - (27.6 / 24.0 - 1.0)), 3.0 * sigma)
        self.assertLess(sigma, 0.1)


if __name__ == "__main__":
    unittest.main()
