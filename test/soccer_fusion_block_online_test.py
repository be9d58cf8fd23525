#!/usr/bin/python3
"""The soccer fusion block online (test/soccer_fusion_block_online.test): four 1 ms nodes
(vision_kf, encoder_kf, cwa_x, cwa_y) on the /clock of rosbag play --clock --hz=1000.

A node whose clock appears to run backwards resets its filter and counts it in its
/diagnostics ("clock resets"). The bag's clock only runs forwards, so every node must report
0 resets after the bag has played; before the schedule fix (doc/filter_node.md, "Bad input,
clock jumps and failures") the same clock reading passed twice near 1.7e9 s reset the nodes
in most 10 s runs. Independent of the counter, the fused position must be more accurate
against the bag's ground truth than the raw vision frames it is built from (each frame at its
own stamp): a reset throws the block back to its initial belief (doc/fusion_block.md: fused
RMSE 0.078 m in a run with a reset, against vision frames of about 0.016 m).
"""

import bisect
import math
import os
import sys
import time
import unittest

import rospy
import rostest
from rosgraph_msgs.msg import Clock

PKG_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(PKG_DIR, "tools", "eval"))
sys.dont_write_bytecode = True
import evaluate  # noqa: E402
import fusion_block  # noqa: E402  (sf_msgs/OutputEntityStamped without generated Python)
from any_message import AnyMessageDecoder  # noqa: E402

NODES = ["vision_kf", "encoder_kf", "cwa_x", "cwa_y"]
NAMESPACE = "fusion_block"
STARTUP = 0.1  # s of bag time
PERIOD = 0.001  # s, ESTIMATION_PERIOD of the block's nodes
WALL_TIMEOUT = 45.0  # s for the bag to play (2 s delay + 10 s) and the last reports
# The fused estimates are waited for up to this before the bag's end: the CWA nodes estimate a
# period once its stamped inputs may have come (their measurement lag, a few periods), and the
# player's last /clock may be a clock step (1 ms) before the end - 0.1 s covers both widely
# while being far inside the asserted span (duration - STARTUP - 1 s).
FUSED_END_MARGIN = 0.1


class SoccerFusionBlockOnlineTest(unittest.TestCase):
    def test_no_clock_reset_and_fused_beats_vision(self):
        bag = rospy.get_param("~bag")
        duration = rospy.get_param("~duration")

        reports = {}  # node -> (wall time, {key: value}) of its latest estimation status
        latest_clock = [0.0]
        fused = ({}, {})  # x, y: stamp -> value (finite variance only)
        rospy.Subscriber("/clock", Clock, lambda m: latest_clock.__setitem__(
            0, max(latest_clock[0], m.clock.to_sec())))

        decode = AnyMessageDecoder()

        def on_diagnostics(raw):
            msg = decode(raw)
            for status in msg.status:
                for node in NODES:
                    if status.name == "%s/%s: estimation" % (NAMESPACE, node):
                        reports[node] = (time.monotonic(),
                                         {kv.key: kv.value for kv in status.values})
        rospy.Subscriber("/diagnostics", rospy.AnyMsg, on_diagnostics)
        OutputEntityStamped = fusion_block.output_entity_class()
        for k, axis in enumerate("xy"):
            def on_fused(msg, k=k):
                if math.isfinite(msg.variance):
                    fused[k][msg.header.stamp.to_sec()] = msg.value
            rospy.Subscriber("/%s/fused/position/%s" % (NAMESPACE, axis), OutputEntityStamped,
                             on_fused)
        # The bag is read before the player starts: reading it costs about 2 s of CPU, which
        # on a loaded machine the four 1 ms nodes need while the bag plays.
        truth = evaluate.load_truth(bag)
        end = truth.t[0] + duration
        vision = evaluate.load_pose_bag(bag, "vision/pose", with_heading=False)
        # The player waits for a subscriber on each of its topics (--wait-for-subscribers in
        # the launch file); no node reads the ground truth, so it starts once this test is
        # subscribed, not after a fixed delay that a loaded machine outlasts (the first 5 s of
        # fused positions were lost so while the test was still reading the bag).
        rospy.Subscriber("/ground_truth/pose", rospy.AnyMsg, lambda _: None)

        start = time.monotonic()
        while time.monotonic() - start < WALL_TIMEOUT and latest_clock[0] < end - 0.01:
            time.sleep(0.1)
        self.assertGreaterEqual(latest_clock[0], end - 0.01, "the bag did not play to its end")
        # The nodes estimate behind the clock (on a loaded machine by seconds of wall time: the
        # CWA nodes' inputs are the other nodes' estimates): wait for fused positions of both
        # axes up to the end, as far as their 1 ms periods and lag reach, then for every
        # node's report (diagnostics come every 1 s of wall time).
        while (time.monotonic() - start < WALL_TIMEOUT
               and not all(fused[k] and max(fused[k]) >= end - FUSED_END_MARGIN for k in (0, 1))):
            time.sleep(0.1)
        played = time.monotonic()
        while (time.monotonic() - start < WALL_TIMEOUT
               and not all(n in reports and reports[n][0] > played + 0.1 for n in NODES)):
            time.sleep(0.1)
        for node in NODES:
            self.assertIn(node, reports, "no /diagnostics from %s" % node)
            self.assertGreater(reports[node][0], played, "no report of %s after the end" % node)
        resets = {n: int(reports[n][1]["clock resets"]) for n in NODES}
        estimates = {n: int(reports[n][1].get("estimates", "-1")) for n in NODES}

        # Left out: the first STARTUP s, in which the CWA nodes publish their initial belief
        # (value 0, finite variance) for the periods before their first input (the offline
        # evaluation leaves out the first estimate for the same reason; online there are a
        # few, as the nodes start on the clock of the player's delay).
        # The x and y nodes each start their 1 ms schedule at the first clock reading they
        # see: when one starts after the player has begun (a loaded machine), their period
        # ends differ by a fraction of a period. A position pairs each x estimate with the y
        # estimate of the period that overlaps it most (stamps less than half a period apart).
        ys = sorted(fused[1])
        stamps, xs_at, ys_at = [], [], []
        for t in sorted(t for t in fused[0] if t >= truth.t[0] + STARTUP):
            k = bisect.bisect_left(ys, t)
            near = min((ys[j] for j in (k - 1, k) if 0 <= j < len(ys)), default=None,
                       key=lambda u: abs(u - t))
            if near is not None and abs(near - t) < 0.5 * PERIOD:
                stamps.append(t)
                xs_at.append(fused[0][t])
                ys_at.append(fused[1][near])
        self.assertTrue(stamps, "no fused position received")
        online = evaluate.make_trajectory(stamps, xs_at, ys_at)
        ev_fused = evaluate.evaluate(online, truth)
        frames = [i for i, t in enumerate(vision.t) if stamps[0] <= t <= stamps[-1]]
        ev_vision = evaluate.evaluate(evaluate.make_trajectory(
            [vision.t[i] for i in frames], [vision.x[i] for i in frames],
            [vision.y[i] for i in frames]), truth)
        print("clock resets %s; estimates %s; fused x %d from %.4f to %.4f s, y %d from %.4f to "
              "%.4f s; %d fused positions over %.3f s (%.4f to %.4f), RMSE %.4f m; %d vision "
              "frames, RMSE %.4f m" % (
                  resets, estimates, len(fused[0]), min(fused[0]) - truth.t[0],
                  max(fused[0]) - truth.t[0], len(fused[1]), min(fused[1]) - truth.t[0],
                  max(fused[1]) - truth.t[0], len(stamps), stamps[-1] - stamps[0],
                  stamps[0] - truth.t[0], stamps[-1] - truth.t[0], ev_fused.rmse_pos,
                  len(frames), ev_vision.rmse_pos))
        self.assertEqual(resets, {n: 0 for n in NODES})
        # the block fuses over (nearly) the whole bag: one position per 1 ms period, of which
        # the recorder-free subscriber may lose some at 1 kHz
        self.assertGreater(stamps[-1] - stamps[0], duration - STARTUP - 1.0)
        self.assertGreater(len(stamps), 0.5 * (duration - STARTUP) / PERIOD)
        self.assertLess(ev_fused.rmse_pos, ev_vision.rmse_pos)


if __name__ == "__main__":
    rospy.init_node("soccer_fusion_block_online_test")
    rostest.rosrun("sf_pkg", "soccer_fusion_block_online", SoccerFusionBlockOnlineTest, sys.argv)
