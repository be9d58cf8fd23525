"""Offline replay of bags/soccer_lost_vision.bag through sf_soccer_kf (config/soccer_kf.h,
Wang et al.'s reference-[10] Kalman filter): the position error is consistent with the
filter's own covariance, far below a vision frame's noise, and stays bounded through the
stretches of lost vision frames.

References: the simulator's vision noise (0.0112 m per axis, tools/sim/soccer_sim.py) and
ground truth; the filter's covariance (var0 + var1) for the consistency check. One period
of latency (1 ms at up to 1.32 m/s, doc/bags.md) is added to the bounds: the estimate at a
period's end holds the encoder sample from its start.
"""

import math
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "tools", "eval"))
sys.path.insert(0, os.path.join(REPO, "tools", "sim"))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True
import evaluate  # noqa: E402
import soccer_report  # noqa: E402
import soccer_sim  # noqa: E402
from replay_helpers import read_rows, replay_exe  # noqa: E402

BAG = os.path.join(REPO, "bags", "soccer_lost_vision.bag")
LATENCY = 1.4 * 0.001          # [m]: 1.32 m/s top speed for one 1 ms period
SETTLE = 1.0                   # [s] left out of the consistency check: the start-up transient


class SoccerReplayTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix="sf_soccer_test_")
        csv_path = os.path.join(cls.tmp.name, "kf.csv")
        replay_exe("sf_soccer_kf", BAG, csv_path)
        cls.rows = read_rows(csv_path)
        cls.truth = evaluate.load_truth(BAG)
        cls.ev = evaluate.evaluate(evaluate.load_result_csv(csv_path, ["x0", "x1"]), cls.truth)
        cls.sigma = {r["time"]: math.sqrt(r["var0"] + r["var1"]) for r in cls.rows}
        vision = evaluate.load_pose_bag(BAG, soccer_report.VISION_TOPIC, with_heading=False)
        cls.gaps = soccer_report.gaps(vision.t)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_error_far_below_the_vision_noise(self):
        vision_rms_2d = soccer_sim.VISION_STD * math.sqrt(2)
        self.assertLess(self.ev.rmse_pos, vision_rms_2d / 3)

    def test_error_consistent_with_the_filters_covariance(self):
        # normalised squared error of the 2-D position: mean 2 for a consistent filter; the
        # latency adds a little, so accept 1 to 4
        t0 = self.truth.t[0]
        nees = [(e * e) / (self.sigma[t] ** 2) for t, e in zip(self.ev.times, self.ev.pos_errors)
                if t - t0 > SETTLE]
        mean = sum(nees) / len(nees)
        self.assertGreater(mean, 1.0)
        self.assertLess(mean, 4.0)

    def test_error_bounded_while_vision_is_lost(self):
        self.assertEqual(len(self.gaps), 2, "the bag has two stretches of lost frames")
        for start, end in self.gaps:
            inside = [(t, e) for t, e in zip(self.ev.times, self.ev.pos_errors) if start < t < end]
            self.assertTrue(inside)
            worst_sigma = max(self.sigma[t] for t, _ in inside)
            # the uncertainty grows without vision (about 2.5x in the 2.5 s gap) ...
            self.assertGreater(worst_sigma, 1.5 * self.sigma[inside[0][0]])
            # ... and the error stays within it
            for t, e in inside:
                self.assertLess(e, 4 * worst_sigma + LATENCY,
                                "error %.4f m at %.3f s" % (e, t - self.truth.t[0]))


if __name__ == "__main__":
    unittest.main()
