"""Unit tests of tools/eval/gps_holdout.py: the split into fused and held-out fixes, the turn
of ENU into the odom frame, the held track, the errors at held-out points, the yaw offset
measured on a track turned by a known angle, and the reduced bag (hand-made, written with
rosbag) that leaves out exactly the held-out fixes; the whole evaluation with the replays
replaced by known tracks: fixes before the first estimate (issue 37: TypeError) and the
nodes, topic, remaps, static transforms and parameters given as options."""

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
import gps_holdout as gh  # noqa: E402

try:
    import rosbag
    import rospy
    from sensor_msgs.msg import NavSatFix
    from std_msgs.msg import Float64
except ImportError:  # pragma: no cover - Debian's python3-rosbag is a package dependency
    rosbag = None


def fix(t, status=1, lat=49.0, lon=8.0, alt=100.0):
    return (t, status, lat, lon, alt)


class SplitTest(unittest.TestCase):
    def test_every_nth_valid_fix_is_fused(self):
        fixes = [fix(float(k)) for k in range(11)]
        fused, held = gh.split_fixes(fixes, 5)
        self.assertEqual([f[0] for f in fused], [0.0, 5.0, 10.0])
        self.assertEqual(len(held), 8)
        self.assertNotIn(5.0, [f[0] for f in held])

    def test_invalid_fixes_are_in_neither_and_do_not_count(self):
        fixes = [fix(0.0, status=-1), fix(1.0), fix(2.0), fix(3.0, lat=float("nan")), fix(4.0)]
        fused, held = gh.split_fixes(fixes, 2)
        self.assertEqual([f[0] for f in fused], [1.0, 4.0])
        self.assertEqual([f[0] for f in held], [2.0])

    def test_refuses_to_hold_nothing_out(self):
        with self.assertRaises(ValueError):
            gh.split_fixes([fix(0.0)], 1)
        with self.assertRaises(ValueError):
            gh.split_fixes([fix(0.0, status=-1)], 5)


class OdomFrameTest(unittest.TestCase):
    def test_to_odom_matches_the_node_convention(self):
        # Offset 90 deg: the odom x axis points north.
        x, y = gh.to_odom(0.0, 100.0, math.pi / 2)
        self.assertAlmostEqual(x, 100.0)
        self.assertAlmostEqual(y, 0.0)
        x, y = gh.to_odom(100.0, 0.0, math.pi / 2)
        self.assertAlmostEqual(x, 0.0)
        self.assertAlmostEqual(y, -100.0)
        x, y = gh.to_odom(3.0, 4.0, 0.3)
        self.assertAlmostEqual(math.hypot(x, y), 5.0)

    def test_calibrated_offset_is_the_turn_of_the_track(self):
        # A track in the odom frame, and the same track in ENU turned by 40 deg: the offset
        # measured is 40 deg, whatever the shift.
        a = math.radians(40.0)
        t = [0.1 * k for k in range(200)]
        xs = [0.5 * tk + 0.02 * tk * tk for tk in t]
        ys = [0.3 * math.sin(0.4 * tk) for tk in t]
        track = ev.make_trajectory(t, xs, ys)
        enu = []
        for tk, xk, yk in zip(t[::20], xs[::20], ys[::20]):
            e = math.cos(a) * xk - math.sin(a) * yk + 7.0
            n = math.sin(a) * xk + math.cos(a) * yk - 3.0
            enu.append((tk, e, n))
        self.assertAlmostEqual(gh.calibrate_yaw_offset(track, enu, 10.0), a, places=9)
        # Turning the ENU points by the offset gives the track back (up to the shift).
        back = [gh.to_odom(e, n, a) for _, e, n in enu]
        self.assertAlmostEqual(back[1][0] - back[0][0], xs[20] - xs[0], places=9)
        with self.assertRaises(ValueError):
            gh.calibrate_yaw_offset(track, enu[:1], 10.0)


class ErrorTest(unittest.TestCase):
    def test_errors_at_points_without_alignment(self):
        track = ev.make_trajectory([0.0, 10.0], [0.0, 10.0], [0.0, 0.0])
        errors = gh.holdout_errors(track, [(5.0, 5.0, 3.0), (2.0, 2.0, -4.0), (50.0, 0.0, 0.0)])
        self.assertEqual(len(errors), 2)  # the last point is outside the track's time range
        self.assertAlmostEqual(errors[0], 3.0)
        self.assertAlmostEqual(errors[1], 4.0)

    def test_held_track_holds_each_point_until_the_next(self):
        held = gh.held_track([(0.0, 1.0, 2.0), (2.0, 5.0, 6.0)])
        self.assertEqual(ev.interpolate(held, 1.9)[:2], (1.0, 2.0))
        self.assertEqual(ev.interpolate(held, 2.0)[:2], (5.0, 6.0))


@unittest.skipIf(rosbag is None, "python3-rosbag missing")
class ReducedBagTest(unittest.TestCase):
    def test_leaves_out_exactly_the_held_out_fixes(self):
        with tempfile.TemporaryDirectory() as tmp:
            inp, out = os.path.join(tmp, "in.bag"), os.path.join(tmp, "out.bag")
            with rosbag.Bag(inp, "w") as bag:
                for k in range(6):
                    m = NavSatFix()
                    m.header.stamp = rospy.Time.from_sec(100.0 + 0.4 * k)
                    m.latitude = 49.0 + 1e-5 * k
                    bag.write("/fix", m, rospy.Time.from_sec(100.001 + 0.4 * k))
                    bag.write("/other", Float64(data=k), rospy.Time.from_sec(100.1 + 0.4 * k))
            left_out = gh.write_reduced_bag(inp, out, [100.0, 101.2])
            self.assertEqual(left_out, 4)
            with rosbag.Bag(out) as bag:
                fixes = [m for _, m, _ in bag.read_messages(topics=["/fix"])]
                others = [m for _, m, _ in bag.read_messages(topics=["/other"])]
            self.assertEqual([round(m.header.stamp.to_sec(), 3) for m in fixes], [100.0, 101.2])
            self.assertEqual(len(others), 6)


@unittest.skipIf(rosbag is None, "python3-rosbag missing")
class EvaluateHoldoutTest(unittest.TestCase):
    """evaluate_holdout with pioneer_nodes.replay replaced by a writer of a known track: the
    robot drives east at 1 m/s, the track 0.5 m ahead of it, from t = 100.066 s (the first
    estimate 66 ms after the first fix, as on the recording of issue 37); fixes every 0.4 s
    from t = 100.0 s on the true path, on the bag's topic /gps/fix."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.bag = os.path.join(self.tmp.name, "in.bag")
        self.calls = []
        self.frame = None
        with rosbag.Bag(self.bag, "w") as bag:
            for k in range(60):
                t = 100.0 + 0.4 * k
                m = NavSatFix()
                m.header.stamp = rospy.Time.from_sec(t)
                m.status.status = 0
                m.latitude, m.longitude, m.altitude = self.latlon(t - 100.0)
                bag.write("/gps/fix", m, rospy.Time.from_sec(t + 0.001))
        self.saved_replay = gh.pioneer_nodes.replay
        gh.pioneer_nodes.replay = self.fake_replay

    def tearDown(self):
        gh.pioneer_nodes.replay = self.saved_replay
        self.tmp.cleanup()

    @staticmethod
    def latlon(east):
        """The point `east` metres east of 49 N 8 E along its parallel (WGS84: the parallel's
        radius is N cos(lat), N the prime vertical radius; a few mm off the tangent plane)."""
        lat = math.radians(49.0)
        n = 6378137.0 / math.sqrt(1.0 - 6.69437999014e-3 * math.sin(lat) ** 2)
        return 49.0, 8.0 + math.degrees(east / (n * math.cos(lat))), 100.0

    def fake_replay(self, exe, bag, csv_path, extra=()):
        self.calls.append((os.path.basename(exe), list(extra)))
        with open(csv_path, "w") as f:
            f.write("time,pose_x,pose_y,pose_heading\n")
            for k in range(3000):
                t = 100.066 + 0.01 * k
                f.write("%.3f,%.6f,0,0\n" % (t, t - 100.0 + 0.5))
        return "summary"

    def test_fixes_before_the_first_estimate_and_the_options(self):
        setup = gh.HoldoutSetup("sf_my_gps", "sf_my_odom", "/gps/fix",
                                gh.replay_args(["odom:=/wheels/odom"],
                                               [["0", "0", "0.2", "0", "0", "0", "base_link",
                                                 "imu"]]),
                                None, yaw_state=None)
        result = gh.evaluate_holdout(self.bag, "/nowhere", self.tmp.name, 5, 10.0, setup)
        transform = ["--static-transform", "0", "0", "0.2", "0", "0", "0", "base_link", "imu"]
        self.assertEqual(self.calls[0], ("sf_my_odom", ["odom:=/wheels/odom"] + transform))
        self.assertEqual(self.calls[1][0], "sf_my_gps")
        self.assertEqual(self.calls[1][1][2:], ["odom:=/wheels/odom"] + transform)
        self.assertEqual(result["left_out"], 48)  # 60 fixes, every 5th fused
        self.assertAlmostEqual(result["yaw_offset"], 0.0, places=3)  # both east
        by_label = {r["label"]: r for r in result["rows"]}
        # The fused fix at 100.0 s lies before the track: left out of the fit, which moves the
        # track back by its 0.5 m; every held-out fix lies inside the track and is compared.
        fit = by_label["no GPS, best fit on the fused fixes"]
        self.assertEqual(fit["n"], 48)
        self.assertLess(fit["rmse"], 0.01)
        self.assertAlmostEqual(by_label["no GPS, same frame (`sf_my_odom`)"]["rmse"], 0.5,
                               delta=0.01)

    def test_user_parameters_go_to_both_replays_and_keep_the_measured_offset(self):
        params = os.path.join(self.tmp.name, "user.yaml")
        with open(params, "w") as f:
            f.write("max_measurement_lag: 0.05\ngps_yaw_offset: 1.0\n")
        setup = gh.HoldoutSetup(fix_topic="/gps/fix", params=params, yaw_state=None)
        gh.evaluate_holdout(self.bag, "/nowhere", self.tmp.name, 5, 10.0, setup)
        self.assertEqual(self.calls[0][1], ["--params", params])
        with open(os.path.join(self.tmp.name, "gps.yaml")) as f:
            written = f.read().splitlines()
        self.assertEqual(written[0], "max_measurement_lag: 0.05")
        self.assertEqual(len(written), 2)
        self.assertAlmostEqual(float(written[1].split(":")[1]), 0.0, places=3)

    def test_yaw_and_error_states_give_the_predicted_fix_without_a_fit(self):
        # The GPS node's CSV holds its yaw state (x8, 90 deg: the odom x axis points north)
        # and the fixes' offset (x9 + x11 = 0.3 m east, x10 + x12 = -0.4 m north: the slow
        # error and the start about the datum, the header's states); its pose runs along odom
        # -y, i.e. east, 0.5 m ahead of the robot. Its position in ENU is 0.5 m east of each
        # fix, its predicted fix 0.8 m east and 0.4 m south. Nothing is written for
        # ~gps_yaw_offset and the replay gets no --params.
        def state_replay(exe, bag, csv_path, extra=()):
            self.calls.append((os.path.basename(exe), list(extra)))
            with open(csv_path, "w") as f:
                f.write("time,pose_x,pose_y,pose_heading,x8,x9,x10,x11,x12\n")
                for k in range(3000):
                    t = 100.066 + 0.01 * k
                    f.write("%.3f,0,%.6f,0,%.9f,0.1,-0.5,0.2,0.1\n"
                            % (t, -(t - 100.0 + 0.5), math.pi / 2))
            return "summary"

        gh.pioneer_nodes.replay = state_replay
        setup = gh.HoldoutSetup("sf_my_gps", "sf_my_odom", "/gps/fix")
        result = gh.evaluate_holdout(self.bag, "/nowhere", self.tmp.name, 5, 10.0, setup)
        self.assertFalse(os.path.exists(os.path.join(self.tmp.name, "gps.yaml")))
        self.assertEqual(self.calls[1][1], [])
        self.assertAlmostEqual(result["yaw_state"], math.pi / 2)
        by_label = {r["label"]: r for r in result["rows"]}
        predicted = by_label["GPS node, predicted fix (`sf_my_gps`)"]
        self.assertAlmostEqual(predicted["rmse"], math.hypot(0.8, 0.4), delta=0.01)
        self.assertAlmostEqual(by_label["GPS node, position (`sf_my_gps`)"]["rmse"], 0.5,
                               delta=0.01)
        self.assertIsNone(predicted["truth_rmse"])

    def test_bad_options_are_refused(self):
        with self.assertRaises(ValueError):
            gh.replay_args(["odom"], [])
        with self.assertRaises(ValueError):
            gh.replay_args([], [["0", "0", "x", "0", "0", "0", "a", "b"]])


if __name__ == "__main__":
    unittest.main()
