#!/usr/bin/python3
"""A static transform the documented way (test/static_transform.test, issue 13):
launch/diff_drive_odom_imu.launch with imu_mount:="0.1 0 0.2 0 0 3.14159265" starts
`tf2_ros static_transform_publisher` (Debian: tf2-tools) for an IMU mounted upside down in
imu_link; the test launch adds one in the quaternion form (gyro_link), as
doc/spatial_alignment.md writes it.

- /tf_static holds both transforms with the arguments in static_transform_publisher's order
  (x y z yaw pitch roll, x y z qx qy qz qw);
- the fusion node (sf_diff_drive_odom_imu, input 2 the IMU's angular_velocity.z rotated into
  base_link) uses the mount: fed an odometry yaw rate of 0.3 rad/s and an IMU in imu_link
  reading -(0.3 + 0.04) rad/s, it counts the IMU among the inputs of its periods (a value
  without a transform would be dropped) and its gyro bias state converges to +0.04 (the
  reading not rotated would make it -0.64).
Events only: the test waits for /tf_static and for the node's ~state messages; the deadlines
bound a failure.
"""

import math
import sys
import unittest

import rospy
import rostest
from nav_msgs.msg import Odometry
from sensor_msgs.msg import Imu
from sf_msgs.msg import StateEstimateStamped
from tf2_msgs.msg import TFMessage

from node_conventions_test import wait_until

YAW_RATE = 0.3  # rad/s, base_link z
GYRO_BIAS = 0.04  # rad/s
INPUTS = 3  # config/diff_drive_odom_imu.h: odometry speed, odometry yaw rate, IMU yaw rate
BIAS, YAW_RATE_STATE = 5, 4  # state indices in the header


class StaticTransformTest(unittest.TestCase):
    def setUp(self):
        self.tf_static = []
        self.states = []
        self.subscribers = [
            rospy.Subscriber("/tf_static", TFMessage, self.tf_static.append),
            rospy.Subscriber("/fused_odometry/fusion_node/state", StateEstimateStamped,
                             self.states.append, queue_size=1000)]

    def tearDown(self):
        for s in self.subscribers:
            s.unregister()

    def static_transform(self, child):
        wait_until(lambda: any(t.child_frame_id == child for m in self.tf_static
                               for t in m.transforms), "/tf_static with " + child)
        return next(t for m in self.tf_static for t in m.transforms if t.child_frame_id == child)

    def assert_transform(self, t, parent, translation, quaternion):
        self.assertEqual(t.header.frame_id, parent)
        v = t.transform.translation
        for got, want in zip((v.x, v.y, v.z), translation):
            self.assertAlmostEqual(got, want, places=6)
        q = t.transform.rotation
        # q and -q are the same rotation
        sign = 1.0 if q.x * quaternion[0] + q.y * quaternion[1] + q.z * quaternion[2]\
            + q.w * quaternion[3] >= 0 else -1.0
        for got, want in zip((q.x, q.y, q.z, q.w), quaternion):
            self.assertAlmostEqual(sign * got, want, places=6)

    def test_mount_published_in_both_argument_orders(self):
        # x y z yaw pitch roll: roll = pi, the IMU upside down (yaw = pi would be (0, 0, 1, 0))
        self.assert_transform(self.static_transform("imu_link"), "base_link", (0.1, 0.0, 0.2),
                              (1.0, 0.0, 0.0, math.cos(3.14159265 / 2)))
        # x y z qx qy qz qw
        self.assert_transform(self.static_transform("gyro_link"), "base_link", (0.0, 0.0, 0.3),
                              (0.0, 0.7071068, 0.0, 0.7071068))

    def test_node_rotates_the_imu_by_the_mount(self):
        self.static_transform("imu_link")
        odom_pub = rospy.Publisher("/odom", Odometry, queue_size=10)
        imu_pub = rospy.Publisher("/imu/data", Imu, queue_size=10)
        odom = Odometry()
        odom.header.frame_id = "odom"
        odom.child_frame_id = "base_link"
        odom.twist.twist.linear.x = 0.5
        odom.twist.twist.angular.z = YAW_RATE
        imu = Imu()
        imu.header.frame_id = "imu_link"
        imu.angular_velocity.z = -(YAW_RATE + GYRO_BIAS)  # upside down: z reversed

        def tick():
            odom.header.stamp = imu.header.stamp = rospy.Time.now()
            odom_pub.publish(odom)
            imu_pub.publish(imu)

        def with_imu():
            return [s for s in self.states if s.present_inputs == INPUTS]

        wait_until(lambda: len(with_imu()) >= 50, "50 periods with the IMU among the inputs",
                   tick)
        state = with_imu()[-1].state
        self.assertAlmostEqual(state[BIAS], GYRO_BIAS, delta=0.01)
        self.assertAlmostEqual(state[YAW_RATE_STATE], YAW_RATE, delta=0.02)


if __name__ == "__main__":
    rospy.init_node("static_transform_test")
    rostest.rosrun("sf_pkg", "static_transform", StaticTransformTest, sys.argv)
