#!/usr/bin/python3
"""The fusion node as a nodelet (test/nodelet.test). The generic robot's header
(config/diff_drive_odom_imu.h) runs as a nodelet in a manager and, as the reference, as a node
process; the skid-steer header's nodelet runs in the same manager (two headers' plugins in one
process). The test drives /clock in steps of the period and publishes the same wheel odometry
and IMU messages to all three. Every input is aligned by stamp with a lag of 0.5 s, so each
value counts for the period of its stamp whatever the order in which the processes receive the
messages and the clock. Checked:
- the nodelet's state of every period equals the node's (same header, inputs and periods);
- the estimates use the inputs: the velocity and yaw rate approach the published ones and the
  heading turns to the left;
- the skid-steer nodelet estimates the same motion with its own header (its state size),
  in the same manager: each plugin library runs its own header whichever loaded first;
- the nodelets' diagnostics and ~set_pose service carry the nodelet's name, not the manager's.
"""

import math
import sys
import time
import unittest

import rosservice
import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import Imu
from sf_msgs.msg import StateEstimateStamped

PERIOD = 0.02  # ESTIMATION_PERIOD 20 of both headers
LAG = 0.5  # ~max_measurement_lag in nodelet.test
V, OMEGA = 0.5, 0.2  # the published motion: forward speed [m/s], yaw rate [rad/s]
STEPS = 100  # periods with inputs
NAMES = ("node/fusion", "nodelet/fusion", "skid/fusion")


class NodeletTest(unittest.TestCase):
    def setUp(self):
        self.states = {name: {} for name in NAMES}
        for name in NAMES:
            rospy.Subscriber("/%s/state" % name, StateEstimateStamped, self.on_state, name)
        self.statuses = {}
        rospy.Subscriber("/diagnostics", DiagnosticArray, self.on_diagnostics)
        # Synchronous publishing (queue_size=None; rospy warns about it once): each message is
        # written to every subscriber's connection before the next clock step goes out. With a
        # queue, rospy sends from one thread per connection; under load the thread feeding the
        # node process's /odom fell 25 steps behind its /clock, and the node dropped those
        # values as later than the lag while the nodelets used them.
        self.clock = rospy.Publisher("/clock", Clock, queue_size=None)
        self.odom = rospy.Publisher("/odom", Odometry, queue_size=None)
        self.imu = rospy.Publisher("/imu/data", Imu, queue_size=None)

    def on_state(self, msg, name):
        self.states[name][msg.header.stamp.to_nsec()] = msg

    def on_diagnostics(self, msg):
        for s in msg.status:
            self.statuses[s.name] = s

    def wait_for(self, predicate, seconds, what):
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            if predicate():
                return
            time.sleep(0.005)
        self.fail("timed out waiting for " + what)

    def publish_clock(self, t):
        self.clock.publish(Clock(clock=rospy.Time.from_sec(t)))

    def newest(self, name):
        return max(self.states[name]) * 1e-9 if self.states[name] else -1.0

    def test_nodelet_estimates_as_the_node(self):
        # Every process subscribed to the inputs (the manager once for both nodelets).
        for publisher in (self.odom, self.imu, self.clock):
            self.wait_for(lambda p=publisher: p.get_num_connections() >= 2, 60,
                          "subscribers of " + publisher.resolved_name)
        t0 = 100.0
        self.publish_clock(t0)
        # The schedule starts at the first clock reading each process sees; all must see t0:
        # each reports its estimation status once it runs (before: "waiting for /clock").
        def started(name):
            s = self.statuses.get(name + ": estimation")
            return s is not None and "waiting for /clock" not in s.message
        for name in NAMES:
            self.wait_for(lambda n=name: started(n), 30, "the estimation status of " + name)
            self.assertNotIn("/manager: estimation", self.statuses)
        for k in range(STEPS + int(LAG / PERIOD) + 3):
            t = t0 + (k + 0.5) * PERIOD
            self.publish_clock(t)
            if k < STEPS:
                stamp = rospy.Time.from_sec(t)
                odom = Odometry()
                odom.header.stamp = stamp
                odom.header.frame_id = "odom"
                odom.child_frame_id = "base_link"
                odom.twist.twist.linear.x = V
                odom.twist.twist.angular.z = OMEGA
                self.odom.publish(odom)
                imu = Imu()
                imu.header.stamp = stamp
                imu.header.frame_id = "imu_link"
                imu.angular_velocity.z = OMEGA
                self.imu.publish(imu)
            # Lock step: every process has estimated the periods the lag has closed.
            closed = t - LAG - 2 * PERIOD
            for name in NAMES if closed > t0 else ():
                self.wait_for(lambda n=name: self.newest(n) >= closed, 20,
                              "%s's state at %.2f s" % (name, closed))

        node, nodelet, skid = (self.states[n] for n in NAMES)
        # Each runs its own header, whichever plugin library the manager loaded first: the
        # differential-drive header has 6 states, the skid-steer header 7 (its slip state).
        # Before the plugins were linked -Bsymbolic, the second library's call of the
        # per-header headerDefinition() resolved to the first library's (same symbol name),
        # and both nodelets ran the header loaded first.
        for name, states, size in ((NAMES[0], node, 6), (NAMES[1], nodelet, 6), (NAMES[2], skid, 7)):
            sizes = {len(m.state) for m in states.values()}
            self.assertEqual(sizes, {size}, "%s: state sizes %s" % (name, sizes))
        used = sorted(s for s in node if node[s].present_inputs > 0)
        self.assertGreaterEqual(len(used), STEPS - 5, "the node used too few periods' inputs")
        for stamp in used:
            self.assertIn(stamp, nodelet, "the nodelet has no state at %d ns" % stamp)
            a, b = node[stamp], nodelet[stamp]
            self.assertEqual(a.present_inputs, b.present_inputs)
            for x, y in zip(a.state + a.covariance, b.state + b.covariance):
                self.assertAlmostEqual(x, y, delta=1e-9 * max(1.0, abs(x)),
                                       msg="state at %d ns: node %r, nodelet %r"
                                       % (stamp, a.state, b.state))
        last = nodelet[used[-1]].state
        self.assertAlmostEqual(last[3], V, delta=0.02)  # x[3]: v
        self.assertAlmostEqual(last[4], OMEGA, delta=0.02)  # x[4]: omega
        self.assertGreater(last[2], 0.0)  # x[2]: heading, turned left
        skid_used = [s for s in skid if skid[s].present_inputs > 0]
        self.assertGreaterEqual(len(skid_used), STEPS - 5)
        self.assertAlmostEqual(skid[max(skid_used)].state[3], V, delta=0.02)

        # The nodelet's own name: its diagnostics and its ~set_pose service.
        for name in NAMES[1:]:
            self.assertIn(name + ": input 0 (odom twist.twist.linear.x)", self.statuses)
        services = rosservice.get_service_list()
        self.assertIn("/nodelet/fusion/set_pose", services)
        self.assertIn("/skid/fusion/set_pose", services)


if __name__ == "__main__":
    rospy.init_node("nodelet_test")
    rostest.rosrun("sf_pkg", "nodelet", NodeletTest, sys.argv)
