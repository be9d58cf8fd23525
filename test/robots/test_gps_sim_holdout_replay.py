"""The GPS header on a simulated Husky-class recording with GPS (issue 37 item 5): a 120 s
run of tools/sim/diff_drive_sim.py --realistic husky --no-stops --imu-mount level --gps
(seed 1; the fixes at 2.5 Hz with the receiver's error measured on the real recording: a
Gauss-Markov part of 1.1 m and 60 s per axis, 0.05 m white, 1.1 m declared; the odom frame's
x axis at 60 deg in ENU), replayed through config/husky_skid_steer_gps.h with the bag's topics
remapped. Against independent references:
  - every 5th fix fused (tools/eval/gps_holdout.py): the fix the node predicts beats holding
    the last fused fix by at least 20 % RMSE on the 240 held-out fixes, with no fitted yaw;
  - its yaw state ends within 10 deg of the simulator's 60 deg;
  - every fix fused (2.5 Hz): its track is closer to the simulator's true pose (the odom
    frame, no alignment) than the same robot's odometry + IMU track without GPS.

The executables come from $SF_LIB_DIR or the sourced devel space (skipped when not built).
"""

import math
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(REPO, "tools", "sim"))
sys.path.insert(0, HERE)
from replay_helpers import built_lib_dir  # noqa: E402  (and tools/eval)
import diff_drive_sim as sim  # noqa: E402
import evaluate as ev  # noqa: E402
import gps_holdout as gh  # noqa: E402
import pioneer_nodes  # noqa: E402

HEADING_DEG = 60.0
REMAP = ["/encoder:=odom"]  # the simulator's imu/data and fix are the header's topics


class GpsHoldoutOnSimulatedHusky(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.lib_dir = built_lib_dir(gh.GPS_NODE, gh.BASELINE_NODE)
        cls.tmp = tempfile.TemporaryDirectory()
        cls.bag = os.path.join(cls.tmp.name, "husky_gps_sim.bag")
        sim.main(["--seed", "1", "--duration", "120", "--no-stops", "--imu-mount", "level",
                  "--realistic", "husky", "--gps", "--gps-heading", str(HEADING_DEG),
                  "--out", cls.bag, "--compression", "none"])
        cls.truth = ev.load_truth(cls.bag, "ground_truth/pose")
        setup = gh.HoldoutSetup(fix_topic="fix", replay_args=gh.replay_args(REMAP, []))
        out = os.path.join(cls.tmp.name, "holdout")
        os.mkdir(out)
        cls.result = gh.evaluate_holdout(cls.bag, cls.lib_dir, out, 5, 10.0, setup,
                                         gh.rotated_track(cls.truth, math.radians(HEADING_DEG)))
        cls.rows = {r["label"].split(" (")[0]: r for r in cls.result["rows"]}

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_beats_the_held_fix_by_a_fifth(self):
        self.assertEqual(len(self.result["held"]), 240)
        gps = self.rows["GPS node, predicted fix"]
        self.assertEqual(gps["n"], 240)
        self.assertLessEqual(gps["rmse"], 0.8 * self.rows["fused fixes held"]["rmse"])

    def test_yaw_state_finds_the_heading(self):
        error = self.result["yaw_state"] - math.radians(HEADING_DEG)
        self.assertLess(abs(math.atan2(math.sin(error), math.cos(error))), math.radians(10.0))

    def test_every_fix_fused_beats_dead_reckoning_against_the_truth(self):
        rmse = {}
        for node in (gh.GPS_NODE, gh.BASELINE_NODE):
            csv_path = os.path.join(self.tmp.name, node + "_full.csv")
            pioneer_nodes.replay(os.path.join(self.lib_dir, node), self.bag, csv_path, REMAP)
            rmse[node] = ev.evaluate(ev.load_result_csv(csv_path), self.truth).rmse_pos
        self.assertLess(rmse[gh.GPS_NODE], rmse[gh.BASELINE_NODE])


if __name__ == "__main__":
    unittest.main()
