"""Unit tests of tools/sf_configure's decisions against hand-computed answers: the robot class
from the wheels' against the gyro's turn, the measurement lag from the delays, the period from
the rate, and the static transform that puts a found gyro axis on the base's z (checked by
rotating the axis with hand-written rotation matrices)."""

import importlib.machinery
import importlib.util
import math
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.dont_write_bytecode = True


def load_tool():
    path = os.path.join(REPO, "tools", "sf_configure")
    loader = importlib.machinery.SourceFileLoader("sf_configure", path)
    spec = importlib.util.spec_from_loader("sf_configure", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


sfc = load_tool()


def matrix_rpy(yaw, pitch, roll):
    """Rz(yaw) Ry(pitch) Rx(roll) written out (the tf2 / static_transform_publisher order)."""
    cy, sy, cp, sp, cr, sr = (math.cos(yaw), math.sin(yaw), math.cos(pitch), math.sin(pitch),
                              math.cos(roll), math.sin(roll))
    return [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr]]


class DecisionsTest(unittest.TestCase):
    def test_robot_class_by_the_wheels_turn(self):
        self.assertEqual(sfc.robot_class(1.0), sfc.DIFF_DRIVE)
        self.assertEqual(sfc.robot_class(1.09), sfc.DIFF_DRIVE)
        self.assertEqual(sfc.robot_class(0.91), sfc.DIFF_DRIVE)
        self.assertEqual(sfc.robot_class(1.11), sfc.SKID_STEER)
        self.assertEqual(sfc.robot_class(2.06), sfc.SKID_STEER)  # the Husky recording
        with self.assertRaisesRegex(sfc.ConfigureError, "0.50 times the gyro's turn"):
            sfc.robot_class(0.5)

    def test_lag_is_the_worst_p99_plus_20_ms_delivery_rounded_up_to_5_ms(self):
        # 9.5 ms + 20 = 29.5 -> 30; 34.2 + 20 = 54.2 -> 55; exactly 15 + 20 = 35 stays 35;
        # delays of 0 (a recording stamped at arrival) -> the delivery's 20 alone.
        self.assertAlmostEqual(sfc.measurement_lag([0.004, 0.0095]), 0.030, delta=1e-12)
        self.assertAlmostEqual(sfc.measurement_lag([0.0, 0.0342]), 0.055, delta=1e-12)
        self.assertAlmostEqual(sfc.measurement_lag([0.015]), 0.035, delta=1e-12)
        self.assertAlmostEqual(sfc.measurement_lag([0.0, 0.0]), 0.020, delta=1e-12)
        self.assertAlmostEqual(sfc.measurement_lag([]), 0.020, delta=1e-12)
        self.assertAlmostEqual(sfc.measurement_lag([None, 0.001]), 0.025, delta=1e-12)

    def test_period_is_one_over_the_rate_in_milliseconds(self):
        self.assertAlmostEqual(sfc.estimation_period(10.0), 0.1, delta=1e-12)
        self.assertAlmostEqual(sfc.estimation_period(8.3), 0.120, delta=1e-12)
        self.assertAlmostEqual(sfc.estimation_period(50.0), 0.02, delta=1e-12)

    def test_static_transform_puts_the_gyro_axis_on_the_base_z(self):
        for axis in range(3):
            for sign in (1, -1):
                ypr = sfc.yaw_axis_transform(axis, sign)
                m = matrix_rpy(*ypr)
                # The IMU's axis `axis` with `sign`, in the base frame: the column of m.
                in_base = [sign * m[row][axis] for row in range(3)]
                for got, want in zip(in_base, (0.0, 0.0, 1.0)):
                    self.assertAlmostEqual(got, want, delta=1e-12, msg="axis %d sign %d" % (axis, sign))
                for got, want in zip(sfc.rotate(ypr, [sign * (k == axis) for k in range(3)]),
                                     in_base):
                    self.assertAlmostEqual(got, want, delta=1e-12)


def tf_message(*edges):
    """A tf message (attribute access as rosbag's) of (parent, child, z, yaw) edges."""
    ns = lambda **kw: type("M", (), kw)  # noqa: E731
    return ns(transforms=[ns(header=ns(frame_id=parent), child_frame_id=child, transform=ns(
        translation=ns(x=0.0, y=0.0, z=z),
        rotation=ns(x=0.0, y=0.0, z=math.sin(yaw / 2), w=math.cos(yaw / 2))))
        for parent, child, z, yaw in edges])


class MountOnTfTest(unittest.TestCase):
    """A mount published on /tf with one value throughout is written as static transforms
    (the Husky recording: base_footprint -> base_link -> imu_link on /tf, leading slashes)."""

    def test_a_constant_chain_on_tf_becomes_static_transforms(self):
        msgs = [(False, tf_message(("/base_footprint", "/base_link", 0.1386, 0.0),
                                   ("/base_link", "/wheel", 0.0, 0.5 * k)))
                for k in range(3)] + [(False, tf_message(("/base_link", "/imu_link", 0.0, 0.3)))] * 2
        edges = sfc.constant_tf_edges(msgs, "base_footprint", "imu_link")
        self.assertEqual([(p, c) for p, c, _, _ in edges],
                         [("base_link", "imu_link"), ("base_footprint", "base_link")])
        self.assertAlmostEqual(edges[0][3][0], 0.3, delta=1e-9)  # yaw
        self.assertAlmostEqual(edges[1][2][2], 0.1386, delta=1e-9)  # z
        config = {"static_transform": None, "tf_edges": edges}
        self.assertEqual(sfc.static_transforms(config)[1],
                         ("static_base_link", ["0", "0", "0.1386", "0", "0", "0",
                                               "base_footprint", "base_link"]))

    def test_a_moving_or_unconnected_mount_is_left_to_tf(self):
        moving = [(False, tf_message(("base_link", "imu_link", 0.0, 0.1 * k))) for k in range(2)]
        self.assertEqual(sfc.constant_tf_edges(moving, "base_link", "imu_link"), [])
        other_tree = [(False, tf_message(("map", "imu_link", 0.0, 0.0)))]
        self.assertEqual(sfc.constant_tf_edges(other_tree, "base_link", "imu_link"), [])
        # on /tf_static already: nothing to add
        static = [(True, tf_message(("base_link", "imu_link", 0.0, 0.0)))]
        self.assertEqual(sfc.constant_tf_edges(static, "base_link", "imu_link"), [])

    def test_the_node_publishes_the_base_frame_and_leaves_an_existing_parent_alone(self):
        config = {"estimation_period": 0.1, "max_measurement_lag": 0.03,
                  "base_frame": "base_footprint", "base_has_parent": False}
        params = sfc.parameters(config)
        self.assertEqual(params["child_frame_id"], "base_footprint")
        self.assertNotIn("publish_tf", params)
        odom = [(False, tf_message(("odom_combined", "base_footprint", 0.0, 0.0)))]
        config["base_has_parent"] = sfc.has_tf_parent(odom, "base_footprint")
        self.assertIs(sfc.parameters(config)["publish_tf"], False)


# --tune's lines as the node prints them (abridged from the Husky recording's): a first
# identification, the entries' verdicts, the identification again with the identified ones,
# the hold-out guard, the tuned NIS.
TUNE_OUTPUT = """\
sf_x: --tune: Q.3    start 0.025        tuned 0.0006       (x 0.024)
sf_x: --tune: R.0    start 0.0001       tuned 1.8e-07      (x 0.0018)
sf_x: --tune: Q.3    identified: the cost rises by 115.8 at x 1/2 and by 72.97 at x 2
sf_x: --tune: R.0    not identified: the cost rises by -0.0882 at x 1/2 and by 0.1764 at x 2 (below 3.84: flat)
sf_x: --tune: R.0    kept at its start value (--tune-keep-unidentified writes the tuned one)
sf_x: --tune: again with the identified entries only
sf_x: --tune: Q.3    start 0.025        tuned 0.000651515  (x 0.02606)
sf_x: --tune: hold-out: tuned on the first 70 % of the recording (29 replays), on the last 30 % (114 periods) mean log det S + NIS per period: start -0.8, tuned -5.5; gain 539 against 3.841 (chi-square 95 %, 1 entries): better
sf_x (tuned): NIS input 0 (odom twist.twist.linear.x): mean 0.854 over 379 periods (expected 1; lag-1 autocorrelation 0.2, worth 250 independent periods), 95 % bounds [0.8, 1.2]: consistent; window of 300 periods inconsistent in 0 of 80 judged periods
sf_x: --tune: wrote robot_tuned.yaml
"""


class TuneSummaryTest(unittest.TestCase):
    def test_identified_entries_changed_unidentified_kept_and_the_guards_verdict(self):
        self.assertEqual(sfc.tune_summary(TUNE_OUTPUT), [
            "- `Q.3` identified (the cost rises by 115.8 at x 1/2 and by 72.97 at x 2): "
            "0.025 -> 0.000651515",
            "- `R.0` not identified (the cost rises by -0.0882 at x 1/2 and by 0.1764 at x 2 "
            "(below 3.84: flat)): kept at 0.0001",
            "- hold-out guard: tuned on the first 70 % of the recording (29 replays), on the last "
            "30 % (114 periods) mean log det S + NIS per period: start -0.8, tuned -5.5; gain 539 "
            "against 3.841 (chi-square 95 %, 1 entries): better",
            "- tuned NIS input 0 (odom twist.twist.linear.x): mean 0.854 (expected 1): consistent"])

    def test_the_guard_keeping_the_start_values_changes_nothing(self):
        kept = TUNE_OUTPUT.replace(": better", ": not better: ...").replace(
            "wrote robot_tuned.yaml", "wrote robot_tuned.yaml with the start values")
        lines = sfc.tune_summary(kept)
        self.assertEqual(lines[0], "- `Q.3` identified (the cost rises by 115.8 at x 1/2 and by "
                                   "72.97 at x 2): kept at 0.025")


class OutputsTest(unittest.TestCase):
    """Every output is checked as the C++ tools check theirs (doc/reliability.md): an output
    that is an input, or a symbolic link, is refused before anything is written."""

    def run_tool(self, *args):
        return subprocess.run([sys.executable, os.path.join(REPO, "tools", "sf_configure")] + list(args),
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True,
                              timeout=120)

    def test_an_output_that_is_the_input_bag_is_refused(self):
        with tempfile.TemporaryDirectory(prefix="sf_configure_out_") as tmp:
            bag = os.path.join(tmp, "robot.launch")
            os.link(os.path.join(REPO, "bags", "diff_drive_seed1.bag"), bag)
            before = os.stat(bag)
            proc = self.run_tool(bag, "--out", tmp, "--no-replay")
            self.assertEqual(proc.returncode, 1, proc.stdout + proc.stderr)
            self.assertIn("is the input", proc.stderr)
            self.assertEqual(os.stat(bag).st_size, before.st_size)
            self.assertEqual(sorted(os.listdir(tmp)), ["robot.launch"])

    def test_a_symbolic_link_is_refused_and_its_target_kept(self):
        with tempfile.TemporaryDirectory(prefix="sf_configure_out_") as tmp:
            target = os.path.join(tmp, "kept.md")
            with open(target, "w") as f:
                f.write("mine\n")
            os.symlink(target, os.path.join(tmp, "report.md"))
            proc = self.run_tool(os.path.join(REPO, "bags", "diff_drive_seed1.bag"), "--out", tmp,
                                 "--no-replay")
            self.assertEqual(proc.returncode, 1, proc.stdout + proc.stderr)
            self.assertIn("report.md: it is not a regular file", proc.stderr)
            with open(target) as f:
                self.assertEqual(f.read(), "mine\n")
            self.assertFalse(os.path.exists(os.path.join(tmp, "robot.yaml")))


if __name__ == "__main__":
    unittest.main()
