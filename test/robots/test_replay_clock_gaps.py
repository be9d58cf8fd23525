"""The offline replay through a gap between messages (sf_filter/include/sf_filter/replay/
bag_replay.hpp, doc/replay.md): online the node's ros::Timer estimates every period while
rosbag play's clock runs through the gap; the replay, whose clock is the messages' recorded
time, must do the same, also for a gap longer than the 100 periods beyond which the core
skips a clock jump with a single estimate.

sf_soccer_vision_kf (config/soccer_vision_kf.h: 1 ms period, constant-velocity Kalman filter
per axis) on a hand-made bag of vision frames and a single encoder message (the replay
needs every topic the header reads; the shipped bags' 1 kHz encoder messages tick its
clock, precisely to avoid gaps, and their values never enter the filter): a target moving at a constant 0.5 m/s along x, frames at 32 Hz
for 0.5 s, none for 0.3 s (300 periods), then frames again. References: the online timer's
schedule (one estimate per 1 ms from the first frame to the last), and the motion itself -
through the gap the filter only predicts, so at constant velocity its position follows the
target (to its velocity error times the gap), and its position variance grows every period.
"""

import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True
from replay_helpers import read_rows, replay_exe  # noqa: E402

PERIOD = 0.001
START = 1700000300.0
FRAME = 1.0 / 32.0
SPEED = 0.5  # m/s along x
GAP = (0.5, 0.8)  # s after START: no frames in between
END = 1.0


def frame_times():
    times, k = [], 0
    while k * FRAME <= END + 1e-9:
        t = k * FRAME
        if not GAP[0] < t < GAP[1]:
            times.append(t)
        k += 1
    # the first frame after the gap at exactly GAP[1], so the gap spans 300 periods
    return sorted(set(times + [GAP[1]]))


class ReplayThroughAGapTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        import rosbag
        import rospy
        from geometry_msgs.msg import PointStamped

        cls.tmp = tempfile.TemporaryDirectory(prefix="sf_gap_test_")
        bag_path = os.path.join(cls.tmp.name, "frames.bag")
        cls.frames = frame_times()
        with rosbag.Bag(bag_path, "w") as bag:
            first = rospy.Time.from_sec(START)
            encoder = PointStamped()
            encoder.header.stamp = first
            bag.write("/encoder/pose", encoder, first)
            for t in cls.frames:
                stamp = rospy.Time.from_sec(START + t)
                msg = PointStamped()
                msg.header.stamp = stamp
                msg.header.frame_id = "field"
                msg.point.x = SPEED * t
                bag.write("/vision/pose", msg, stamp)
        csv_path = os.path.join(cls.tmp.name, "vision_kf.csv")
        cls.summary = replay_exe("sf_soccer_vision_kf", bag_path, csv_path).stdout
        cls.rows = read_rows(csv_path)
        # the schedule starts at the first frame; row k ends period k + 1
        cls.in_gap = [r for r in cls.rows
                      if START + GAP[0] < r["time"] < START + GAP[1] - PERIOD / 2]

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_one_estimate_per_period_through_the_gap(self):
        expected = int(round((self.frames[-1] - self.frames[0]) / PERIOD))
        self.assertEqual(len(self.rows), expected, self.summary)
        for k, row in enumerate(self.rows):
            self.assertAlmostEqual(row["time"], START + self.frames[0] + (k + 1) * PERIOD,
                                   delta=1e-6, msg="estimate %d" % k)

    def test_the_filter_predicts_every_period_of_the_gap(self):
        self.assertEqual(len(self.in_gap), int(round((GAP[1] - GAP[0]) / PERIOD)) - 1)
        for a, b in zip(self.in_gap, self.in_gap[1:]):
            self.assertGreater(b["var0"], a["var0"], "at %.3f" % b["time"])
        # at constant velocity the prediction follows the target: its error at the end of
        # the gap is the velocity error times 0.3 s; a filter frozen through the gap would
        # stay at its last position, SPEED * 0.3 s = 0.15 m behind
        last = self.in_gap[-1]
        truth = SPEED * (last["time"] - START)
        self.assertLess(abs(last["x0"] - truth), 0.1 * SPEED * (GAP[1] - GAP[0]))


if __name__ == "__main__":
    unittest.main()
