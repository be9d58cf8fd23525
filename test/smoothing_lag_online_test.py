#!/usr/bin/python3
"""The fixed-lag smoother online equals the replay's, period for period
(test/smoothing_lag_online.test; issue 39: "the online fixed-lag output equals the replay's
fixed-lag output with the same lag").

sf_diff_drive_odom_imu with ~smoothing_lag 0.3 s (15 periods) and ~max_measurement_lag 0.1 s
(test/configs/smoothing_lag_online.yaml) runs on the /clock of the player; the replay of the
same bag gets the same file by --params (--smooth-lag through its smoothing_lag). Every
odometry/smoothed message must equal the lagged_* columns of the replay's row of its period.

Why equal, not within a bound. The header aligns all its inputs by stamp (ALIGN_BY_STAMP) and
has no control, so a value belongs to the period that contains its stamp, online as offline,
as long as it arrives before that period is estimated (within the 0.1 s lag: the test checks
that no value was dropped online); one stamped ahead of the node's clock (a /clock message
still on its way) waits in its own period (the core's queued periods). The periods' length is fixed and
the model uses it, not the clock, so the same values in the same periods give the same
numbers; online and offline run the same core, filter and smoother. What differs is the
schedule's phase: offline the periods start one lag before the first input message (an IMU
value stamped 3 ms into the bag), online one lag before the first /clock, which the player
publishes from the bag's first message (the ground truth, at 0 ms) on. The period k then ends
up to 3 ms earlier online; the bag's stamps (odometry at 10 ms, IMU at 3 and 13 ms in each
20 ms) keep 3 ms or more from both phases' period ends (both group the same values), so the
estimates of period k are the same, stamped with a constant offset below half a period. The
test therefore matches each online message to the replay's row nearest in time, requires one
offset for all of them (to 1 us), and the values to 1e-9 relative: they are computed from the
same doubles by the same code, so the difference is rounding at most (measured: 1.1e-16).

The smoothed stream must differ from the filtered one at the same period (the node could not
pass by publishing odometry/filtered on odometry/smoothed), and every period from the first
with a measured value to the bag's end must come online once. The node's /diagnostics report
the smoother (doc/filter_node.md): its lag, the periods and bytes it holds, as the replay's
summary has them, and the smoothing correction (what stands for a NIS, doc/smoothing.md) over
the periods it smoothed, recomputed from the replay's CSV for as many periods.
"""

import bisect
import math
import os
import re
import subprocess
import sys
import tempfile
import time
import unittest

import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Odometry

PKG_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(PKG_DIR, "test", "robots"))
sys.dont_write_bytecode = True
from nav3ctrl_online_test import find_executable, wait_until_nodes_connected  # noqa: E402
from replay_helpers import correction, read_rows  # noqa: E402

EXE = "sf_diff_drive_odom_imu"
PERIOD = 0.02  # s, the header's ESTIMATION_PERIOD
LAG_PERIODS = 15  # smoothing_lag 0.3 s of the parameter file
ANGLE_STATES = (2,)  # the header's ANGLE_STATES: the heading
RELATIVE = 1e-9  # rounding at most (the docstring)
SUMMARY_RELATIVE = 1e-5  # the diagnostics print 6 significant digits
# The bag's last smoothed period ends this long before its last message at most: the
# measurement lag (0.1 s), the smoothing lag (0.3 s), a period, the phase (< 1 period) and the
# player's last /clock step (1 ms), with room.
END_MARGIN = 0.5
WALL_TIMEOUT = 60.0


def odometry_values(m):
    """(x, y, heading, linear velocity, angular velocity) and their variances of an Odometry."""
    q = m.pose.pose.orientation
    heading = math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))
    c, t = m.pose.covariance, m.twist.covariance
    return (m.pose.pose.position.x, m.pose.pose.position.y, heading, m.twist.twist.linear.x,
            m.twist.twist.angular.z), (c[0], c[7], c[35], t[0], t[35])


def row_values(row, prefix):
    """The same of a replay CSV row's `prefix` columns (pose x, y, heading = states 0-2;
    velocities = states 3, 4)."""
    return tuple(row["%sx%d" % (prefix, i)] for i in range(5)), tuple(
        row["%svar%d" % (prefix, i)] for i in range(5))


def estimation_status(reports, node):
    """{key: value} of the node's latest estimation status in `reports`, or {}."""
    name = node.lstrip("/") + ": estimation"
    for array in reversed(reports):
        for s in array.status:
            if s.name == name:
                return {v.key: v.value for v in s.values}
    return {}


def input_drops(reports, node):
    """{status name: dropped} of the node's latest input statuses."""
    drops = {}
    prefix = node.lstrip("/") + ": input "
    for array in reports:
        for s in array.status:
            if s.name.startswith(prefix):
                drops[s.name] = int({v.key: v.value for v in s.values}.get("dropped", -1))
    return drops


class SmoothingLagOnlineTest(unittest.TestCase):
    def test_online_fixed_lag_equals_the_replay(self):
        node = rospy.get_param("~node")
        bag, params = rospy.get_param("~bag"), rospy.get_param("~params")
        smoothed, filtered, reports = [], {}, []
        rospy.Subscriber("odometry/smoothed", Odometry, lambda m: smoothed.append(
            (m.header.stamp.to_sec(),) + odometry_values(m)))
        rospy.Subscriber("odometry/filtered", Odometry, lambda m: filtered.__setitem__(
            m.header.stamp.to_sec(), odometry_values(m)))
        rospy.Subscriber("/diagnostics", DiagnosticArray, reports.append)
        # the replay before the player starts: it costs CPU the node needs while the bag plays
        rows, summary = self.replay(bag, params)
        times = [r["time"] for r in rows]
        import rosbag
        with rosbag.Bag(bag) as b:
            end = b.get_start_time() + rospy.get_param("~seconds") - END_MARGIN
        wait_until_nodes_connected(self, [node], WALL_TIMEOUT)
        # the player's last waited-for topic: only this test reads it, so it starts the bag
        rospy.Subscriber("ground_truth/pose", PoseStamped, lambda m: None)
        start = time.monotonic()
        while not rospy.is_shutdown() and time.monotonic() - start < WALL_TIMEOUT:
            # a report after the last smoothed message: the figures of a finished run
            if smoothed and smoothed[-1][0] >= end and estimation_status(reports, node).get(
                    "smoothing correction periods") == str(self.smoothed_periods(rows, smoothed)):
                break
            time.sleep(0.1)
        self.assertTrue(smoothed, "no odometry/smoothed received")
        self.assertGreaterEqual(smoothed[-1][0], end, "the node did not smooth up to the end")
        self.assertEqual(input_drops(reports, node),
                         {k: 0 for k in input_drops(reports, node)}, "values dropped online")
        matched = self.check_periods(smoothed, times)
        self.check_values(smoothed, filtered, rows, matched)
        self.check_diagnostics(estimation_status(reports, node), summary, rows)

    @staticmethod
    def smoothed_periods(rows, smoothed):
        """The periods smoothed online once the period of the newest smoothed message was:
        the rows up to and including its row (the online periods are the replay's)."""
        times = [r["time"] for r in rows]
        k = bisect.bisect_left(times, smoothed[-1][0] - PERIOD / 2)
        return k + 1

    def check_periods(self, smoothed, times):
        """The replay's row index of every online message: one constant offset below half a
        period, every period once from the first with a measured value on."""
        matched = [bisect.bisect_left(times, t - PERIOD / 2) for t, *_ in smoothed]
        offsets = [t - times[k] for (t, *_), k in zip(smoothed, matched)]
        print("%d smoothed messages online, rows %d-%d of the replay, offset %.6f s (online - "
              "offline, %.2e s spread)" % (len(smoothed), matched[0], matched[-1], offsets[0],
                                           max(offsets) - min(offsets)))
        self.assertLess(abs(offsets[0]), PERIOD / 2)
        self.assertLess(max(offsets) - min(offsets), 1e-6, "the online periods' phase moved")
        self.assertEqual(matched, list(range(matched[0], matched[0] + len(matched))),
                         "online periods missing or repeated")
        return matched

    def check_values(self, smoothed, filtered, rows, matched):
        """Each online smoothed message is its row's lagged belief; it is not the filtered one."""
        worst, moved = 0.0, 0.0
        for (t, values, variances), k in zip(smoothed, matched):
            ref_values, ref_variances = row_values(rows[k], "lagged_")
            self.assertFalse(math.isnan(ref_values[0]), "row %d has no lagged belief" % k)
            for name, online, offline in (("value", values, ref_values),
                                          ("variance", variances, ref_variances)):
                for i, (a, b) in enumerate(zip(online, offline)):
                    d = abs(a - b) if i != 2 or name == "variance" else abs(
                        math.atan2(math.sin(a - b), math.cos(a - b)))
                    worst = max(worst, d / (1.0 + abs(b)))
                    self.assertLessEqual(d, RELATIVE * (1.0 + abs(b)), "row %d: %s %d: online %r, "
                                         "offline %r" % (k, name, i, a, b))
            if t in filtered:
                moved = max(moved, math.hypot(values[0] - filtered[t][0][0],
                                              values[1] - filtered[t][0][1]))
        print("online - offline: largest relative difference %.3g; smoothed - filtered online: "
              "largest position difference %.4f m" % (worst, moved))
        # the smoothed pose is not the filtered one (measured 0.003 m at most on these 10 s)
        self.assertGreater(moved, 1e-4, "odometry/smoothed is the filtered pose")

    def check_diagnostics(self, status, summary, rows):
        """The smoother's report against the replay's summary and CSV."""
        m = re.search(r"fixed-lag smoother, lag (\d+) periods \(([0-9.eE+-]+) s; [^)]*\), (\d+) "
                      r"periods held, (\d+) bytes held", summary)
        self.assertTrue(m, summary)
        print("the node's smoother report: %s" % {k: v for k, v in status.items()
                                                   if k.startswith("smoothing")})
        self.assertEqual(int(status["smoothing lag [periods]"]), LAG_PERIODS)
        self.assertEqual(int(m.group(1)), LAG_PERIODS)
        self.assertAlmostEqual(float(status["smoothing lag [s]"]), LAG_PERIODS * PERIOD,
                               delta=1e-9)
        self.assertEqual(int(status["smoothing periods held"]), LAG_PERIODS + 1)
        self.assertEqual(int(status["smoothing bytes held"]), int(m.group(4)))
        n = int(status["smoothing correction periods"])
        figures = [correction(r, "lagged_", ANGLE_STATES) for r in rows[:n]]
        self.assertNotIn(None, figures)
        for key, reference in (
                ("smoothing correction RMS [sd]",
                 math.sqrt(sum(c[0] for c in figures) / n)),
                ("smoothing correction expected RMS [sd]",
                 math.sqrt(sum(c[1] for c in figures) / n)),
                ("smoothing correction, last period [sd]", math.sqrt(figures[-1][0])),
                ("smoothing correction expected, last period [sd]", math.sqrt(figures[-1][1]))):
            self.assertAlmostEqual(float(status[key]), reference,
                                   delta=SUMMARY_RELATIVE * abs(reference) + 1e-12, msg=key)

    @staticmethod
    def replay(bag, params):
        """The replay's CSV rows and summary, given the node's parameter file."""
        with tempfile.TemporaryDirectory(prefix="sf_smoothing_lag_online_") as tmp:
            csv_path = os.path.join(tmp, "offline.csv")
            proc = subprocess.run([find_executable(EXE), "--replay", bag, "--csv", csv_path,
                                   "--params", params], check=True, stdout=subprocess.PIPE,
                                  universal_newlines=True, timeout=60)
            return read_rows(csv_path), proc.stdout


if __name__ == "__main__":
    rospy.init_node("smoothing_lag_online_test")
    rostest.rosrun("sf_pkg", "smoothing_lag_online", SmoothingLagOnlineTest, sys.argv)
