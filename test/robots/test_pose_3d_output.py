"""POSE_OUT_3D and TWIST_OUT_3D (doc/filter_node.md, "Published topics"): config/imu_odometry_3d.h
replays a small rigid-body simulation (tools/sim/rigid_body_sim.py, 20 s of the slow motion,
default sensor noise, written here) with --bag, and its output bag holds

- one nav_msgs/Odometry on /odometry/filtered per CSV row, odom -> base_link, its pose and
  body twist the CSV's state (p x0..2, q x3..6, v x7..9, omega x10..12) and the diagonals of
  its 6x6 covariances the CSV's variances (the orientation rows are the quaternion's x, y, z
  tangent rows var4..6); both 6x6 covariances symmetric and positive semi-definite;
- its pose against the simulation's ground truth after the first SKIP_S seconds: position RMSE
  below BOUND_POSITION_M (three times the position sensor's 0.01 m) and orientation RMSE below
  BOUND_DEG (the accelerometer's 3 sigma, 0.9 deg, and the gyro's heading walk, 0.15 deg over
  30 s: test_imu_3d_replay.py's bounds, which derive them);
- one geometry_msgs/Vector3Stamped on /fused/euler per row, in the odom frame: roll, pitch and
  yaw (Z-Y-X) of the Odometry's quaternion, computed here by the textbook formulas.

The executables come from $SF_LIB_DIR or the sourced devel space (skipped when not built).
"""

import math
import os
import sys
import unittest

sys.dont_write_bytecode = True
from rigid_body_case import RigidBodyReplayCase, pose3d_error  # noqa: E402

NODE = "sf_imu_odometry_3d"
BOUND_POSITION_M = 0.03
BOUND_DEG = 1.0
SKIP_S = 2.0


def bag_messages(path, topic):
    import rosbag  # ROS python, imported here so that the module loads without it
    with rosbag.Bag(path) as bag:
        return [m.message for m in bag.read_messages(topics=[topic])]


def euler_of(w, x, y, z):
    """Roll, pitch, yaw (Z-Y-X) of a unit quaternion."""
    roll = math.atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y))
    pitch = math.asin(max(-1.0, min(1.0, 2 * (w * y - z * x))))
    yaw = math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))
    return roll, pitch, yaw


class Pose3dOutput(RigidBodyReplayCase):
    SIM_ARGS = ("--seed", "7", "--duration", "20")

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        out_bag = os.path.join(cls.tmp.name, NODE + ".bag")
        cls.rows = cls.replay(NODE, "--bag", out_bag)
        cls.odometry = bag_messages(out_bag, "/odometry/filtered")
        cls.euler = bag_messages(out_bag, "/fused/euler")

    def test_odometry_is_the_state(self):
        self.assertGreater(len(self.rows), 1900)
        self.assertEqual(len(self.odometry), len(self.rows))
        for row, m in zip(self.rows, self.odometry):
            self.assertEqual((m.header.frame_id, m.child_frame_id), ("odom", "base_link"))
            self.assertAlmostEqual(m.header.stamp.to_sec(), row["time"], delta=1e-6)
            p, q = m.pose.pose.position, m.pose.pose.orientation
            self.assertEqual([p.x, p.y, p.z, q.w, q.x, q.y, q.z], [row["x%d" % i] for i in range(7)])
            t = m.twist.twist
            self.assertEqual([t.linear.x, t.linear.y, t.linear.z, t.angular.x, t.angular.y,
                              t.angular.z], [row["x%d" % i] for i in range(7, 13)])
            self.assertEqual([m.pose.covariance[k * 7] for k in range(6)],
                             [row["var%d" % i] for i in (0, 1, 2, 4, 5, 6)])
            self.assertEqual([m.twist.covariance[k * 7] for k in range(6)],
                             [row["var%d" % i] for i in range(7, 13)])

    def test_covariances_are_symmetric_and_positive_semidefinite(self):
        import numpy
        correlated = 0
        for m in self.odometry:
            for flat in (m.pose.covariance, m.twist.covariance):
                c = numpy.array(flat).reshape(6, 6)
                self.assertTrue(numpy.array_equal(c, c.T))
                eigen = numpy.linalg.eigvalsh(c)
                self.assertGreaterEqual(eigen.min(), -1e-12 * eigen.max())
            correlated += abs(m.pose.covariance[0 * 6 + 4]) > 0  # x with the rotation about y
        # The cross terms are there: the position and the orientation are correlated.
        self.assertGreater(correlated, len(self.odometry) // 2)

    def test_pose_against_ground_truth(self):
        rows = [{"time": m.header.stamp.to_sec(),
                 "x0": m.pose.pose.position.x, "x1": m.pose.pose.position.y,
                 "x2": m.pose.pose.position.z, "x3": m.pose.pose.orientation.w,
                 "x4": m.pose.pose.orientation.x, "x5": m.pose.pose.orientation.y,
                 "x6": m.pose.pose.orientation.z} for m in self.odometry]
        e = pose3d_error.errors(rows, self.truth, quaternion=3, position=0, skip=SKIP_S)
        self.assertGreater(len(e["orientation"]), 1500)
        self.assertLess(pose3d_error.rms(e["position"]), BOUND_POSITION_M)
        self.assertLess(math.degrees(pose3d_error.rms(e["orientation"])), BOUND_DEG)

    def test_euler_angles_of_the_orientation(self):
        self.assertEqual(len(self.euler), len(self.odometry))
        pitches = []
        for m, o in zip(self.euler, self.odometry):
            self.assertEqual(m.header.frame_id, "odom")
            self.assertEqual(m.header.stamp, o.header.stamp)
            q = o.pose.pose.orientation
            roll, pitch, yaw = euler_of(q.w, q.x, q.y, q.z)
            self.assertAlmostEqual(m.vector.x, roll, places=9)
            self.assertAlmostEqual(m.vector.y, pitch, places=9)
            self.assertAlmostEqual(m.vector.z, yaw, places=9)
            pitches.append(abs(pitch))
        # The body tilts on this recording: the angles are not all zero.
        self.assertGreater(max(pitches), 0.02)


if __name__ == "__main__":
    unittest.main()
