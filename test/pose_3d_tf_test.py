#!/usr/bin/python3
"""POSE_OUT_3D online (test/pose_3d_tf.test): config/imu_attitude.h (POSE_OUT_3D (0), the
orientation only) fed a resting IMU rolled by ROLL about its x axis (gyro zero, accelerometer
R^T (0, 0, g) = (0, g sin ROLL, g cos ROLL)):

- odometry/filtered, world -> imu_body (~frame_id, ~child_frame_id): its roll converges to
  ROLL, pitch and yaw stay 0 (fused/euler, in the world frame), the position is 0 with the
  variance 1e6;
- /tf carries world -> imu_body with the Odometry's pose, stamp for stamp: translation 0 and
  the rotation equal to the orientation;
- with ~publish_tf false (the second node, child quiet_body) the Odometry comes and no tf.
Events only: the test waits for the node's messages; the deadlines bound a failure.
"""

import math
import sys
import unittest

import rospy
import rostest
from geometry_msgs.msg import Vector3Stamped
from nav_msgs.msg import Odometry
from sensor_msgs.msg import Imu
from tf2_msgs.msg import TFMessage

from node_conventions_test import wait_until

ROLL = 0.3  # rad
GRAVITY = 9.80665


class Pose3dTfTest(unittest.TestCase):
    def setUp(self):
        self.tf, self.odometry, self.euler, self.quiet = [], [], [], []
        self.subscribers = [
            rospy.Subscriber("/tf", TFMessage, self.tf.append, queue_size=1000),
            rospy.Subscriber("/tilted/odometry/filtered", Odometry, self.odometry.append,
                             queue_size=1000),
            rospy.Subscriber("/tilted/fused/euler", Vector3Stamped, self.euler.append,
                             queue_size=1000),
            rospy.Subscriber("/quiet/odometry/filtered", Odometry, self.quiet.append,
                             queue_size=1000)]
        publishers = [rospy.Publisher(ns + "/imu/data", Imu, queue_size=10)
                      for ns in ("/tilted", "/quiet")]
        imu = Imu()
        imu.header.frame_id = "imu_body"
        imu.linear_acceleration.y = GRAVITY * math.sin(ROLL)
        imu.linear_acceleration.z = GRAVITY * math.cos(ROLL)

        def tick():
            imu.header.stamp = rospy.Time.now()
            for p in publishers:
                p.publish(imu)

        self.tick = tick

    def tearDown(self):
        for s in self.subscribers:
            s.unregister()

    def transforms(self, child):
        return [t for m in list(self.tf) for t in m.transforms if t.child_frame_id == child]

    def test_odometry_euler_and_tf(self):
        wait_until(lambda: self.euler and abs(self.euler[-1].vector.x - ROLL) < 1e-3,
                   "fused/euler's roll at %g" % ROLL, self.tick)
        e = self.euler[-1]
        self.assertEqual(e.header.frame_id, "world")
        self.assertAlmostEqual(e.vector.y, 0.0, delta=1e-3)
        self.assertAlmostEqual(e.vector.z, 0.0, delta=1e-3)
        by_stamp = {o.header.stamp: o for o in list(self.odometry)}
        wait_until(lambda: any(t.header.stamp in by_stamp for t in self.transforms("imu_body")),
                   "a tf world -> imu_body at an odometry's stamp", self.tick)
        t = next(t for t in self.transforms("imu_body") if t.header.stamp in by_stamp)
        o = by_stamp[t.header.stamp]
        self.assertEqual((o.header.frame_id, o.child_frame_id), ("world", "imu_body"))
        self.assertEqual(t.header.frame_id, "world")
        p, q = o.pose.pose.position, o.pose.pose.orientation
        self.assertEqual((p.x, p.y, p.z), (0.0, 0.0, 0.0))
        self.assertEqual(o.pose.covariance[0], 1e6)
        v, r = t.transform.translation, t.transform.rotation
        self.assertEqual((v.x, v.y, v.z), (0.0, 0.0, 0.0))
        self.assertEqual((r.w, r.x, r.y, r.z), (q.w, q.x, q.y, q.z))
        self.assertGreater(abs(q.x), 0.1)  # rolled: not the identity

    def test_no_tf_with_publish_tf_false(self):
        wait_until(lambda: len(self.quiet) >= 20 and self.transforms("imu_body"),
                   "20 odometries of the quiet node and a tf of the other", self.tick)
        self.assertEqual(self.quiet[-1].child_frame_id, "quiet_body")
        self.assertEqual(self.transforms("quiet_body"), [])


if __name__ == "__main__":
    rospy.init_node("pose_3d_tf_test")
    rostest.rosrun("sf_pkg", "pose_3d_tf", Pose3dTfTest, sys.argv)
