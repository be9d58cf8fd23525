"""The offline replay with the node's private parameters (issue 13 item 2, replay parity):
`--params FILE.yaml` is parsed and checked by the node's own code (ros_parameters.hpp through
a YAML ParameterSource), topic remaps `FROM:=TO` as rosrun takes them, and
`--static-transform X Y Z YAW PITCH ROLL PARENT CHILD` for a bag without /tf_static.

Through sf_diff_drive_odom_imu (config/diff_drive_odom_imu.h) on the small bags of
test_replay_faults.py. References: the replay's own options, whose meaning is independent
of the YAML path (--scale-r multiplies the header's R, --estimation-period sets the period,
--gate sets a chi-square threshold: k sigma on a scalar input is k^2), and the replay of the
same data under the configured topic names with the transform in the bag.
"""

import math
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True
from test_replay_faults import executable, write_small_bag  # noqa: E402

# the header's R diagonal (config/diff_drive_odom_imu.h); times 4, a power of two, so that
# the YAML's numbers equal the header's scaled by --scale-r 4 to the last bit
HEADER_R = (2.5e-5, 4e-4, 1.25e-5)


class ReplayParametersTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.exe = executable()

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory(prefix="sf_replay_params_")
        self.bag = self.path("in.bag")
        write_small_bag(self.bag)

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.tmp.name, name)

    def replay(self, bag, *extra, exe=None):
        csv = self.path("out_%d.csv" % len(os.listdir(self.tmp.name)))
        proc = subprocess.run([exe or self.exe, "--replay", bag, "--csv", csv] + list(extra),
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              universal_newlines=True, timeout=120)
        text = None
        if os.path.exists(csv):
            with open(csv) as f:
                text = f.read()
        return proc, text

    def yaml(self, text):
        path = self.path("params.yaml")
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_params_file_equals_the_options(self):
        r = [[0.0] * 3 for _ in range(3)]
        for k, v in enumerate(HEADER_R):
            r[k][k] = v * 4
        params = self.yaml("measurement_noise_covariance: %r\nestimation_period: 0.04\n"
                           "input_gate_sigma: [0, 0, 3]\n" % r)
        by_options, expected = self.replay(self.bag, "--scale-r", "4", "--estimation-period",
                                           "0.04", "--gate", "2=9")
        self.assertEqual(by_options.returncode, 0, by_options.stderr)
        by_file, got = self.replay(self.bag, "--params", params)
        self.assertEqual(by_file.returncode, 0, by_file.stderr)
        self.assertEqual(got, expected)
        # and the header alone differs (the file had an effect)
        plain, header = self.replay(self.bag)
        self.assertEqual(plain.returncode, 0, plain.stderr)
        self.assertNotEqual(header, expected)
        # an option overrides the file
        both, overridden = self.replay(self.bag, "--params", params, "--estimation-period",
                                       "0.02", "--scale-r", "1")
        self.assertEqual(both.returncode, 0, both.stderr)
        first, second = [float(line.split(",")[0]) for line in overridden.splitlines()[1:3]]
        self.assertAlmostEqual(second - first, 0.02, delta=2 * 2.0 ** -22)

    def test_params_file_refused_like_the_node(self):
        for text, words in (
                ("estimation_period: 50\n", "parameter ~estimation_period must be 0.0001 .. 10 s, "
                 "found 50 (seconds, not milliseconds: 50 ms is 0.05 s)"),
                ("measurement_noise_covariance: [1, 0, 0]\n",
                 "parameter ~measurement_noise_covariance: expected 9 numbers (3x3, row-major), "
                 "found 3"),
                ("frame_id: ''\n", "parameter ~frame_id: '' is not a tf2 frame name"),
                ("periods_on_clock_grid: 1\n",
                 "parameter ~periods_on_clock_grid: expected true or false, found"),
                ("unstamped_cadence: yes please\n",
                 "parameter ~unstamped_cadence: expected true or false, found"),
                ("[1, 2]\n", "expected a dictionary of private parameters")):
            with self.subTest(text=text):
                proc, out = self.replay(self.bag, "--params", self.yaml(text))
                self.assertEqual(proc.returncode, 2, proc.stderr)
                self.assertIn(words, proc.stderr.splitlines()[0])
                self.assertIsNone(out)

    def test_periods_on_the_clock_grid(self):
        # the schedule starts one lag before the first message; on the grid every period ends
        # on a multiple of the period in clock time (doc/filter_node.md)
        def phases(*extra):
            proc, text = self.replay(self.bag, "--estimation-period", "0.03", *extra)
            self.assertEqual(proc.returncode, 0, proc.stderr)
            times = [float(line.split(",")[0]) for line in text.splitlines()[1:]]
            return {round(math.fmod(t, 0.03), 6) % 0.03 for t in times}
        on_grid = phases("--params", self.yaml("periods_on_clock_grid: true\n"))
        self.assertTrue(all(min(p, 0.03 - p) < 1e-6 for p in on_grid), on_grid)
        self.assertFalse(all(min(p, 0.03 - p) < 1e-6 for p in phases()))

    def test_unknown_parameter_in_the_file_is_warned_about(self):
        proc, out = self.replay(self.bag, "--params", self.yaml("two_d_mode: true\n"))
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("unknown private parameter ~two_d_mode ignored (a robot_localization",
                      proc.stderr)

    def test_a_methods_own_parameter_from_the_file(self):
        """random_seed is the particle filter's own parameter, declared in its traits header
        (config/methods/particle_filter_sir.hpp) and read from there: the header's seed (1,
        config/pioneer/common.h) in the file gives the header's replay, another seed another
        one, a seed of the wrong type is refused by name. ukf_alpha, the UKF's, is known to a
        particle-filter node too (no unknown-parameter warning)."""
        exe = os.path.join(os.path.dirname(self.exe), "sf_nav1_pf")
        bag = os.path.join(HERE, "..", "..", "bags", "pioneer_seed1.bag")
        if not os.access(exe, os.X_OK):
            self.skipTest("sf_nav1_pf not built")
        plain, header = self.replay(bag, exe=exe)
        self.assertEqual(plain.returncode, 0, plain.stderr)
        same, got = self.replay(bag, "--params", self.yaml("random_seed: 1\nukf_alpha: 0.5\n"),
                                exe=exe)
        self.assertEqual(same.returncode, 0, same.stderr)
        self.assertNotIn("unknown private parameter", same.stderr)
        self.assertTrue(got == header, "random_seed 1 (the header's) changed the replay")
        other, moved = self.replay(bag, "--params", self.yaml("random_seed: 2\n"), exe=exe)
        self.assertEqual(other.returncode, 0, other.stderr)
        self.assertTrue(moved != header, "random_seed 2 did not change the replay")
        bad, out = self.replay(bag, "--params", self.yaml("random_seed: one\n"), exe=exe)
        self.assertEqual(bad.returncode, 2, bad.stderr)
        self.assertIn("parameter ~random_seed: expected an integer, found", bad.stderr)
        self.assertIsNone(out)

    def rewrite(self, name, rename=None, drop=()):
        """A copy of the input bag with topics renamed and some left out."""
        import rosbag

        path = self.path(name)
        with rosbag.Bag(self.bag) as src, rosbag.Bag(path, "w") as dst:
            for topic, msg, t in src.read_messages(raw=True):
                if topic in drop:
                    continue
                dst.write((rename or {}).get(topic, topic), msg, t, raw=True)
        return path

    def test_remapped_topics(self):
        plain, expected = self.replay(self.bag)
        self.assertEqual(plain.returncode, 0, plain.stderr)
        renamed = self.rewrite("renamed.bag", {"odom": "/robot/odom",
                                               "imu/data": "/robot/imu/data"})
        missing, _ = self.replay(renamed)
        self.assertEqual(missing.returncode, 1, missing.stderr)
        proc, got = self.replay(renamed, "odom:=/robot/odom", "imu/data:=/robot/imu/data")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(got, expected)
        wrong, _ = self.replay(renamed, "no_such_topic:=/x")
        self.assertEqual(wrong.returncode, 2, wrong.stderr)
        self.assertIn("no configured topic no_such_topic", wrong.stderr.splitlines()[0])

    def test_remap_onto_another_configured_topic_of_another_type(self):
        # odom (nav_msgs/Odometry) remapped onto imu/data, which the configuration reads as
        # sensor_msgs/Imu: refused with the type message (the replay read imu/data as Imu
        # only, the odometry "0 received", exit 0 even with --strict: issue 38 D5).
        for remap in ("odom:=imu/data", "odom:=/imu/data"):
            proc, csv = self.replay(self.bag, remap, "--strict")
            self.assertEqual(proc.returncode, 1, proc.stdout + proc.stderr)
            self.assertIn("topic /imu/data: two configured topics resolve onto it (a remap?), one "
                          "read as nav_msgs/Odometry, the other as sensor_msgs/Imu", proc.stderr)
            self.assertIsNone(csv)
        # Swapped, each is read from a topic of the other type: the bag's types are refused.
        swapped, _ = self.replay(self.bag, "odom:=imu/data", "imu/data:=odom")
        self.assertEqual(swapped.returncode, 1, swapped.stderr)
        self.assertIn("holds sensor_msgs/Imu, the configuration reads nav_msgs/Odometry",
                      swapped.stderr)

    def test_static_transform_for_a_bag_without_one(self):
        plain, expected = self.replay(self.bag)
        self.assertEqual(plain.returncode, 0, plain.stderr)
        bare = self.rewrite("no_tf.bag", drop=("/tf_static",))
        without, _ = self.replay(bare)
        self.assertEqual(without.returncode, 0, without.stderr)
        self.assertIn("100 values dropped: not rotatable", without.stdout)
        proc, got = self.replay(bare, "--static-transform", "0", "0", "0", "0", "0", "0",
                                "base_link", "imu_link")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("0 values dropped: not rotatable", proc.stdout)
        self.assertEqual(got, expected)


if __name__ == "__main__":
    unittest.main()
