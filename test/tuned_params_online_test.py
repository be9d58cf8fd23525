#!/usr/bin/python3
"""A YAML file written by `--tune` (doc/tuning.md) changes the online node's estimates as it
changes the offline replay's, without a rebuild (test/tuned_params_online.test).

The test identifies Q and R of test/configs/tune_cart_kf.h on a simulated cart bag
(tools/sim/cart_sim.py, seed 1), loads the written file into the node's namespace with
`rosparam load`, starts the node (sf_tune_cart_kf), plays a second cart bag (seed 2,
readings in mid-period: --mid-period) with `rosbag play --clock --hz=1000` once the node is
subscribed and this test connected to its output, and compares
the states the node publishes on ~state with the offline replay of the same bag given the
file by --params.

Why the two must agree to rounding: the model is linear and time-invariant, so a period's
estimate depends only on which readings fall into which period. Offline the schedule starts
at the first message, online at the first /clock the node sees, the bag's start; every reading lies 30 ms or more from a period end (the
bag's --mid-period layout), so scheduling jitter below that does not move a reading into
another period. A reading that a stall of more than 30 ms did move shows as a run of
differing periods, which the test counts and prints; it requires identical estimates (1e-9)
in at least 90 % of the periods and the median difference far below what the file changes.
"""

import os
import subprocess
import sys
import tempfile
import time
import unittest

import rospy
import rostest

PKG_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(PKG_DIR, "tools", "sim"))
sys.dont_write_bytecode = True
import cart_sim  # noqa: E402
from nav3ctrl_online_test import find_executable  # noqa: E402  (the workspace lookup)

NODE = "sf_tune_cart_kf"
NAME = "cart_kf"
PERIOD = 0.1
ONLINE_PERIODS = 300
WALL_TIMEOUT = 120.0


def read_states(csv_path):
    """[(time, x0, x1)] of a replay CSV."""
    rows = []
    with open(csv_path) as f:
        header = f.readline().strip().split(",")
        i_t, i_0, i_1 = header.index("time"), header.index("x0"), header.index("x1")
        for line in f:
            cols = line.strip().split(",")
            rows.append((float(cols[i_t]), float(cols[i_0]), float(cols[i_1])))
    return rows


def nearest(rows, t):
    best = min(rows, key=lambda r: abs(r[0] - t))
    return best if abs(best[0] - t) < PERIOD / 2 else None


class TunedParamsOnlineTest(unittest.TestCase):
    def test_online_node_and_replay_take_the_tuned_file_alike(self):
        from sf_msgs.msg import StateEstimateStamped

        exe = find_executable(NODE)
        with tempfile.TemporaryDirectory(prefix="sf_tuned_online_") as tmp:
            tuning_bag = os.path.join(tmp, "tuning.bag")
            online_bag = os.path.join(tmp, "online.bag")
            tuned = os.path.join(tmp, "tuned.yaml")
            cart_sim.write_bag(tuning_bag, cart_sim.simulate(1, 3000))
            cart_sim.write_bag(online_bag, cart_sim.simulate(2, ONLINE_PERIODS), mid_period=True)
            subprocess.run([exe, "--tune", tuning_bag, "--out", tuned], check=True,
                           stdout=subprocess.PIPE, timeout=600)
            offline_csv = os.path.join(tmp, "offline.csv")
            header_csv = os.path.join(tmp, "header.csv")
            subprocess.run([exe, "--replay", online_bag, "--csv", offline_csv, "--params", tuned],
                           check=True, stdout=subprocess.PIPE, timeout=120)
            subprocess.run([exe, "--replay", online_bag, "--csv", header_csv], check=True,
                           stdout=subprocess.PIPE, timeout=120)
            offline, header = read_states(offline_csv), read_states(header_csv)

            states = []
            subscriber = rospy.Subscriber("/%s/state" % NAME, StateEstimateStamped,
                                          lambda m: states.append(
                                              (m.header.stamp.to_sec(), m.state[0], m.state[1])))
            subprocess.run(["rosparam", "load", tuned, "/" + NAME], check=True)
            node = subprocess.Popen([exe, "__name:=" + NAME])
            player = None
            try:
                # Events, not delays: the player starts once this test is connected to the
                # node's output and the node subscribed to both topics of the bag
                # (--wait-for-subscribers); the node's schedule starts at the first /clock.
                start = time.monotonic()
                while subscriber.get_num_connections() == 0:
                    self.assertLess(time.monotonic() - start, WALL_TIMEOUT,
                                    "not connected to the node's %s/state" % NAME)
                    self.assertIsNone(node.poll(), "the node exited")
                    time.sleep(0.05)
                player = subprocess.Popen(["rosbag", "play", "--clock", "--hz=1000",
                                           "--wait-for-subscribers", "-q", online_bag])
                end = offline[-1][0] - PERIOD / 2
                start = time.monotonic()
                while time.monotonic() - start < WALL_TIMEOUT and not rospy.is_shutdown():
                    if states and states[-1][0] >= end:
                        break
                    time.sleep(0.2)
            finally:
                for proc in (player, node):
                    if proc is not None:
                        proc.terminate()
                        proc.wait(timeout=30)
        self.assertTrue(states, "no state received from the node")
        diffs, changes = [], []
        for t, x0, x1 in states:
            ref = nearest(offline, t)
            if ref is None:
                continue
            diffs.append(max(abs(x0 - ref[1]), abs(x1 - ref[2])))
            h = nearest(header, ref[0])
            changes.append(max(abs(ref[1] - h[1]), abs(ref[2] - h[2])))
        self.assertGreater(len(diffs), 0.9 * len(offline), "too few online estimates")
        diffs_sorted, changes_sorted = sorted(diffs), sorted(changes)
        identical = sum(1 for d in diffs if d < 1e-9)
        median = diffs_sorted[len(diffs) // 2]
        change = changes_sorted[len(changes) // 2]
        print("online against offline, both with the tuned file: %d of %d periods identical "
              "(1e-9), median difference %.3g, max %.3g; the file moves the offline estimate by "
              "a median %.3g (max %.3g)" % (identical, len(diffs), median, diffs_sorted[-1], change,
                                             changes_sorted[-1]))
        self.assertGreaterEqual(identical, 0.9 * len(diffs))
        self.assertLess(median, 1e-9)
        self.assertGreater(change, 1e-3)


if __name__ == "__main__":
    rospy.init_node("tuned_params_online_test")
    rostest.rosrun("sf_pkg", "tuned_params_online", TunedParamsOnlineTest, sys.argv)
