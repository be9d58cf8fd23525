"""Offline replay of bags/diff_drive_seed1.bag through sf_diff_drive_odom_imu
(config/diff_drive_odom_imu.h): the gyro bias is estimated and the pose error stays within
bounds derived from the simulator's noise, the IMU's angular velocity is rotated into
base_link with the bag's /tf_static, and values without a transform are dropped and counted.

The executable is taken from $SF_LIB_DIR (set by the CMake test registration), else from
the sourced devel space. Run by hand:
  SF_LIB_DIR=$WS/devel/lib/sf_pkg test/eval/run_unittests.py --start-dir test/robots -v

The bounds (the simulator's values are its module constants; the filter's from the header):
  Bias. Per 20 ms period the odometry measures omega with variance r_o and the gyro omega + b
  with r_g (the mean of its two samples); omega itself is free from period to period (its
  process noise, 0.02 rad^2/s^2 per period, dwarfs both), so each period tells b with
  variance r = r_o + r_g: a measurement of b with noise density rho = r T. The filter models
  b as a random walk (q_b), so its belief P(t) follows dP/dt = q_b - P^2/rho from P0 (the
  scalar Kalman-Bucy Riccati equation, solved in closed form below). The true bias is
  constant, and the error of the estimate then follows the same equation without q_b, so
  its variance stays below P(t): sigma_b(t) = sqrt(P(t)), 0.54 mrad/s after 60 s.
  Heading. The yaw rate follows the gyro corrected by the bias estimate, so the heading error
  is the integral of the bias error plus the integrated gyro noise; by the triangle
  inequality sigma_theta(t) <= int_0^t sigma_b + sqrt(s_g^2 dt_imu t).
  Position. A heading error e turns the step v dt sideways by e v dt, and the speed's noise
  integrates: sigma_p(t) <= int_0^t |v| sigma_theta + sqrt(r_v T t), plus the latency of one
  period (v_max T: the estimate at a period's end averages the period's inputs).
The checks use 4 sigma for the bias and 3 sigma for the pose (the sigmas are already upper
bounds); the control run without the rotation must break them.
"""

import bisect
import math
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "tools", "eval"))
sys.path.insert(0, os.path.join(REPO, "tools", "sim"))
sys.dont_write_bytecode = True
sys.path.insert(0, HERE)
import diff_drive_sim as sim  # noqa: E402
import evaluate  # noqa: E402
from replay_helpers import read_rows, replay_exe  # noqa: E402

EXE = "sf_diff_drive_odom_imu"
BAG = os.path.join(REPO, "bags", "diff_drive_seed1.bag")

# config/diff_drive_odom_imu.h
PERIOD = 0.020            # ESTIMATION_PERIOD [s]
P0_BIAS = 2.5e-3          # INITIAL_ERROR_COVARIANCE of b_g
Q_BIAS = 1e-8             # PROCESS_NOISE_COVARIANCE of b_g per second

# tools/sim/diff_drive_sim.py
TRUE_BIAS = sim.base_z_bias(sim.DEFAULT_GYRO_BIAS)
R_SPEED = sim.WHEEL_STD ** 2 / 2                      # odometry v per message
R_YAW_ODOM = 2 * sim.WHEEL_STD ** 2 / sim.TRACK ** 2  # odometry omega per message
IMU_DT = sim.IMU_PERIOD_MS * 1e-3
R_YAW_GYRO = sim.GYRO_STD ** 2 * IMU_DT / PERIOD       # mean of a period's gyro samples
V_MAX = 0.7                                           # pioneer_sim.V_MAX, the teleop bound


def replay(bag, csv_path, *extra):
    return replay_exe(EXE, bag, csv_path, *extra)


def sigma_bias(t):
    """sqrt of the solution of dP/dt = q - P^2 / rho, P(0) = P0 (rho = r T: the noise density
    of the bias information): the variance of the filter's bias belief, which bounds the
    error variance of its estimate of a constant bias (that error obeys the same equation
    without q)."""
    rho = (R_YAW_ODOM + R_YAW_GYRO) * PERIOD
    a, k = math.sqrt(Q_BIAS * rho), math.sqrt(Q_BIAS / rho)
    th = math.tanh(k * t)
    return math.sqrt(a * (P0_BIAS + a * th) / (a + P0_BIAS * th))


class Bounds:
    """sigma_theta(t) and sigma_p(t) on the estimate times, integrated along the true path."""

    def __init__(self, truth, times):
        t0 = truth.t[0]
        speed = [0.0] + [math.hypot(truth.x[k] - truth.x[k - 1], truth.y[k] - truth.y[k - 1])
                         / (truth.t[k] - truth.t[k - 1]) for k in range(1, len(truth.t))]
        self.t, self.theta, self.pos = [], [], []
        bias_integral = pos_integral = 0.0
        prev = 0.0
        for stamp in times:
            s = stamp - t0
            n = 20  # midpoint rule within the step
            h = (s - prev) / n
            for i in range(n):
                u = prev + (i + 0.5) * h
                bias_integral += sigma_bias(u) * h
                theta_u = bias_integral + math.sqrt(sim.GYRO_STD ** 2 * IMU_DT * u)
                k = min(bisect.bisect_right(truth.t, t0 + u), len(speed) - 1)
                pos_integral += speed[k] * theta_u * h
            prev = s
            theta = bias_integral + math.sqrt(sim.GYRO_STD ** 2 * IMU_DT * s)
            self.t.append(stamp)
            self.theta.append(theta)
            self.pos.append(pos_integral + math.sqrt(R_SPEED * PERIOD * s))


class DiffDriveReplayTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix="sf_diff_drive_test_")
        cls.csv = os.path.join(cls.tmp.name, "fused.csv")
        cls.proc = replay(BAG, cls.csv)
        cls.rows = read_rows(cls.csv)
        cls.truth = evaluate.load_truth(BAG)
        cls.ev = evaluate.evaluate(evaluate.load_result_csv(cls.csv), cls.truth)
        cls.bounds = Bounds(cls.truth, cls.ev.times)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_imu_rotated_with_the_bags_static_transform(self):
        self.assertIn("transforms read from the bag", self.proc.stdout)
        self.assertIn("0 values dropped: not rotatable into 'base_link'", self.proc.stdout)
        # one estimate per 20 ms period of the 60 s run, all with the gyro present
        self.assertGreater(len(self.rows), 2900)
        with_gyro = sum(1 for r in self.rows if r["present_inputs"] == 3)
        self.assertGreater(with_gyro, 0.99 * len(self.rows))

    def test_gyro_bias_estimated_within_derived_bound(self):
        end = self.rows[-1]
        t = end["time"] - self.truth.t[0]
        bound = 4 * sigma_bias(t)
        self.assertLess(bound, 0.25 * abs(TRUE_BIAS), "bound too loose to show anything")
        self.assertLess(abs(end["x5"] - TRUE_BIAS), bound,
                        "bias %.6f rad/s, true %.6f" % (end["x5"], TRUE_BIAS))
        # the filter's own uncertainty agrees with the derivation within a factor of 2
        self.assertLess(math.sqrt(end["var5"]), 2 * sigma_bias(t))
        self.assertGreater(math.sqrt(end["var5"]), 0.5 * sigma_bias(t))

    def test_pose_error_within_derived_bound(self):
        latency = V_MAX * PERIOD
        for stamp, err, bound in zip(self.ev.times, self.ev.pos_errors, self.bounds.pos):
            self.assertLess(err, 3 * bound + latency,
                            "position error %.3f m at %.2f s" % (err, stamp - self.truth.t[0]))
        self.assertLess(abs(math.radians(self.ev.final_heading_err_deg)),
                        3 * self.bounds.theta[-1])
        # the run returns to its start, so the final error is the dead-reckoning drift
        self.assertLess(self.ev.final_pos_err, 3 * self.bounds.pos[-1] + latency)

    def test_without_the_rotation_the_bounds_fail(self):
        # --base-frame imu_link: the vectors are "rotated" into their own frame, so the filter
        # reads the sensor's z axis, which does not see the yaw rate (the mount puts it on y)
        path = os.path.join(self.tmp.name, "unrotated.csv")
        replay(BAG, path, "--base-frame", "imu_link")
        rows = read_rows(path)
        t = rows[-1]["time"] - self.truth.t[0]
        self.assertGreater(abs(rows[-1]["x5"] - TRUE_BIAS), 4 * sigma_bias(t))
        ev = evaluate.evaluate(evaluate.load_result_csv(path), self.truth)
        self.assertGreater(max(ev.pos_errors), 3 * self.bounds.pos[-1] + V_MAX * PERIOD)


class MissingTransformTest(unittest.TestCase):
    """A bag without the IMU's transform: every gyro value is dropped and counted, the run
    still succeeds on the odometry alone."""

    def test_values_without_transform_are_dropped_and_counted(self):
        import rosbag  # Debian: python3-rosbag

        with tempfile.TemporaryDirectory(prefix="sf_diff_drive_test_") as tmp:
            bag_path = os.path.join(tmp, "no_tf.bag")
            imu = 0
            with rosbag.Bag(BAG) as src, rosbag.Bag(bag_path, "w") as dst:
                for topic, msg, t in src.read_messages(topics=["odom", "imu/data"]):
                    if t.to_sec() - src.get_start_time() > 5.0:
                        break
                    imu += topic == "imu/data"
                    dst.write(topic, msg, t)
            csv_path = os.path.join(tmp, "out.csv")
            proc = replay(bag_path, csv_path)
            self.assertIn("%d values dropped: not rotatable into 'base_link'" % imu, proc.stdout)
            self.assertIn("no transform from frame 'imu_link' into 'base_link'", proc.stderr)
            rows = read_rows(csv_path)
            self.assertTrue(rows)
            self.assertTrue(all(r["present_inputs"] <= 2 for r in rows))
            # nothing measured the bias: it keeps its initial value
            self.assertEqual(rows[-1]["x5"], 0.0)


if __name__ == "__main__":
    unittest.main()
