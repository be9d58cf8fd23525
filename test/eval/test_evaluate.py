#!/usr/bin/python3
"""Unit tests of tools/eval/evaluate.py's core (standard library only).

Run: /usr/bin/python3 -m unittest discover -s test/eval   (or test/eval/run_unittests.py)
"""

import math
import os
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "tools", "eval"))
import evaluate as ev  # noqa: E402

T0 = 1700000000.0  # the simulated bags' clock start: stamps of this size must not lose precision


def straight_line(n=901, dt=0.01, v=0.5, heading=0.0):
    """Truth along a straight line through the origin, at 100 Hz by default."""
    t = [T0 + k * dt for k in range(n)]
    s = [v * k * dt for k in range(n)]
    return ev.make_trajectory(t, [d * math.cos(heading) for d in s],
                              [d * math.sin(heading) for d in s], [heading] * n)


def circle(n=2001, dt=0.01, radius=2.0, omega=0.4):
    """Truth on a circle about the origin, counter-clockwise, heading tangential (wraps)."""
    t = [T0 + k * dt for k in range(n)]
    phi = [omega * k * dt for k in range(n)]
    return ev.make_trajectory(t, [radius * math.cos(p) for p in phi],
                              [radius * math.sin(p) for p in phi],
                              [ev.wrap_angle(p + math.pi / 2) for p in phi])


class WrapTest(unittest.TestCase):
    def test_range(self):
        for a in [0.0, 1.0, -1.0, math.pi, -math.pi, 3 * math.pi, -3 * math.pi, 7.5, -7.5, 100.0]:
            w = ev.wrap_angle(a)
            self.assertGreater(w, -math.pi)
            self.assertLessEqual(w, math.pi)
            self.assertAlmostEqual(math.cos(w), math.cos(a), places=12)
            self.assertAlmostEqual(math.sin(w), math.sin(a), places=12)

    def test_values(self):
        self.assertAlmostEqual(ev.wrap_angle(0.5), 0.5)
        self.assertAlmostEqual(ev.wrap_angle(2 * math.pi + 0.5), 0.5)
        self.assertAlmostEqual(ev.wrap_angle(-2 * math.pi - 0.5), -0.5)
        self.assertAlmostEqual(ev.wrap_angle(-math.pi), math.pi)
        self.assertAlmostEqual(ev.wrap_angle(math.pi), math.pi)

    def test_difference_across_the_wrap(self):
        # 179 deg against -179 deg: 2 deg apart, not 358
        d = ev.angle_diff(math.radians(179), math.radians(-179))
        self.assertAlmostEqual(math.degrees(d), -2.0, places=9)
        d = ev.angle_diff(math.radians(-179), math.radians(179))
        self.assertAlmostEqual(math.degrees(d), 2.0, places=9)
        # a heading integrated past 2 pi (as the replay's theta is) against a wrapped truth
        self.assertAlmostEqual(ev.angle_diff(6.2781637328444093, 0.0), 6.2781637328444093 - 2 * math.pi)

    def test_yaw_from_quaternion(self):
        for yaw in [0.0, 0.3, -2.0, math.pi - 1e-9, 3.0]:
            q = (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))
            self.assertAlmostEqual(ev.yaw_from_quaternion(*q), yaw, places=9)


class InterpolateTest(unittest.TestCase):
    def test_intermediate_stamps(self):
        truth = straight_line(v=0.5)
        for offset in [0.0, 0.001, 0.005, 0.0099, 1.234, 8.999]:
            x, y, h = ev.interpolate(truth, T0 + offset)
            self.assertAlmostEqual(x, 0.5 * offset, places=6)
            self.assertAlmostEqual(y, 0.0, places=12)
            self.assertAlmostEqual(h, 0.0, places=12)

    def test_quadratic_truth_is_interpolated_linearly(self):
        t = [T0, T0 + 1.0, T0 + 2.0]
        truth = ev.make_trajectory(t, [0.0, 1.0, 4.0], [0.0, -1.0, -4.0])
        x, y, h = ev.interpolate(truth, T0 + 1.25)
        self.assertAlmostEqual(x, 1.75)
        self.assertAlmostEqual(y, -1.75)
        self.assertIsNone(h)

    def test_heading_interpolates_the_short_way_round(self):
        t = [T0, T0 + 1.0]
        truth = ev.make_trajectory(t, [0.0, 0.0], [0.0, 0.0],
                                   [math.radians(170), math.radians(-170)])
        _, _, h = ev.interpolate(truth, T0 + 0.5)
        self.assertAlmostEqual(abs(math.degrees(h)), 180.0, places=9)
        _, _, h = ev.interpolate(truth, T0 + 0.25)
        self.assertAlmostEqual(math.degrees(h), 175.0, places=9)
        _, _, h = ev.interpolate(truth, T0 + 0.75)
        self.assertAlmostEqual(math.degrees(h), -175.0, places=9)

    def test_outside_the_range(self):
        truth = straight_line(n=101)
        self.assertIsNone(ev.interpolate(truth, T0 - 0.01))
        self.assertIsNone(ev.interpolate(truth, T0 + 1.01))
        # within the tolerance: the end sample
        x, _, _ = ev.interpolate(truth, T0 + 1.0 + 5e-7)
        self.assertAlmostEqual(x, 0.5, places=9)
        self.assertIsNotNone(ev.interpolate(truth, T0 - 5e-7))
        self.assertIsNone(ev.interpolate(truth, T0 - 5e-7, tolerance=0.0))

    def test_make_trajectory_sorts_and_drops_repeated_stamps(self):
        tr = ev.make_trajectory([3.0, 1.0, 2.0, 2.0], [30.0, 10.0, 20.0, 21.0], [0, 0, 0, 0])
        self.assertEqual(tr.t, [1.0, 2.0, 3.0])
        self.assertEqual(tr.x, [10.0, 21.0, 30.0])  # the later of the two samples at 2.0
        with self.assertRaises(ValueError):
            ev.make_trajectory([1.0, 2.0], [1.0], [1.0, 2.0])


class RmseTest(unittest.TestCase):
    def test_rmse(self):
        self.assertAlmostEqual(ev.rmse([3.0, 4.0]), math.sqrt(12.5))
        self.assertAlmostEqual(ev.rmse([-0.3] * 10), 0.3)
        self.assertIsNone(ev.rmse([]))


def offset_estimate(truth, times, dx, dy, dheading=0.0):
    """Estimate at `times`: the exact truth shifted by (dx, dy) and turned by dheading."""
    xs, ys, hs = [], [], []
    for t in times:
        x, y, h = ev.interpolate(truth, t)
        xs.append(x + dx)
        ys.append(y + dy)
        hs.append(ev.wrap_angle(h + dheading))
    return ev.make_trajectory(times, xs, ys, hs)


class EvaluateTest(unittest.TestCase):
    def test_straight_line_constant_offset(self):
        truth = straight_line()
        # estimates at 10 Hz, phase 5 ms: all between the truth's samples
        times = [T0 + 0.005 + 0.1 * k for k in range(90)]
        est = offset_estimate(truth, times, 0.0, 0.3)
        r = ev.evaluate(est, truth)
        self.assertEqual((r.n_total, r.n_used), (90, 90))
        self.assertAlmostEqual(r.rmse_pos, 0.3, places=9)
        self.assertAlmostEqual(r.final_pos_err, 0.3, places=9)
        self.assertAlmostEqual(r.final_heading_err_deg, 0.0, places=9)
        self.assertAlmostEqual(r.rmse_heading_deg, 0.0, places=9)
        self.assertAlmostEqual(r.final_time, times[-1])
        self.assertEqual(len(r.pos_errors), 90)

    def test_circle_radial_offset_and_heading_offset_across_the_wrap(self):
        truth = circle()  # heading passes through +-180 deg at phi = pi/2
        times = [T0 + 0.1 * k + 0.003 for k in range(200)]
        # 0.3 m radially outwards, heading +5 deg: crosses the wrap where the truth is near 180
        xs, ys, hs = [], [], []
        for t in times:
            x, y, h = ev.interpolate(truth, t)
            r = math.hypot(x, y)
            xs.append(x * (r + 0.3) / r)
            ys.append(y * (r + 0.3) / r)
            hs.append(ev.wrap_angle(h + math.radians(5)))
        est = ev.make_trajectory(times, xs, ys, hs)
        self.assertTrue(any(h < -3.0 for h in hs) and any(h > 3.0 for h in hs))
        r = ev.evaluate(est, truth)
        self.assertAlmostEqual(r.rmse_pos, 0.3, places=4)  # chord vs arc: below 1e-4 m
        self.assertAlmostEqual(r.final_pos_err, 0.3, places=4)
        self.assertAlmostEqual(r.rmse_heading_deg, 5.0, places=6)
        self.assertAlmostEqual(r.final_heading_err_deg, 5.0, places=6)
        self.assertTrue(all(abs(e - 5.0) < 1e-6 for e in r.heading_errors_deg))

    def test_final_heading_error_is_signed_and_wrapped(self):
        truth = straight_line(heading=math.radians(178))
        times = [T0 + 0.1 * k for k in range(1, 90)]
        est = offset_estimate(truth, times, 0.0, 0.0, math.radians(-6))
        r = ev.evaluate(est, truth)
        self.assertAlmostEqual(r.final_heading_err_deg, -6.0, places=6)
        self.assertAlmostEqual(r.rmse_heading_deg, 6.0, places=6)
        self.assertAlmostEqual(r.rmse_pos, 0.0, places=6)
        # an estimate whose heading went once more round the circle
        est2 = ev.make_trajectory(est.t, est.x, est.y, [h + 2 * math.pi for h in est.heading])
        self.assertAlmostEqual(ev.evaluate(est2, truth).final_heading_err_deg, -6.0, places=6)

    def test_growing_error_and_final_error(self):
        truth = straight_line(n=1001)  # 10 s
        times = [T0 + 0.1 * k for k in range(101)]
        est = ev.make_trajectory(times, [ev.interpolate(truth, t)[0] + 0.01 * k
                                         for k, t in enumerate(times)],
                                 [0.0] * 101, [0.0] * 101)
        r = ev.evaluate(est, truth)
        expect = math.sqrt(sum((0.01 * k) ** 2 for k in range(101)) / 101)
        self.assertAlmostEqual(r.rmse_pos, expect, places=9)
        self.assertAlmostEqual(r.final_pos_err, 1.0, places=9)

    def test_mismatched_time_ranges(self):
        truth = straight_line(n=501)  # T0 .. T0 + 5 s
        # estimates from 2 s before the truth to 3 s after it
        times = [T0 - 2.0 + 0.1 * k + 0.05 for k in range(100)]
        est = ev.make_trajectory(times, [1.0] * 100, [0.0] * 100, [0.0] * 100)
        r = ev.evaluate(est, truth)
        inside = [t for t in times if T0 <= t <= T0 + 5.0]
        self.assertEqual(r.n_total, 100)
        self.assertEqual(r.n_used, len(inside))
        self.assertEqual(r.times, inside)
        self.assertAlmostEqual(r.final_time, inside[-1])
        # the last estimate inside the truth's range, against the truth at its stamp
        self.assertAlmostEqual(r.final_pos_err, abs(1.0 - 0.5 * (inside[-1] - T0)), places=6)

    def test_no_overlap_raises(self):
        truth = straight_line(n=101)
        est = ev.make_trajectory([T0 + 10.0, T0 + 11.0], [0.0, 0.0], [0.0, 0.0])
        with self.assertRaises(ValueError):
            ev.evaluate(est, truth)
        with self.assertRaises(ValueError):
            ev.evaluate(ev.make_trajectory([], [], []), truth)

    def test_without_heading(self):
        truth = straight_line()
        times = [T0 + 0.1 * k for k in range(10)]
        est = ev.make_trajectory(times, [ev.interpolate(truth, t)[0] for t in times],
                                 [0.3] * 10)  # no heading column
        r = ev.evaluate(est, truth)
        self.assertAlmostEqual(r.rmse_pos, 0.3)
        self.assertIsNone(r.final_heading_err_deg)
        self.assertIsNone(r.rmse_heading_deg)
        self.assertIsNone(r.heading_errors_deg)
        table = ev.format_table([("pos-only", r, None)])
        self.assertIn("pos-only", table)
        self.assertIn("0.3000", table)


class FilesAndFormatTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def write(self, name, text):
        path = os.path.join(self.dir.name, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_result_csv_pose_columns(self):
        path = self.write("r.csv",
                          "time,x0,x1,var0,var1,pose_x,pose_y,pose_heading,present_inputs\n"
                          "1700000000.2,9,9,1,1,0.2,0.1,0.5,4\n"
                          "1700000000.0999999,9,9,1,1,0.1,0.0,6.3,4\n")
        tr = ev.load_result_csv(path)
        self.assertEqual(tr.t, [1700000000.0999999, 1700000000.2])  # sorted
        self.assertEqual(tr.x, [0.1, 0.2])
        self.assertEqual(tr.heading, [6.3, 0.5])
        tr = ev.load_result_csv(path, ["x0", "x1"])
        self.assertEqual(tr.x, [9.0, 9.0])
        self.assertIsNone(tr.heading)

    def test_result_csv_without_pose_columns(self):
        path = self.write("r.csv", "time,x0,x1,var0,var1,present_inputs\n1,2,3,1,1,2\n")
        with self.assertRaisesRegex(ValueError, "pose-columns"):
            ev.load_result_csv(path)

    def test_truth_csv_with_and_without_header(self):
        a = ev.load_truth_csv(self.write("a.csv", "time,x,y,heading\n0,0,0,0\n1,1,2,0.5\n"))
        b = ev.load_truth_csv(self.write("b.csv", "0,0,0,0\n1,1,2,0.5\n"))
        c = ev.load_truth_csv(self.write("c.csv", "t,y,x\n0,0,0\n1,2,1\n"))
        self.assertEqual(a, b)
        self.assertEqual((c.x, c.y, c.heading), ([0.0, 1.0], [0.0, 2.0], None))

    def test_split_label(self):
        self.assertEqual(ev.split_label("ukf=out/u.csv"), ("ukf", "out/u.csv"))
        self.assertEqual(ev.split_label("/tmp/a/nav_ekf.csv"), ("nav_ekf", "/tmp/a/nav_ekf.csv"))
        self.assertEqual(ev.split_label("dir/x=1/e.bag"), ("e", "dir/x=1/e.bag"))

    def test_parse_summary_timing(self):
        line = ("sf_nav3ctrl_ukf: 20700 messages, 899 estimates, 0 dropped values, "
                "2.42871 us per estimation step, 0.515755 s in all\n")
        self.assertAlmostEqual(ev.parse_summary_timing(line), 2.42871)
        self.assertAlmostEqual(ev.parse_summary_timing("x, 1.5e+03 us per estimation step"), 1500.0)
        self.assertIsNone(ev.parse_summary_timing("no timing here"))

    def test_summary_line_is_found_before_the_per_input_lines(self):
        output = ("n: 10 messages, 4 estimates, 0 dropped values (0 late), 0 gated, 0 substitutes, "
                  "1.5 us per estimation step, 0.1 s in all\n"
                  "n: input 0: 10 received, 10 used, dropped: none, 0 gated, 0 periods timed out\n")
        self.assertTrue(ev.summary_line(output).startswith("n: 10 messages, 4 estimates"))
        self.assertEqual(ev.summary_line("only line\n"), "only line")
        self.assertEqual(ev.summary_line(""), "")

    def test_table(self):
        truth = straight_line()
        times = [T0 + 0.1 * k for k in range(10)]
        r = ev.evaluate(offset_estimate(truth, times, 0.0, 0.3), truth)
        text = ev.format_table([("ukf", r, 2.5), ("ekf", r, None)])
        lines = text.splitlines()
        self.assertEqual(len(lines), 3)
        self.assertIn("RMSE pos [m]", lines[0])
        self.assertIn("2.50", lines[1])
        self.assertTrue(lines[2].rstrip().endswith("-"))
        md = ev.format_table([("ukf", r, 2.5)], markdown=True)
        self.assertTrue(md.startswith("| filter |"))


class DeadReckoningTest(unittest.TestCase):
    """Paths from logged velocities: eqs. 5.1-5.3 and 5.5, checked against closed forms."""

    def test_straight_line_with_the_models_delay(self):
        # ds_0 = 0 and ds_k = v dt: the position trails the velocity by one sample.
        dt, v = 0.1, 0.5
        t = [T0 + k * dt for k in range(11)]
        tr = ev.dead_reckon(t, [v] * 11, [0.0] * 11)
        self.assertEqual(tr.t, t)
        self.assertEqual(tr.x[0], 0.0)
        self.assertEqual(tr.x[1], 0.0)
        for k in range(1, 11):
            self.assertAlmostEqual(tr.x[k], (k - 1) * v * dt, places=6)  # dt from 1.7e9 stamps
            self.assertEqual(tr.y[k], 0.0)
            self.assertEqual(tr.heading[k], 0.0)

    def test_constant_turn_matches_the_closed_form(self):
        # theta_k = k w dt; x_k = sum_{j=1}^{k-1} v dt cos(j w dt), and the sum of cos(j p)
        # for j = 1..m is sin(m p / 2) cos((m + 1) p / 2) / sin(p / 2) (same with sin for y).
        dt, v, w = 0.01, 0.4, 0.7
        n = 500
        t = [k * dt for k in range(n)]
        tr = ev.dead_reckon(t, [v] * n, [w] * n)
        p = w * dt
        for k in (2, 17, 250, n - 1):
            m = k - 1
            common = v * dt * math.sin(m * p / 2) / math.sin(p / 2)
            self.assertAlmostEqual(tr.x[k], common * math.cos((m + 1) * p / 2), places=9)
            self.assertAlmostEqual(tr.y[k], common * math.sin((m + 1) * p / 2), places=9)
            self.assertAlmostEqual(tr.heading[k], k * p, places=9)

    def test_full_turn_closes_the_polygon(self):
        # N steps of 2 pi / N: the N chords sum to zero, so sample N + 1 is the start again.
        n, dt, v = 40, 0.1, 1.0
        t = [k * dt for k in range(n + 2)]
        tr = ev.dead_reckon(t, [v] * (n + 2), [2 * math.pi / (n * dt)] * (n + 2),
                            start=(3.0, -1.0, 0.0))
        self.assertAlmostEqual(tr.x[n + 1], 3.0, places=9)
        self.assertAlmostEqual(tr.y[n + 1], -1.0, places=9)
        # it went round (a circle of 4 m: 1.27 m across), it did not stand still
        self.assertGreater(max(tr.y) - (-1.0), 1.2)

    def test_start_pose_and_heading(self):
        t = [0.0, 1.0, 2.0, 3.0]
        tr = ev.dead_reckon(t, [2.0] * 4, [0.0] * 4, start=(1.0, 2.0, math.pi / 2))
        self.assertAlmostEqual(tr.x[3], 1.0, places=12)
        self.assertAlmostEqual(tr.y[3], 2.0 + 2 * 2.0, places=12)  # two intervals of ds = 2
        self.assertEqual(tr.heading, [math.pi / 2] * 4)

    def test_non_finite_values_hold(self):
        self.assertEqual(ev.hold_finite([float("nan"), 1.0, float("nan"), float("inf"), 2.0]),
                         [0.0, 1.0, 1.0, 1.0, 2.0])
        t = [0.0, 1.0, 2.0, 3.0]
        tr = ev.dead_reckon(t, [float("nan"), 1.0, float("nan"), 1.0], [0.0] * 4)
        self.assertEqual(tr.x, [0.0, 0.0, 0.0, 1.0])  # ds_1 = 0 (nan as 0), ds_2 = 1

    def test_length_mismatch(self):
        with self.assertRaises(ValueError):
            ev.dead_reckon([0.0, 1.0], [1.0], [0.0, 0.0])
        with self.assertRaises(ValueError):
            ev.dead_reckon([], [], [])

    def test_integrate_acceleration(self):
        # eq. 5.6 from rest with a = 0.3: v_k = 0.3 k dt; the last a is not used.
        t = [k * 0.1 for k in range(6)]
        v = ev.integrate_acceleration(t, [0.3] * 5 + [99.0])
        for k in range(6):
            self.assertAlmostEqual(v[k], 0.03 * k, places=12)

    def test_wheel_velocities(self):
        v, w = ev.wheel_velocities([400.0, -300.0], [600.0, 300.0], 0.3)
        self.assertAlmostEqual(v[0], 0.5)
        self.assertAlmostEqual(w[0], 0.2 / 0.6)  # (0.6 - 0.4) m/s over 2 R
        self.assertAlmostEqual(v[1], 0.0)  # turning in place
        self.assertAlmostEqual(w[1], 1.0)
        with self.assertRaises(ValueError):
            ev.wheel_velocities([1.0], [1.0], 0.0)

    def test_parse_specs(self):
        self.assertEqual(ev.parse_dead_reckoning("v=x5,omega=x3"),
                         ("velocities", {"v": "x5", "omega": "x3"}))
        self.assertEqual(ev.parse_dead_reckoning(" omega=x0 , a=x1 "),
                         ("acceleration", {"a": "x1", "omega": "x0"}))
        self.assertEqual(ev.parse_dead_reckoning("wheels=x0,x1"),
                         ("wheels", {"wheels": ["x0", "x1"]}))
        for bad in ["v=x1", "v=x1,omega=x0,a=x2", "wheels=x0", "wheels=x0,v=x1", "speed=x1",
                    "v=x1,v=x2", "x1,x2", "v=,omega=x0"]:
            with self.assertRaises(ValueError, msg=bad):
                ev.parse_dead_reckoning(bad)


class DeadReckonedCsvTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def write(self, text):
        path = os.path.join(self.dir.name, "r.csv")
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_wheel_columns(self):
        # Both wheels at 500 mm/s (the missing value holds): 0.5 m/s straight on; with the
        # model's delay ds = 0, 0.5, 0.5, so x = 0, 0, 0.5, 1.0.
        path = self.write("time,x0,x1,var0,var1,present_inputs\n"
                          "0,500,500,0,0,2\n1,500,500,0,0,2\n2,500,500,0,0,2\n"
                          "3,,500,0,0,1\n")
        tr = ev.load_result_dead_reckoned(path, "wheels=x0,x1")
        self.assertEqual(tr.x, [0.0, 0.0, 0.5, 1.0])
        self.assertEqual(tr.heading, [0.0] * 4)
        with self.assertRaisesRegex(ValueError, "no column x7"):
            ev.load_result_dead_reckoned(path, "v=x7,omega=x0")

    def test_acceleration_columns(self):
        # a = 0.5 m/s^2 from rest: v = 0, 0.5, 1.0, 1.5 (eq. 5.6), ds = 0, 0, 0.5, so
        # x = 0, 0, 0, 0.5; omega = 0.25 rad/s turns the heading by 0.25 per second.
        path = self.write("time,x0,x1\n0,0.25,0.5\n1,0.25,0.5\n2,0.25,0.5\n3,0.25,0.5\n")
        tr = ev.load_result_dead_reckoned(path, "a=x1,omega=x0")
        self.assertEqual(tr.heading, [0.0, 0.25, 0.5, 0.75])
        self.assertAlmostEqual(tr.x[3], 0.5 * math.cos(0.5), places=12)
        self.assertAlmostEqual(tr.y[3], 0.5 * math.sin(0.5), places=12)
        self.assertEqual(tr.x[:3], [0.0, 0.0, 0.0])


class MeanSpreadTest(unittest.TestCase):
    def test_values(self):
        self.assertEqual(ev.mean_spread([1.0, 2.0, 3.0]), (2.0, 1.0))  # sample deviation
        self.assertEqual(ev.mean_spread([4.0, None, 8.0]), (6.0, math.sqrt(8.0)))
        self.assertEqual(ev.mean_spread([5.0]), (5.0, 0.0))
        self.assertEqual(ev.mean_spread([]), (None, None))
        self.assertEqual(ev.mean_spread([None]), (None, None))


class ShiftTest(unittest.TestCase):
    def test_a_delayed_estimate_matches_after_the_shift(self):
        # The estimate reports at t the truth of t - 0.2 s: 0.1 m behind at 0.5 m/s; moved
        # 0.2 s earlier it lies on the truth.
        truth = straight_line()
        times = [T0 + 0.5 + 0.1 * k for k in range(60)]
        delayed = ev.make_trajectory(times, [0.5 * (t - T0 - 0.2) for t in times],
                                     [0.0] * 60, [0.0] * 60)
        self.assertAlmostEqual(ev.evaluate(delayed, truth).rmse_pos, 0.1, places=6)
        shifted = ev.shift_trajectory(delayed, -0.2)
        self.assertAlmostEqual(ev.evaluate(shifted, truth).rmse_pos, 0.0, places=6)
        self.assertEqual(shifted.x, delayed.x)
        self.assertAlmostEqual(shifted.t[0], delayed.t[0] - 0.2, places=6)


if __name__ == "__main__":
    unittest.main()
