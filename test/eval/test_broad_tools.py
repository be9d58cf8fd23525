"""Unit tests of the BROAD tools (tools/data/broad_trial.py, broad_to_bag.py,
tools/eval/attitude_baselines.py) against hand computations: the benchmark's error angle and
RMSE over the movement phase with the reference's gaps left out; one step of Madgwick's and
of Mahony's filter from the level orientation (the gradient of Madgwick's paper, eq. 25-26,
at q = 1); the initial orientation of a sensor at rest; and a bag converted from a
hand-made trial (rates, units, gaps left out, seeded vision noise)."""

import math
import os
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(REPO, "tools", "data"))
sys.path.insert(0, os.path.join(REPO, "tools", "eval"))

import attitude_baselines as ab  # noqa: E402
import broad_trial as bt  # noqa: E402

try:
    import rosbag
    import scipy.io
    import broad_to_bag
except ImportError:  # pragma: no cover - python3-rosbag and python3-scipy are package dependencies
    rosbag = None

RATE = 285.7142857142857


def about(axis, angle):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    return np.concatenate([[math.cos(angle / 2)], math.sin(angle / 2) * axis])


def make_trial(n=600, gap=(100, 160)):
    """A sensor turning about z at 0.5 rad/s from a tilt of 0.1 rad about x, at rest otherwise."""
    t = np.arange(n) / RATE
    quats = np.array([bt.quat_product(about([0, 0, 1], 0.5 * s), about([1, 0, 0], 0.1)) for s in t])
    opt = quats.copy()
    opt[gap[0]:gap[1]] = np.nan
    conj = bt.quat_conjugate(quats)
    acc = np.array([bt.quat_product(bt.quat_product(c, [0, 0, 0, 9.81]), q)[1:] for c, q in zip(conj, quats)])
    mag = np.array([bt.quat_product(bt.quat_product(c, [0, 0, 20, -35]), q)[1:] for c, q in zip(conj, quats)])
    gyr = np.tile(bt.quat_product(bt.quat_product(about([1, 0, 0], -0.1), [0, 0, 0, 0.5]), about([1, 0, 0], 0.1))[1:], (n, 1))
    arrays = dict(imu_gyr=gyr, imu_acc=acc, imu_mag=mag, opt_quat=opt, opt_pos=np.column_stack([t, 2 * t, 0 * t]),
                  movement=np.arange(n) >= 50)
    return bt.Trial("98_test_trial", RATE, arrays), quats


class ErrorMetric(unittest.TestCase):
    def test_angle_of_the_relative_rotation(self):
        reference = np.array([about([0, 1, 0], 0.3), about([1, 1, 0], 2.0)])
        estimate = np.array([bt.quat_product(about([1, 0, 0], 0.1), reference[0]),  # earth-frame error 0.1
                             -bt.quat_product(reference[1], about([0, 0, 1], 0.25))])  # body-frame, sign flipped
        np.testing.assert_allclose(bt.error_angles(estimate, reference), [0.1, 0.25], atol=1e-12)

    def test_rmse_over_the_movement_without_the_gaps(self):
        trial, quats = make_trial()
        errors = np.linspace(0.01, 0.05, len(quats))  # rad, about y
        estimate = np.array([bt.quat_product(q, about([0, 1, 0], e)) for q, e in zip(quats, errors)])
        kept = trial.movement & np.all(np.isfinite(trial.opt_quat), axis=1)
        expected = math.degrees(math.sqrt(np.mean(errors[kept] ** 2)))
        self.assertAlmostEqual(bt.rmse_deg(trial, estimate), expected, places=9)
        self.assertGreater(abs(expected - math.degrees(math.sqrt(np.mean(errors ** 2)))), 1e-4)


class Baselines(unittest.TestCase):
    def test_madgwick_step_from_level(self):
        # q = 1, gyro w, acc tilted by s about x: gradient J^T f = (0, -2 a_y, 2 a_x, 0) (paper, eq. 25-26).
        dt, beta, s = 0.01, 0.12, 0.2
        w = (0.1, -0.2, 0.3)
        q = ab.madgwick_step([1.0, 0.0, 0.0, 0.0], w, (0.0, 9.81 * math.sin(s), 9.81 * math.cos(s)), None, beta, dt)
        expected = np.array([1.0, 0.5 * w[0] * dt + beta * dt, 0.5 * w[1] * dt, 0.5 * w[2] * dt])
        np.testing.assert_allclose(q, expected / np.linalg.norm(expected), atol=1e-15)

    def test_mahony_step_from_level(self):
        # e = a x v = (sin s, 0, 0); w' = w + kp e + ki e dt.
        dt, kp, ki, s = 0.01, 0.74, 0.0012, 0.2
        q, integral = ab.mahony_step([1.0, 0.0, 0.0, 0.0], [0.0] * 3, (0.0, 0.0, 0.0),
                                     (0.0, 9.81 * math.sin(s), 9.81 * math.cos(s)), None, kp, ki, dt)
        rate = (kp + ki * dt) * math.sin(s)
        expected = np.array([1.0, 0.5 * rate * dt, 0.0, 0.0])
        np.testing.assert_allclose(q, expected / np.linalg.norm(expected), atol=1e-15)
        np.testing.assert_allclose(integral, [ki * math.sin(s) * dt, 0.0, 0.0], atol=1e-18)

    def test_initial_orientation_of_a_sensor_at_rest(self):
        trial, quats = make_trial()
        q = ab.initial_enu(trial.imu_acc[0], trial.imu_mag[0])
        self.assertLess(bt.error_angles(q[None, :], quats[:1])[0], 1e-12)

    def test_filters_hold_a_perfect_stream(self):
        # The estimate after sample k has integrated sample k's rate: it is the orientation of
        # sample k + 1 (the benchmark's convention, a lag of one sample against sample k).
        # Madgwick's normalised step moves by beta dt (0.024 deg) at every sample whatever
        # the error, which the lagging accelerometer never lets vanish.
        trial, quats = make_trial(gap=(0, 0))
        for name, tolerance in (("madgwick9", 0.06), ("mahony9", 0.01), ("madgwick6", 0.06)):
            estimate = ab.run_baseline(trial, name)
            self.assertLess(np.degrees(bt.error_angles(estimate[:-1], quats[1:]).max()), tolerance, name)


@unittest.skipIf(rosbag is None, "rosbag or scipy not importable")
class BagConversion(unittest.TestCase):
    def test_topics_rates_gaps_and_seeded_noise(self):
        trial, quats = make_trial()
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "98_test_trial.mat")
            scipy.io.savemat(path, dict(imu_gyr=trial.imu_gyr, imu_acc=trial.imu_acc, imu_mag=trial.imu_mag,
                                        opt_quat=trial.opt_quat, opt_pos=trial.opt_pos,
                                        movement=trial.movement.astype(np.uint8), sampling_rate=RATE))
            bags = [os.path.join(tmp, "a.bag"), os.path.join(tmp, "b.bag")]
            for bag in bags:
                broad_to_bag.main([path, bag, "--seed", "7", "--vision-position-std", "0.01"])
            with open(bags[0], "rb") as a, open(bags[1], "rb") as b:
                self.assertEqual(a.read(), b.read())
            messages = {}
            with rosbag.Bag(bags[0]) as bag:
                for topic, msg, t in bag.read_messages():
                    messages.setdefault(topic, []).append((msg, (t.secs - 1700000000) + 1e-9 * t.nsecs))
        self.assertEqual(len(messages["imu/data"]), 600)
        self.assertEqual(len(messages["ground_truth/pose"]), 540)  # 60 samples of gap left out
        imu, t = messages["imu/data"][10]
        self.assertAlmostEqual(t, 10 / RATE, places=8)
        self.assertEqual(imu.orientation_covariance[0], -1.0)
        self.assertAlmostEqual(imu.linear_acceleration.z, trial.imu_acc[10, 2])
        self.assertAlmostEqual(messages["imu/mag"][10][0].magnetic_field.y, trial.imu_mag[10, 1] * 1e-6)
        # Ticks every 80 ms at samples round(j * rate / 12.5): 27 up to sample 599, those in the gap left out.
        ticks = [round(j * RATE / 12.5) for j in range(27)]
        kept = [k for k in ticks if not 100 <= k < 160]
        vision = messages["vision/pose"]
        self.assertEqual([round(t * RATE) for _, t in vision], kept)
        offsets = np.array([[m.pose.pose.position.x - trial.opt_pos[k, 0], m.pose.pose.position.y - trial.opt_pos[k, 1]]
                            for (m, _), k in zip(vision, kept)])
        self.assertTrue(0.003 < np.std(offsets) < 0.03)  # std 0.01 m
        self.assertAlmostEqual(vision[0][0].pose.covariance[0], 1e-4)
        self.assertAlmostEqual(vision[0][0].pose.covariance[35], 1e-4)


    def test_shipped_bag(self):
        # bags/broad_21_fast_combined.bag (doc/bags.md): the documented counts, and vision
        # frames that lie 5 mm (std) from the reference at the same stamp.
        path = os.path.join(REPO, "bags", "broad_21_fast_combined.bag")
        with rosbag.Bag(path) as bag:
            counts = {t: info.message_count for t, info in bag.get_type_and_topic_info().topics.items()}
            truth, offsets = {}, []
            for topic, msg, _ in bag.read_messages(topics=["ground_truth/pose", "vision/pose"]):
                stamp = msg.header.stamp.to_nsec()
                if topic == "ground_truth/pose":
                    truth[stamp] = msg.pose.position
                else:
                    p = truth[stamp]
                    offsets.append([msg.pose.pose.position.x - p.x, msg.pose.pose.position.y - p.y,
                                    msg.pose.pose.position.z - p.z])
        self.assertEqual(counts, {"imu/data": 53612, "imu/mag": 53612, "ground_truth/pose": 51386, "vision/pose": 2249})
        self.assertAlmostEqual(float(np.std(offsets)), 0.005, delta=0.0003)


if __name__ == "__main__":
    unittest.main()
