"""Unit tests of the statistics of tools/data/real_bag_stats.py on synthetic series with
known answers (hand-computed values and closed forms)."""

import io
import math
import os
import random
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(REPO, "tools", "data"))
import real_bag_stats as rs  # noqa: E402

try:
    import rosbag  # noqa: F401
except ImportError:  # pragma: no cover - Debian's python3-rosbag is a package dependency
    rosbag = None


class BasicsTest(unittest.TestCase):
    def test_mean_stdev(self):
        # 2, 4, 4, 4, 5, 5, 7, 9: mean 5, sum of squares about it 32, n - 1 = 7
        v = [2, 4, 4, 4, 5, 5, 7, 9]
        self.assertEqual(rs.mean(v), 5.0)
        self.assertAlmostEqual(rs.stdev(v), math.sqrt(32 / 7), delta=1e-15)
        self.assertIsNone(rs.stdev([1.0]))

    def test_percentile(self):
        v = [5.0, 1.0, 3.0, 2.0, 4.0]       # sorted 1..5
        self.assertEqual(rs.percentile(v, 50), 3.0)
        self.assertEqual(rs.percentile(v, 0), 1.0)
        self.assertEqual(rs.percentile(v, 100), 5.0)
        self.assertAlmostEqual(rs.percentile(v, 95), 4.8, delta=1e-12)   # rank 3.8
        self.assertEqual(rs.percentile([1.0, 2.0, 3.0, 4.0], 50), 2.5)  # rank 1.5
        self.assertIsNone(rs.percentile([], 50))

    def test_interpolate_at(self):
        t = [0.0, 1.0, 3.0]
        v = [0.0, 10.0, 30.0]
        got = rs.interpolate_at(t, v, [-0.5, 0.0, 0.25, 1.0, 2.0, 3.0, 3.5])
        self.assertEqual(got, [(1, 0.0), (2, 2.5), (3, 10.0), (4, 20.0), (5, 30.0)])

    def test_correlation(self):
        a = [1.0, 2.0, 3.0, 4.0]
        self.assertAlmostEqual(rs.correlation(a, [2 * x + 7 for x in a]), 1.0, delta=1e-15)
        self.assertAlmostEqual(rs.correlation(a, [-x for x in a]), -1.0, delta=1e-15)
        # a = 1,2,3,4 against b = 1,3,2,4: centred (-1.5,-.5,.5,1.5) and (-1.5,.5,-.5,1.5):
        # sum of products 4, sums of squares 5 and 5 -> 0.8
        self.assertAlmostEqual(rs.correlation(a, [1.0, 3.0, 2.0, 4.0]), 0.8, delta=1e-15)
        self.assertIsNone(rs.correlation(a, [1.0] * 4))


class FitTest(unittest.TestCase):
    def test_scale_fit_exact(self):
        x = [-0.5, 0.2, 0.4, 1.0]
        s, res = rs.scale_fit(x, [1.8 * a for a in x])
        self.assertAlmostEqual(s, 1.8, delta=1e-14)
        self.assertAlmostEqual(res, 0.0, delta=1e-14)

    def test_scale_fit_hand_values(self):
        # x = (1, 2), y = (2, 3): s = (2 + 6) / 5 = 1.6; residuals 0.4, -0.2;
        # residual std sqrt((0.16 + 0.04) / 1)
        s, res = rs.scale_fit([1.0, 2.0], [2.0, 3.0])
        self.assertAlmostEqual(s, 1.6, delta=1e-15)
        self.assertAlmostEqual(res, math.sqrt(0.2), delta=1e-15)

    def test_affine_fit(self):
        x = [0.1, -0.3, 0.7, 0.2]
        s, b = rs.affine_fit(x, [1.5 * (a - 0.04) for a in x])
        self.assertAlmostEqual(s, 1.5, delta=1e-13)
        self.assertAlmostEqual(b, 0.04, delta=1e-13)

    def test_yaw_rate_comparison_finds_a_rotated_axis(self):
        # the yaw rate is on -y of the gyro (IMU mounted rotated about x); the wheels report
        # 2 x the true yaw rate. Gyro at 8 Hz, odometry at 10 Hz; the yaw rate is linear in
        # time between samples, so the interpolation is exact.
        true = lambda t: 0.3 * t - 0.5 if t < 2.0 else 0.1 - 0.7 * (t - 2.0)
        imu_t = [k / 8.0 for k in range(33)]                     # 0 .. 4 s
        imu_t.insert(16, 2.0)                                    # the kink is a sample
        imu_t = sorted(set(imu_t))
        imu_w = [(0.01 * math.sin(7 * t), -true(t), 0.02 * math.cos(3 * t)) for t in imu_t]
        odom_t = [0.05 + k / 10.0 for k in range(45)]           # 0.05 .. 4.45 s
        odom_wz = [2.0 * true(t) for t in odom_t]
        r = rs.yaw_rate_comparison(odom_t, odom_wz, imu_t, imu_w)
        self.assertEqual(r["n"], 40)                              # 0.05 .. 3.95 inside
        self.assertEqual(r["axis"], 1)
        self.assertEqual(r["sign"], -1)
        self.assertAlmostEqual(r["correlation"], -1.0, delta=1e-12)
        self.assertAlmostEqual(r["scale"], -2.0, delta=1e-12)
        self.assertAlmostEqual(r["residual_std"], 0.0, delta=1e-12)
        self.assertAlmostEqual(r["gyro_offset"], 0.0, delta=1e-12)

    def test_yaw_rate_residual_std_of_known_noise(self):
        # wheel = 1.25 * gyro + noise of std 0.05: the fitted scale and the residual std
        # approach them (tolerances ~4 standard errors for n = 4000)
        rng = random.Random("real_bag_stats/noise")
        t = [k * 0.1 for k in range(4001)]
        gyro = [math.sin(0.37 * x) + 0.5 * math.sin(1.3 * x) for x in t]
        wheel = [1.25 * g + rng.gauss(0.0, 0.05) for g in gyro]
        r = rs.yaw_rate_comparison(t, wheel, t, [(0.0, 0.0, g) for g in gyro])
        self.assertEqual(r["axis"], 2)
        self.assertAlmostEqual(r["scale"], 1.25, delta=4 * 0.05 / math.sqrt(4001 * 0.625))
        self.assertAlmostEqual(r["residual_std"], 0.05, delta=4 * 0.05 / math.sqrt(2 * 4000))


class LagTest(unittest.TestCase):
    def test_recovers_a_known_stamp_offset(self):
        # the gyro stamps the same motion 0.07 s later than the odometry
        f = lambda t: math.sin(1.1 * t) + 0.4 * math.sin(2.9 * t)
        odom_t = [k * 0.1 for k in range(5, 300)]
        imu_t = [k * 0.01 for k in range(3100)]
        imu_w = [(0.0, 0.0, f(t - 0.07)) for t in imu_t]
        lag, c = rs.best_lag(odom_t, [1.5 * f(t) for t in odom_t], imu_t, imu_w, 2)
        self.assertAlmostEqual(lag, 0.07, delta=1e-9)
        self.assertGreater(c, 0.9999)


class StandstillTest(unittest.TestCase):
    def test_samples_between_two_still_odometry_messages(self):
        odom_t = [0.0, 1.0, 2.0, 3.0, 4.0]
        odom_v = [0.5, 0.0, 0.0, 0.0, 0.3]
        odom_w = [0.1, 0.0, 0.0, 0.0, 0.0]
        imu_t = [0.5, 1.0, 1.5, 2.5, 3.0, 3.5, 4.5]
        gyro = [9.0, 0.01, 0.03, -0.01, 0.05, 9.0, 9.0]
        # 0.5: before is moving; 1.0 .. 2.5: both neighbours still; 3.0: before = 3.0 still,
        # after = 4.0 moving; 3.5 likewise; 4.5: no message after
        got = rs.standstill_samples(odom_t, odom_v, odom_w, imu_t, gyro)
        self.assertEqual(got, [0.01, 0.03, -0.01])
        self.assertAlmostEqual(rs.mean(got), 0.01, delta=1e-15)
        self.assertAlmostEqual(rs.stdev(got), 0.02, delta=1e-15)  # deviations 0, .02, -.02

    def test_tolerance(self):
        got = rs.standstill_samples([0.0, 1.0], [0.001, -0.002], [0.0, 0.0005], [0.5], [7.0],
                                    tol=0.002)
        self.assertEqual(got, [7.0])
        self.assertEqual(rs.standstill_samples([0.0, 1.0], [0.001, -0.002], [0.0, 0.0005],
                                               [0.5], [7.0]), [])


class StampTest(unittest.TestCase):
    def test_rate_and_gaps(self):
        # 10 Hz with samples 3, 4 and 8 missing, one stamp repeated, one going back
        stamps = [k * 0.1 for k in (0, 1, 2, 5, 6, 7, 9, 10)]
        r = rs.rate_stats(stamps)
        self.assertEqual(r["n"], 8)
        self.assertAlmostEqual(r["rate"], 7 / 1.0, delta=1e-12)
        self.assertAlmostEqual(r["median_period"], 0.1, delta=1e-12)
        self.assertAlmostEqual(r["max_period"], 0.3, delta=1e-12)
        self.assertEqual((r["gaps"], r["missing"]), (2, 3))
        self.assertEqual((r["repeated"], r["backwards"]), (0, 0))
        r = rs.rate_stats([0.0, 0.1, 0.1, 0.2, 0.15, 0.3])
        self.assertEqual((r["repeated"], r["backwards"]), (1, 1))

    def test_seq(self):
        self.assertEqual(rs.seq_stats([5, 6, 8, 8, 12, 11]), (1 + 3, 1, 1))

    def test_latency(self):
        stamps = [float(k) for k in range(5)]
        recv = [s + d for s, d in zip(stamps, [0.01, 0.05, 0.02, 0.03, 0.04])]
        med, p95 = rs.latency_stats(stamps, recv)
        self.assertAlmostEqual(med, 0.03, delta=1e-12)
        self.assertAlmostEqual(p95, 0.048, delta=1e-12)  # rank 3.8 of .01 .02 .03 .04 .05


@unittest.skipIf(rosbag is None, "python3-rosbag missing")
class HuskyBagTest(unittest.TestCase):
    def test_report_runs_on_the_shipped_bag(self):
        out = io.StringIO()
        self.assertEqual(rs.report(os.path.join(REPO, "bags", "husky_gps.bag"), out=out), 0)
        text = out.getvalue()
        self.assertIn("yaw axis: +z", text)
        self.assertIn("| `/encoder` | nav_msgs/Odometry | 380 |", text)


if __name__ == "__main__":
    unittest.main()
