#!/usr/bin/python3
"""End-to-end tests of tools/sim/diff_drive_sim.py's path and mount options: --no-stops (a
path never at rest), --imu-mount level, and the defaults, which must still write the
shipped bags byte for byte.

The checks read only the written bag (ground truth and IMU messages) and compare with
values worked out here from the options, never with an output copied from a run. Needs the
ROS python modules: run with /usr/bin/python3, e.g. test/eval/run_unittests.py sim_paths.
"""

import math
import os
import shutil
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
REPO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
SIM = os.path.join(REPO, "tools", "sim")
sys.path.insert(0, SIM)

REST_SPEED = 0.02   # [m/s] below this and REST_RATE the robot counts as at rest
REST_RATE = 0.02    # [rad/s]


def yaw_of(q):
    return 2.0 * math.atan2(q.z, q.w)


def unwrap(angles):
    out = [angles[0]]
    for a in angles[1:]:
        out.append(out[-1] + math.atan2(math.sin(a - out[-1]), math.cos(a - out[-1])))
    return out


def longest_rest(poses):
    """Longest run of consecutive ground-truth intervals (t, x, y, yaw) in which both the
    speed and the yaw rate, by finite differences, are below the rest thresholds."""
    run = longest = 0
    for (t0, x0, y0, a0), (t1, x1, y1, a1) in zip(poses, poses[1:]):
        dt = t1 - t0
        at_rest = (math.hypot(x1 - x0, y1 - y0) / dt < REST_SPEED and abs(a1 - a0) / dt < REST_RATE)
        run = run + 1 if at_rest else 0
        longest = max(longest, run)
    return longest


class DiffDriveSimPathsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        try:
            import diff_drive_sim
            import pioneer_sim
            import rosbag
        except ImportError as exc:  # no ROS python modules
            raise unittest.SkipTest("needs the ROS python modules: %s" % exc)
        cls.diff, cls.pioneer, cls.rosbag = diff_drive_sim, pioneer_sim, rosbag
        cls.tmp = tempfile.mkdtemp(prefix="sf_sim_paths_")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def simulate(self, name, argv):
        path = os.path.join(self.tmp, name)
        with open(os.devnull, "w") as null:
            saved, sys.stdout = sys.stdout, null
            try:
                self.assertEqual(self.diff.main(argv + ["--out", path]), 0)
            finally:
                sys.stdout = saved
        return path

    def read(self, path):
        """(ground truth poses (t, x, y, unwrapped yaw), IMU (t, x, y, z) rates, tf_static)"""
        poses, gyro, static = [], [], []
        with self.rosbag.Bag(path) as bag:
            for topic, msg, _ in bag.read_messages():
                if topic == "ground_truth/pose":
                    p = msg.pose
                    poses.append((msg.header.stamp.to_sec(), p.position.x, p.position.y,
                                  yaw_of(p.orientation)))
                elif topic == "imu/data":
                    w = msg.angular_velocity
                    gyro.append((msg.header.stamp.to_sec(), w.x, w.y, w.z))
                elif topic == "tf_static":
                    static.extend(msg.transforms)
        yaws = unwrap([p[3] for p in poses])
        return [p[:3] + (a,) for p, a in zip(poses, yaws)], gyro, static

    def test_no_stops_path_is_never_at_rest(self):
        # the same seed and length with and without the option: the default path stands
        # still (at its start, its stops and its end: the detector finds them), the
        # --no-stops one never for more than one ground-truth interval (20 ms)
        args = ["--seed", "3", "--duration", "120", "--compression", "none"]
        default, _, _ = self.read(self.simulate("stops.bag", args))
        moving, _, _ = self.read(self.simulate("no_stops.bag", args + ["--no-stops"]))
        self.assertGreater(longest_rest(default), 50)   # at least 1 s at rest (the final 2 s)
        self.assertLessEqual(longest_rest(moving), 1)
        # the requested length at 50 Hz, and a path that goes somewhere
        self.assertEqual(len(moving), 120 * 50 + 1)
        self.assertAlmostEqual(moving[-1][0] - moving[0][0], 120.0, places=6)
        travelled = sum(math.hypot(b[1] - a[1], b[2] - a[2]) for a, b in zip(moving, moving[1:]))
        self.assertGreater(travelled, 120 * self.pioneer.V_MOVING_MIN)

    def test_no_stops_with_realistic_errors_is_never_at_rest(self):
        # --realistic husky adds the lateral slip to the true motion: still never at rest
        path = self.simulate("no_stops_husky.bag", ["--seed", "4", "--duration", "60", "--compression",
                                                    "none", "--no-stops", "--realistic", "husky"])
        self.assertLessEqual(longest_rest(self.read(path)[0]), 1)

    def test_level_mount_puts_the_yaw_rate_on_z(self):
        # gyro bias (bx, by, bz) in the IMU's frame; planar motion: with a level mount the
        # mean of z is the mean true yaw rate (heading change / time) plus bz, x and y read
        # their bias only. Noise 0.005 rad/s over 6000 samples: std of a mean 6.5e-5 rad/s.
        # --no-stops: the default path ends at its start heading (mean yaw rate 0)
        bias = (0.004, 0.012, -0.006)
        path = self.simulate("level.bag", ["--seed", "2", "--duration", "60", "--compression", "none",
                                           "--no-stops", "--imu-mount", "level",
                                           "--gyro-bias", "%g,%g,%g" % bias])
        poses, gyro, static = self.read(path)
        self.assertEqual(len(static), 1)
        q = static[0].transform.rotation
        self.assertEqual((q.x, q.y, q.z, q.w), (0.0, 0.0, 0.0, 1.0))
        mean_rate = (poses[-1][3] - poses[0][3]) / (poses[-1][0] - poses[0][0])
        self.assertGreater(abs(mean_rate), 1e-3)   # the path turns: z is told apart from x, y
        means = [sum(g[i] for g in gyro) / len(gyro) for i in (1, 2, 3)]
        for got, want in zip(means, (bias[0], bias[1], mean_rate + bias[2])):
            self.assertLess(abs(got - want), 5e-4, (means, mean_rate))
        self.assertAlmostEqual(self.diff.base_z_bias(bias, self.diff.MOUNTS["level"]), bias[2], places=12)

    def test_defaults_write_the_shipped_bag(self):
        # tools/sim/make_bags.sh's command for bags/diff_drive_seed1.bag, byte for byte
        path = self.simulate("diff_drive_seed1.bag", ["--seed", "1", "--duration", "60"])
        with open(path, "rb") as made, open(os.path.join(REPO, "bags", "diff_drive_seed1.bag"), "rb") as shipped:
            self.assertTrue(made.read() == shipped.read(), "diff_drive_sim's defaults changed the bag")


if __name__ == "__main__":
    unittest.main()
