"""Unit tests of tools/eval/wheel_gyro_reference.py on synthetic tracks: the yaw integral of
a piecewise-linear gyro signal against hand-computed values, and the dead-reckoned pose of
a straight line, a circle and a track whose gyro runs at another rate than the odometry,
against their closed forms."""

import math
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(REPO, "tools", "eval"))
import evaluate as ev  # noqa: E402
import wheel_gyro_reference as wg  # noqa: E402


class YawIncrement(unittest.TestCase):
    def test_constant_and_ramp(self):
        self.assertAlmostEqual(wg.yaw_increment([(0.0, 0.5), (10.0, 0.5)], 1.0, 3.0), 1.0)
        # omega(t) = t on [0, 4]: integral over (1, 3] = (9 - 1) / 2 = 4
        ramp = [(0.0, 0.0), (2.0, 2.0), (4.0, 4.0)]
        self.assertAlmostEqual(wg.yaw_increment(ramp, 1.0, 3.0), 4.0)

    def test_held_outside_the_samples(self):
        # before the first sample 1, after the last 3; linear 1 -> 3 over [1, 2]
        samples = [(1.0, 1.0), (2.0, 3.0)]
        self.assertAlmostEqual(wg.yaw_increment(samples, 0.0, 1.0), 1.0)
        self.assertAlmostEqual(wg.yaw_increment(samples, 1.0, 2.0), 2.0)
        self.assertAlmostEqual(wg.yaw_increment(samples, 2.0, 4.0), 6.0)
        self.assertEqual(wg.yaw_increment(samples, 2.0, 2.0), 0.0)
        self.assertEqual(wg.yaw_increment([], 0.0, 1.0), 0.0)


class DeadReckon(unittest.TestCase):
    def test_straight_line(self):
        odom = [(0.1 * k, 0.5) for k in range(101)]
        t, x, y, h = wg.dead_reckon(odom, [(0.0, 0.0), (10.0, 0.0)])
        self.assertAlmostEqual(x[-1], 5.0, places=9)
        self.assertAlmostEqual(y[-1], 0.0, places=12)
        self.assertEqual(len(t), 101)

    def test_circle(self):
        # v = 1 m/s, omega = 0.2 rad/s: a circle of radius 5 m about (0, 5).
        v, w, dt = 1.0, 0.2, 0.1
        odom = [(dt * k, v) for k in range(201)]
        gyro = [(0.0125 * k, w) for k in range(1601)]   # 80 Hz gyro, 10 Hz odometry
        t, x, y, h = wg.dead_reckon(odom, gyro)
        r = v / w
        tf = t[-1]
        self.assertAlmostEqual(h[-1], w * tf, places=9)
        # Each step v dt along the mid heading instead of the chord 2 r sin(w dt / 2):
        # relative step error (w dt)^2 / 24 = 1.7e-5, so 20 m of path is off by < 1 mm.
        self.assertLess(math.hypot(x[-1] - r * math.sin(w * tf),
                                   y[-1] - r * (1 - math.cos(w * tf))), 1e-3)

    def test_gyro_bias_and_rates(self):
        # A gyro at 8 Hz with a ramp in yaw rate; the odometry at 10 Hz: the heading is the
        # exact integral of the ramp (the trapezoid rule is exact for linear pieces).
        odom = [(0.1 * k, 0.3) for k in range(51)]
        gyro = [(0.125 * k, 0.02 * 0.125 * k) for k in range(41)]  # omega(t) = 0.02 t
        t, x, y, h = wg.dead_reckon(odom, gyro)
        self.assertAlmostEqual(h[-1], 0.01 * t[-1] ** 2, places=9)

    def test_csv_is_read_as_a_replay_result(self):
        odom = [(100.0 + 0.1 * k, 0.5) for k in range(11)]
        track = wg.dead_reckon(odom, [(100.0, 0.1)])
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "hand.csv")
            wg.write_csv(path, track)
            traj = ev.load_result_csv(path)
        self.assertEqual(len(traj.t), 11)
        self.assertAlmostEqual(traj.heading[-1], 0.1, places=6)

    def test_no_odometry(self):
        with self.assertRaises(ValueError):
            wg.dead_reckon([], [])


if __name__ == "__main__":
    unittest.main()
