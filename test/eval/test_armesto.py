"""Tests of the reproduction of Armesto, Tornero and Vincze's inertial+vision filter
(tools/eval/armesto_run.py, sf_estimation_armesto_fusion; doc/armesto.md): the paper's costs
J_p and J_q (eq. 24) and the held vision on hand-computed cases; the stream made from a
hand-made trial (rates, dropouts in the reference's gaps, the vision noise's size); and the
program on a synthetic stream with a known truth, where the fused MR-EKF and MR-UKF must beat
the vision held and the IMU alone, and reach the accuracy that the vision noise allows.

The program is taken from $SF_ARMESTO_BINARY when set, else compiled here with g++ (about
a minute of CPU)."""

import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(REPO, "tools", "data"))
sys.path.insert(0, os.path.join(REPO, "tools", "eval"))

import armesto_bag_run as abr  # noqa: E402
import armesto_run as ar  # noqa: E402
import broad_trial as bt  # noqa: E402

G = 9.81
ESTIMATION = os.path.join(REPO, "sf_estimation")


def build_program(directory):
    """Compiles sf_estimation_armesto_fusion into `directory` (the library sources it needs)."""
    binary = os.path.join(directory, "sf_estimation_armesto_fusion")
    sources = [os.path.join(ESTIMATION, "bench", "armesto", "armesto_fusion.cpp")] + [
        os.path.join(ESTIMATION, "src", name + ".cpp")
        for name in ("errors", "measurement_checks", "numerical_repairs", "parameter_checks")]
    subprocess.run(["g++", "-std=c++17", "-O1", "-DEIGEN_CACHEFRIENDLY_PRODUCT_THRESHOLD=16",
                    "-DSF_ESTIMATION_IMPLICIT_INSTANCES", "-I" + os.path.join(ESTIMATION, "include"),
                    "-I/usr/include/eigen3"] + sources + ["-o", binary], check=True)
    return binary


def rz(angle):
    return np.array([math.cos(angle / 2), 0.0, 0.0, math.sin(angle / 2)])


def rx(angle):
    return np.array([math.cos(angle / 2), math.sin(angle / 2), 0.0, 0.0])


def rotate_inverse(q, v):
    return ar.quat_product(ar.quat_product(q * [1, -1, -1, -1], np.concatenate([[0.0], v])), q)[1:]


def synthetic_stream(seconds=40.0, seed=3, gap=(1200, 1500)):
    """A sensor moving on p(t) = A sin(w t) per axis and turning as Rz(psi(t)) Rx(phi(t)), its
    ideal IMU at 10 ms with the paper's R as white noise and an accelerometer bias, vision every
    80 ms with the paper's R (none in `gap`); the truth as the reference."""
    rng = np.random.default_rng(seed)
    t = np.arange(0.0, seconds, ar.PERIOD)
    amp, w = np.array([0.4, 0.3, 0.2]), np.array([0.9, 0.7, 1.1])
    p = amp * np.sin(np.outer(t, w))
    acc = -amp * w ** 2 * np.sin(np.outer(t, w))
    psi, dpsi = 0.8 * np.sin(0.6 * t), 0.48 * np.cos(0.6 * t)
    phi, dphi = 0.5 * np.sin(0.9 * t), 0.45 * np.cos(0.9 * t)
    q = np.array([ar.quat_product(rz(a), rx(b)) for a, b in zip(psi, phi)])
    # Body rate of Rz(psi) Rx(phi): Rx(phi)^T (0, 0, psi') + (phi', 0, 0).
    gyro = np.array([[dx, math.sin(b) * dz, math.cos(b) * dz] for dx, dz, b in zip(dphi, dpsi, phi)])
    force = np.array([rotate_inverse(qq, a + [0.0, 0.0, G]) for qq, a in zip(q, acc)]) + [0.05, -0.03, 0.04]
    imu = np.hstack([force + rng.standard_normal(force.shape) * math.sqrt(ar.PAPER_R["acc"]),
                     gyro + rng.standard_normal(gyro.shape) * math.sqrt(ar.PAPER_R["gyro"])])
    seen = (np.arange(len(t)) % ar.VISION_EVERY == 0) & ~((np.arange(len(t)) >= gap[0]) & (np.arange(len(t)) < gap[1]))
    noisy_p, noisy_q = ar.add_vision_noise(p, q, ar.PAPER_R["pos"], ar.PAPER_R["quat"], rng)
    vision = np.where(seen[:, None], np.hstack([noisy_p, noisy_q]), np.nan)
    return ar.Stream(imu, seen, vision, p, q, np.ones(len(t), bool))


class Costs(unittest.TestCase):
    def test_eq24_by_hand(self):
        # Three samples in movement, one of them in a gap of the reference, one outside movement.
        ref_p = np.array([[0.0, 0, 0], [1.0, 2.0, 2.0], [np.nan, 0, 0], [5.0, 5.0, 5.0]])
        ref_q = np.array([[1.0, 0, 0, 0], [0.6, 0.8, 0, 0], [np.nan, 0, 0, 0], [1.0, 0, 0, 0]])
        stream = ar.Stream(None, None, None, ref_p, ref_q, np.array([True, True, True, False]))
        p = np.array([[0.1, 0.0, 0.0], [1.0, 2.0, 1.7], [9.0, 9.0, 9.0], [0.0, 0.0, 0.0]])
        # The second estimate is -(0.8, 0.6, 0, 0): the sign of the reference is taken, (0.8, 0.6).
        q = np.array([[0.0, 1.0, 0, 0], [-0.8, -0.6, 0, 0], [1.0, 0, 0, 0], [0.0, 1.0, 0, 0]])
        jp, jq = ar.costs(stream, p, q)
        self.assertAlmostEqual(jp, (0.01 + 0.09) / 2, places=14)
        # |(1,0,0,0) - (0,1,0,0)|^2 = 2 (its dot product is 0: sign kept); |(0.6,0.8)-(0.8,0.6)|^2 = 0.08.
        self.assertAlmostEqual(jq, (2.0 + 0.08) / 2, places=14)

    def test_diverged_run_costs_infinity(self):
        stream = ar.Stream(None, None, None, np.zeros((2, 3)), np.tile([1.0, 0, 0, 0], (2, 1)), np.ones(2, bool))
        self.assertEqual(ar.costs(stream, None, None), (math.inf, math.inf))

    def test_vision_held(self):
        seen = np.array([True, False, False, True, False])
        vision = np.arange(35.0).reshape(5, 7)
        p, q = ar.vision_held(ar.Stream(None, seen, vision, None, None, None))
        np.testing.assert_array_equal(p[:, 0], [0.0, 0.0, 0.0, 21.0, 21.0])
        np.testing.assert_array_equal(q[:, 0], [3.0, 3.0, 3.0, 24.0, 24.0])


class StreamFromTrial(unittest.TestCase):
    def test_rates_dropouts_and_noise(self):
        rate, n = 285.7142857142857, 8000
        t = np.arange(n) / rate
        ref_q = np.tile([1.0, 0.0, 0.0, 0.0], (n, 1))
        ref_p = np.column_stack([t, 0 * t, 0 * t])
        ref_q[:40], ref_p[2000:2600] = np.nan, np.nan  # the first frame waits; a gap of 2.1 s
        arrays = dict(imu_gyr=np.column_stack([t, 2 * t, 3 * t]), imu_acc=np.tile([0, 0, G], (n, 1)),
                      imu_mag=np.zeros((n, 3)), opt_quat=ref_q, opt_pos=ref_p, movement=np.ones(n, bool))
        r = dict(r_pos=1e-4, r_quat=1e-4)
        stream = ar.from_trial(bt.Trial("97_test", rate, arrays), seed=5, **r)
        # 40 samples = 0.14 s of no reference: the first frame is the tick at 0.16 s (line 16).
        np.testing.assert_allclose(stream.imu[0, 3:], [0.16, 0.32, 0.48], atol=1e-12)  # interpolated
        self.assertTrue(stream.seen[0])
        self.assertTrue(np.all(np.flatnonzero(stream.seen) % 8 == 0))
        times = 0.16 + np.arange(len(stream.seen)) * 0.01
        nearest = np.round(times * rate).astype(int)
        in_gap = (nearest >= 2000) & (nearest < 2600)
        self.assertFalse(stream.seen[in_gap].any())
        self.assertEqual(int(stream.seen[~in_gap].sum()), int(np.sum(np.arange(len(times))[~in_gap] % 8 == 0)))
        error_p = (stream.vision[stream.seen, :3] - stream.ref_p[stream.seen])
        angle = 2 * stream.vision[stream.seen, 4:7]  # small rotations: the vector part is half the rotation vector
        self.assertAlmostEqual(float(np.std(error_p)), math.sqrt(r["r_pos"]), delta=0.1 * math.sqrt(r["r_pos"]))
        self.assertAlmostEqual(float(np.std(angle)), 2 * math.sqrt(r["r_quat"]), delta=0.2 * math.sqrt(r["r_quat"]))


class StreamFromBag(unittest.TestCase):
    """armesto_bag_run.py: the node's periods and SAMPLED inputs as the program's stream."""

    def test_periods_are_the_nodes(self):
        # [k T - T, k T) from the first message: a message on a period's end opens the next.
        self.assertEqual([abr.period_of(t) for t in (0.0, 0.0099, 0.01, 0.08 - 5e-7, 0.0801)],
                         [1, 1, 2, 9, 9])

    def test_stream_starts_at_the_first_frame_and_holds_the_imu(self):
        imu = {k: (k, 0, 9.8, 0, 0, 0.1 * k) for k in (1, 2, 3, 5)}
        vision = {2: (1, 2, 3, 1, 0, 0, 0), 5: (4, 5, 6, 0, 1, 0, 0)}
        ks, text = abr.stream(imu, vision)
        self.assertEqual(ks, [2, 3, 4, 5])
        lines = [[float(v) for v in line.split(",")] for line in text.split()]
        self.assertEqual(lines[0], [2, 0, 9.8, 0, 0, 0.2, 1, 1, 2, 3, 1, 0, 0, 0])
        self.assertEqual(lines[1], [3, 0, 9.8, 0, 0, 0.3, 0] + [0] * 7)
        self.assertEqual(lines[2], lines[1])  # no IMU message in period 4: the last one held
        self.assertEqual(lines[3], [5, 0, 9.8, 0, 0, 0.5, 1, 4, 5, 6, 0, 1, 0, 0])


class Program(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.directory = tempfile.mkdtemp(prefix="armesto_")
        cls.binary = os.environ.get("SF_ARMESTO_BINARY") or build_program(cls.directory)
        cls.stream = synthetic_stream()

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.directory, ignore_errors=True)

    def test_fusion_beats_either_sensor(self):
        held = ar.costs(self.stream, *ar.vision_held(self.stream))
        p, q, _ = ar.run(self.stream, "ekf", self.binary, ["--no-vision"])
        imu = ar.costs(self.stream, p, q)
        # What the vision noise alone costs, were a frame there at every line: 3 r_pos, and for
        # the quaternion's vector part 3 r_quat (its w part is second order). Fusion must beat
        # either sensor by at least that; the gyro's noise is small enough that the orientation
        # beats even the vision noise (the position crosses a gap of 3 s on the accelerometer).
        floor = (3 * ar.PAPER_R["pos"], 3 * ar.PAPER_R["quat"])
        for kind in ("ekf", "ukf"):
            p, q, cpu = ar.run(self.stream, kind, self.binary)
            fused = ar.costs(self.stream, p, q)
            self.assertGreater(cpu, 0.0)
            for k in (0, 1):
                self.assertLess(fused[k] + floor[k], min(held[k], imu[k]), (kind, k, fused, held, imu))
            self.assertLess(fused[1], floor[1], (kind, fused))

    def test_refuses_a_stream_without_a_first_frame(self):
        stream = ar.Stream(self.stream.imu[:5], np.zeros(5, bool), self.stream.vision[:5], None, None, None)
        done = subprocess.run([self.binary, "--filter", "ekf"], input=stream.csv(), capture_output=True, text=True)
        self.assertEqual(done.returncode, 2)
        self.assertIn("the first line must carry a vision frame", done.stderr)


if __name__ == "__main__":
    unittest.main()
