#!/usr/bin/python3
"""Unit tests of tools/eval/pose3d_error.py's selection of the compared estimates: --skip
(seconds after the first row) and --window (a span of times fixed in the recording, used by
test/imu_odometry_3d_online_test.py to compare a node with its replay, whose rows start a lag
earlier). Expected values are worked out by hand from the synthetic truth and rows.
"""

import math
import os
import sys
import unittest

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools",
                                "eval"))
import pose3d_error  # noqa: E402

# truth every 10 ms from 100 s to 101 s: at rest at the origin, level
TIMES = [100.0 + 0.01 * k for k in range(101)]
TRUTH = (TIMES, [(1.0, 0.0, 0.0, 0.0)] * len(TIMES), [(0.0, 0.0, 0.0)] * len(TIMES))


def row(t, x):
    """A replay row at time t with the position (x, 0, 0) and the identity quaternion."""
    values = [x, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]
    return dict({"x%d" % i: v for i, v in enumerate(values)}, time=t)


class SelectionTest(unittest.TestCase):
    def setUp(self):
        # 1 m off until 100.5 s, then on the truth; from 100.2 s (a node's first /clock)
        self.rows = [row(t, 1.0 if t < 100.5 - 1e-9 else 0.0) for t in TIMES[20:]]

    def test_skip_counts_from_the_first_row(self):
        e = pose3d_error.errors(self.rows, TRUTH, 3, 0, skip=0.2)
        # rows from 100.4 s: 100.40-100.49 off by 1 m (10 rows), 100.50-101.00 on (51)
        self.assertEqual(len(e["position"]), 61)
        self.assertAlmostEqual(pose3d_error.rms(e["position"]), math.sqrt(10 / 61))

    def test_window_is_fixed_in_time(self):
        # the same window for rows starting at 100.2 s and at 100.0 s: the same estimates
        for rows in (self.rows, [row(t, 1.0) for t in TIMES[:20]] + self.rows):
            e = pose3d_error.errors(rows, TRUTH, 3, 0, skip=5.0, window=(100.45, 100.6))
            # 100.45-100.49 off (5 rows), 100.50-100.60 on (11), both ends included
            self.assertEqual(len(e["position"]), 16)
            self.assertAlmostEqual(pose3d_error.rms(e["position"]), math.sqrt(5 / 16))
            self.assertEqual(max(e["orientation"]), 0.0)


if __name__ == "__main__":
    unittest.main()
