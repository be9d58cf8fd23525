#!/usr/bin/python3
"""A GPS fix's covariance through the node (test/gps_covariance.test): a Kalman filter of a
position held still (x0 = 0, P0 = I, Q = 0, header R = 4 I) reads EAST and NORTH of
sensor_msgs/NavSatFix, with ~gps_yaw_offset 30 degrees (odom x points 30 degrees north of
east: x = c e + s n, y = -s e + c n). Each fix must give the Kalman update computed by hand
(test/kalman_2d.py) with R = Rot C Rot^T, Rot = [[c, s], [-s, c]], turned by hand here:
  1. the datum (value 0, 0), DIAGONAL_KNOWN with east 1, north 3 (and off-diagonal entries
     the type says to ignore): R has a covariance of x and y, 3 c s - c s = sqrt 3 / 2;
  2. 100 m north (x = 100 s, y = 100 c), KNOWN with east 1, north 2 and their covariance 0.5;
  3. the same point with COVARIANCE_TYPE_UNKNOWN: the header's R = 4 I.
"""

import math
import sys
import unittest

import rospy
import rostest
from sensor_msgs.msg import NavSatFix

from kalman_2d import product, update
from node_test_helpers import subscribe_states, wait_for

LAT, LON, ALT = 43.5, 7.25, 272.4
YAW = math.pi / 6  # the launch file's ~gps_yaw_offset
ROT = [[math.cos(YAW), math.sin(YAW)], [-math.sin(YAW), math.cos(YAW)]]


def turned(C):
    """Rot C Rot^T."""
    return product(product(ROT, C), [[ROT[j][i] for j in range(2)] for i in range(2)])


def hundred_metres_north():
    """Latitude [deg] 100 m north of LAT at height ALT (WGS84 meridian radius M + h)."""
    a, f = 6378137.0, 1.0 / 298.257223563
    e2 = f * (2 - f)
    s = math.sin(math.radians(LAT))
    m = a * (1 - e2) / (1 - e2 * s * s) ** 1.5
    return LAT + math.degrees(100.0 / (m + ALT))


def fix(lat, covariance, covariance_type):
    m = NavSatFix()
    m.header.stamp = rospy.Time.now()
    m.header.frame_id = "gps"
    m.status.status = 0  # STATUS_FIX
    m.latitude, m.longitude, m.altitude = lat, LON, ALT
    m.position_covariance = covariance
    m.position_covariance_type = covariance_type
    return m


class GpsCovarianceTest(unittest.TestCase):
    def setUp(self):
        self.states = subscribe_states("/gps_block/state")

    def measured(self):
        """The states of periods that had both inputs."""
        return [s for s in self.states if s.present_inputs == 2]

    def step(self, publisher, message, z, R):
        """Publishes `message`, waits for its period and checks the state against the update
        of the previous one with z and R."""
        count = len(self.measured())
        publisher.publish(message)
        self.assertTrue(wait_for(lambda: len(self.measured()) > count, 5.0),
                        "no measured period after fix %d" % (count + 1))
        self.x, self.P = update(self.x, self.P, z, R)
        state = self.measured()[count]
        for i in range(2):
            # The hand-computed position of the fix holds to 1e-6 m (the meridian's radius).
            self.assertAlmostEqual(state.state[i], self.x[i], delta=1e-5)
            for j in range(2):
                self.assertAlmostEqual(state.covariance[2 * i + j], self.P[i][j], places=9)

    def test_turned_and_correlated_covariances(self):
        publisher = rospy.Publisher("/fix", NavSatFix, queue_size=1)
        self.assertTrue(wait_for(lambda: publisher.get_num_connections() >= 1, 20.0),
                        "the node did not subscribe to /fix")
        self.assertTrue(wait_for(lambda: self.states, 20.0), "no ~state from the node")
        self.x, self.P = [0.0, 0.0], [[1.0, 0.0], [0.0, 1.0]]
        c, s = math.cos(YAW), math.sin(YAW)

        R1 = turned([[1.0, 0.0], [0.0, 3.0]])
        self.assertAlmostEqual(R1[0][1], math.sqrt(3.0) / 2, places=12)  # 3 c s - c s
        self.step(publisher, fix(LAT, [1.0, 0.7, 0, 0.7, 3.0, 0, 0, 0, 9.0],
                                 NavSatFix.COVARIANCE_TYPE_DIAGONAL_KNOWN), [0.0, 0.0], R1)

        north = [100.0 * s, 100.0 * c]
        R2 = turned([[1.0, 0.5], [0.5, 2.0]])
        self.step(publisher, fix(hundred_metres_north(), [1.0, 0.5, 0, 0.5, 2.0, 0, 0, 0, 9.0],
                                 NavSatFix.COVARIANCE_TYPE_KNOWN), north, R2)

        self.step(publisher, fix(hundred_metres_north(), [0.0] * 9,
                                 NavSatFix.COVARIANCE_TYPE_UNKNOWN), north,
                  [[4.0, 0.0], [0.0, 4.0]])


if __name__ == "__main__":
    rospy.init_node("gps_covariance_test")
    rostest.rosrun("sf_pkg", "gps_covariance", GpsCovarianceTest, sys.argv)
