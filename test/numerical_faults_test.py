#!/usr/bin/python3
"""Numerical faults through running fusion nodes (test/numerical_faults.test,
doc/reliability.md): the filters repair them, the nodes keep publishing, and /diagnostics
reports the repairs (estimation WARN "N numerical repairs by the filter ...", the counts
by kind in the key values).

- numerics_ukf (test/configs/numerics_ukf.h): a UKF whose state is 1e9 m; every step needs
  a wider alpha (repairs: sigma spread). Fed a constant 1e9 + 0.5 m, the Kalman gain's
  steady state (Q = 0.01, R = 1: K = 0.095) brings the estimate to within 0.5 * 0.905^k of
  it after k periods: below 1e-3 m after 70; with the default alpha the rounding of the
  sigma points alone costs tenths of a metre (sf_estimation's BadlyScaledUkf test).
- numerics_pf (test/configs/numerics_pf.h): a particle filter of a constant 1.0 fed 1e200
  for one second: every particle weight vanishes, that measurement is dropped (repairs:
  particle weights), and the estimate stays at the constant.
The test drives /clock (5x real time) and publishes the sensors.
"""

import os
import sys
import time
import unittest

import rospy
import rostest
from rosgraph_msgs.msg import Clock
from std_msgs.msg import Float64

PKG_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(PKG_DIR, "tools", "eval"))
sys.dont_write_bytecode = True
import fusion_block  # noqa: E402  (sf_msgs/OutputEntityStamped without generated Python)
from any_message import AnyMessageDecoder  # noqa: E402

START = 100.0  # s of simulated time
DURATION = 12.0
BURST = (104.0, 105.0)  # 1e200 on the particle filter's input
FAR = 1e9 + 0.5
WARN = 1


class NumericalFaultsTest(unittest.TestCase):
    def test_repairs_are_reported_and_the_estimates_go_on(self):
        clock = rospy.Publisher("/clock", Clock, queue_size=10)
        far = rospy.Publisher("/numerics/far_position", Float64, queue_size=100)
        level = rospy.Publisher("/numerics/level", Float64, queue_size=100)
        statuses = {"numerics_ukf": [], "numerics_pf": []}  # node -> [(level, message, keys)]
        estimates = {"numerics_ukf": [], "numerics_pf": []}  # node -> [(stamp, value)]
        decode = AnyMessageDecoder()

        def on_diagnostics(raw):
            for status in decode(raw).status:
                for node in statuses:
                    if status.name == node + ": estimation":
                        statuses[node].append((status.level, status.message,
                                               {kv.key: kv.value for kv in status.values}))
        rospy.Subscriber("/diagnostics", rospy.AnyMsg, on_diagnostics)
        OutputEntityStamped = fusion_block.output_entity_class()
        for node, topic in (("numerics_ukf", "far_position"), ("numerics_pf", "level")):
            rospy.Subscriber("/numerics/estimate/" + topic, OutputEntityStamped,
                             lambda m, node=node: estimates[node].append(
                                 (m.header.stamp.to_sec(), m.value)))

        deadline = time.monotonic() + 20.0
        while time.monotonic() < deadline and (far.get_num_connections() < 1
                                               or level.get_num_connections() < 1):
            clock.publish(Clock(clock=rospy.Time.from_sec(START)))
            time.sleep(0.05)
        self.assertGreaterEqual(far.get_num_connections(), 1, "numerics_ukf did not subscribe")
        self.assertGreaterEqual(level.get_num_connections(), 1, "numerics_pf did not subscribe")
        time.sleep(0.5)

        # Every 10 ms of simulated time a clock tick; in the middle of each 100 ms period one
        # value per sensor.
        for k in range(int(DURATION / 0.01) + 1):
            t = START + 0.01 * k
            clock.publish(Clock(clock=rospy.Time.from_sec(t)))
            if k % 10 == 5:
                far.publish(Float64(FAR))
                level.publish(Float64(1e200 if BURST[0] <= t < BURST[1] else 1.0))
            time.sleep(0.002)
        time.sleep(1.0)  # the last reports (every 0.2 s of wall time)

        for node in statuses:
            self.assertTrue(statuses[node], "no /diagnostics from " + node)
            self.assertTrue(estimates[node], "no estimates from " + node)
            warned = [s for s in statuses[node]
                      if s[0] == WARN and "numerical repairs by the filter" in s[1]]
            self.assertTrue(warned, "%s never reported its repairs: %s" % (
                node, sorted({s[1] for s in statuses[node]})))
            final = statuses[node][-1][2]
            self.assertEqual(final["estimation failures"], "0", node)
            self.assertGreater(int(final["estimates"]), 100, node)

        ukf = statuses["numerics_ukf"][-1][2]
        pf = statuses["numerics_pf"][-1][2]
        print("numerics_ukf: %s; numerics_pf: %s" % (
            {k: v for k, v in ukf.items() if k.startswith("repairs") or k == "estimates"},
            {k: v for k, v in pf.items() if k.startswith("repairs") or k == "estimates"}))
        # A UKF step widens alpha in its prediction (from the previous belief) and again for the
        # correction's sigma points; a step counts once.
        self.assertGreater(int(ukf["repairs: sigma spread"]), 100)
        self.assertEqual(ukf["repairs: covariance"], "0")
        self.assertEqual(ukf["repairs: particle weights"], "0")
        late = [v for t, v in estimates["numerics_ukf"] if t > START + 8.0]
        self.assertTrue(late)
        self.assertLess(max(abs(v - FAR) for v in late), 1e-3)

        # One repair per period that averaged a 1e200: 10 values, at most 10 periods.
        weights = int(pf["repairs: particle weights"])
        self.assertGreaterEqual(weights, 1)
        self.assertLessEqual(weights, 10)
        self.assertEqual(pf["repairs: sigma spread"], "0")
        during = [v for t, v in estimates["numerics_pf"] if BURST[0] + 0.1 < t <= BURST[1]]
        after = [v for t, v in estimates["numerics_pf"] if t > BURST[1] + 1.0]
        self.assertGreaterEqual(len(during), 5, "the particle filter stopped publishing")
        self.assertTrue(after)
        self.assertLess(max(abs(v - 1.0) for v in during + after), 0.1)


if __name__ == "__main__":
    rospy.init_node("numerical_faults_test")
    rostest.rosrun("sf_pkg", "numerical_faults", NumericalFaultsTest, sys.argv)
