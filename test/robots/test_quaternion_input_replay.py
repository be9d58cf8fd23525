"""A measured quaternion (QUATERNION_INPUTS) replayed offline: config/imu_odometry_pose_3d.h,
config/imu_odometry_3d.h with the vision pose's orientation compared on SO(3), on a rigid-body
simulation (tools/sim/rigid_body_sim.py, 30 s of the slow motion, default noise, a gyro bias
of GYRO_BIAS rad/s on every axis) whose every other vision orientation is written as -q (the
same rotation; ROS leaves the sign to the sensor), against its ground truth
(tools/eval/pose3d_error.py), after the first SKIP_S seconds.

Without the orientation input (config/imu_odometry_3d.h) the heading follows the biased gyro,
weighed against the odometry's unbiased turn rate, and nothing observes it: it drifts by
degrees. With it the heading is pinned by the vision's 0.01 rad per pose: the orientation RMSE
stays below BOUND_DEG, three times the vision's noise (0.57 deg), and below a fifth of the
header's without it. The quaternion rows compared by subtraction (z - h per component) take a
flipped reading as a rotation by 180 deg: the same test fails then (checked: doc/manifolds.md).
The executables come from $SF_LIB_DIR or the sourced devel space (skipped when not built).
"""

import math
import os
import subprocess
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True
HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(REPO, "tools", "eval"))
import pose3d_error  # noqa: E402
from replay_helpers import read_rows, replay_exe  # noqa: E402

SIM = os.path.join(REPO, "tools", "sim", "rigid_body_sim.py")
GYRO_BIAS = 0.02
BOUND_DEG = 3 * math.degrees(0.01)
SKIP_S = 2.0


def flip_every_other_orientation(source, target):
    """Copies the bag, writing every other vision/pose orientation as -q."""
    import rosbag  # Debian: python3-rosbag
    count = 0
    with rosbag.Bag(source) as bag_in, rosbag.Bag(target, "w") as bag_out:
        for topic, msg, t in bag_in.read_messages(raw=False):
            if topic.lstrip("/") == "vision/pose":
                if count % 2 == 1:
                    o = msg.pose.pose.orientation
                    o.w, o.x, o.y, o.z = -o.w, -o.x, -o.y, -o.z
                count += 1
            bag_out.write(topic, msg, t)
    return count


class QuaternionInputReplay(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        simulated = os.path.join(cls.tmp.name, "simulated.bag")
        subprocess.run([sys.executable, SIM, "--seed", "5", "--duration", "30",
                        "--gyro-bias-init", str(GYRO_BIAS), "--out", simulated],
                       check=True, stdout=subprocess.PIPE)
        cls.bag = os.path.join(cls.tmp.name, "flipped.bag")
        cls.poses = flip_every_other_orientation(simulated, cls.bag)
        cls.truth = pose3d_error.load_truth(cls.bag)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def orientation_rms_deg(self, node):
        csv_path = os.path.join(self.tmp.name, node + ".csv")
        replay_exe(node, self.bag, csv_path)
        rows = read_rows(csv_path)
        e = pose3d_error.errors(rows, self.truth, quaternion=3, position=0, skip=SKIP_S)
        self.assertGreater(len(e["orientation"]), 2500)
        return math.degrees(pose3d_error.rms(e["orientation"]))

    def test_orientation_input_pins_the_heading(self):
        self.assertGreater(self.poses, 300)
        with_input = self.orientation_rms_deg("sf_imu_odometry_pose_3d")
        without = self.orientation_rms_deg("sf_imu_odometry_3d")
        print("orientation RMSE: %.3f deg with the quaternion input, %.3f deg without"
              % (with_input, without))
        self.assertLess(with_input, BOUND_DEG)
        self.assertLess(with_input, without / 5.0)


if __name__ == "__main__":
    unittest.main()
