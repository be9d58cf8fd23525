#!/usr/bin/python3
"""Unit tests of the computations of tools/eval/chapter5_page.py: the comparison rule that
decides the page's verdicts, the statistics over bags and the true acceleration."""

import math
import os
import sys
import unittest

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "tools", "eval"))
import chapter5_page as page  # noqa: E402
import evaluate as ev  # noqa: E402


def measurements(finals, twists=None):
    """Measurements whose path `label` has the final errors finals[label] (one per bag)."""
    bags = ["b%d" % k for k in range(len(next(iter(finals.values()))))]
    evaluations = {}
    for k, bag in enumerate(bags):
        evaluations[bag] = {}
        for label, values in finals.items():
            evaluations[bag][label] = ev.Evaluation(
                n_total=1, n_used=1, rmse_pos=2 * values[k], final_pos_err=values[k],
                final_heading_err_deg=-values[k], rmse_heading_deg=None, final_time=0.0,
                times=[0.0], pos_errors=[values[k]], heading_errors_deg=None)
    return page.Measurements(bags=bags, paths=[], runs=[], replays={}, truths={},
                             twists=twists or {}, trajectories={}, evaluations=evaluations)


class CompareTest(unittest.TestCase):
    def test_smaller_in_every_bag_and_by_more_than_ten_percent(self):
        m = measurements({"a": [0.8, 1.6, 0.9], "b": [1.0, 2.0, 1.0]})
        word, rel, k = page.compare(m, "a", "b")
        self.assertEqual(word, "smaller")
        self.assertAlmostEqual(rel, (3.3 / 3 - 4.0 / 3) / (4.0 / 3))  # -17.5 %
        self.assertEqual(k, 3)
        self.assertEqual(page.compare(m, "b", "a")[0], "larger")

    def test_a_small_change_is_no_clear_difference(self):
        m = measurements({"a": [0.95, 1.9, 0.95], "b": [1.0, 2.0, 1.0]})  # -5 %
        self.assertEqual(page.compare(m, "a", "b")[0], "no clear difference")

    def test_a_mixed_sign_is_no_clear_difference(self):
        # The mean drops by 45 %, but one bag goes the other way.
        m = measurements({"a": [0.1, 0.1, 1.1], "b": [1.0, 1.0, 1.0]})
        word, rel, k = page.compare(m, "a", "b")
        self.assertEqual((word, k), ("no clear difference", 2))
        self.assertAlmostEqual(rel, -0.566666, places=5)

    def test_other_metrics(self):
        m = measurements({"a": [1.0, 1.0], "b": [2.0, 2.0]})
        self.assertEqual(page.compare(m, "a", "b", "rmse")[0], "smaller")
        self.assertEqual(page.mean_of(m, "a", "heading"), 1.0)  # |final heading error|
        self.assertEqual(m.stat("b", "rmse"), (4.0, 0.0))

    def test_change_text(self):
        m = measurements({"a": [0.5, 0.5], "b": [1.0, 1.0]})
        self.assertEqual(page.change_text(m, "a", "b"), "smaller (-50 %, smaller in 2 of 2 bags)")


class FormatTest(unittest.TestCase):
    def test_pm(self):
        self.assertEqual(page.pm((0.0301, 0.0158)), "0.030 ± 0.016")
        self.assertEqual(page.pm((None, None)), "-")
        self.assertEqual(page.pm_auto((0.983, 0.018)), "0.983 ± 0.018")
        self.assertEqual(page.pm_auto((145.2, 27.0)), "145 ± 27")
        self.assertEqual(page.pm_auto((1.70, 0.04)), "1.70 ± 0.04")

    def test_dist(self):
        self.assertEqual(page.dist((0.0011, 0.0004)), "1.1 ± 0.4 mm")
        self.assertEqual(page.dist((0.132, 0.213)), "0.132 ± 0.213 m")


class TrueAccelerationTest(unittest.TestCase):
    def test_difference_quotient_at_the_midpoints(self):
        # v = 0.3 t (constant 0.3 m/s^2), then constant speed.
        t = [k * 0.01 for k in range(11)]
        v = [0.3 * s if s < 0.05 + 1e-9 else 0.015 for s in t]
        m = measurements({"a": [1.0]}, twists={"b0": (t, v, [0.0] * 11)})
        ta, a = page.true_acceleration(m)
        self.assertEqual(len(a), 10)
        for k in range(5):
            self.assertAlmostEqual(a[k], 0.3, places=9)
            self.assertAlmostEqual(ta[k], 0.005 + 0.01 * k, places=12)
        for k in range(5, 10):
            self.assertAlmostEqual(a[k], 0.0, places=9)


if __name__ == "__main__":
    unittest.main()
