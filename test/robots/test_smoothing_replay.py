"""The replay's offline smoothing (`--replay BAG --smooth`, doc/smoothing.md): after the
forward run, the Rauch-Tung-Striebel backward pass over every period, written as smoothed_*
columns after the filtered ones.

References: the plain replay's CSV (the filtered columns of --smooth must be it, byte for
byte; the plain CSV itself was checked byte-identical to the one before --smooth existed, on
config/nav3ctrl_ekf.h and bags/pioneer_seed1.bag); the simulator's ground truth of
bags/soccer_lost_vision_ideal.bag (config/soccer_kf.h, a KF that fuses 32 Hz vision fixes
with the encoder): the smoothed position must be markedly closer to the truth (measured
2.1 mm RMSE against the filter's 3.8 mm) and consistent with its own covariance, as the
filter's is (test_soccer_replay.py: mean normalised squared 2-D error 1 to 4; measured 1.32),
with a variance never above the filtered one. On the Pioneer's dead reckoning
(config/nav3ctrl_ekf.h, nav3ctrl_ukf.h) nothing measures the pose, so later periods hold no
information about an earlier pose: the smoothed pose stays within a hundredth of the filtered
standard deviation (measured 5e-7 for x and y, 7.3e-4 for the heading), while the travelled
distance of a period, which the later wheel readings inform, moves by up to 0.23. A filter without a smoother (the particle filter) is refused.
"""

import math
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "tools", "eval"))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True
import evaluate  # noqa: E402
from replay_helpers import (assert_smoothed_csv_extends_plain, built_exe,  # noqa: E402
                            read_rows, replay_exe)

SOCCER_BAG = os.path.join(REPO, "bags", "soccer_lost_vision_ideal.bag")
PIONEER_BAG = os.path.join(REPO, "bags", "pioneer_seed1.bag")
SETTLE = 1.0  # [s] left out of the consistency check, as in test_soccer_replay.py


def evaluation(csv_path, truth, prefix):
    return evaluate.evaluate(evaluate.load_result_csv(csv_path, [prefix + "x0", prefix + "x1"]),
                             truth)


class SoccerSmoothingTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix="sf_smoothing_test_")
        cls.plain = os.path.join(cls.tmp.name, "plain.csv")
        cls.smoothed = os.path.join(cls.tmp.name, "smoothed.csv")
        replay_exe("sf_soccer_kf", SOCCER_BAG, cls.plain)
        cls.proc = replay_exe("sf_soccer_kf", SOCCER_BAG, cls.smoothed, "--smooth")
        cls.rows = read_rows(cls.smoothed)
        cls.truth = evaluate.load_truth(SOCCER_BAG)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_filtered_columns_are_the_plain_replay(self):
        assert_smoothed_csv_extends_plain(self, self.plain, self.smoothed, self.proc)

    def test_smoothed_track_closer_to_the_truth(self):
        filtered = evaluation(self.smoothed, self.truth, "")
        smoothed = evaluation(self.smoothed, self.truth, "smoothed_")
        self.assertLess(smoothed.rmse_pos, 0.7 * filtered.rmse_pos,
                        "filtered %.4g m, smoothed %.4g m" % (filtered.rmse_pos, smoothed.rmse_pos))

    def test_smoothed_error_consistent_with_its_covariance(self):
        ev = evaluation(self.smoothed, self.truth, "smoothed_")
        sigma = {r["time"]: math.sqrt(r["smoothed_var0"] + r["smoothed_var1"]) for r in self.rows}
        t0 = self.truth.t[0]
        nees = [(e * e) / (sigma[t] ** 2) for t, e in zip(ev.times, ev.pos_errors)
                if t - t0 > SETTLE]
        mean = sum(nees) / len(nees)
        self.assertGreater(mean, 1.0)
        self.assertLess(mean, 4.0)

    def test_smoothed_variance_never_above_the_filtered(self):
        for i in range(6):
            worst = max(r["smoothed_var%d" % i] / r["var%d" % i] for r in self.rows)
            self.assertLessEqual(worst, 1.0 + 1e-9, "var%d" % i)
            last = self.rows[-1]
            self.assertEqual(last["smoothed_var%d" % i], last["var%d" % i])
            self.assertEqual(last["smoothed_x%d" % i], last["x%d" % i])


class DeadReckoningSmoothingTest(unittest.TestCase):
    def test_unobserved_pose_keeps_its_filtered_value(self):
        with tempfile.TemporaryDirectory(prefix="sf_smoothing_test_") as tmp:
            for node in ("sf_nav3ctrl_ekf", "sf_nav3ctrl_ukf"):
                csv_path = os.path.join(tmp, node + ".csv")
                replay_exe(node, PIONEER_BAG, csv_path, "--smooth")
                rows = read_rows(csv_path)

                def largest_move(i):
                    """Largest |smoothed - filtered| of state i in filtered std. deviations."""
                    return max(abs(r["smoothed_x%d" % i] - r["x%d" % i]) / math.sqrt(r["var%d" % i])
                               for r in rows)

                for i in (0, 1, 2):  # x, y, heading
                    self.assertLess(largest_move(i), 0.01, "%s x%d" % (node, i))
                # ... while the travelled distance, which later wheel readings inform, moves
                self.assertGreater(largest_move(4), 0.1, node)


class RefusalTest(unittest.TestCase):
    def test_particle_filter_has_no_smoother(self):
        exe = built_exe("sf_train_pf")
        with tempfile.TemporaryDirectory(prefix="sf_smoothing_test_") as tmp:
            out = os.path.join(tmp, "pf.csv")
            proc = subprocess.run([exe, "--replay", PIONEER_BAG, "--smooth", "--csv", out],
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                  universal_newlines=True, timeout=120)
            self.assertNotEqual(proc.returncode, 0)
            self.assertIn("--smooth: the", proc.stderr)
            self.assertIn("has no smoother", proc.stderr)
            self.assertFalse(os.path.exists(out))


if __name__ == "__main__":
    unittest.main()
