"""ACCEL_OUT (doc/filter_node.md, "Published topics"): config/nav1_ekf.h with ACCEL_OUT (6)
(test/configs/nav1_accel_ekf.h) replays bags/pioneer_seed1.bag to

- the CSV of sf_nav1_ekf byte for byte (the output changes nothing else);
- an output bag whose accel/filtered holds one geometry_msgs/AccelWithCovarianceStamped per
  estimate, stamped as the CSV row, in the robot's frame, with linear.x = x6 and its variance
  var6 from the CSV, every other component 0 with variance 1e6;
- sf_nav1_ekf's output bag plus that topic: every other message equal.

The executables come from $SF_LIB_DIR or the sourced devel space (skipped when not built).
"""

import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.dont_write_bytecode = True
sys.path.insert(0, HERE)
from replay_helpers import read_rows, replay_exe  # noqa: E402

BAG = os.path.join(REPO, "bags", "pioneer_seed1.bag")


def bag_messages(path):
    import rosbag  # ROS python, imported here so that the module loads without it
    with rosbag.Bag(path) as bag:
        return [(m.topic, m.timestamp, m.message) for m in bag.read_messages()]


class AccelOutput(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.outputs = {}
        for exe in ("sf_nav1_ekf", "sf_test_nav1_accel_ekf"):
            csv_path = os.path.join(cls.tmp.name, exe + ".csv")
            bag_path = os.path.join(cls.tmp.name, exe + ".bag")
            replay_exe(exe, BAG, csv_path, "--bag", bag_path)
            with open(csv_path, "rb") as f:
                cls.outputs[exe] = (f.read(), csv_path, bag_path)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_csv_unchanged(self):
        plain = self.outputs["sf_nav1_ekf"][0]
        self.assertGreater(len(plain), 10000)
        self.assertEqual(plain, self.outputs["sf_test_nav1_accel_ekf"][0])

    def test_acceleration_is_the_state(self):
        _, csv_path, bag_path = self.outputs["sf_test_nav1_accel_ekf"]
        rows = read_rows(csv_path)
        accels = [(t, m) for topic, t, m in bag_messages(bag_path) if topic == "/accel/filtered"]
        self.assertEqual(len(accels), len(rows))
        for row, (stamp, m) in zip(rows, accels):
            self.assertEqual(m._type, "geometry_msgs/AccelWithCovarianceStamped")
            self.assertEqual(m.header.frame_id, "base_link")
            self.assertAlmostEqual(m.header.stamp.to_sec(), row["time"], delta=1e-6)
            self.assertEqual(stamp, m.header.stamp)
            self.assertEqual(m.accel.accel.linear.x, row["x6"])
            self.assertEqual(m.accel.covariance[0], row["var6"])
            self.assertEqual([m.accel.covariance[k * 7] for k in range(1, 6)], [1e6] * 5)
            self.assertEqual((m.accel.accel.linear.y, m.accel.accel.angular.z), (0.0, 0.0))
        # The robot accelerates on this bag: the values are not a constant.
        self.assertGreater(max(abs(row["x6"]) for row in rows), 0.01)

    def test_other_messages_unchanged(self):
        plain = bag_messages(self.outputs["sf_nav1_ekf"][2])
        accel = [m for m in bag_messages(self.outputs["sf_test_nav1_accel_ekf"][2])
                 if m[0] != "/accel/filtered"]
        # The ~state topic is named after the executable.
        rename = {"/sf_nav1_ekf/state": "/sf_test_nav1_accel_ekf/state"}
        self.assertEqual(len(plain), len(accel))
        for a, b in zip(plain, accel):
            self.assertEqual((rename.get(a[0], a[0]), a[1], a[2]), b)


if __name__ == "__main__":
    unittest.main()
