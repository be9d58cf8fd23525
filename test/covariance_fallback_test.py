#!/usr/bin/python3
"""INPUT_COVARIANCE's fallback counted in /diagnostics (test/covariance_fallback.test): a node
whose input 0 is the yaw of sensor_msgs/Imu with its variance from orientation_covariance[8]
receives one message with a known covariance and two whose covariance ROS marks unknown (all
zero; -1 in the first entry). Input 0's diagnostic status must show 2 for "covariance
unknown, header R used" once all three were received, and nothing before an unknown one.
"""

import sys
import unittest

import rospy
import rostest
from sensor_msgs.msg import Imu

from node_test_helpers import subscribe_diagnostics, wait_for

KEY = "covariance unknown, header R used"


def imu(first, yaw_variance, stamp):
    m = Imu()
    m.header.stamp = stamp
    m.header.frame_id = "imu_link"
    m.orientation.w = 1.0
    m.orientation_covariance[0] = first
    m.orientation_covariance[8] = yaw_variance
    return m


class CovarianceFallbackTest(unittest.TestCase):
    def setUp(self):
        self.reports = subscribe_diagnostics()

    def input0(self):
        """The values of input 0's newest report, None before one."""
        for array in reversed(self.reports):
            for status in array.status:
                if status.name.startswith("derived_inputs: input 0 "):
                    return {v.key: v.value for v in status.values}
        return None

    def test_unknown_covariances_are_counted(self):
        publisher = rospy.Publisher("/imu/data", Imu, queue_size=10)
        self.assertTrue(wait_for(lambda: publisher.get_num_connections() >= 1, 20.0),
                        "the node did not subscribe to /imu/data")
        start = rospy.Time.now()
        publisher.publish(imu(0.01, 0.02, start))  # known
        self.assertTrue(wait_for(
            lambda: (self.input0() or {}).get("received") == "1", 10.0),
            "the known message was not reported received: %s" % self.input0())
        self.assertNotIn(KEY, self.input0())
        for k, first in enumerate((0.0, -1.0)):  # all zero; ROS's "unknown"
            # A stamp of its own per message (a repeated stamp is dropped).
            publisher.publish(imu(first, 0.0, start + rospy.Duration(0.001 * (k + 1))))
        self.assertTrue(wait_for(lambda: (self.input0() or {}).get(KEY) == "2", 10.0),
                        "input 0's report: %s" % self.input0())


if __name__ == "__main__":
    rospy.init_node("covariance_fallback_test")
    rostest.rosrun("sf_pkg", "covariance_fallback", CovarianceFallbackTest, sys.argv)
