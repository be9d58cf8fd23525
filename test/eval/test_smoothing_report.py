"""Unit tests of tools/eval/smoothing_report.py: every track is compared with the truth on the
same periods (those before the end minus the largest lag), computed by hand on small tracks.
"""

import math
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(REPO, "tools", "eval"))
import evaluate as ev  # noqa: E402
import smoothing_report as sr  # noqa: E402


class CutTest(unittest.TestCase):
    def test_keeps_the_periods_up_to_the_end(self):
        track = ev.make_trajectory([0.0, 1.0, 2.0, 3.0], [0, 1, 2, 3], [0, 0, 0, 0],
                                   [0.0, 0.1, 0.2, 0.3])
        part = sr.cut(track, 2.0)
        self.assertEqual(part.t, [0.0, 1.0, 2.0])
        self.assertEqual(part.x, [0, 1, 2])
        self.assertEqual(part.heading, [0.0, 0.1, 0.2])

    def test_a_track_without_heading_stays_without(self):
        part = sr.cut(ev.make_trajectory([0.0, 1.0], [0, 1], [0, 0]), 0.5)
        self.assertEqual(part.t, [0.0])
        self.assertIsNone(part.heading)


class CaseRowsTest(unittest.TestCase):
    def test_every_track_on_the_filtered_tracks_span_less_the_largest_lag(self):
        # Truth: x = t on [0, 4]. The filtered track is 0.3 m off everywhere; the lagged one
        # ends at t = 3 (its last period NaN in the CSV, left out by the loader), 0.1 m off; the
        # smoothed one is exact except 1 m off at t = 4, which the cut at 4 - 1 leaves out.
        truth = ev.make_trajectory([0.0, 4.0], [0.0, 4.0], [0.0, 0.0], [0.0, 0.0])
        t = [0.0, 1.0, 2.0, 3.0, 4.0]
        tracks = {
            "filtered": ev.make_trajectory(t, [v + 0.3 for v in t], [0.0] * 5, [0.0] * 5),
            "lag 1 s": ev.make_trajectory(t[:4], [v + 0.1 for v in t[:4]], [0.0] * 4,
                                          [0.02] * 4),
            "smoothed (RTS)": ev.make_trajectory(t, t[:4] + [5.0], [0.0] * 5, [0.0] * 5),
        }
        rows = sr.case_rows("case", tracks, truth, 1.0)
        self.assertEqual([r[1] for r in rows], ["filtered", "lag 1 s", "smoothed (RTS)"])
        self.assertEqual([r[2] for r in rows], [4, 4, 4])
        self.assertAlmostEqual(rows[0][3], 0.3, places=12)
        self.assertAlmostEqual(rows[1][3], 0.1, places=12)
        self.assertAlmostEqual(rows[2][3], 0.0, places=12)
        self.assertAlmostEqual(rows[1][4], math.degrees(0.02), places=9)


if __name__ == "__main__":
    unittest.main()
