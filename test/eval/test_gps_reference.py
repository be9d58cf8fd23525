"""Unit tests of tools/eval/gps_reference.py: the WGS84 geodesy against closed forms
(semi-axes, points on the meridian and on the parallel of a datum), the rigid 2-D fit
against a known rotation and shift, and the error figures against hand-computed values.
"""

import contextlib
import io
import math
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(REPO, "tools", "eval"))
import evaluate as ev  # noqa: E402
import gps_reference as gr  # noqa: E402

try:
    import rosbag  # noqa: F401
except ImportError:  # pragma: no cover - Debian's python3-rosbag is a package dependency
    rosbag = None

A = 6378137.0                 # WGS84 semi-major axis [m]
B = 6356752.314245            # WGS84 semi-minor axis [m], as published (NIMA TR8350.2)
F = 1 / 298.257223563
E2 = 2 * F - F * F

# The Husky recording's first fix (bags/husky_gps.bag) as a realistic datum.
LAT0, LON0, H0 = 43.409915833333336, -80.44827966666666, 273.2


def radii(lat_deg):
    """Meridian radius of curvature M and prime-vertical radius N at a latitude."""
    s = math.sin(math.radians(lat_deg))
    w2 = 1 - E2 * s * s
    return A * (1 - E2) / w2 ** 1.5, A / math.sqrt(w2)


class EcefTest(unittest.TestCase):
    def assertVec(self, got, want, tol):
        for g, w in zip(got, want):
            self.assertAlmostEqual(g, w, delta=tol)

    def test_semi_axes(self):
        self.assertVec(gr.geodetic_to_ecef(0, 0, 0), (A, 0, 0), 1e-6)
        self.assertVec(gr.geodetic_to_ecef(0, 90, 0), (0, A, 0), 1e-6)
        self.assertVec(gr.geodetic_to_ecef(0, 180, 0), (-A, 0, 0), 1e-6)
        self.assertVec(gr.geodetic_to_ecef(90, 0, 0), (0, 0, B), 1e-3)   # b to the published mm
        self.assertVec(gr.geodetic_to_ecef(-90, 0, 0), (0, 0, -B), 1e-3)

    def test_height_along_the_normal(self):
        self.assertVec(gr.geodetic_to_ecef(0, 0, 100.0), (A + 100, 0, 0), 1e-6)
        self.assertVec(gr.geodetic_to_ecef(90, 0, -50.0), (0, 0, B - 50), 1e-3)

    def test_latitude_45(self):
        # N = a / sqrt(1 - e^2/2), X = N cos 45 = a / sqrt(2 - e^2), Z = (1 - e^2) X
        x = A / math.sqrt(2 - E2)
        self.assertVec(gr.geodetic_to_ecef(45, 0, 0), (x, 0, (1 - E2) * x), 1e-6)
        # the same point 90 deg further east
        self.assertVec(gr.geodetic_to_ecef(45, 90, 0), (0, x, (1 - E2) * x), 1e-6)


class EnuTest(unittest.TestCase):
    def test_datum_is_the_origin(self):
        frame = gr.LocalFrame(LAT0, LON0, H0)
        for v in frame.enu(LAT0, LON0, H0):
            self.assertAlmostEqual(v, 0.0, delta=1e-9)

    def test_straight_up(self):
        frame = gr.LocalFrame(LAT0, LON0, H0)
        e, n, u = frame.enu(LAT0, LON0, H0 + 50.0)
        self.assertAlmostEqual(e, 0.0, delta=1e-6)
        self.assertAlmostEqual(n, 0.0, delta=1e-6)
        self.assertAlmostEqual(u, 50.0, delta=1e-6)

    def test_missing_altitude_is_the_datums(self):
        frame = gr.LocalFrame(LAT0, LON0, H0)
        self.assertEqual(frame.enu(LAT0, LON0, float("nan")), frame.enu(LAT0, LON0, H0))

    def test_100_m_north_along_the_meridian(self):
        # Arc length 100 m along the meridian at height h: dlat = 100 / (M + h) (M varies
        # by ~1e-7 over it, i.e. ~1e-5 m). The chord's north part is 100 m less
        # s^3/(6 (M + h)^2) (~4e-9 m); its drop below the tangent plane is s^2 / (2 (M + h)).
        m, _ = radii(LAT0)
        lat = LAT0 + math.degrees(100.0 / (m + H0))
        e, n, u = gr.LocalFrame(LAT0, LON0, H0).enu(lat, LON0, H0)
        self.assertAlmostEqual(e, 0.0, delta=1e-9)
        self.assertAlmostEqual(n, 100.0, delta=1e-4)
        self.assertAlmostEqual(u, -100.0 ** 2 / (2 * (m + H0)), delta=1e-5)

    def test_100_m_east_along_the_parallel(self):
        # Along the parallel (radius r = N cos lat about the axis) an arc of 100 m spans
        # dlon = 100 / r. The chord is r sin(dlon) east; the point moved r (1 - cos dlon)
        # towards the axis, which is sin(lat) of it north and cos(lat) of it down.
        _, n0 = radii(LAT0)
        r = n0 * math.cos(math.radians(LAT0))
        dlon = 100.0 / r
        d = r * (1 - math.cos(dlon))
        e, n, u = gr.LocalFrame(LAT0, LON0, 0.0).enu(LAT0, LON0 + math.degrees(dlon), 0.0)
        self.assertAlmostEqual(e, r * math.sin(dlon), delta=1e-6)
        self.assertAlmostEqual(n, math.sin(math.radians(LAT0)) * d, delta=1e-6)
        self.assertAlmostEqual(u, -math.cos(math.radians(LAT0)) * d, delta=1e-6)
        self.assertAlmostEqual(e, 100.0, delta=1e-3)

    def test_meridian_ellipse_at_the_equator(self):
        # Datum (0, 0, 0): east = +Y, north = +Z, up = +X of ECEF. A point at latitude lat on
        # the prime meridian is (N cos lat, 0, N (1 - e^2) sin lat).
        frame = gr.LocalFrame(0.0, 0.0, 0.0)
        for lat in (0.001, 0.5, -3.0):
            _, n_lat = radii(lat)
            e, n, u = frame.enu(lat, 0.0, 0.0)
            self.assertAlmostEqual(e, 0.0, delta=1e-9)
            self.assertAlmostEqual(n, n_lat * (1 - E2) * math.sin(math.radians(lat)), delta=1e-6)
            self.assertAlmostEqual(u, n_lat * math.cos(math.radians(lat)) - A, delta=1e-6)


class GpsTrackTest(unittest.TestCase):
    def test_invalid_fixes_skipped_and_datum_first_valid(self):
        m, _ = radii(LAT0)
        dlat = math.degrees(10.0 / (m + H0))  # 10 m north at height H0
        fixes = [
            (1.0, -1, LAT0 + 1.0, LON0, H0),            # no fix: skipped, not the datum
            (2.0, 0, float("nan"), LON0, H0),           # no position: skipped
            (3.0, 0, LAT0, LON0, H0),                   # datum
            (4.0, -1, LAT0 + dlat, LON0 + 1.0, H0),     # no fix again
            (5.0, 2, LAT0 + dlat, LON0, float("nan")),  # GBAS fix, no altitude
        ]
        frame, track = gr.gps_track(fixes)
        self.assertEqual((frame.lat, frame.lon, frame.h), (LAT0, LON0, H0))
        self.assertEqual(track.t, [3.0, 5.0])
        self.assertAlmostEqual(track.x[0], 0.0, delta=1e-9)
        self.assertAlmostEqual(track.y[0], 0.0, delta=1e-9)
        self.assertAlmostEqual(track.x[1], 0.0, delta=1e-9)
        self.assertAlmostEqual(track.y[1], 10.0, delta=1e-5)

    def test_no_valid_fix(self):
        with self.assertRaises(ValueError):
            gr.gps_track([(1.0, -1, LAT0, LON0, H0)])


def rotate_shift(points, theta, tx, ty):
    c, s = math.cos(theta), math.sin(theta)
    return [(c * x - s * y + tx, s * x + c * y + ty) for x, y in points]


class FitTest(unittest.TestCase):
    TRACK = [(0.0, 0.0), (1.0, 0.2), (2.5, 1.0), (3.0, 3.0), (1.0, 4.0), (-2.0, 2.5)]

    def test_recovers_known_rotation_and_shift(self):
        for theta, tx, ty in [(0.7, 3.0, -2.0), (-2.9, -100.0, 55.5), (math.pi / 2, 0.0, 0.0),
                              (0.0, 1e5, -1e5)]:
            q = rotate_shift(self.TRACK, theta, tx, ty)
            got = gr.fit_rigid_2d(self.TRACK, q)
            self.assertAlmostEqual(math.cos(got[0]), math.cos(theta), delta=1e-12)
            self.assertAlmostEqual(math.sin(got[0]), math.sin(theta), delta=1e-12)
            self.assertAlmostEqual(got[1], tx, delta=1e-9)
            self.assertAlmostEqual(got[2], ty, delta=1e-9)
            for a, b in zip(gr.apply_rigid_2d(got, self.TRACK), q):
                self.assertAlmostEqual(a[0], b[0], delta=1e-9)
                self.assertAlmostEqual(a[1], b[1], delta=1e-9)

    def test_symmetric_misfit(self):
        # p = (+-1, 0); q = (0, +-(1 + d)) + (5, 5): the best fit turns by 90 deg and shifts by
        # (5, 5); each point is then d off.
        d = 0.3
        theta, tx, ty = gr.fit_rigid_2d([(1, 0), (-1, 0)], [(5, 6 + d), (5, 4 - d)])
        self.assertAlmostEqual(theta, math.pi / 2, delta=1e-12)
        self.assertAlmostEqual(tx, 5.0, delta=1e-12)
        self.assertAlmostEqual(ty, 5.0, delta=1e-12)

    def test_single_point_is_a_shift(self):
        self.assertEqual(gr.fit_rigid_2d([(1.0, 2.0)], [(4.0, 6.0)]), (0.0, 3.0, 4.0))

    def test_fit_minimises_the_squared_errors(self):
        # perturbing the fitted transform never lowers the sum of squares
        q = [(x + 0.1 * k, y - 0.05 * k * k) for k, (x, y) in enumerate(rotate_shift(
            self.TRACK, 0.4, 2.0, 1.0))]
        best = gr.fit_rigid_2d(self.TRACK, q)

        def sse(tr):
            return sum((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2
                       for a, b in zip(gr.apply_rigid_2d(tr, self.TRACK), q))
        for dt in [(1e-3, 0, 0), (-1e-3, 0, 0), (0, 1e-3, 0), (0, 0, -1e-3)]:
            self.assertGreater(sse(tuple(a + b for a, b in zip(best, dt))), sse(best))


class CompareTest(unittest.TestCase):
    def test_errors_against_hand_values(self):
        # estimate on the x axis at 1 m/s, t = 0..4; fixes at t = 0.5, 1.5, 2.5, 3.5 displaced by
        # (0,0), (3,4), (0,-1), (2,0) from the interpolated estimate, plus one fix outside.
        est = ev.make_trajectory([0, 1, 2, 3, 4], [0, 1, 2, 3, 4], [0] * 5)
        ref = ev.make_trajectory([0.5, 1.5, 2.5, 3.5, 9.0],
                                 [0.5, 1.5 + 3, 2.5, 3.5 + 2, 0.0], [0, 4, -1, 0, 0])
        r = gr.compare(est, ref, align=False)
        self.assertEqual(r["n"], 4)
        self.assertIsNone(r["transform"])
        for got, want in zip(r["errors"], [0.0, 5.0, 1.0, 2.0]):
            self.assertAlmostEqual(got, want, delta=1e-12)
        self.assertAlmostEqual(r["rmse"], math.sqrt((0 + 25 + 1 + 4) / 4), delta=1e-12)
        self.assertEqual(r["max"], 5.0)
        self.assertAlmostEqual(r["final"], 2.0, delta=1e-12)

    def test_aligned_track_has_no_error(self):
        t = [float(k) for k in range(20)]
        x = [math.cos(0.3 * k) * (1 + 0.1 * k) for k in range(20)]
        y = [math.sin(0.3 * k) * 2 for k in range(20)]
        est = ev.make_trajectory(t, x, y)
        moved = rotate_shift(list(zip(x, y)), -1.2, 40.0, -7.0)
        ref = ev.make_trajectory(t, [p[0] for p in moved], [p[1] for p in moved])
        r = gr.compare(est, ref)
        self.assertAlmostEqual(r["transform"][0], -1.2, delta=1e-12)
        self.assertLess(r["max"], 1e-9)
        unaligned = gr.compare(est, ref, align=False)
        self.assertGreater(unaligned["rmse"], 10.0)

    def test_aligned_symmetric_misfit(self):
        est = ev.make_trajectory([0.0, 1.0], [1.0, -1.0], [0.0, 0.0])
        ref = ev.make_trajectory([0.0, 1.0], [5.0, 5.0], [6.3, 3.7])
        r = gr.compare(est, ref)
        self.assertAlmostEqual(r["rmse"], 0.3, delta=1e-12)
        self.assertAlmostEqual(r["max"], 0.3, delta=1e-12)
        self.assertAlmostEqual(r["final"], 0.3, delta=1e-12)

    def test_error_stats(self):
        self.assertEqual(gr.error_stats([3.0, 4.0]), (math.sqrt(12.5), 4.0, 4.0))
        with self.assertRaises(ValueError):
            gr.error_stats([])

    def test_no_overlap(self):
        est = ev.make_trajectory([0, 1], [0, 1], [0, 0])
        ref = ev.make_trajectory([5, 6], [0, 1], [0, 0])
        with self.assertRaises(ValueError):
            gr.compare(est, ref)


@unittest.skipIf(rosbag is None, "python3-rosbag missing")
class HuskyBagTest(unittest.TestCase):
    """The recording's /gps (nav_msgs/Odometry) is its own driver's conversion of the fixes
    to a local metric frame: an independent reference for the ENU track up to a shift."""
    BAG = os.path.join(REPO, "bags", "husky_gps.bag")

    def test_gps_odometry_matches_the_enu_track(self):
        frame, track = gr.gps_track(gr.read_fixes(self.BAG))
        self.assertEqual((frame.lat, frame.lon), (LAT0, LON0))
        r = gr.compare(ev.load_pose_bag(self.BAG, "/gps", with_heading=False), track)
        self.assertGreater(r["n"], 90)
        self.assertLess(abs(math.degrees(r["transform"][0])), 0.1)
        self.assertLess(r["rmse"], 0.01)

    def test_command_line(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "gps.csv")
            buf = io.StringIO()
            with contextlib.redirect_stdout(buf):
                rc = gr.main([self.BAG, self.BAG, "--odom-topic", "/encoder",
                              "--write-track", out])
            self.assertEqual(rc, 0)
            self.assertIn("RMSE", buf.getvalue())
            truth = ev.load_truth_csv(out)
            self.assertEqual((truth.x[0], truth.y[0]), (0.0, 0.0))
            self.assertEqual(len(truth.t), 95)

    def test_replay_csv_estimate(self):
        # a replay-format CSV whose pose is the GPS track itself, turned by -0.5 rad and moved
        # by (10, -4) m: the fit undoes it (to the CSV's 1e-6 m printing)
        _, track = gr.gps_track(gr.read_fixes(self.BAG))
        est = rotate_shift(list(zip(track.x, track.y)), -0.5, 10.0, -4.0)
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "replay.csv")
            with open(path, "w") as f:
                f.write("time,x0,var0,pose_x,pose_y,pose_heading,present_inputs\n")
                for t, (x, y) in zip(track.t, est):
                    f.write("%.9f,0,1,%.6f,%.6f,0,3\n" % (t, x, y))
            r = gr.compare(ev.load_result(path, ["pose_x", "pose_y"]), track)
            buf = io.StringIO()
            with contextlib.redirect_stdout(buf):
                self.assertEqual(gr.main([self.BAG, path]), 0)
        self.assertEqual(r["n"], len(track.t))
        self.assertAlmostEqual(r["transform"][0], 0.5, delta=1e-7)
        self.assertLess(r["max"], 1e-5)
        self.assertIn("fit: rotation 28.65 deg", buf.getvalue())   # 0.5 rad



class CovarianceSummaryTest(unittest.TestCase):
    def test_counts_types_correlations_and_unequal_variances(self):
        diagonal = (0.81, 0, 0, 0, 0.81, 0, 0, 0, 3.24)
        correlated = (1.0, 0.5, 0, 0.5, 1.0, 0, 0, 0, 4.0)
        unequal = (1.0, 0, 0, 0, 2.0, 0, 0, 0, 4.0)
        up_only = (1.0, 0, 0.2, 0, 1.0, 0, 0.2, 0, 4.0)
        s = gr.covariance_summary([(1, diagonal), (1, diagonal), (3, correlated), (2, unequal),
                                   (3, up_only), (0, (0.0,) * 9), (7, diagonal)])
        self.assertEqual(s["types"], {"APPROXIMATED": 2, "KNOWN": 2, "DIAGONAL_KNOWN": 1,
                                      "UNKNOWN": 1, "7": 1})
        self.assertEqual(s["off_diagonal"], 2)
        self.assertEqual(s["unequal_en"], 1)

class PairedGainTest(unittest.TestCase):
    """paired_gain: B closer to the fixes than A by more than chance (one-sided 95 %)."""

    def test_hand_computed_bound(self):
        # d = e_b^2 - e_a^2 = (-1, 0, -1, 0): mean -0.5, variance 1/3, lag-1 autocorrelation
        # -0.75 (kept at 0): bound -0.5 + 1.6449 sqrt(1/12) = -0.02516 < 0: a gain
        mean, bound, gain = gr.paired_gain([1, 1, 1, 1], [0, 1, 0, 1])
        self.assertAlmostEqual(mean, -0.5, delta=1e-12)
        self.assertAlmostEqual(bound, -0.5 + 1.6448536269514722 * math.sqrt(1 / 12), delta=1e-12)
        self.assertTrue(gain)

    def test_correlated_differences_count_as_fewer_fixes(self):
        # d = (-1, -1, 0, 0): mean -0.5, variance 1/3, lag-1 autocorrelation
        # (0.25 - 0.25 + 0.25) / (3 * 1/3) = 0.25: n_eff = 4 * 0.75 / 1.25 = 2.4,
        # bound -0.5 + 1.6449 sqrt(1/3 / 2.4) = 0.1130: no gain (independent: -0.0252, a gain)
        mean, bound, gain = gr.paired_gain([1, 1, 1, 1], [0, 0, 1, 1])
        self.assertAlmostEqual(bound, -0.5 + 1.6448536269514722 * math.sqrt(1 / 3 / 2.4),
                               delta=1e-12)
        self.assertFalse(gain)

    def test_a_worse_or_equal_track_is_no_gain(self):
        self.assertFalse(gr.paired_gain([1.0, 2.0, 1.5, 0.5], [1.0, 2.0, 1.5, 0.5])[2])
        self.assertFalse(gr.paired_gain([1.0, 2.0, 1.5, 0.5], [1.1, 2.0, 1.6, 0.5])[2])
        self.assertFalse(gr.paired_gain([1.0, 2.0], [0.0, 0.0])[2])  # too few fixes


if __name__ == "__main__":
    unittest.main()
