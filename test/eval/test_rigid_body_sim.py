"""Tests of tools/sim/rigid_body_sim.py: its analytic motion against finite differences (the
velocity and acceleration are the position's derivatives; the body rates turn the
orientation as a central difference of the rotation matrices does), the accelerometer's
specific force by hand (level and at rest: +g on z; rolled 90 degrees: +g on y), the
odometry's dead reckoning of the noise-free twist, and a written bag's topics, rates and
latency."""

import math
import os
import statistics
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(REPO, "tools", "sim"))
import rigid_body_sim as rb  # noqa: E402
from diff_drive_sim import rotation_rpy  # noqa: E402

SIM = os.path.join(REPO, "tools", "sim", "rigid_body_sim.py")


def vee_of_log(m):
    """Rotation vector of a small rotation matrix (first order: the skew part)."""
    return [(m[2][1] - m[1][2]) / 2, (m[0][2] - m[2][0]) / 2, (m[1][0] - m[0][1]) / 2]


class MotionTest(unittest.TestCase):
    def test_derivatives_are_the_finite_differences(self):
        for kind in ("slow", "fast"):
            motion = rb.Motion(kind)
            h = 1e-5
            for t in (0.0, 3.7, 41.2):
                p0, v0, a0, rpy0, rate0 = rb.pose(motion, t - h)
                p1, v1, a1, rpy1, rate1 = rb.pose(motion, t + h)
                _, v, a, rpy, rate = rb.pose(motion, t)
                for i in range(3):
                    self.assertAlmostEqual((p1[i] - p0[i]) / (2 * h), v[i], delta=1e-6)
                    self.assertAlmostEqual((v1[i] - v0[i]) / (2 * h), a[i], delta=1e-6)
                    self.assertAlmostEqual((rpy1[i] - rpy0[i]) / (2 * h), rate[i], delta=1e-6)
                # R(t + h) = R(t - h) exp(w 2h): the body rates from the rotation matrices.
                r0, r1 = rotation_rpy(*rpy0), rotation_rpy(*rpy1)
                relative = [[sum(r0[k][r] * r1[k][c] for k in range(3)) for c in range(3)]
                            for r in range(3)]
                omega = [x / (2 * h) for x in vee_of_log(relative)]
                for got, want in zip(omega, rb.body_rates(rpy, rate)):
                    self.assertAlmostEqual(got, want, delta=1e-6)

    def test_specific_force_by_hand(self):
        level = rb.specific_force([0.0, 0.0, 0.3], [0.0, 0.0, 0.0])
        for got, want in zip(level, (0.0, 0.0, rb.G)):
            self.assertAlmostEqual(got, want, delta=1e-12)
        # Rolled +90 degrees: the world's up is the body's +y.
        rolled = rb.specific_force([math.pi / 2, 0.0, 0.0], [0.0, 0.0, 0.0])
        for got, want in zip(rolled, (0.0, rb.G, 0.0)):
            self.assertAlmostEqual(got, want, delta=1e-12)
        # Level, accelerating 2 m/s^2 along the world's x with yaw 90 degrees: body -y.
        turned = rb.specific_force([0.0, 0.0, math.pi / 2], [2.0, 0.0, 0.0])
        for got, want in zip(turned, (0.0, -2.0, rb.G)):
            self.assertAlmostEqual(got, want, delta=1e-12)


class BagTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        try:
            import rosbag  # noqa: F401
        except ImportError:  # pragma: no cover - python3-rosbag is a package dependency
            raise unittest.SkipTest("python3-rosbag missing")
        cls.tmp = tempfile.TemporaryDirectory(prefix="rigid_body_test_")
        cls.bag = os.path.join(cls.tmp.name, "rb.bag")
        subprocess.run([sys.executable, SIM, "--seed", "2", "--duration", "20", "--imu-latency-ms",
                        "25", "--compression", "none", "--out", cls.bag], check=True,
                       stdout=subprocess.DEVNULL)
        import rosbag
        cls.messages = {}
        with rosbag.Bag(cls.bag) as bag:
            for topic, msg, t in bag.read_messages():
                cls.messages.setdefault(topic, []).append((t.to_sec(), msg))

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_topics_and_rates(self):
        counts = {topic: len(v) for topic, v in self.messages.items()}
        self.assertEqual(counts, {"imu/data": 2001, "odom": 1001, "vision/pose": 251,
                                  "ground_truth/pose": 2001, "tf_static": 1})

    def test_imu_latency_and_gravity(self):
        delays = [t - m.header.stamp.to_sec() for t, m in self.messages["imu/data"]]
        self.assertAlmostEqual(statistics.median(delays), 0.025, delta=1e-6)
        # Mean specific force's norm: g plus the motion's accelerations, which average out.
        norms = [math.sqrt(m.linear_acceleration.x ** 2 + m.linear_acceleration.y ** 2 +
                           m.linear_acceleration.z ** 2) for _, m in self.messages["imu/data"]]
        self.assertAlmostEqual(statistics.mean(norms), rb.G, delta=0.05)

    def test_odometry_dead_reckoning_stays_near_the_truth(self):
        # Noise 0.02 m/s per 20 ms step for 20 s: a random walk of about 0.02 * 0.02 * sqrt(1000)
        # = 0.013 m per axis, plus the heading's drift; 0.2 m bounds it with a wide margin, a
        # wrong frame (world twist integrated as body twist) is metres off.
        t_end, odom = self.messages["odom"][-1]
        truth = self.messages["ground_truth/pose"][-1][1].pose.position
        p = odom.pose.pose.position
        self.assertLess(math.dist((p.x, p.y, p.z), (truth.x, truth.y, truth.z)), 0.2)


if __name__ == "__main__":
    unittest.main()
