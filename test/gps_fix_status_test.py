#!/usr/bin/python3
"""A GPS input's fixes without a valid status in the node's diagnostics (test/gps_fix_status.test):
fixes with status STATUS_NO_FIX on /fix are dropped before the filter and counted, and the
reports of both GPS inputs (/fix longitude east, /fix latitude north) say so at ERROR level
(no value of the input reached the filter), naming the reason; a valid fix afterwards
reaches the filter (the report's "received" count grows)."""

import sys
import time
import unittest

import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticStatus
from sensor_msgs.msg import NavSatFix, NavSatStatus

from node_test_helpers import subscribe_diagnostics

REASON = "GPS fix status below STATUS_FIX"
INPUTS = ("/fix longitude east", "/fix latitude north")


def fix(status):
    m = NavSatFix()
    m.header.stamp = rospy.Time.now()
    m.header.frame_id = "gps"
    m.status.status = status
    m.latitude, m.longitude, m.altitude = 43.5, 7.25, 272.4
    m.position_covariance = [1.0, 0, 0, 0, 1.0, 0, 0, 0, 4.0]
    m.position_covariance_type = NavSatFix.COVARIANCE_TYPE_DIAGONAL_KNOWN
    return m


class GpsFixStatusTest(unittest.TestCase):
    def setUp(self):
        self.reports = subscribe_diagnostics()
        self.publisher = rospy.Publisher("/fix", NavSatFix, queue_size=10)

    def wait_for(self, predicate, seconds, publish=None):
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            if publish is not None:
                self.publisher.publish(fix(publish))
            if predicate():
                return True
            time.sleep(0.1)
        return False

    def statuses(self, name):
        return [s for a in self.reports for s in a.status if name in s.name]

    def test_no_fix_is_dropped_and_reported(self):
        self.assertTrue(self.wait_for(lambda: self.publisher.get_num_connections() >= 1, 20.0),
                        "the node did not subscribe to /fix")

        def reported():
            return all(any(REASON in s.message and s.level == DiagnosticStatus.ERROR
                           for s in self.statuses(name)) for name in INPUTS)
        self.assertTrue(self.wait_for(reported, 15.0, publish=NavSatStatus.STATUS_NO_FIX),
                        "no ERROR report naming '%s' for both GPS inputs; last: %s" %
                        (REASON, [(s.name, s.message) for s in self.statuses("/fix")[-2:]]))
        for name in INPUTS:
            dropped = [dict((kv.key, kv.value) for kv in s.values).get("dropped before the filter")
                       for s in self.statuses(name) if REASON in s.message]
            self.assertGreater(int(dropped[-1]), 0)

        def received():
            values = [dict((kv.key, kv.value) for kv in s.values)
                      for s in self.statuses(INPUTS[0])[-1:]]
            return any(int(v.get("received", "0")) > 0 for v in values)
        self.assertTrue(self.wait_for(received, 15.0, publish=NavSatStatus.STATUS_FIX),
                        "a valid fix did not reach the filter: %s" %
                        [s.values for s in self.statuses(INPUTS[0])[-1:]])


if __name__ == "__main__":
    rospy.init_node("gps_fix_status_test")
    rostest.rosrun("sf_pkg", "gps_fix_status", GpsFixStatusTest, sys.argv)
