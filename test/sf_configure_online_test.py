#!/usr/bin/python3
"""The configuration sf_configure writes runs online as it runs offline
(test/sf_configure_online.test; issue 37: "runs online and offline with the same estimates").

In its setup the test runs tools/sf_configure on ~bag with the workspace's built nodes: it
writes robot.yaml, robot.launch, replay.sh and report.md, and replays the bag offline through
the chosen node into robot.csv. The test then starts the written robot.launch with roslaunch
(a subprocess on rostest's master, /use_sim_time set by the .test), waits until the node is
connected to the player on every topic it plays, and only then subscribes to the ground truth,
the player's last waited-for topic, which starts the bag (tools/play_bag.py --clock
--wait-for-subscribers). It collects the node's odometry/filtered up to the bag's end and its
/diagnostics until they count every message of the bag.

What may differ, and the bound. The configured node aligns its inputs by stamp (the generic
headers' ALIGN_BY_STAMP): a value belongs to the period that contains its header.stamp, online
as offline, provided it arrives before that period is estimated, i.e. within
~max_measurement_lag L of the period's end. Online a value arrives later than its recorded
time by the player's and roscpp's transport (in ROS time: the wall latency times the play
rate); offline it arrives at its recorded time. So:
- a value the transport delays beyond L is dropped online as `late` and kept offline: the
  test requires every input's drop counts online to equal the offline replay's (and every
  message received: a queue overflow loses values as surely). This is what the lag rule of
  sf_configure leaves room for (the 20 ms for the delivery to the node, tools/sf_configure;
  with the earlier rule's 5 ms on diff_drive_seed1.bag this check failed, 14 values late);
- the schedule's phase: offline the periods start one lag before the first message, online
  one lag before the first /clock the node sees. With the same values in periods of the same
  length T (~estimation_period), a phase difference moves a value into at most the
  neighbouring period, which shifts the inputs by at most T; shifting the inputs of a
  dead-reckoning filter by T shifts its path in time by at most T, which moves a point on it
  by at most v_max T (v_max: the offline estimate's top speed, or the truth's if higher).
  That is the bound DELTA on the distance between the online and the offline estimate at the
  same time (offline interpolated between its periods), everywhere and at the end; on
  diff_drive_seed1.bag 0.62 m/s x 20 ms = 0.012 m, below the issue's 0.05 m, which caps it.
The online track's final error and RMSE against the ground truth must be within the offline
ones + DELTA. A recording without ground truth (the real Husky's, `bag:=.../husky_gps.bag`) is
compared with the replay alone, the bag's end standing for the truth's; the test then
subscribes to every topic of the bag, which starts the player.
"""

import math
import os
import re
import signal
import subprocess
import sys
import tempfile
import time
import unittest
import xml.etree.ElementTree as ElementTree

import rosbag
import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray
from nav_msgs.msg import Odometry

PKG_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TOOL = os.path.join(PKG_DIR, "tools", "sf_configure")
sys.path.insert(0, os.path.join(PKG_DIR, "tools", "eval"))
sys.dont_write_bytecode = True
import evaluate  # noqa: E402
from nav3ctrl_online_test import (find_executable, player_connections,  # noqa: E402
                                  wait_until_nodes_connected)

AGREEMENT = 0.05  # m, the "online and offline agree to 0.05 m"
TRUTH_TOPIC = "ground_truth/pose"
WALL_TIMEOUT = 150.0
OUTPUT = "odometry/filtered"


def bag_topics(path):
    """The topics of the bag (without a leading /) and its end time [s]."""
    with rosbag.Bag(path) as bag:
        info = bag.get_type_and_topic_info()
        return sorted(t.lstrip("/") for t in info.topics), bag.get_end_time()


def read_parameters(path):
    """{key: float} of the written robot.yaml's numeric `key: value` lines."""
    params = {}
    with open(path) as f:
        for line in f:
            key, _, value = line.partition(":")
            if value and not line.startswith("#"):
                try:
                    params[key.strip()] = float(value)
                except ValueError:
                    pass
    return params


def offline_counters(report):
    """{input: (received, dropped)} of the replay's summary in report.md."""
    counters = {}
    for m in re.finditer(r": input (\d+): (\d+) received, \d+ used, dropped: ([^,]+),", report):
        counters[int(m.group(1))] = (int(m.group(2)),
                                     sum(int(n) for n in re.findall(r"\d+", m.group(3))))
    return counters


def launched_node(launch_path):
    """(name, type) of the sf_pkg node in the written launch file, and the names of its
    static transform publishers."""
    nodes = list(ElementTree.parse(launch_path).getroot().iter("node"))
    node = [n for n in nodes if n.get("pkg") == "sf_pkg"]
    if len(node) != 1:
        raise AssertionError("%s: %d sf_pkg nodes, expected 1" % (launch_path, len(node)))
    statics = ["/" + n.get("name") for n in nodes if n.get("type") == "static_transform_publisher"]
    return "/" + node[0].get("name"), node[0].get("type"), statics


def wait_until_static_transforms_delivered(test, node, publishers, timeout):
    """Until each of the launch file's static transform publishers is connected to `node` on
    /tf_static: the latched transforms reach its tf listener on connecting, before the player
    starts, as on a robot whose static transforms are up before its sensors. (A /tf message of
    the same frame received first would make tf2 keep the frame as a dynamic one.)"""
    start = time.monotonic()
    while not all(node in (player_connections(p) or {}).get("/tf_static", set())
                  for p in publishers):
        test.assertLess(time.monotonic() - start, timeout,
                        "%s did not connect to the static transforms of %s" % (node, publishers))
        time.sleep(0.05)


class SfConfigureOnlineTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.bag = rospy.get_param("~bag")
        cls.tmp = tempfile.TemporaryDirectory(prefix="sf_configure_online_")
        cls.out = cls.tmp.name
        # the built nodes: the workspace's lib/sf_pkg (CMAKE_PREFIX_PATH, as rosrun finds them)
        lib_dir = os.path.dirname(find_executable("sf_diff_drive_odom_imu"))
        # without the tuning (test/robots/test_sf_configure_replay.py checks it): this test
        # is about online against offline, under the rostest's time limit
        proc = subprocess.run([sys.executable, TOOL, cls.bag, "--out", cls.out,
                               "--lib-dir", lib_dir, "--no-tune"],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              universal_newlines=True, timeout=300)
        print(proc.stdout)
        if proc.returncode != 0:
            raise AssertionError("sf_configure failed (%d):\n%s" % (proc.returncode, proc.stdout))
        with open(os.path.join(cls.out, "report.md")) as f:
            cls.report = f.read()
        cls.params = read_parameters(os.path.join(cls.out, "robot.yaml"))
        launch = os.path.join(cls.out, "robot.launch")
        cls.node, cls.node_type, cls.statics = launched_node(launch)
        cls.log_path = os.path.join(cls.out, "roslaunch.log")
        cls.log = open(cls.log_path, "w")
        cls.launch = subprocess.Popen(["roslaunch", "--wait", launch], stdout=cls.log,
                                      stderr=subprocess.STDOUT)

    @classmethod
    def tearDownClass(cls):
        # roslaunch's Ctrl-C: it stops the node and exits
        if cls.launch.poll() is None:
            cls.launch.send_signal(signal.SIGINT)
            try:
                cls.launch.wait(timeout=20)
            except subprocess.TimeoutExpired:
                cls.launch.kill()
                cls.launch.wait()
        cls.log.close()
        cls.tmp.cleanup()

    def node_log(self, lines=40):
        with open(self.log_path) as f:
            return "".join(f.readlines()[-lines:])

    def test_online_estimates_match_the_offline_replay(self):
        offline = evaluate.load_result_csv(os.path.join(self.out, "robot.csv"),
                                           ["pose_x", "pose_y"])
        counted = offline_counters(self.report)
        self.assertTrue(counted, "no replay summary in report.md:\n" + self.report)
        received, diagnostics = [], {}
        rospy.Subscriber(OUTPUT, Odometry, lambda m: received.append(
            (m.header.stamp.to_sec(), m.pose.pose.position.x, m.pose.pose.position.y)))
        prefix = self.node.lstrip("/") + ": input "  # the status names have no leading /
        rospy.Subscriber("/diagnostics", DiagnosticArray, lambda a: diagnostics.update(
            {int(s.name[len(prefix):].split()[0]): {v.key: v.value for v in s.values}
             for s in a.status if s.name.startswith(prefix)}))
        # read before the player starts: it costs CPU the node needs while the bag plays
        topics, bag_end = bag_topics(self.bag)
        truth = evaluate.load_truth(self.bag) if TRUTH_TOPIC in topics else None
        try:
            wait_until_nodes_connected(self, [self.node], WALL_TIMEOUT, subscribed_only=True)
            wait_until_static_transforms_delivered(self, self.node, self.statics, WALL_TIMEOUT)
        except AssertionError as e:
            raise AssertionError("%s\nroslaunch (exit %s):\n%s" % (e, self.launch.poll(),
                                                                   self.node_log()))
        # the player's last waited-for topic: only this test reads it, so it starts the bag;
        # a recording without ground truth (the real Husky's): every topic, the ones nobody
        # else reads last
        for topic in [TRUTH_TOPIC] if truth else topics:
            rospy.Subscriber(topic, rospy.AnyMsg, lambda m: None)

        # The last estimate: the node estimates a period once its clock passed the period's
        # end + L; its last clock reading is at least the last message - the clock's step, and its
        # periods' phase is that of its first /clock, so the last estimated period ends less
        # than T before that reading - L.
        period, lag = self.params["estimation_period"], self.params["max_measurement_lag"]
        # rosbag play publishes /clock every ~clock_step s of bag time (rate / its --hz)
        end = (truth.t[-1] if truth else bag_end) - rospy.get_param("~clock_step") - lag - period
        # ~wall_timeout: longer for a long recording (the shipped bag plays in 60 s)
        start, timeout = time.monotonic(), rospy.get_param("~wall_timeout", WALL_TIMEOUT)
        while not rospy.is_shutdown() and time.monotonic() - start < timeout:
            if received and received[-1][0] >= end and all(
                    int(diagnostics.get(i, {}).get("received", -1)) == n
                    for i, (n, _) in counted.items()):
                break
            time.sleep(0.2)
        failures = self.check_counters(counted, diagnostics)
        if not (received and received[-1][0] >= end):
            failures.append("the node did not estimate up to the bag's end (%s < %.3f s)" % (
                received[-1][0] if received else "nothing", end))
        if received:
            failures += self.check_estimates(evaluate.make_trajectory(*zip(*received)), offline,
                                             truth, period)
        if failures:
            self.fail("\n".join(failures) + "\nthe node's log:\n" + self.node_log())

    def check_counters(self, counted, diagnostics):
        """The failed checks, as texts, of: every message received online, and dropped as often
        as offline (late ones above all)."""
        figures = ["input %d: received %s (offline %d), dropped %s (offline %d; late %s), "
                   "stamp-to-arrival delay median %s ms, p95 %s ms" % (
                       i, diagnostics.get(i, {}).get("received"), n,
                       diagnostics.get(i, {}).get("dropped"), dropped,
                       diagnostics.get(i, {}).get("dropped: late"),
                       diagnostics.get(i, {}).get("stamp-to-arrival delay median [ms]"),
                       diagnostics.get(i, {}).get("stamp-to-arrival delay p95 [ms]"))
                   for i, (n, dropped) in sorted(counted.items())]
        print("%s online (~max_measurement_lag %.3f s):\n  %s" % (
            self.node, self.params["max_measurement_lag"], "\n  ".join(figures)))
        return ["online " + figures[i] for i, (n, dropped) in sorted(counted.items())
                if int(diagnostics.get(i, {}).get("received", -1)) != n or
                int(diagnostics.get(i, {}).get("dropped", -1)) != dropped]

    def check_estimates(self, online, offline, truth, period):
        """The failed checks, as texts, of: the online track within DELTA of the offline one,
        and as good against the truth."""
        speed = max(math.hypot(t.x[k + 1] - t.x[k], t.y[k + 1] - t.y[k]) / (t.t[k + 1] - t.t[k])
                    for t in (offline, truth) if t for k in range(len(t.t) - 1))
        delta = min(speed * period, AGREEMENT)
        gaps = []
        for t, x, y in zip(online.t, online.x, online.y):
            ref = evaluate.interpolate(offline, t)
            if ref is not None:
                gaps.append(math.hypot(x - ref[0], y - ref[1]))
        if len(gaps) <= 0.9 * len(offline.t):
            return ["too few online estimates (%d of %d)" % (len(gaps), len(offline.t))]
        final_gap = math.hypot(online.x[-1] - offline.x[-1], online.y[-1] - offline.y[-1])
        print("%s: online %d estimates, offline %d; online - offline: final %.4f m, max %.4f m, "
              "mean %.4f m (bound %.4f m: top speed %.3f m/s x period %.3f s, at most %.2f m)" % (
                  self.node, len(online.t), len(offline.t), final_gap, max(gaps),
                  sum(gaps) / len(gaps), delta, speed, period, AGREEMENT))
        checks = [("max online - offline gap", max(gaps), delta),
                  ("final online - offline gap", final_gap, delta)]
        if truth:
            ev_on, ev_off = evaluate.evaluate(online, truth), evaluate.evaluate(offline, truth)
            print("against the truth: online final error %.4f m, RMSE %.4f m; offline %.4f m, "
                  "%.4f m" % (ev_on.final_pos_err, ev_on.rmse_pos, ev_off.final_pos_err,
                              ev_off.rmse_pos))
            checks += [("online final error", ev_on.final_pos_err, ev_off.final_pos_err + delta),
                       ("online RMSE", ev_on.rmse_pos, ev_off.rmse_pos + delta)]
        return ["%s %.4f m, not below %.4f m" % (name, value, bound)
                for name, value, bound in checks if not value < bound]


if __name__ == "__main__":
    rospy.init_node("sf_configure_online_test")
    rostest.rosrun("sf_pkg", "sf_configure_online", SfConfigureOnlineTest, sys.argv)
