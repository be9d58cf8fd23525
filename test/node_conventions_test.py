#!/usr/bin/python3
"""The fusion node's ROS conventions and what its diagnostics and log say (issues 15 and 17),
through sf_diff_drive_odom_imu (config/diff_drive_odom_imu.h: inputs 0, 1 from odom, input 2
the IMU's angular_velocity.z rotated into base_link, pose outputs with tf). Each case starts
the node itself in its own namespace, so that the topics of the cases do not meet, and waits
for events (log lines, messages), never for a fixed time; the deadlines only bound a failure.

- no odometry and no tf before the first estimate from a measured input (the initial belief
  at the origin is not a pose of the robot);
- an input whose every value is dropped before the filter (an IMU with an empty frame_id) is
  ERROR in /diagnostics with the reason, while its messages arrive;
- a publisher of another message type on an input topic is ERROR naming the topic and both
  types;
- use_sim_time without /clock is said in the log and in /diagnostics;
- unknown private parameters are warned about, robot_localization's names with a hint;
- ~frequency [Hz] sets the period; a ~transform_timeout above 60 s is refused.
"""

import os
import queue
import signal
import subprocess
import sys
import threading
import time
import unittest

import rospy
import rostest

EXE_NAME = "sf_diff_drive_odom_imu"
DEADLINE = 60.0  # s: bounds a failing wait only


def find_executable(name):
    from catkin.find_in_workspaces import find_in_workspaces

    found = find_in_workspaces(["libexec"], project="sf_pkg", path=name)
    if not found:
        raise RuntimeError("%s not found in the catkin workspaces" % name)
    return found[0]


class Node:
    """The node under test, its log read line by line by a thread."""

    def __init__(self, exe, ns, params):
        self.name = "/%s/fusion" % ns
        for key, value in params.items():
            rospy.set_param("%s/%s" % (self.name, key), value)
        # INFO goes to stdout, WARN and above to stderr: both read, stdout line-buffered
        env = dict(os.environ, ROSCONSOLE_STDOUT_LINE_BUFFERED="1")
        self.proc = subprocess.Popen(
            [exe, "__ns:=/" + ns, "__name:=fusion"], stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT, universal_newlines=True, env=env)
        self.lines = queue.Queue()
        self.seen = []
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        for line in self.proc.stdout:
            self.lines.put(line)

    def wait_for_line(self, *words):
        """The first line of stderr that holds every one of `words`."""
        for line in self.seen:
            if all(w in line for w in words):
                return line
        end = time.monotonic() + DEADLINE
        while time.monotonic() < end:
            try:
                line = self.lines.get(timeout=0.5)
            except queue.Empty:
                if self.proc.poll() is not None and self.lines.empty():
                    break
                continue
            self.seen.append(line)
            if all(w in line for w in words):
                return line
        raise AssertionError("no line with %r in the node's log:\n%s" % (words, "".join(self.seen)))

    def stop(self):
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGINT)
            try:
                self.proc.wait(timeout=30)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()


def wait_until(condition, what, tick=None):
    end = time.monotonic() + DEADLINE
    while time.monotonic() < end and not rospy.is_shutdown():
        if condition():
            return
        if tick:
            tick()
        time.sleep(0.02)
    raise AssertionError("timed out waiting for " + what)


class NodeConventionsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.exe = find_executable(EXE_NAME)

    def setUp(self):
        self.nodes = []
        self.subscribers = []

    def tearDown(self):
        for s in self.subscribers:
            s.unregister()
        for n in self.nodes:
            n.stop()

    def start(self, ns, **params):
        node = Node(self.exe, ns, params)
        self.nodes.append(node)
        node.wait_for_line("state ->")  # the start-up summary's end: subscribed, publishing
        return node

    def collect(self, topic, cls):
        got = []
        self.subscribers.append(rospy.Subscriber(topic, cls, got.append, queue_size=1000))
        return got

    def diagnostics(self):
        from diagnostic_msgs.msg import DiagnosticArray

        return self.collect("/diagnostics", DiagnosticArray)

    @staticmethod
    def input_status(arrays, node, index):
        """Every status of input `index` of `node` received so far."""
        prefix = "%s: input %d (" % (node.name.lstrip("/"), index)
        return [s for a in arrays for s in a.status if s.name.lstrip("/").startswith(prefix)]

    def test_no_pose_before_a_measured_input(self):
        from nav_msgs.msg import Odometry
        from tf2_msgs.msg import TFMessage

        states = self.collect("/pose_case/fusion/state", rospy.AnyMsg)
        odometry = self.collect("/pose_case/odometry/filtered", Odometry)
        tf = self.collect("/tf", TFMessage)
        self.start("pose_case", publish_tf=True, child_frame_id="pose_case_base")
        # 10 periods estimated without any input: neither odometry nor tf
        wait_until(lambda: len(states) >= 10, "10 estimates of the node")
        self.assertEqual(len(odometry), 0, "odometry published before any input")
        ours = [t for m in tf for t in m.transforms if t.child_frame_id == "pose_case_base"]
        self.assertEqual(ours, [], "tf published before any input")
        # the first measured value: the pose follows
        pub = rospy.Publisher("/pose_case/odom", Odometry, queue_size=10)
        msg = Odometry()
        msg.header.frame_id = "odom"
        msg.twist.twist.linear.x = 0.5

        def tick():
            msg.header.stamp = rospy.Time.now()
            pub.publish(msg)

        wait_until(lambda: len(odometry) > 0, "odometry after a measured input", tick)
        wait_until(lambda: any(t.child_frame_id == "pose_case_base"
                               for m in tf for t in m.transforms), "tf after a measured input",
                   tick)

    def test_every_value_dropped_is_an_error(self):
        from sensor_msgs.msg import Imu

        arrays = self.diagnostics()
        node = self.start("frame_case", transform_timeout=0.1, diagnostic_period=0.2)
        pub = rospy.Publisher("/frame_case/imu/data", Imu, queue_size=10)
        msg = Imu()
        msg.header.frame_id = ""  # no frame: no transform into base_link

        def tick():
            msg.header.stamp = rospy.Time.now()
            pub.publish(msg)

        def error_reported():
            return any(s.level == s.ERROR and "every value dropped" in s.message
                       and "no transform from frame ''" in s.message
                       for s in self.input_status(arrays, node, 2))

        wait_until(error_reported, "input 2 ERROR with the reason in /diagnostics", tick)

    def test_publisher_of_another_type_is_an_error(self):
        from std_msgs.msg import String

        arrays = self.diagnostics()
        node = self.start("type_case", diagnostic_period=0.2)
        pub = rospy.Publisher("/type_case/imu/data", String, queue_size=10)

        def error_reported():
            return any(s.level == s.ERROR and "/type_case/imu/data" in s.message
                       and "std_msgs/String" in s.message and "sensor_msgs/Imu" in s.message
                       for s in self.input_status(arrays, node, 2))

        wait_until(error_reported, "input 2 ERROR naming the topic and both types",
                   lambda: pub.publish(String(data="not an imu")))

    def test_waiting_for_clock_is_logged_and_reported(self):
        arrays = self.diagnostics()
        rospy.set_param("/use_sim_time", True)
        try:
            node = Node(self.exe, "clock_case", {"diagnostic_period": 0.2})
            self.nodes.append(node)
            node.wait_for_line("waiting for /clock")
        finally:
            rospy.delete_param("/use_sim_time")
        wait_until(lambda: any(s.level == s.WARN and "waiting for /clock" in s.message
                               and s.name.startswith("clock_case/fusion: estimation")
                               for a in arrays for s in a.status),
                   "WARN waiting for /clock in /diagnostics")

    def test_unknown_parameters_are_warned_about(self):
        node = Node(self.exe, "unknown_case", {"two_d_mode": True, "estimation_perod": 0.05,
                                              "odom0": "odom"})
        self.nodes.append(node)
        line = node.wait_for_line("unknown private parameter ~two_d_mode ignored",
                                  "robot_localization")
        self.assertIn("known: estimation_period, frequency", line)
        node.wait_for_line("unknown private parameter ~estimation_perod ignored")
        node.wait_for_line("unknown private parameter ~odom0 ignored", "robot_localization")

    def test_huge_transform_timeout_is_refused(self):
        # only a node with FRAME_ALIGNED_INPUTS reads it: 1e9 s froze the node without a word
        node = Node(self.exe, "tf_timeout_case", {"transform_timeout": 1e9})
        self.nodes.append(node)
        node.wait_for_line("refusing to start: parameter ~transform_timeout: expected 0 .. 60 s")
        self.assertEqual(node.proc.wait(timeout=DEADLINE), 1)

    def test_frequency_sets_the_period(self):
        node = Node(self.exe, "frequency_case", {"frequency": 25})
        self.nodes.append(node)
        node.wait_for_line("period 40.0 ms")


if __name__ == "__main__":
    rospy.init_node("node_conventions_test")
    rostest.rosrun("sf_pkg", "node_conventions", NodeConventionsTest, sys.argv)
