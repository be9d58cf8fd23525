#!/usr/bin/python3
"""set_pose and initialpose at run time (test/set_pose.test): a fusion node with POSE_OUT
(test/configs/derived_inputs_ekf.h, state (x, y, yaw, v, omega), no sensor publishing) is sent
a geometry_msgs/PoseWithCovarianceStamped on set_pose, then on /initialpose (rviz's 2D Pose
Estimate), and through the ~set_pose service. Each time the published nav_msgs/Odometry must
hold the sent pose (v = 0, so the prediction keeps it) and, in its x, y, yaw slots, the sent
covariance block plus at most the growth of the periods since (bound below). A pose the
service refuses (a negative variance) is answered with the reason and leaves the pose as it
was; the estimation diagnostics count both. A pose in another frame (map) is turned into the
odom frame through tf, or refused without a transform; x beyond 1e100 is refused as
~initial_state is; the log lines of set and refused poses are throttled (issue 38 D6, D7).
"""

import math
import sys
import time
import unittest

import rosservice
import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import PoseWithCovarianceStamped, TransformStamped
from roslib.message import get_service_class
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Log
from sensor_msgs.msg import Imu

from node_test_helpers import subscribe_diagnostics, wait_for


SERVICE = "/derived_inputs/set_pose"


def pose_message(x, y, yaw, covariance):
    """covariance: {(row slot, column slot): value} of the 6 x 6 (x y z roll pitch yaw)."""
    m = PoseWithCovarianceStamped()
    m.header.stamp = rospy.Time.now()
    m.header.frame_id = "odom"
    m.pose.pose.position.x = x
    m.pose.pose.position.y = y
    m.pose.pose.orientation.z = math.sin(yaw / 2)
    m.pose.pose.orientation.w = math.cos(yaw / 2)
    c = [0.0] * 36
    for (r, k), v in covariance.items():
        c[r * 6 + k] = v
        c[k * 6 + r] = v
    m.pose.covariance = c
    return m


def yaw_of(q):
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


class SetPoseTest(unittest.TestCase):
    def setUp(self):
        self.odometry = []
        self.states = []
        rospy.Subscriber("/odometry/filtered", Odometry, self.odometry.append)
        # The node publishes its state every period from the start; odometry only once a
        # period had a measured value or a pose was set (no pose at the origin before).
        rospy.Subscriber("/derived_inputs/state", rospy.AnyMsg, self.states.append)
        self.diagnostics = subscribe_diagnostics()

    def send(self, topic, message):
        """Publishes `message` on `topic` once the node listens; returns the time it did."""
        publisher = rospy.Publisher(topic, PoseWithCovarianceStamped, queue_size=1, latch=True)
        self.assertTrue(wait_for(lambda: publisher.get_num_connections() >= 1, 20.0),
                        "the node did not subscribe to " + topic)
        sent = rospy.Time.now()
        publisher.publish(message)
        return sent

    def call(self, message):
        """Calls the node's ~set_pose service with `message`; returns its response. The type
        is read from the running service, so the test does not name the package defining it."""
        rospy.wait_for_service(SERVICE, timeout=20.0)
        service = rospy.ServiceProxy(SERVICE, get_service_class(rosservice.get_service_type(SERVICE)))
        return service(pose=message)

    def check(self, topic, x, y, yaw, covariance):
        self.assertTrue(wait_for(lambda: self.states, 20.0), "no ~state from the node")
        message = pose_message(x, y, yaw, covariance)
        if topic == SERVICE:
            rospy.wait_for_service(SERVICE, timeout=20.0)
            sent = rospy.Time.now()
            response = self.call(message)
            self.assertTrue(response.success, response.message)
            self.assertEqual(response.message, "")
        else:
            sent = self.send(topic, message)

        def arrived():
            return [m for m in self.odometry if m.header.stamp > sent + rospy.Duration(0.15)]
        self.assertTrue(wait_for(lambda: len(arrived()) >= 1, 5.0),
                        "no odometry after the pose was sent on " + topic)
        odom = arrived()[0]
        p = odom.pose.pose
        self.assertAlmostEqual(p.position.x, x, places=6)
        self.assertAlmostEqual(p.position.y, y, places=6)
        self.assertAlmostEqual(yaw_of(p.orientation), yaw, places=6)
        c = odom.pose.covariance
        # k periods since the pose was set: Q adds k 1e-4, the speed and turn rate at most
        # k^2 T^2 P(v) (P(omega)) through x, y and yaw and their growing correlations with v
        # and omega (which set_pose made 0); P(v), P(omega) are the Odometry's twist variances
        # (TWIST_OUT), which only grow while no sensor reports.
        k = math.ceil((odom.header.stamp - sent).to_sec() / 0.1) + 1
        rates = max(odom.twist.covariance[0], odom.twist.covariance[35])
        growth = k * 1e-4 + k * k * 0.01 * rates
        for (r, k), v in covariance.items():
            if r == k:
                self.assertGreaterEqual(c[r * 6 + k], v - 1e-12, (topic, r))
                self.assertLessEqual(c[r * 6 + k], v + growth, (topic, r))
            else:
                self.assertAlmostEqual(c[r * 6 + k], v, delta=growth)
        return odom

    def pose_counts(self, after):
        """(poses set, poses refused) of the newest estimation report stamped after `after`,
        None before there is one."""
        for array in reversed(self.diagnostics):
            if array.header.stamp <= after:
                break
            for status in array.status:
                if status.name.endswith("derived_inputs: estimation"):
                    values = {v.key: v.value for v in status.values}
                    return int(values["poses set"]), int(values["poses refused"])
        return None

    def node_lines(self, level, text):
        return [m for m in self.log if m.name == "/derived_inputs" and m.level == level
                and text in m.msg]

    def burst(self, message):
        """Calls the service with `message` 100 times as fast as it answers; returns the
        seconds that took."""
        rospy.wait_for_service(SERVICE, timeout=20.0)
        service = rospy.ServiceProxy(SERVICE, get_service_class(rosservice.get_service_type(SERVICE)),
                                     persistent=True)
        start = time.monotonic()
        for _ in range(100):
            service(pose=message)
        return time.monotonic() - start

    def test_a_pose_logs_are_throttled(self):
        # Issue 38 D6: 1 kHz of valid poses wrote 9 996 INFO lines in 10 s, refused ones one
        # ERROR line each. Now at most one line per second and kind (kPoseLogPeriod): a burst
        # of 100 calls lasting E s may log at most 1 + E lines. The lines of one node reach
        # /rosout in order, so the first line of the other kind, logged after the burst, says
        # that every line of the burst has arrived. Named to run first: both kinds of line
        # must not have been logged before (a fresh node).
        self.log = []
        rospy.Subscriber("/rosout", Log, self.log.append)
        self.assertTrue(wait_for(lambda: self.states, 20.0), "no ~state from the node")
        valid = pose_message(1.0, 2.0, 0.5, {(0, 0): 0.2, (1, 1): 0.2, (5, 5): 0.1})
        refused = pose_message(1.0, 2.0, 0.5, {(0, 0): -1.0, (1, 1): 0.2, (5, 5): 0.1})
        took = self.burst(valid)
        self.assertFalse(self.call(refused).success)  # the first refusal: logged
        self.assertTrue(wait_for(lambda: self.node_lines(Log.ERROR, "pose refused"), 10.0),
                        "no line of the refused pose on /rosout")
        lines = len(self.node_lines(Log.INFO, "pose set to"))
        self.assertGreaterEqual(lines, 1)
        self.assertLessEqual(lines, 1 + took, "%d lines in %.2f s" % (lines, took))
        # Refused poses, then a value the node drops (a NaN heading): its first warning.
        took = self.burst(refused)
        imu = rospy.Publisher("/imu/data", Imu, queue_size=1, latch=True)
        self.assertTrue(wait_for(lambda: imu.get_num_connections() >= 1, 20.0))
        nan = Imu()
        nan.header.stamp = rospy.Time.now()
        nan.orientation.w = float("nan")
        imu.publish(nan)
        self.assertTrue(wait_for(lambda: self.node_lines(Log.WARN, "dropped a value"), 10.0),
                        "no warning of the NaN heading on /rosout")
        # The refusal before the burst, and the burst's at most 1 + E.
        lines = len(self.node_lines(Log.ERROR, "pose refused"))
        self.assertLessEqual(lines, 2 + took, "%d lines in %.2f s" % (lines, took))
        imu.unregister()

    def test_pose_beyond_1e100_is_refused_like_the_initial_state(self):
        # Issue 38 D7: x = 1e300 was set (and published) while ~initial_state refuses entries
        # above 1e100; the same bound (withinParameterMagnitude) refuses it, the pose unchanged.
        self.assertTrue(wait_for(lambda: self.states, 20.0), "no ~state from the node")
        for x, y in ((1e300, 0.0), (0.0, -1e101)):
            response = self.call(pose_message(x, y, 0.0, {(0, 0): 0.1, (1, 1): 0.1, (5, 5): 0.1}))
            self.assertFalse(response.success, (x, y))
            self.assertEqual(response.message,
                             "the pose's x or y is not a finite number of magnitude at most 1e100")
        # 1e100 itself is within the bound.
        self.assertTrue(self.call(pose_message(1e100, 0.0, 0.0, {(0, 0): 0.1, (1, 1): 0.1,
                                                                  (5, 5): 0.1})).success)

    def test_pose_in_another_frame_is_turned_through_tf(self):
        # rviz publishes initialpose in its fixed frame, often map; it was taken as odom. With
        # map -> odom a static transform (odom's origin at map (10, -4), turned by +90 deg), a
        # pose at map (10, -1), yaw pi/2, is odom (3, 0), yaw 0: p_odom = R(-90) (p_map - t);
        # its x, y variances (0.3, 0.1) swap, the yaw variance stays.
        broadcaster = tf2_ros.StaticTransformBroadcaster()
        t = TransformStamped()
        t.header.stamp = rospy.Time.now()
        t.header.frame_id = "map"
        t.child_frame_id = "odom"
        t.transform.translation.x = 10.0
        t.transform.translation.y = -4.0
        t.transform.rotation.z = math.sin(math.pi / 4)
        t.transform.rotation.w = math.cos(math.pi / 4)
        broadcaster.sendTransform(t)
        message = pose_message(10.0, -1.0, math.pi / 2, {(0, 0): 0.3, (1, 1): 0.1, (5, 5): 0.05})
        message.header.frame_id = "map"
        sent = rospy.Time.now()
        response = self.call(message)
        self.assertTrue(response.success, response.message)
        # The first such pose waits for tf's first transform, and the node then estimates the
        # periods of the wait (with the pose before): the estimates after the answer hold it.
        answered = rospy.Time.now()

        def arrived():
            return [m for m in self.odometry if m.header.stamp > answered + rospy.Duration(0.15)]
        self.assertTrue(wait_for(lambda: len(arrived()) >= 1, 5.0), "no odometry")
        odom = arrived()[0]
        self.assertAlmostEqual(odom.pose.pose.position.x, 3.0, places=6)
        self.assertAlmostEqual(odom.pose.pose.position.y, 0.0, places=6)
        self.assertAlmostEqual(yaw_of(odom.pose.pose.orientation), 0.0, places=6)
        # The variances grow from the set values by the periods since (bound as in check()).
        k = math.ceil((odom.header.stamp - sent).to_sec() / 0.1) + 1
        growth = k * 1e-4 + k * k * 0.01 * max(odom.twist.covariance[0], odom.twist.covariance[35])
        c = odom.pose.covariance
        for slot, variance in ((0, 0.1), (7, 0.3), (35, 0.05)):
            self.assertGreaterEqual(c[slot], variance - 1e-12, slot)
            self.assertLessEqual(c[slot], variance + growth, slot)
        # A frame tf does not know: refused naming both frames, the pose unchanged.
        message.header.frame_id = "nowhere"
        response = self.call(message)
        self.assertFalse(response.success)
        self.assertIn("no transform from the pose's frame 'nowhere' into the odom frame 'odom'",
                      response.message)

    def test_set_pose_then_initialpose_then_service(self):
        # The counts of the poses the other tests sent, from a report after they were.
        start = rospy.Time.now()
        self.assertTrue(wait_for(lambda: self.pose_counts(start) is not None, 10.0),
                        "no estimation diagnostics")
        before = self.pose_counts(start)
        self.check("/set_pose", 3.0, -2.0, 1.0, {(0, 0): 0.25, (1, 1): 0.16, (5, 5): 0.04,
                                                   (0, 1): 0.05})
        # rviz's pose estimate, across the seam of the heading.
        self.check("/initialpose", -1.0, 5.0, -3.1, {(0, 0): 0.5, (1, 1): 0.5, (5, 5): 0.07})
        # The service, with a correlated block.
        self.check(SERVICE, 0.5, 1.5, 2.0, {(0, 0): 0.3, (1, 1): 0.2, (5, 5): 0.1, (1, 5): 0.02})
        # Refused: a negative variance is no covariance. The answer says why; the pose stays.
        response = self.call(pose_message(9.0, 9.0, 0.0, {(0, 0): -1.0, (1, 1): 0.2, (5, 5): 0.1}))
        self.assertFalse(response.success)
        self.assertIn("covariance", response.message.lower())
        refused = rospy.Time.now()
        self.assertTrue(wait_for(
            lambda: [m for m in self.odometry if m.header.stamp > refused], 5.0))
        after = [m for m in self.odometry if m.header.stamp > refused][0].pose.pose.position
        self.assertAlmostEqual(after.x, 0.5, places=6)
        self.assertAlmostEqual(after.y, 1.5, places=6)
        # Three poses set (two topics, one service call), one refused.
        self.assertTrue(wait_for(lambda: self.pose_counts(refused) is not None, 10.0),
                        "no estimation diagnostics after the refused pose")
        self.assertEqual(self.pose_counts(refused), (before[0] + 3, before[1] + 1))


if __name__ == "__main__":
    rospy.init_node("set_pose_test")
    rostest.rosrun("sf_pkg", "set_pose", SetPoseTest, sys.argv)
