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
"""

import math
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True
from replay_helpers import REPO, read_rows, replay_exe  # noqa: E402

BAG = os.path.join(REPO, "bags", "diff_drive_seed1.bag")
NODE = "sf_diff_drive_odom_imu"
LAG_S, PERIOD_S, MAX_MEASUREMENT_LAG_S = 0.5, 0.02, 0.02  # the header's period and lag
LAG = int(round(LAG_S / PERIOD_S))


def cut_bag(source, target, end):
    """`source`'s messages recorded up to `end` [s], and every /tf_static message."""
    import rosbag
    with rosbag.Bag(source) as bag, rosbag.Bag(target, "w") as out:
        for topic, msg, t, header in bag.read_messages(return_connection_header=True):
            if t.to_sec() <= end or topic.lstrip("/") == "tf_static":
                out.write(topic, msg, t, connection_header=header)


class FixedLagReplayTest(unittest.TestCase):
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

    def test_output_bag_has_the_smoothed_odometry(self):
        import rosbag
        with rosbag.Bag(self.bag_out) as bag:
            topics = bag.get_type_and_topic_info().topics
        self.assertEqual(topics["/odometry/smoothed"].msg_type, "nav_msgs/Odometry")
        self.assertEqual(topics["/odometry/smoothed"].message_count, len(self.lagged) - LAG)


if __name__ == "__main__":
    unittest.main()
