#!/usr/bin/python3
"""INPUT_COVARIANCE_BLOCK through the node (test/covariance_block.test): a Kalman filter of a
position held still (x0 = 0, P0 = I, Q = 0, header R = 4 I) reads x and y of
geometry_msgs/PoseWithCovarianceStamped with rows 0 and 1 of pose.covariance. A pose (1, 2)
with the block [[1, .5], [.5, 1]] must give the update computed by hand (test/kalman_2d.py; the
correlation moves y to 3.5 / 3.75 = 0.933; without it y would be 1); a second pose whose
covariance is all zero (ROS's "unknown") must be fused with the header's R = 4 I; a third whose
block is asymmetric in the last bit is rounding, fused with the pair's mean.
"""

import math
import sys
import unittest

import rospy
import rostest
from geometry_msgs.msg import PoseWithCovarianceStamped

from kalman_2d import update
from node_test_helpers import subscribe_states, wait_for


def pose(x, y, block):
    m = PoseWithCovarianceStamped()
    m.header.stamp = rospy.Time.now()
    m.header.frame_id = "odom"
    m.pose.pose.position.x = x
    m.pose.pose.position.y = y
    m.pose.pose.orientation.w = 1.0
    c = [0.0] * 36
    c[0], c[1], c[6], c[7] = block[0][0], block[0][1], block[1][0], block[1][1]
    m.pose.covariance = c
    return m


class CovarianceBlockTest(unittest.TestCase):
    def setUp(self):
        self.states = subscribe_states("/pose_block/state")

    def measured_after(self, count):
        """The states of periods that had both inputs, once there are more than `count`."""
        measured = [s for s in self.states if s.present_inputs == 2]
        return measured if len(measured) > count else None

    def check(self, state, x, P):
        for i in range(2):
            self.assertAlmostEqual(state.state[i], x[i], places=9)
            for j in range(2):
                self.assertAlmostEqual(state.covariance[2 * i + j], P[i][j], places=9)

    def test_correlated_then_unknown_covariance(self):
        publisher = rospy.Publisher("/pose", PoseWithCovarianceStamped, queue_size=1)
        self.assertTrue(wait_for(lambda: publisher.get_num_connections() >= 1, 20.0),
                        "the node did not subscribe to /pose")
        self.assertTrue(wait_for(lambda: self.states, 20.0), "no ~state from the node")
        x, P = [0.0, 0.0], [[1.0, 0.0], [0.0, 1.0]]
        block = [[1.0, 0.5], [0.5, 1.0]]
        publisher.publish(pose(1.0, 2.0, block))
        self.assertTrue(wait_for(lambda: self.measured_after(0), 5.0), "no measured period")
        x, P = update(x, P, [1.0, 2.0], block)
        self.assertAlmostEqual(x[1], 3.5 / 3.75, places=12)  # the hand computation itself
        self.check(self.measured_after(0)[0], x, P)
        # Unknown covariance (all zero): the header's R.
        publisher.publish(pose(2.0, -1.0, [[0.0, 0.0], [0.0, 0.0]]))
        self.assertTrue(wait_for(lambda: self.measured_after(1), 5.0),
                        "no second measured period")
        x, P = update(x, P, [2.0, -1.0], [[4.0, 0.0], [0.0, 4.0]])
        self.check(self.measured_after(1)[1], x, P)
        # Asymmetric in the last bit (0.5 against nextafter(0.5), issue 38 D4: every such
        # message was dropped as "variance is not finite, positive and at most 1e100"): within
        # the relative tolerance 1e-9, used with the mean of the pair.
        upper = math.nextafter(0.5, 1.0)
        publisher.publish(pose(0.5, 1.5, [[1.0, upper], [0.5, 1.0]]))
        self.assertTrue(wait_for(lambda: self.measured_after(2), 5.0),
                        "no third measured period: the rounded block was dropped")
        mean = (0.5 + upper) / 2
        x, P = update(x, P, [0.5, 1.5], [[1.0, mean], [mean, 1.0]])
        self.check(self.measured_after(2)[2], x, P)


if __name__ == "__main__":
    rospy.init_node("covariance_block_test")
    rostest.rosrun("sf_pkg", "covariance_block", CovarianceBlockTest, sys.argv)
