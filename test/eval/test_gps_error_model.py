"""Unit tests of tools/eval/gps_error_model.py (the fixes' slow error measured against a dead-
reckoned track) and of tools/sim/gps_sim.py (the simulated receiver): the similarity fit
recovers a known rotation, scale and shift; the structure function of a known Gauss-Markov
error gives back its sigma and time constant; the simulated fixes convert back to the true
ENU points plus an error with the configured statistics."""

import math
import os
import random
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(REPO, "tools", "eval"))
sys.path.insert(0, os.path.join(REPO, "tools", "sim"))
import evaluate as ev  # noqa: E402
import gps_error_model as gem  # noqa: E402
import gps_reference as gr  # noqa: E402
import gps_sim  # noqa: E402


class SimilarityTest(unittest.TestCase):
    def test_recovers_rotation_scale_and_shift(self):
        src = [(0.3 * k, math.sin(0.2 * k)) for k in range(50)]
        a, s, tx, ty = 0.7, 1.15, 4.0, -2.0
        dst = [(s * (math.cos(a) * x - math.sin(a) * y) + tx,
                s * (math.sin(a) * x + math.cos(a) * y) + ty) for x, y in src]
        fit = gem.fit_similarity_2d(src, dst)
        for got, want in zip(fit, (a, s, tx, ty)):
            self.assertAlmostEqual(got, want, places=9)


class GaussMarkovTest(unittest.TestCase):
    def test_structure_function_gives_back_sigma_and_tau(self):
        # 40000 fixes at 2.5 Hz of a Gauss-Markov error (sigma 1.1 m, tau 60 s) per axis and
        # 0.05 m white; the fit on lags up to 12 s (as on the recording) finds tau and sigma
        # within 25 % and the white part within 0.03 m.
        rng = random.Random(3)
        model = gps_sim.GaussMarkov(rng, 1.1, 60.0, 0.4)
        other = gps_sim.GaussMarkov(rng, 1.1, 60.0, 0.4)
        res = [(0.4 * k, model.step() + rng.gauss(0, 0.05), other.step() + rng.gauss(0, 0.05))
               for k in range(40000)]
        d = gem.structure_function(res, [0.4 * k for k in range(1, 31)])
        w, sigma, tau = gem.fit_gauss_markov(d)
        self.assertAlmostEqual(tau, 60.0, delta=15.0)
        self.assertAlmostEqual(sigma, 1.1, delta=0.275)
        self.assertLess(abs(w - 0.05), 0.03)


class SimulatedFixTest(unittest.TestCase):
    def test_fixes_are_the_turned_truth_plus_the_error(self):
        # Without error the fixes are the true points turned by the heading, to 1e-6 m; with
        # the default error the spread of fix - truth is sigma^2 + white^2 per axis.
        states = [(0.001 * k, 0.0005 * k) for k in range(20001)]
        exact = gps_sim.GpsModel(heading_deg=30.0, sigma=0.0, white=0.0)
        frame = gr.LocalFrame(*gps_sim.DEFAULT_DATUM)
        a = math.radians(30.0)
        for k, e, n, _, lat, lon, alt in gps_sim.fixes(exact, random.Random(1), states, 20000):
            x, y = states[k]
            got = frame.enu(lat, lon, alt)
            self.assertAlmostEqual(got[0], math.cos(a) * x - math.sin(a) * y, places=6)
            self.assertAlmostEqual(got[1], math.sin(a) * x + math.cos(a) * y, places=6)
            self.assertAlmostEqual(got[0], e, places=6)
        with self.assertRaises(ValueError):
            gps_sim.GpsModel(rate_hz=0.0)

    def test_fix_message_declares_the_approximated_covariance(self):
        msg = gps_sim.fix_message(gps_sim.GpsModel(declared=1.2), 3, None, 1.0, 2.0, 3.0)
        self.assertEqual(msg.position_covariance_type, 1)
        self.assertAlmostEqual(msg.position_covariance[0], 1.44)
        self.assertAlmostEqual(msg.position_covariance[4], 1.44)
        self.assertEqual(msg.position_covariance[1], 0.0)


if __name__ == "__main__":
    unittest.main()
