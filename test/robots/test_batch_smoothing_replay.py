"""The replay's batch MAP track (`--replay BAG --smooth batch`, doc/smoothing.md): after the
forward run, the maximum-a-posteriori track of the whole recording by Gauss-Newton (the
iterated extended Kalman smoother), written in the smoothed_* columns that --smooth writes.

References: for a linear model the RTS smoother's track is the MAP track, so on
config/soccer_kf.h (a KF) with bags/soccer_lost_vision_ideal.bag `--smooth batch` must equal
`--smooth` to 1e-9 relative (with 1e-3 of the column's largest magnitude as the floor for
values near zero; measured 1.5e-11), after two iterations (the first exact, the second
confirming). On config/diff_drive_odom_imu.h (an EKF) with bags/diff_drive_seed1.bag the RTS
pass linearises each transition about the filtered estimate instead of iterating: the MAP
track differs from it by an error of first order in the noise (in standard deviations),
measured as 0.0048 smoothed standard deviations at most (7.9e-5 m of position); both tracks
are compared with the simulator's ground truth by tools/eval/evaluate.py (position RMSE
0.0263 m filtered, 0.01732 m RTS, 0.01733 m MAP). In both, the filtered columns are the plain
replay's and the summary reports the iterations, the costs and convergence. A filter without a
batch smoother (the particle filter) is refused.
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
DIFF_DRIVE_BAG = os.path.join(REPO, "bags", "diff_drive_seed1.bag")
PIONEER_BAG = os.path.join(REPO, "bags", "pioneer_seed1.bag")
POSE = ["pose_x", "pose_y", "pose_heading"]
# The EKF bag: MAP - RTS of any state at most 0.05 smoothed standard deviations (measured
# 0.0048, the pose; the other states' transitions are linear and agree to 1e-12). In standard
# deviations the RTS pass's error is of first order in the noise (test_rts_smoother.cpp: 0.45
# on its unicycle, 0.045 with the noise ten times smaller); the heading, whose spread makes the
# transition nonlinear, has a smoothed standard deviation below 0.025 rad here, so a gap ten
# times the measured one would be a wrong step, not that error.
GAP_BOUND = 0.05
# ... and at least 1e-3 of a standard deviation: the iterations moved the track (a batch mode
# that only ran the RTS pass would agree to 1e-12).
MIN_GAP = 1e-3


def run_three(node, bag, tmp):
    """The plain, --smooth and --smooth batch replays of `bag`: their rows and the batch run."""
    paths = [os.path.join(tmp, name + ".csv") for name in ("plain", "rts", "batch")]
    replay_exe(node, bag, paths[0])
    replay_exe(node, bag, paths[1], "--smooth")
    proc = replay_exe(node, bag, paths[2], "--smooth", "batch")
    return paths, proc


def smoothed_keys(row):
    return [k for k in row if k.startswith("smoothed_")]


def summary_numbers(stdout):
    """(iterations, cost, filtered cost, converged) of the summary's batch line."""
    line = next(l for l in stdout.splitlines() if "batch MAP track:" in l)
    words = line.replace(",", "").replace("(", "").replace(")", "").split()
    iterations = int(words[words.index("iterations") - 1])
    cost = float(words[words.index("cost") + 1])
    filtered = float(words[words.index("track", words.index("cost")) + 1])
    return iterations, cost, filtered, "NOT converged" not in line


class BatchSmoothingCase(unittest.TestCase):
    """Shared checks; subclasses set NODE and BAG."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix="sf_batch_smoothing_test_")
        paths, cls.proc = run_three(cls.NODE, cls.BAG, cls.tmp.name)
        cls.plain_path, cls.rts_path, cls.batch_path = paths
        cls.plain, cls.rts, cls.batch = (read_rows(p) for p in paths)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def check_filtered_columns_are_the_plain_replay(self):
        assert_smoothed_csv_extends_plain(self, self.plain_path, self.batch_path, self.proc)


class LinearBatchSmoothingTest(BatchSmoothingCase):
    NODE, BAG = "sf_soccer_kf", SOCCER_BAG

    def test_filtered_columns_are_the_plain_replay(self):
        self.check_filtered_columns_are_the_plain_replay()

    def test_batch_track_is_the_rts_track(self):
        keys = smoothed_keys(self.rts[0])
        self.assertGreater(len(keys), 10)
        floor = {k: max(abs(r[k]) for r in self.rts) for k in keys}
        worst = 0.0
        for rts, batch in zip(self.rts, self.batch):
            for k in keys:
                worst = max(worst, abs(batch[k] - rts[k]) / max(abs(rts[k]), 1e-3 * floor[k]))
        self.assertLess(worst, 1e-9)
        # ... and not the filtered one (the comparison is not vacuous).
        moved = max(abs(r["smoothed_x0"] - r["x0"]) for r in self.batch)
        self.assertGreater(moved, 1e-3)

    def test_two_iterations_and_a_lower_cost(self):
        iterations, cost, filtered, converged = summary_numbers(self.proc.stdout)
        self.assertEqual(iterations, 2)
        self.assertTrue(converged)
        self.assertLess(cost, filtered)


class NonlinearBatchSmoothingTest(BatchSmoothingCase):
    NODE, BAG = "sf_diff_drive_odom_imu", DIFF_DRIVE_BAG

    def test_filtered_columns_are_the_plain_replay(self):
        self.check_filtered_columns_are_the_plain_replay()

    def test_converged_to_a_lower_cost(self):
        iterations, cost, filtered, converged = summary_numbers(self.proc.stdout)
        self.assertTrue(converged)
        self.assertGreater(iterations, 2)
        self.assertLess(cost, filtered)

    def test_gap_to_the_rts_track(self):
        """Largest |MAP - RTS| of each state in smoothed standard deviations."""
        n = len([k for k in self.batch[0] if k.startswith("smoothed_var")])
        gaps = [max(abs(b["smoothed_x%d" % i] - r["smoothed_x%d" % i])
                    / math.sqrt(b["smoothed_var%d" % i]) for b, r in zip(self.batch, self.rts))
                for i in range(n)]
        message = "MAP - RTS in smoothed std. deviations: " + ", ".join("%.3g" % g for g in gaps)
        self.assertLess(max(gaps), GAP_BOUND, message)
        self.assertGreater(max(gaps), MIN_GAP, message)

    def test_accuracy_against_the_truth(self):
        truth = evaluate.load_truth(self.BAG)
        rmse = {}
        for label, prefix, path in (("filtered", "", self.batch_path),
                                    ("rts", "smoothed_", self.rts_path),
                                    ("batch", "smoothed_", self.batch_path)):
            rmse[label] = evaluate.evaluate(
                evaluate.load_result_csv(path, [prefix + c for c in POSE]), truth).rmse_pos
        message = "position RMSE [m]: " + ", ".join("%s %.5f" % kv for kv in sorted(rmse.items()))
        self.assertLess(rmse["batch"], 0.75 * rmse["filtered"], message)  # measured 0.66
        # The two tracks' RMSEs differ by at most the RMS of their difference (triangle
        # inequality), 3.8e-5 m measured: 1 % of the RMSE is 1.7e-4 m.
        self.assertLess(abs(rmse["batch"] - rmse["rts"]), 0.01 * rmse["rts"], message)


class DeadReckoningBatchSmoothingTest(unittest.TestCase):
    """config/nav3ctrl_ekf.h: five of its seven states have no process noise (the pose, the
    travelled distance, the speed), so their transitions are constraints, which the smoother
    keeps by rolling them forward; judged by a cost that ignored them, the steps had stalled
    (4 iterations, not converged). The pose is measured by nothing, the speed by the wheels."""

    def test_converges_and_keeps_the_pose_unobserved(self):
        with tempfile.TemporaryDirectory(prefix="sf_batch_smoothing_test_") as tmp:
            for node in ("sf_nav3ctrl_ekf", "sf_nav3ctrl_ukf"):
                csv_path = os.path.join(tmp, node + ".csv")
                proc = replay_exe(node, PIONEER_BAG, csv_path, "--smooth", "batch")
                iterations, cost, filtered, converged = summary_numbers(proc.stdout)
                self.assertTrue(converged, node)
                self.assertLessEqual(cost, filtered, node)
                rows = read_rows(csv_path)
                # The transitions hold: the travelled distance x4 of a period is v x5 T.
                for before, after in zip(rows, rows[1:]):
                    self.assertAlmostEqual(after["smoothed_x4"], before["smoothed_x5"] * 0.1,
                                           delta=1e-9)


class RefusalTest(unittest.TestCase):
    def test_particle_filter_has_no_batch_smoother(self):
        exe = built_exe("sf_train_pf")
        with tempfile.TemporaryDirectory(prefix="sf_batch_smoothing_test_") as tmp:
            out = os.path.join(tmp, "pf.csv")
            proc = subprocess.run([exe, "--replay", PIONEER_BAG, "--smooth", "batch", "--csv", out],
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                  universal_newlines=True, timeout=120)
            self.assertNotEqual(proc.returncode, 0)
            self.assertIn("--smooth batch: the", proc.stderr)
            self.assertIn("has no batch smoother", proc.stderr)
            self.assertFalse(os.path.exists(out))


if __name__ == "__main__":
    unittest.main()
