"""A user's first hour on a recording (issue 37), config/skid_steer_odom_imu.h replayed offline.

Late values named (item 2 of "What to build"): on a simulated recording whose IMU messages arrive 25 ms plus an exponential jitter of mean 3 ms
after their stamps (tools/sim/diff_drive_sim.py --imu-latency-ms 25 --imu-jitter-ms 3), with
the header's MAX_MEASUREMENT_LAG of 20 ms:

- the replay summary gives each input's stamp-to-arrival delay: the IMU's median and p95 are
  those of the simulated latency (25 + 3 ln 2 = 27.1 ms, 25 + 3 ln 20 = 34.0 ms, to the
  estimator's 2.2 % and the sample's spread), the odometry's 0 (recorded at its stamps);
- it names the late IMU values with their share, the delays and the lag that would keep 99 % of
  them, which is at least the latency's p99 (25 + 3 ln 100 = 38.8 ms) and at most one bin
  (4.4 %) and a millisecond above it;
- replayed with that lag, at most 1 % of the IMU's values are late.

No assumed standstill at the start (item 3): a simulated skid-steer recording (the wheels' yaw
rate twice the true one, --slip-chi 2) cut to start in a turn (wheels -1.35 rad/s, gyro
-0.67 rad/s). Until the first standstill the gyro bias cannot be observed and its estimate
must stay within 2 of its own standard deviations of the simulator's bias; the header's old
start at v = omega = 0 read the first period as standstill and wrote 0.057 times the slip,
about 0.04 rad/s (8 standard deviations), into it. The Odometry's twist (TWIST_OUT, item 6)
is the state's v and omega with their variances, for this header and a Pioneer one.

The executable comes from $SF_LIB_DIR or the sourced devel space (skipped when not built).
"""

import math
import os
import re
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(REPO, "tools", "sim"))
sys.path.insert(0, HERE)
import diff_drive_sim as sim  # noqa: E402
from replay_helpers import read_rows, replay_exe  # noqa: E402

NODE = "sf_skid_steer_odom_imu"
LATENCY_MS, JITTER_MS = 25.0, 3.0
IMU = 2  # the header's input 2: imu/data angular_velocity.z


def latency_quantile(q):
    """The q-quantile of the simulated IMU latency [ms]: base + exponential jitter."""
    return LATENCY_MS - JITTER_MS * math.log(1.0 - q)


def input_line(output, index):
    """The summary's line of input `index` (printInputCounters)."""
    match = re.search(r"^\S+: input %d: .*$" % index, output, re.M)
    if match is None:
        raise AssertionError("no summary line of input %d in:\n%s" % (index, output))
    return match.group(0)


def delays(line):
    """(median, p95) [ms] of a summary line's stamp-to-arrival delay."""
    match = re.search(r"stamp-to-arrival delay median (\S+) ms, p95 (\S+) ms", line)
    if match is None:
        raise AssertionError("no delays in: " + line)
    return float(match.group(1)), float(match.group(2))


def late_counts(line):
    """(late, received) of a summary line."""
    received = int(re.search(r": (\d+) received", line).group(1))
    late = re.search(r"(\d+) late", line)
    return (int(late.group(1)) if late else 0), received


class LateValuesReplay(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix="sf_first_hour_late_test_")
        cls.bag = os.path.join(cls.tmp.name, "late_imu.bag")
        sim.main(["--seed", "3", "--duration", "40", "--imu-latency-ms", str(LATENCY_MS),
                  "--imu-jitter-ms", str(JITTER_MS), "--compression", "none", "--out", cls.bag])
        cls.output = cls.replay().stdout

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    @classmethod
    def replay(cls, *extra):
        return replay_exe(NODE, cls.bag, os.path.join(cls.tmp.name, "out.csv"), *extra)

    def test_summary_gives_each_inputs_delay(self):
        median, p95 = delays(input_line(self.output, IMU))
        self.assertAlmostEqual(median, latency_quantile(0.5), delta=0.03 * latency_quantile(0.5))
        self.assertAlmostEqual(p95, latency_quantile(0.95), delta=0.04 * latency_quantile(0.95))
        self.assertEqual(delays(input_line(self.output, 0)), (0.0, 0.0))  # odometry: at its stamp

    def test_late_values_are_named_with_the_lag_that_keeps_them(self):
        late, received = late_counts(input_line(self.output, IMU))
        self.assertGreater(late, 0, self.output)
        advice = re.search(r"^\S+: input 2 \(imu/data[^)]*\): (\d+) % of values dropped as late "
                           r"\((\d+) of (\d+)\): stamp-to-arrival delay median .* ms; "
                           r"--max-lag \(~max_measurement_lag\) (\S+) would keep 99 % "
                           r"\(now 0\.02\)$", self.output, re.M)
        self.assertIsNotNone(advice, self.output)
        self.assertEqual(int(advice.group(1)), round(100.0 * late / received))
        self.assertEqual((int(advice.group(2)), int(advice.group(3))), (late, received))
        lag_ms = 1e3 * float(advice.group(4))
        self.assertGreaterEqual(lag_ms, latency_quantile(0.99))
        self.assertLessEqual(lag_ms, 1.045 * latency_quantile(0.99) + 1.0)
        with_lag = self.replay("--max-lag", advice.group(4)).stdout
        late_after, received_after = late_counts(input_line(with_lag, IMU))
        self.assertEqual(received_after, received)
        self.assertLessEqual(late_after, 0.01 * received, with_lag)
        if late_after == 0:
            self.assertNotIn("dropped as late", with_lag)


def cut_bag(source, target, skip_s):
    """`source` without its first `skip_s` seconds (tf_static kept): a recording started later."""
    import rosbag  # noqa: E402  (ROS Python, as the simulator)
    with rosbag.Bag(source) as bag_in, rosbag.Bag(target, "w") as bag_out:
        start = bag_in.get_start_time()
        for topic, msg, t in bag_in.read_messages(raw=True):
            if t.to_sec() >= start + skip_s or topic.lstrip("/") == "tf_static":
                bag_out.write(topic, msg, t, raw=True)


SLIP_BIAS = 0.003  # [rad/s] the simulated gyro's yaw-rate bias in base_link
CUT_S = 5.0        # the cut recording starts in a turn


class StartInMotion(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix="sf_start_in_motion_test_")
        full = os.path.join(cls.tmp.name, "slip.bag")
        sim.main(["--seed", "1", "--duration", "60", "--slip-chi", "2", "--gyro-bias",
                  "0.004,0.003,-0.006", "--compression", "none", "--out", full])
        assert abs(sim.base_z_bias([0.004, 0.003, -0.006]) - SLIP_BIAS) < 1e-12
        cls.bag = os.path.join(cls.tmp.name, "moving_start.bag")
        cut_bag(full, cls.bag, CUT_S)
        csv_path = os.path.join(cls.tmp.name, "out.csv")
        cls.output = replay_exe(NODE, cls.bag, csv_path, "--bag",
                                os.path.join(cls.tmp.name, "out.bag")).stdout
        cls.rows = read_rows(csv_path)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_bias_not_learned_from_the_initial_state(self):
        first_stop = next(i for i, r in enumerate(self.rows)
                          if i > 0 and abs(r["x3"]) < 0.01 and abs(r["x4"]) < 0.01)
        self.assertGreater(self.rows[first_stop]["time"] - self.rows[0]["time"], 10.0)
        worst = max(abs(r["x5"] - SLIP_BIAS) / math.sqrt(r["var5"])
                    for r in self.rows[:first_stop])
        self.assertLess(worst, 2.0)

    def test_odometry_twist_is_the_states_velocity(self):
        check_twist(self, os.path.join(self.tmp.name, "out.bag"), self.rows, 3, 4)


def check_twist(test, out_bag, rows, v, omega):
    """The replay's /odometry/filtered twist is x[v] and x[omega] with their variances."""
    import rosbag  # noqa: E402
    by_time = {round(r["time"], 6): r for r in rows}
    seen = 0
    with rosbag.Bag(out_bag) as bag:
        for _, msg, _ in bag.read_messages(topics=["/odometry/filtered"]):
            row = by_time[round(msg.header.stamp.to_sec(), 6)]
            test.assertAlmostEqual(msg.twist.twist.linear.x, row["x%d" % v], places=9)
            test.assertAlmostEqual(msg.twist.twist.angular.z, row["x%d" % omega], places=9)
            test.assertAlmostEqual(msg.twist.covariance[0], row["var%d" % v], places=12)
            test.assertAlmostEqual(msg.twist.covariance[35], row["var%d" % omega], places=12)
            test.assertEqual(msg.twist.covariance[7], 1e6)  # lateral speed: not estimated
            seen += 1
    test.assertGreater(seen, 100)


class PioneerTwist(unittest.TestCase):
    """The Pioneer headers' Odometry twist (TWIST_OUT (5)(3): v = x[5], omega = x[3])."""

    def test_nav3ctrl_ekf(self):
        with tempfile.TemporaryDirectory(prefix="sf_pioneer_twist_test_") as tmp:
            csv_path, out_bag = os.path.join(tmp, "out.csv"), os.path.join(tmp, "out.bag")
            replay_exe("sf_nav3ctrl_ekf", os.path.join(REPO, "bags", "pioneer_seed1.bag"),
                       csv_path, "--bag", out_bag)
            check_twist(self, out_bag, read_rows(csv_path), 5, 3)


if __name__ == "__main__":
    unittest.main()
