#!/usr/bin/python3
"""Unit tests of tools/sim/sensor_errors.py (the simulators' realistic error models) and of
the --realistic husky preset of tools/sim/pioneer_sim.py.

Every expected value is a closed form or a statistical bound worked out here from the
model's definition, never an output copied from a run. The preset test needs the ROS
python modules (python3-rosbag, python3-geometry-msgs, python3-std-msgs): run with
/usr/bin/python3, e.g. test/eval/run_unittests.py sensor_errors.
"""

import argparse
import math
import os
import random
import shutil
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
SIM = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "sim")
sys.path.insert(0, SIM)
import sensor_errors as se  # noqa: E402

G = 9.80665


def sample_variance_bound(n, k=4.0):
    """Relative k-sigma band of a mean of n squared zero-mean Gaussians (chi-square/n):
    its relative std is sqrt(2/n)."""
    return k * math.sqrt(2.0 / n)


class SkidSteerTest(unittest.TestCase):
    def test_effective_track_scales_yaw_rate_by_chi(self):
        # closed form: the wheels' yaw rate is chi * omega, so omega = wheels' / chi
        for v, w, track, chi in [(0.5, 0.3, 0.6, 1.5), (-0.2, -0.7, 0.555, 1.8), (0.0, 0.4, 0.5, 1.3),
                                 (0.7, 0.0, 0.6, 2.0), (0.3, 1e-3, 0.4, 1.0)]:
            left, right = se.skid_track_speeds(v, w, track, chi)
            wheel_yaw = (right - left) / track
            self.assertAlmostEqual(wheel_yaw, chi * w, places=12)
            self.assertAlmostEqual(wheel_yaw / chi, w, places=12)
            self.assertAlmostEqual(0.5 * (left + right), v, places=12)

    def test_slip_rate_adds_to_wheels_yaw_rate(self):
        left, right = se.skid_track_speeds(0.4, 0.2, 0.5, 1.2, slip_rate=0.05)
        self.assertAlmostEqual((right - left) / 0.5, 1.2 * 0.2 + 0.05, places=12)
        self.assertAlmostEqual(0.5 * (left + right), 0.4, places=12)

    def test_slip_gate(self):
        self.assertEqual(se.slip_gate(0.0, 0.0, 0.6), 0.0)
        self.assertAlmostEqual(se.slip_gate(0.05, 0.0, 0.6), 0.5)
        self.assertAlmostEqual(se.slip_gate(0.0, -0.1, 0.6), 0.3)   # 0.3 m * 0.1 rad/s / 0.1 m/s
        self.assertEqual(se.slip_gate(-0.7, 0.0, 0.6), 1.0)

    def test_radius_scales_with_load_transfer(self):
        # turning left at a_lat = g/2: outer (right) tyres compressed by c/2, inner relieved
        left, right = se.radius_scales(0.01, -0.02, 0.04, 0.5 * G)
        self.assertAlmostEqual(left, 1.0 + 0.01 + 0.02, places=12)
        self.assertAlmostEqual(right, 1.0 - 0.02 - 0.02, places=12)
        self.assertEqual(se.radius_scales(0.0, 0.0, 0.3, 0.0), (1.0, 1.0))

    def test_driver_with_wrong_separation(self):
        # a separation 1/7.5 of the true one makes the odometry turn 7.5 times as far
        v, w = se.driver_twist(0.35, 0.65, 0.5, 1.0 / 7.5)
        self.assertAlmostEqual(v, 0.5, places=12)
        self.assertAlmostEqual(w, 7.5 * (0.65 - 0.35) / 0.5, places=12)

    def test_wheel_samples_with_chi_only(self):
        # constant arc: v = 0.4 m/s, omega = 0.3 rad/s; chi 1.6, no other error
        states = [(0.0, 0.0, 0.0, 0.4, 0.3)] * 1001
        prof = se.ErrorProfile(slip_chi=1.6)
        out = se.wheel_speed_samples(random.Random(1), states, 1e-3, 0.6, range(40, 1001, 100), prof)
        self.assertEqual(sorted(out), list(range(40, 1001, 100)))
        for left, right, gl, gr in out.values():
            self.assertAlmostEqual((right - left) / 0.6, 1.6 * 0.3, places=12)
            self.assertAlmostEqual(0.5 * (left + right), 0.4, places=12)
            self.assertEqual((left, right), (gl, gr))

    def test_wheel_samples_radius_error(self):
        # a wheel 2 % larger reports its ground speed / 1.02 (it turns fewer times)
        states = [(0.0, 0.0, 0.0, 0.5, 0.0)] * 201
        prof = se.ErrorProfile(radius_error_left=0.02)
        out = se.wheel_speed_samples(random.Random(1), states, 1e-3, 0.5, [100], prof)
        left, right, _, _ = out[100]
        self.assertAlmostEqual(left, 0.5 / 1.02, places=12)
        self.assertAlmostEqual(right, 0.5, places=12)


class TickCounterTest(unittest.TestCase):
    def test_quantisation_error_at_most_half_a_step(self):
        r = random.Random("ticks")
        step = 0.001
        c = se.TickCounter(step)
        worst = 0.0
        for _ in range(20000):
            c.advance(r.uniform(-0.0004, 0.0012))
            err = abs(c.reading() - c.travel)
            self.assertLessEqual(err, 0.5 * step + 1e-12)
            worst = max(worst, err)
        self.assertGreater(worst, 0.45 * step)   # the bound is attained, not loose

    def test_period_speeds_sum_to_counted_travel(self):
        r = random.Random("ticks2")
        c = se.TickCounter(0.002)
        total = 0.0
        for _ in range(500):
            for _ in range(10):
                c.advance(r.uniform(0.0, 0.001))
            speed = c.speed(0.1)
            self.assertAlmostEqual(speed * 0.1 / 0.002, round(speed * 0.1 / 0.002), places=9)  # whole ticks
            total += speed * 0.1
        self.assertLessEqual(abs(total - c.travel), 0.001 + 1e-9)


class StochasticProcessTest(unittest.TestCase):
    N = 2000

    def test_random_walk_variance_grows_as_sigma2_t(self):
        sigma, dt = 0.3, 0.01
        for steps in (25, 100):
            t = steps * dt
            sq = 0.0
            for i in range(self.N):
                walk = se.RandomWalk(random.Random(i), sigma, dt, x0=0.7)
                for _ in range(steps):
                    walk.step()
                sq += (walk.x - 0.7) ** 2
            ratio = sq / self.N / (sigma ** 2 * t)
            self.assertLess(abs(ratio - 1.0), sample_variance_bound(self.N), (steps, ratio))

    def test_gauss_markov_stationary_and_correlation(self):
        std, tau, dt, lag = 0.1, 1.0, 0.05, 10
        a = math.exp(-dt / tau)
        sq0 = sq1 = prod = 0.0
        for i in range(self.N):
            gm = se.GaussMarkov(random.Random(i), std, tau, dt)
            x0 = gm.x
            for _ in range(lag):
                gm.step()
            sq0 += x0 * x0
            sq1 += gm.x * gm.x
            prod += x0 * gm.x
        bound = sample_variance_bound(self.N)
        self.assertLess(abs(sq0 / self.N / std ** 2 - 1.0), bound)
        self.assertLess(abs(sq1 / self.N / std ** 2 - 1.0), bound)
        # E[x0 x_lag] = std^2 a^lag; the mean of n products has std <= std^2 sqrt((1 + a^2lag)/n)
        rho = a ** lag
        self.assertLess(abs(prod / self.N / std ** 2 - rho), 4.0 * math.sqrt((1.0 + rho * rho) / self.N))


class InertialTest(unittest.TestCase):
    def test_gyro_scale_and_constant_bias(self):
        gyro = se.GyroErrors(random.Random(0), 0.002, 0.0, 0.03, 0.01)
        for w in (0.0, 0.5, -0.7):
            self.assertAlmostEqual(gyro.measure(w), 1.03 * w + 0.002, places=14)

    def test_gyro_bias_walks(self):
        # the bias is the random walk from b0: after n samples var = sigma^2 n dt
        sigma, dt, n = 0.01, 0.01, 400
        sq = 0.0
        for i in range(self.n_seeds()):
            gyro = se.GyroErrors(random.Random(i), 0.001, sigma, 0.0, dt)
            for _ in range(n):
                out = gyro.measure(0.0)
            sq += (out - 0.001) ** 2
        ratio = sq / self.n_seeds() / (sigma ** 2 * n * dt)
        self.assertLess(abs(ratio - 1.0), sample_variance_bound(self.n_seeds()))

    @staticmethod
    def n_seeds():
        return 1000

    def test_tilt_leakage_closed_form(self):
        th = 0.02
        lx, ly, lz = se.tilt_leakage(0.0, th)
        self.assertAlmostEqual(lx, -G * math.sin(th), places=12)
        self.assertEqual(ly, 0.0)
        self.assertAlmostEqual(lz, G * (math.cos(th) - 1.0), places=12)
        lx, ly, lz = se.tilt_leakage(th, 0.0)
        self.assertAlmostEqual(lx, 0.0, places=15)
        self.assertAlmostEqual(ly, G * math.sin(th), places=12)
        # whatever the tilt, the sensor still reads gravity's magnitude g
        lx, ly, lz = se.tilt_leakage(0.03, -0.05)
        self.assertAlmostEqual(math.sqrt(lx * lx + ly * ly + (lz + G) ** 2), G, places=12)


class TransportTest(unittest.TestCase):
    def run_transport(self, n, period_ns, **kw):
        tr = se.Transport(random.Random("transport"), **kw)
        return tr, [(k * period_ns, tr.deliver(k * period_ns)) for k in range(n)]

    def test_drop_and_duplicate_rates_within_binomial_bounds(self):
        n, p_drop, p_dup = 20000, 0.05, 0.03
        tr, out = self.run_transport(n, 100000000, base_ns=0, jitter_ns=0, p_drop=p_drop, p_dup=p_dup)
        dropped = sum(1 for _, a in out if not a)
        dups = sum(1 for _, a in out if len(a) == 2)
        self.assertEqual((dropped, dups), (tr.dropped, tr.duplicated))
        self.assertLess(abs(dropped - n * p_drop), 4.0 * math.sqrt(n * p_drop * (1 - p_drop)))
        m = n - dropped
        self.assertLess(abs(dups - m * p_dup), 4.0 * math.sqrt(m * p_dup * (1 - p_dup)))

    def test_latency_base_plus_exponential_jitter(self):
        n, base, jitter = 20000, 2000000, 1500000
        _, out = self.run_transport(n, 100000000, base_ns=base, jitter_ns=jitter)
        lat = [a[0] - t for t, a in out]
        self.assertGreaterEqual(min(lat), base)
        mean = sum(lat) / n
        # exponential jitter: mean = std = jitter; rounding to ns adds < 1 ns
        self.assertLess(abs(mean - (base + jitter)), 4.0 * jitter / math.sqrt(n) + 1.0)
        var = sum((x - mean) ** 2 for x in lat) / n
        self.assertLess(abs(math.sqrt(var) / jitter - 1.0), 0.1)

    def test_fifo_order_and_no_errors_when_off(self):
        _, out = self.run_transport(5000, 1000000, base_ns=500000, jitter_ns=5000000, p_dup=0.1)
        arrivals = [x for _, a in out for x in a]
        self.assertEqual(arrivals, sorted(arrivals))
        _, out = self.run_transport(100, 1000000, base_ns=0, jitter_ns=0)
        self.assertEqual([a for _, a in out], [[t] for t, _ in out])


class ProfileTest(unittest.TestCase):
    def parse(self, *argv):
        parser = argparse.ArgumentParser()
        se.add_arguments(parser)
        return se.profile_from_args(parser.parse_args(list(argv)))

    def test_default_is_off(self):
        p = self.parse()
        self.assertFalse(p.active)
        self.assertFalse(p.wheels_active or p.gyro_active or p.accel_active or p.transport_active)
        self.assertIsNone(p.transport("pioneer", 1, "angular_velocity", "imu"))

    def test_preset_and_override(self):
        p = self.parse("--realistic", "husky", "--slip-chi", "1.5")
        self.assertTrue(p.wheels_active and p.gyro_active and p.accel_active and p.transport_active)
        self.assertEqual(p.slip_chi, 1.5)
        self.assertEqual(p.gyro_scale, se.PRESETS["husky"]["gyro_scale"])
        self.assertEqual(self.parse("--gyro-scale", "0.02").summary(), "gyro_scale=0.02")


def window_mean_ar1_factor(a, n):
    """var(mean of n consecutive samples of a stationary AR(1), coefficient a) / var(x):
    (1/n^2) sum_{i,j} a^|i-j| = (1/n) (1 + 2 sum_{k=1}^{n-1} (1 - k/n) a^k)."""
    return (1.0 + 2.0 * sum((1.0 - k / n) * a ** k for k in range(1, n))) / n


class HuskyPresetTest(unittest.TestCase):
    """A short simulated Pioneer run with --realistic husky: the wheels' yaw rate against the
    gyro's, compared with (a) the values the preset's parameters predict for the run's true
    motion and (b) the real recordings' order of magnitude (doc/bags.md)."""

    SEEDS = (1, 2, 3)
    DURATION = 60.0

    @classmethod
    def setUpClass(cls):
        try:
            import pioneer_sim
            import yaw_agreement
        except ImportError as exc:  # no ROS python modules
            raise unittest.SkipTest("needs the ROS python modules: %s" % exc)
        cls.sim, cls.agree = pioneer_sim, yaw_agreement
        cls.tmp = tempfile.mkdtemp(prefix="sf_sensor_errors_")
        cls.wheel, cls.gyro = [], []
        cls.pred = {"sww": 0.0, "sgg": 0.0, "swg": 0.0, "sdd": 0.0, "n": 0}
        p = se.ErrorProfile(**se.PRESETS["husky"])
        for seed in cls.SEEDS:
            path = os.path.join(cls.tmp, "p%d.bag" % seed)
            with open(os.devnull, "w") as null:
                saved, sys.stdout = sys.stdout, null
                try:
                    pioneer_sim.main(["--seed", str(seed), "--duration", str(cls.DURATION), "--realistic", "husky",
                                      "--compression", "none", "--out", path])
                finally:
                    sys.stdout = saved
            w, g = yaw_agreement.pair(*yaw_agreement.read_bag(path, "pioneer"))
            cls.wheel += w
            cls.gyro += g
            cls.add_prediction(seed, p)

    @classmethod
    def add_prediction(cls, seed, p):
        """Predicted second moments from the preset's parameters and the true motion only.

        Wheels (ticks counted over the 100 ms since the previous sample, ending at k):
          W = chi * mean(omega over the window) + e_w,
          var(e_w) = slip_std^2 gate^2 f_window + 2 (2 step^2/(12 T^2) + 2e-6) / B^2 (moving),
          where f_window is the AR(1) window-mean factor, 2 step^2/(12 T^2) the variance of
          a difference of two roundings of the count, and 2e-6 (m/s)^2 the wheels' white
          noise plus their 1 mm/s rounding (thesis R = 2 (mm/s)^2); B = 2 R.
        Gyro: G = (1 + scale) omega + e_g, var(e_g) = GYR_STD^2 + GYR_RES^2/12 (the bias
          changes by about 4e-4 rad/s in a minute and is left out)."""
        sim = cls.sim
        truth, _ = sim.plan_run(seed, cls.DURATION, lateral_slip=p.lateral_slip)
        states = truth.log
        n_ms = len(states) - 1
        track = 2.0 * sim.R_EFF
        period = sim.ENC_PERIOD_MS * 1e-3
        a = math.exp(-1e-3 / p.slip_tau)
        tick_var = 2.0 * (2.0 * p.encoder_step ** 2 / 12.0 / period ** 2 + 2.0e-6) / track ** 2
        gyro_var = sim.GYR_STD ** 2 + sim.GYR_RES ** 2 / 12.0
        last = 0
        ws, gs, ew = [], [], []
        for k in range(sim.ENC_PHASE_MS, n_ms + 1, sim.ENC_PERIOD_MS):
            window = [states[j][4] for j in range(last, k)]
            gate = [se.slip_gate(states[j][3], states[j][4], track) for j in range(last, k)]
            moving = any(abs(states[j][3]) + abs(states[j][4]) > 0 for j in range(last, k + 1))
            wbar = sum(window) / len(window)
            g2 = sum(x * x for x in gate) / len(gate)
            ws.append(p.slip_chi * wbar)
            gs.append((1.0 + p.gyro_scale) * states[k][4])
            ew.append(p.slip_std ** 2 * g2 * window_mean_ar1_factor(a, len(window)) + (tick_var if moving else 0.0))
            last = k
        n = len(ws)
        mw, mg = sum(ws) / n, sum(gs) / n
        pr = cls.pred
        pr["sww"] += sum((x - mw) ** 2 for x in ws) + sum(ew)
        pr["sgg"] += sum((x - mg) ** 2 for x in gs) + n * gyro_var
        pr["swg"] += sum((x - mw) * (y - mg) for x, y in zip(ws, gs))
        d = [x - y for x, y in zip(ws, gs)]
        md = sum(d) / n
        pr["sdd"] += sum((x - md) ** 2 for x in d) + sum(ew) + n * gyro_var
        pr["n"] += n

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def measured(self):
        return self.agree.statistics(self.wheel, self.gyro)

    def predicted(self):
        pr = self.pred
        return pr["swg"] / math.sqrt(pr["sww"] * pr["sgg"]), math.sqrt(pr["sdd"] / pr["n"])

    def test_pairs(self):
        n = self.measured()[0]
        expected = len(self.SEEDS) * int(self.DURATION * 10)
        # a few wheel messages are lost (drop_prob 0.002 per side), a few duplicated
        self.assertGreater(n, 0.98 * expected)
        self.assertLess(n, 1.02 * expected)

    def test_statistics_match_the_preset(self):
        _, corr, resid, slope, _ = self.measured()
        corr_p, resid_p = self.predicted()
        # band: the slip disturbance (correlation time 1 s, about 150 independent values
        # over the three runs) dominates the residual; its variance estimate has a
        # relative std of about sqrt(2/150) = 12 %, the std half that; 20 % is > 3 sigma
        self.assertLess(abs(resid / resid_p - 1.0), 0.20, (resid, resid_p))
        self.assertLess(abs(corr - corr_p), 0.03, (corr, corr_p))
        # wheels on gyro: chi (1 + mean radius error) / (1 + gyro scale), within the slip's
        # chance correlation with omega
        p = se.PRESETS["husky"]
        self.assertLess(abs(slope - p["slip_chi"] / (1.0 + p["gyro_scale"])), 0.06, slope)

    def test_residual_correlation_time(self):
        # The residual after the slope is, per 100 ms wheel sample, the window mean of the
        # gated Gauss-Markov slip rate plus white noise (wheel noise, ticks, gyro noise). For
        # window means of such a process the lag correlations satisfy acf(2)/acf(1) =
        # exp(-T/tau) whatever the white part (yaw_agreement.residual_correlation), so the
        # estimate recovers the preset's slip_tau, which is the real recording's 0.12 s
        # (doc/bags.md). Tolerance 50 %: two lag correlations of about 1800 pairs each have a
        # sampling spread of several percent, and the gate (no slip at rest) and the ticks'
        # lag-1 anticorrelation (about 1 % of the variance) bend the ratio a little.
        _, _, _, slope, _ = self.measured()
        _, _, tau = self.agree.residual_correlation(self.wheel, self.gyro, slope)
        self.assertIsNotNone(tau)
        self.assertLess(abs(tau / se.PRESETS["husky"]["slip_tau"] - 1.0), 0.5, tau)

    def test_real_order_of_magnitude(self):
        # real skid-steer recordings (doc/bags.md): correlation 0.87 and 0.94, residual std
        # 0.048 and 0.129 rad/s (0.087 after the scale); the simulated run must lie in the
        # same range, widened by the spread of the yaw-rate signal between paths
        _, corr, resid, _, resid_slope = self.measured()
        self.assertGreater(corr, 0.85)
        self.assertLess(corr, 0.99)
        self.assertGreater(resid, 0.04)
        self.assertLess(resid, 0.15)
        self.assertGreater(resid_slope, 0.04)
        self.assertLess(resid_slope, 0.13)


class SimulatorOptionsTest(unittest.TestCase):
    """Single options end to end: diff_drive_sim's miscalibrated driver and soccer_sim's
    realistic vision transport and encoder ticks."""

    @classmethod
    def setUpClass(cls):
        try:
            import diff_drive_sim
            import rosbag
            import soccer_sim
            import yaw_agreement
        except ImportError as exc:  # no ROS python modules
            raise unittest.SkipTest("needs the ROS python modules: %s" % exc)
        cls.diff, cls.soccer, cls.agree, cls.rosbag = diff_drive_sim, soccer_sim, yaw_agreement, rosbag
        cls.tmp = tempfile.mkdtemp(prefix="sf_sim_options_")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def run_quietly(self, main, argv):
        with open(os.devnull, "w") as null:
            saved, sys.stdout = sys.stdout, null
            try:
                main(argv)
            finally:
                sys.stdout = saved

    def test_driver_separation_scales_odometry_turn(self):
        # S = 1/7.5: the odometry's yaw rate is 7.5 times the wheels' (= the true one here,
        # no slip); against the gyro (noise 0.005 rad/s, base bias 0.012 rad/s) the
        # least-squares slope is 7.5 within a few per cent
        path = os.path.join(self.tmp, "dd.bag")
        self.run_quietly(self.diff.main, ["--seed", "1", "--duration", "60", "--compression", "none",
                                          "--odom-separation-scale", repr(1.0 / 7.5), "--out", path])
        w, g = self.agree.pair(*self.agree.read_bag(path, "diff_drive"))
        slope = self.agree.statistics(w, g)[3]
        self.assertLess(abs(slope / 7.5 - 1.0), 0.03, slope)

    def test_soccer_realistic_vision_and_ticks(self):
        path = os.path.join(self.tmp, "soccer.bag")
        self.run_quietly(self.soccer.main, ["--seed", "1", "--duration", "10", "--compression", "none",
                                            "--realistic", "wang", "--out", path])
        preset = self.soccer.PRESETS["wang"]
        step = preset["encoder_step"]
        x0 = y0 = None
        seqs, stamps = [], []
        with self.rosbag.Bag(path) as bag:
            for topic, msg, t in bag.read_messages():
                if topic == "vision/pose":
                    delay_ms = (t - msg.header.stamp).to_sec() * 1e3
                    self.assertGreaterEqual(delay_ms, preset["vision_delay_ms"] - 1e-6)
                    seqs.append(msg.header.seq)
                    stamps.append(msg.header.stamp.to_nsec())
                elif topic == "encoder/pose":
                    if x0 is None:   # the first reading is the start position, 0 ticks
                        x0, y0 = msg.point.x, msg.point.y
                    for d in (msg.point.x - x0, msg.point.y - y0):
                        self.assertAlmostEqual(d / step, round(d / step), places=6)
        frames = 10 * 32 + 1
        unique = len(set(seqs))
        lost, dups = frames - unique, len(seqs) - unique
        p = preset["vision_drop_prob"]
        self.assertLess(abs(lost - frames * p), 4.0 * math.sqrt(frames * p * (1 - p)) + 1)
        q = preset["vision_dup_prob"]
        self.assertLessEqual(dups, unique * q + 4.0 * math.sqrt(unique * q) + 1)
        # a duplicate repeats the frame: same seq, same stamp
        self.assertEqual(len(set(zip(seqs, stamps))), unique)


if __name__ == "__main__":
    unittest.main()
