#!/usr/bin/python3
"""GPS fused at a reduced rate, measured on the fixes that were not fused.

Usage:
  gps_holdout.py [--bag bags/husky_gps.bag] [--every 5] [--calibration 10] [--lib-dir DIR]
                 [--out-dir DIR] [--plot OUT.png] [--node NODE] [--baseline-node NODE]
                 [--fix-topic /fix] [--remap FROM:=TO]... [--params FILE.yaml]
                 [--static-transform X Y Z YAW PITCH ROLL PARENT CHILD]...

The valid fixes of the bag's /fix (sensor_msgs/NavSatFix, status >= STATUS_FIX) are split:
fix k is *fused* when k % EVERY == 0 (fix 0, the datum, is fused), *held out* otherwise. A
copy of the bag without the held-out fixes (every other message byte for byte) is replayed
through the GPS node (sf_husky_skid_steer_gps, config/husky_skid_steer_gps.h), and the same
bag whole through the odometry + IMU node without GPS (sf_husky_skid_steer_ekf).

The GPS node needs ~gps_yaw_offset, the heading in ENU of the odom frame's x axis (the
recording has no absolute heading). It is measured from fused fixes only: the rotation
that fits the no-GPS track best onto the fused fixes of the first CALIBRATION seconds
(gps_reference.fit_rigid_2d, rotation and shift); it is passed to the replay in a --params
file.

Every fix is taken into that odom frame, about the datum and turned by the offset
(to_odom), and each track is compared with the held-out fixes there, at their header stamps
(estimate interpolated linearly), with no further fitting. Printed after a header (the
split, the yaw offset, what the fixes' position_covariance holds: types, entries off the
diagonal, unequal east and north variances) as a markdown table:
per track the fixes compared and the RMSE, maximum and final horizontal error [m] on the
held-out fixes, and the RMSE on the fused ones; rows:
  GPS node            the replay with the fused fixes
  no GPS, same frame  the odometry + IMU node, in the calibrated frame
  no GPS, best fit    the same track after its best rotation and shift onto the fused fixes
                      (all of them: a batch alignment no online filter has)
  fused fixes held    the last fused fix held until the next one (what the GPS alone gives
                      between fused fixes)

Another robot's recording: --node and --baseline-node name the GPS node and the node without
GPS (built from the user's headers), --fix-topic the bag's NavSatFix topic, and --remap,
--static-transform and --params go to both replays as to the node's own --replay (the
configured topic FROM read from the bag's TO; a transform the bag lacks; a YAML of private
parameters, to which the GPS node's replay adds its own with gps_yaw_offset). Fixes before
the first estimate or after the last (a fix recorded 66 ms before the odometry) are left out
of the comparisons and the fits.

The executables are found as real_robot_report.py finds them (--lib-dir, else the sourced
devel space, else $SF_WS/devel). Needs python3-rosbag, and python3-matplotlib for --plot.
The core functions (split_fixes, to_odom, held_track, holdout_errors) are pure and
unit-tested in test/eval/test_gps_holdout.py.
"""

import argparse
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import evaluate as ev  # noqa: E402
import gps_reference as gr  # noqa: E402
import pioneer_nodes  # noqa: E402

GPS_NODE = "sf_husky_skid_steer_gps"
BASELINE_NODE = "sf_husky_skid_steer_ekf"


def split_fixes(fixes, every):
    """(fused, held): the valid fixes (t, status, lat, lon, alt) in order, fix k fused when
    k % every == 0, held out otherwise. Invalid fixes (gps_reference.valid_fix) are in
    neither."""
    if every < 2:
        raise ValueError("every must be at least 2 (1 would hold no fix out)")
    valid = [f for f in fixes if gr.valid_fix(f[1], f[2], f[3])]
    if not valid:
        raise ValueError("no valid fix")
    fused = [f for k, f in enumerate(valid) if k % every == 0]
    held = [f for k, f in enumerate(valid) if k % every != 0]
    return fused, held


def to_odom(east, north, yaw_offset):
    """(x, y) in the odom frame of an ENU point, the odom x axis at heading yaw_offset in ENU
    (counter-clockwise from east), as the node's GPS input turns it."""
    c, s = math.cos(yaw_offset), math.sin(yaw_offset)
    return c * east + s * north, -s * east + c * north


def odom_points(frame, fixes, yaw_offset):
    """[(t, x, y)] of fixes (t, status, lat, lon, alt) in the odom frame about `frame`'s datum."""
    out = []
    for t, _, lat, lon, alt in fixes:
        e, n, _ = frame.enu(lat, lon, alt)
        x, y = to_odom(e, n, yaw_offset)
        out.append((t, x, y))
    return out


def held_track(points):
    """The Trajectory that holds each point [(t, x, y)] until the next one."""
    t, x, y = [], [], []
    for k, (tk, xk, yk) in enumerate(points):
        t.append(tk)
        x.append(xk)
        y.append(yk)
        if k + 1 < len(points):
            t.append(points[k + 1][0] - 1e-6)
            x.append(xk)
            y.append(yk)
    return ev.make_trajectory(t, x, y)


def holdout_errors(track, points, tolerance=ev.DEFAULT_TIME_TOLERANCE):
    """Horizontal errors [m] of the Trajectory `track` at the points [(t, x, y)] inside its
    time range (interpolated linearly, no alignment)."""
    errors = []
    for t, x, y in points:
        p = ev.interpolate(track, t, tolerance)
        if p is not None:
            errors.append(math.hypot(p[0] - x, p[1] - y))
    if not errors:
        raise ValueError("no point inside the track's time range")
    return errors


def calibrate_yaw_offset(track, fused_points, seconds):
    """The rotation [rad] of the best rigid fit of `track` onto the fused points of the first
    `seconds` (at least two points)."""
    t0 = fused_points[0][0]
    early = [p for p in fused_points if p[0] - t0 <= seconds]
    if len(early) < 2:
        raise ValueError("fewer than 2 fused fixes in the first %g s" % seconds)
    src, dst = [], []
    for t, x, y in early:
        p = ev.interpolate(track, t)
        if p is not None:
            src.append((p[0], p[1]))
            dst.append((x, y))
    return gr.fit_rigid_2d(src, dst)[0]


def best_fit_track(track, points):
    """`track` moved by its best rotation and shift onto the points [(t, x, y)] inside its
    time range (at least two)."""
    src, dst = [], []
    for t, x, y in points:
        p = ev.interpolate(track, t)
        if p is not None:
            src.append(p[:2])
            dst.append((x, y))
    if len(src) < 2:
        raise ValueError("fewer than 2 fused fixes inside the track's time range")
    moved = gr.apply_rigid_2d(gr.fit_rigid_2d(src, dst), list(zip(track.x, track.y)))
    return ev.make_trajectory(track.t, [p[0] for p in moved], [p[1] for p in moved])


class HoldoutSetup:
    """Which nodes replay the recording, and what both replays are given."""

    def __init__(self, node=GPS_NODE, baseline_node=BASELINE_NODE, fix_topic="/fix",
                 replay_args=(), params=None):
        self.node, self.baseline_node, self.fix_topic = node, baseline_node, fix_topic
        self.replay_args = list(replay_args)  # remaps and --static-transform, as --replay takes
        self.params = params  # a YAML of private parameters, or None


def replay_args(remaps, transforms):
    """The replay's arguments for remaps ["FROM:=TO"] and transforms [[X, Y, Z, YAW, PITCH,
    ROLL, PARENT, CHILD]] (checked: FROM:=TO with both names, six numbers)."""
    args = []
    for remap in remaps:
        source, sep, target = remap.partition(":=")
        if not sep or not source or not target:
            raise ValueError("--remap %r: expected FROM:=TO" % remap)
        args.append(remap)
    for t in transforms:
        for value in t[:6]:
            float(value)  # ValueError names the value
        args += ["--static-transform"] + list(t)
    return args


def gps_params(path, yaw_offset, user_params=None):
    """Writes the GPS node's parameter file: the user's YAML (if any) and gps_yaw_offset."""
    text = ""
    if user_params:
        with open(user_params) as f:
            text = "\n".join(line for line in f.read().splitlines()
                             if not line.strip().startswith("gps_yaw_offset:")) + "\n"
    with open(path, "w") as f:
        f.write(text + "gps_yaw_offset: %.9f\n" % yaw_offset)


def write_reduced_bag(in_path, out_path, keep_stamps, topic="/fix"):
    """Copies in_path to out_path without the messages of `topic` whose header stamp is not in
    keep_stamps (raw bytes and connection headers kept); returns the number left out."""
    import rosbag  # Debian: python3-rosbag

    left_out = 0
    keep = {round(s, 6) for s in keep_stamps}
    with rosbag.Bag(in_path) as src, rosbag.Bag(out_path, "w") as dst:
        for name, raw, t, header in src.read_messages(raw=True, return_connection_header=True):
            if name in ev._topic_variants(topic):
                stamp = _fix_stamp(raw, t)
                if round(stamp, 6) not in keep:
                    left_out += 1
                    continue
            dst.write(name, raw, t, raw=True, connection_header=header)
    return left_out


def _fix_stamp(raw, t):
    """The header stamp [s] of a raw NavSatFix (as gps_reference.read_fixes takes it)."""
    msg_type = raw[4]
    msg = msg_type()
    msg.deserialize(raw[1])
    stamp = msg.header.stamp if (msg.header.stamp.secs or msg.header.stamp.nsecs) else t
    return stamp.to_sec()


def evaluate_holdout(bag, lib_dir, out_dir, every=5, calibration=10.0, setup=None):
    """Replays and compares as described above (`setup`: a HoldoutSetup, the shipped Husky
    nodes by default). Returns a dict: fixes (valid), fused and held ([(t, x, y)] in the odom
    frame), left_out (messages left out of the copy), yaw_offset [rad], summary (the GPS
    node's replay output) and rows, one dict per track: label, track, n (held-out fixes
    compared), rmse, max, final, fused_rmse [m]."""
    setup = setup or HoldoutSetup()
    fixes = gr.read_fixes(bag, setup.fix_topic)
    fused, held = split_fixes(fixes, every)
    frame = gr.LocalFrame(fused[0][2], fused[0][3], fused[0][4])
    user = (["--params", setup.params] if setup.params else []) + setup.replay_args

    base_csv = os.path.join(out_dir, setup.baseline_node + ".csv")
    pioneer_nodes.replay(os.path.join(lib_dir, setup.baseline_node), bag, base_csv, user)
    base = ev.load_result_csv(base_csv)
    yaw_offset = calibrate_yaw_offset(base, odom_points(frame, fused, 0.0), calibration)

    reduced = os.path.join(out_dir, "fused_fixes.bag")
    left_out = write_reduced_bag(bag, reduced, [f[0] for f in fused], setup.fix_topic)
    params = os.path.join(out_dir, "gps.yaml")
    gps_params(params, yaw_offset, setup.params)
    gps_csv = os.path.join(out_dir, setup.node + ".csv")
    summary = pioneer_nodes.replay(os.path.join(lib_dir, setup.node), reduced, gps_csv,
                                   ["--params", params] + setup.replay_args)
    gps_track = ev.load_result_csv(gps_csv)

    fused_pts = odom_points(frame, fused, yaw_offset)
    held_pts = odom_points(frame, held, yaw_offset)
    rows = []
    for label, track in (("GPS node (`%s`)" % setup.node, gps_track),
                         ("no GPS, same frame (`%s`)" % setup.baseline_node, base),
                         ("no GPS, best fit on the fused fixes", best_fit_track(base, fused_pts)),
                         ("fused fixes held", held_track(fused_pts))):
        errors = holdout_errors(track, held_pts)
        rmse, emax, final = gr.error_stats(errors)
        rows.append({"label": label, "track": track, "n": len(errors), "rmse": rmse,
                     "max": emax, "final": final,
                     "fused_rmse": ev.rmse(holdout_errors(track, fused_pts))})
    return {"fixes": len(fused) + len(held), "fused": fused_pts, "held": held_pts,
            "left_out": left_out, "yaw_offset": yaw_offset, "summary": summary, "rows": rows}


def main(argv=None):
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    parser.add_argument("--bag", default=os.path.join(REPO, "bags", "husky_gps.bag"))
    parser.add_argument("--every", type=int, default=5, help="fuse every N-th fix (default 5)")
    parser.add_argument("--calibration", type=float, default=10.0,
                        help="seconds of fused fixes the yaw offset is measured on (default 10)")
    parser.add_argument("--lib-dir", help="where the sf_husky_* executables are")
    parser.add_argument("--out-dir", help="keep the bag, parameters and CSVs here")
    parser.add_argument("--plot", help="write the tracks and fixes (PNG)")
    parser.add_argument("--node", default=GPS_NODE, help="the GPS node (default %(default)s)")
    parser.add_argument("--baseline-node", default=BASELINE_NODE,
                        help="the node without GPS (default %(default)s)")
    parser.add_argument("--fix-topic", default="/fix", help="the bag's NavSatFix topic")
    parser.add_argument("--remap", action="append", default=[], metavar="FROM:=TO",
                        help="read the configured topic FROM from the bag's TO (both replays)")
    parser.add_argument("--static-transform", action="append", nargs=8, default=[],
                        metavar=("X", "Y", "Z", "YAW", "PITCH", "ROLL", "PARENT", "CHILD"),
                        help="a transform the bag lacks (both replays)")
    parser.add_argument("--params", help="a YAML of private parameters (both replays)")
    args = parser.parse_args(argv)
    try:
        setup = HoldoutSetup(args.node, args.baseline_node, args.fix_topic,
                             replay_args(args.remap, args.static_transform), args.params)
    except ValueError as e:
        parser.error(str(e))

    # tmp keeps a temporary out_dir until main returns.
    lib_dir, out_dir, tmp = pioneer_nodes.husky_dirs(args.lib_dir, args.out_dir)  # noqa: F841
    if not lib_dir:
        return 2

    result = evaluate_holdout(args.bag, lib_dir, out_dir, args.every, args.calibration, setup)
    print("# %s: %d valid fixes, %d fused (every %d), %d held out; %d /fix messages left out "
          "of the replayed copy" % (os.path.basename(args.bag), result["fixes"],
                                    len(result["fused"]), args.every, len(result["held"]),
                                    result["left_out"]))
    print("# yaw offset from the fused fixes of the first %g s: %.2f deg" %
          (args.calibration, math.degrees(result["yaw_offset"])))
    covariances = gr.covariance_summary(gr.read_covariances(args.bag, args.fix_topic))
    print("# fix covariances: %s; %d with entries off the diagonal, %d with unequal east and "
          "north variances" % (", ".join("%d %s" % (n, t) for t, n in
                                         sorted(covariances["types"].items())),
                               covariances["off_diagonal"], covariances["unequal_en"]))
    print("# %s replay: %s" % (args.node, result["summary"].replace("\n", "\n#   ")))
    print()
    print("| track | held-out fixes | RMSE [m] | max [m] | final [m] | RMSE on fused fixes [m] |")
    print("| --- | --- | --- | --- | --- | --- |")
    for row in result["rows"]:
        print("| %s | %d | %.2f | %.2f | %.2f | %.2f |" % (
            row["label"], row["n"], row["rmse"], row["max"], row["final"], row["fused_rmse"]))
    if args.plot:
        plot(args.plot, [(r["label"], r["track"]) for r in result["rows"]], result["fused"],
             result["held"])
    return 0


def plot(path, rows, fused_pts, held_pts):
    plt = ev._pyplot()
    fig, ax = plt.subplots(figsize=(7, 6))
    for label, track in rows[:3]:
        ax.plot(track.x, track.y, label=label.replace("`", ""))
    ax.plot([p[1] for p in held_pts], [p[2] for p in held_pts], "k.", ms=4, label="held-out fixes")
    ax.plot([p[1] for p in fused_pts], [p[2] for p in fused_pts], "rs", ms=6, mfc="none",
            label="fused fixes")
    ax.set_xlabel("x (odom) [m]")
    ax.set_ylabel("y (odom) [m]")
    ax.set_aspect("equal")
    ax.grid(True)
    ax.legend(fontsize=8, loc="lower left")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())
