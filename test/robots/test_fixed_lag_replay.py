"""The replay's fixed-lag smoothing (`--replay BAG --smooth-lag SECONDS`, doc/smoothing.md):
each CSV row gets lagged_* columns, its own period smoothed with the readings up to the lag
later (NaN for the last lag's rows).

Reference: the offline smoother of the same recording cut where the lag ends. A row's lagged
belief uses the periods up to L periods later; the replay of the recording cut after the
period P ends (plus the maximum measurement lag, so that P is estimated from the same values
as in the whole run) and smoothed with --smooth gives, for its period P - L, the smoothed belief
given the periods up to P: the same numbers, computed by the full backward pass instead of the
fixed-lag ring. Checked on config/diff_drive_odom_imu.h (an EKF, 20 ms periods) with
bags/diff_drive_seed1.bag and a lag of 0.5 s (25 periods); the filtered columns must be the
plain replay's, and the output bag must carry odometry/smoothed.

The smoother's report (issue 39 item 4): the summary's lag, periods held and the smoothing
correction (what stands for a NIS, doc/smoothing.md), recomputed here from the CSV's filtered
and lagged (or smoothed) columns. The full pass's bag (`--smooth --bag`): its odometry/smoothed
must be the CSV's smoothed_pose_* columns, one message per period at the period's time.
"""

import math
import os
import re
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True
from replay_helpers import REPO, built_lib_dir, correction, read_rows, replay_exe  # noqa: E402

BAG = os.path.join(REPO, "bags", "diff_drive_seed1.bag")
NODE = "sf_diff_drive_odom_imu"
LAG_S, PERIOD_S, MAX_MEASUREMENT_LAG_S = 0.5, 0.02, 0.02  # the header's period and lag
LAG = int(round(LAG_S / PERIOD_S))
# The summary prints with 6 significant digits (std::cout's default); the CSV has 17.
SUMMARY_RELATIVE = 1e-5
ANGLE_STATES = (2,)  # the header's ANGLE_STATES: the heading


def cut_bag(source, target, end):
    """`source`'s messages recorded up to `end` [s], and every /tf_static message."""
    import rosbag
    with rosbag.Bag(source) as bag, rosbag.Bag(target, "w") as out:
        for topic, msg, t, header in bag.read_messages(return_connection_header=True):
            if t.to_sec() <= end or topic.lstrip("/") == "tf_static":
                out.write(topic, msg, t, connection_header=header)


def summary_correction(stdout):
    """(periods, RMS, expected RMS, last, last expected) of the summary's correction line."""
    number = r"([-+0-9.eE]+)"
    m = re.search(r"smoothing correction over (\d+) periods: RMS %s filtered standard deviations "
                  r"\(expected %s\), last period %s \(expected %s\)" % ((number,) * 4), stdout)
    if not m:
        raise AssertionError("no smoothing correction in the summary:\n" + stdout)
    return (int(m.group(1)),) + tuple(float(g) for g in m.groups()[1:])


class CorrectionCheck:
    """The summary's correction figures against the CSV's rows."""

    def assert_correction(self, stdout, rows, prefix):
        figures = [c for c in (correction(r, prefix, ANGLE_STATES) for r in rows) if c is not None]
        periods, rms, expected, last, last_expected = summary_correction(stdout)
        self.assertEqual(periods, len(figures))
        for value, reference in (
                (rms, math.sqrt(sum(c[0] for c in figures) / len(figures))),
                (expected, math.sqrt(sum(c[1] for c in figures) / len(figures))),
                (last, math.sqrt(figures[-1][0])), (last_expected, math.sqrt(figures[-1][1]))):
            self.assertAlmostEqual(value, reference, delta=SUMMARY_RELATIVE * abs(reference))
        self.assertGreater(rms, 0.01)  # the smoother moved the estimates


class FixedLagReplayTest(unittest.TestCase, CorrectionCheck):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix="sf_fixed_lag_test_")
        path = lambda name: os.path.join(cls.tmp.name, name)
        replay_exe(NODE, BAG, path("plain.csv"))
        cls.proc = replay_exe(NODE, BAG, path("lagged.csv"), "--smooth-lag", str(LAG_S), "--bag",
                              path("lagged.bag"))
        cls.plain, cls.lagged = read_rows(path("plain.csv")), read_rows(path("lagged.csv"))
        cls.bag_out = path("lagged.bag")
        # Cut after the period that ends 30 s into the run, plus the measurement lag.
        cls.cut_period = 1500
        end = cls.plain[cls.cut_period]["time"] + MAX_MEASUREMENT_LAG_S + 1e-6
        cut_bag(BAG, path("cut.bag"), end)
        replay_exe(NODE, path("cut.bag"), path("cut.csv"), "--smooth")
        cls.cut = read_rows(path("cut.csv"))

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_filtered_columns_are_the_plain_replay(self):
        self.assertEqual(len(self.lagged), len(self.plain))
        for plain, lagged in zip(self.plain, self.lagged):
            for key, value in plain.items():
                self.assertEqual(lagged[key], value, key)

    def test_lag_in_periods_and_the_last_rows_without(self):
        self.assertIn("fixed-lag smoother, lag %d periods" % LAG, self.proc.stdout)
        self.assertTrue(all(math.isnan(r["lagged_x0"]) for r in self.lagged[-LAG:]))
        self.assertFalse(any(math.isnan(r["lagged_x0"]) for r in self.lagged[:-LAG]))

    def test_lagged_row_is_the_full_pass_over_the_recording_up_to_the_lag(self):
        row = self.cut_period - LAG
        self.assertEqual(self.cut[self.cut_period]["time"], self.plain[self.cut_period]["time"])
        self.assertEqual(self.cut[row]["time"], self.lagged[row]["time"])
        keys = [k for k in self.lagged[row] if k.startswith("lagged_")]
        self.assertGreater(len(keys), 10)
        moved = 0.0
        for key in keys:
            smoothed = self.cut[row]["smoothed_" + key[len("lagged_"):]]
            self.assertAlmostEqual(self.lagged[row][key], smoothed,
                                   delta=1e-9 * (1.0 + abs(smoothed)), msg=key)
            filtered = self.lagged[row][key[len("lagged_"):]]
            moved = max(moved, abs(smoothed - filtered))
        self.assertGreater(moved, 1e-6)  # the smoother moved the row: not the filtered values

    def test_summary_reports_the_smoother(self):
        m = re.search(r"fixed-lag smoother, lag (\d+) periods \(([0-9.eE+-]+) s; ([0-9.eE+-]+) s "
                      r"asked\), (\d+) periods held, (\d+) bytes held", self.proc.stdout)
        self.assertTrue(m, self.proc.stdout)
        self.assertEqual(int(m.group(1)), LAG)
        self.assertAlmostEqual(float(m.group(2)), LAG * PERIOD_S, delta=1e-9)
        self.assertEqual(float(m.group(3)), LAG_S)
        self.assertEqual(int(m.group(4)), LAG + 1)  # the ring is full at the end of the run
        self.assertGreater(int(m.group(5)), (LAG + 1) * (6 + 36) * 8)  # at least x and P held
        self.assert_correction(self.proc.stdout, self.lagged, "lagged_")

    def test_output_bag_has_the_smoothed_odometry(self):
        import rosbag
        with rosbag.Bag(self.bag_out) as bag:
            topics = bag.get_type_and_topic_info().topics
        self.assertEqual(topics["/odometry/smoothed"].msg_type, "nav_msgs/Odometry")
        self.assertEqual(topics["/odometry/smoothed"].message_count, len(self.lagged) - LAG)


class FullPassReplayTest(unittest.TestCase, CorrectionCheck):
    """`--smooth --bag`: the full pass's estimates in the output bag, and its report."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix="sf_full_pass_test_")
        cls.bag_out = os.path.join(cls.tmp.name, "smoothed.bag")
        cls.proc = replay_exe(NODE, BAG, os.path.join(cls.tmp.name, "smoothed.csv"), "--smooth",
                              "--bag", cls.bag_out)
        cls.rows = read_rows(os.path.join(cls.tmp.name, "smoothed.csv"))

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_bag_holds_the_smoothed_poses_of_the_csv(self):
        import rosbag
        with rosbag.Bag(self.bag_out) as bag:
            smoothed = [(t, m) for _, m, t in bag.read_messages(topics=["/odometry/smoothed"])]
            states = bag.get_message_count(topic_filters=["/%s/state/smoothed" % NODE])
            filtered = bag.get_message_count(topic_filters=["/odometry/filtered"])
        self.assertEqual(len(smoothed), len(self.rows))
        self.assertEqual(states, len(self.rows))
        self.assertEqual(filtered, len(self.rows))  # the filtered estimates stay
        moved = 0.0
        for (t, m), row in zip(smoothed, self.rows):
            # ros::Time of the period's time: rounded to the nanosecond
            self.assertAlmostEqual(m.header.stamp.to_sec(), row["time"], delta=2e-9)
            self.assertEqual(t, m.header.stamp)
            q = m.pose.pose.orientation
            heading = math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))
            for value, column in ((m.pose.pose.position.x, "smoothed_pose_x"),
                                  (m.pose.pose.position.y, "smoothed_pose_y")):
                self.assertEqual(value, row[column], column)
            self.assertAlmostEqual(math.atan2(math.sin(heading - row["smoothed_pose_heading"]),
                                              math.cos(heading - row["smoothed_pose_heading"])),
                                   0.0, delta=1e-12)
            moved = max(moved, abs(row["smoothed_pose_x"] - row["pose_x"]))
        self.assertGreater(moved, 1e-4)  # the smoothed poses, not the filtered ones

    def test_summary_reports_the_correction(self):
        self.assert_correction(self.proc.stdout, self.rows, "smoothed_")

    def test_smooth_with_smooth_lag_is_refused(self):
        exe = os.path.join(built_lib_dir(NODE), NODE)
        out = os.path.join(self.tmp.name, "both.csv")
        proc = subprocess.run([exe, "--replay", BAG, "--smooth", "--smooth-lag", "0.1", "--csv",
                               out], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              universal_newlines=True, timeout=120)
        self.assertNotEqual(proc.returncode, 0)
        self.assertIn("--smooth and --smooth-lag: give one", proc.stderr)
        self.assertFalse(os.path.exists(out))


if __name__ == "__main__":
    unittest.main()
