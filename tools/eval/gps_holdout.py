#!/usr/bin/python3
"""GPS fused at a reduced rate, measured on the fixes that were not fused.

Usage:
  gps_holdout.py [--bag bags/husky_gps.bag] [--every 5] [--calibration 10] [--lib-dir DIR]
                 [--out-dir DIR] [--plot OUT.png] [--node NODE] [--baseline-node NODE]
                 [--fix-topic /fix] [--remap FROM:=TO]... [--params FILE.yaml]
                 [--static-transform X Y Z YAW PITCH ROLL PARENT CHILD]...
                 [--yaw-state 8] [--error-states 9,11 10,12] [--fitted-yaw]
                 [--truth-topic TOPIC --truth-heading DEG]

The valid fixes of the bag's /fix (sensor_msgs/NavSatFix, status >= STATUS_FIX) are split:
fix k is *fused* when k % EVERY == 0 (fix 0, the datum, is fused), *held out* otherwise. A
copy of the bag without the held-out fixes (every other message byte for byte) is replayed
through the GPS node (sf_husky_skid_steer_gps, config/husky_skid_steer_gps.h), and the same
bag whole through the odometry + IMU node without GPS (sf_husky_skid_steer_ekf).

The GPS node (config/husky_skid_steer_gps.h) estimates the yaw between ENU and its odom
frame, the fixes' slowly changing error and the start's position about the datum as
states (--yaw-state 8; --error-states 9,11 10,12, east and north, whose sums are the
fixes' offset from the odom origin); nothing is fitted for it. Each track is compared with the held-out fixes in ENU
about the datum (the first fused fix), at their header stamps (estimate interpolated
linearly), with no further fitting. Printed after a header (the split, the fitted yaw
offset, what the fixes' position_covariance holds: types, entries off the diagonal,
unequal east and north variances) as a markdown table: per track the fixes compared and
the RMSE, maximum and final horizontal error [m] on the held-out fixes, and the RMSE on the
fused ones; rows:
  GPS node, predicted fix  its pose turned into ENU by its yaw state plus the fixes'
                           offset states: what it predicts the next fix to be
  GPS node, position       its pose turned into ENU by its yaw state (where the robot is)
  no GPS, same frame       the odometry + IMU node turned into ENU by the yaw offset that
                           fits it best onto the fused fixes of the first CALIBRATION
                           seconds (gps_reference.fit_rigid_2d; a diagnostic, and the only
                           frame this track has)
  no GPS, best fit         the same track after its best rotation and shift onto the fused
                           fixes (all of them: a batch alignment no online filter has)
  fused fixes held         the last fused fix held until the next one (what the GPS alone
                           gives between fused fixes)
--fitted-yaw replays a GPS node without those states (the header before issue 37) with the
fitted offset as ~gps_yaw_offset (in a --params file) and gives one "GPS node" row.

A simulated recording (tools/sim/diff_drive_sim.py --gps) has its true pose: --truth-topic
ground_truth/pose --truth-heading DEG (the simulator's --gps-heading) adds the RMSE against
the truth, at the fixes' stamps, of the rows that are positions (the truth turned into ENU
about the start, where the odom frames start).

Another robot's recording: --node and --baseline-node name the GPS node and the node without
GPS (built from the user's headers), --fix-topic the bag's NavSatFix topic, and --remap,
--static-transform and --params go to both replays as to the node's own --replay (the
configured topic FROM read from the bag's TO; a transform the bag lacks; a YAML of private
parameters, to which --fitted-yaw adds gps_yaw_offset). Fixes before
the first estimate or after the last (a fix recorded 66 ms before the odometry) are left out
of the comparisons and the fits.

The executables are found as real_robot_report.py finds them (--lib-dir, else the sourced
devel space, else $SF_WS/devel). Needs python3-rosbag, and python3-matplotlib for --plot.
The core functions (split_fixes, to_odom, to_enu, held_track, holdout_errors) are pure and
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
YAW_STATE = 8  # config/husky_skid_steer_gps.h: the heading of the odom x axis in ENU
# and the offset of the fixes from the odom origin, east and north: the sum of the states
# listed (the receiver's slow error and the start about the datum)
ERROR_STATES = ((9, 11), (10, 12))


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


def to_enu(x, y, yaw):
    """(east, north) of an odom-frame point whose x axis has heading yaw in ENU (the inverse
    of to_odom)."""
    c, s = math.cos(yaw), math.sin(yaw)
    return c * x - s * y, s * x + c * y


def enu_points(frame, fixes):
    """[(t, east, north)] of fixes (t, status, lat, lon, alt) about `frame`'s datum."""
    return [(t,) + tuple(frame.enu(lat, lon, alt)[:2]) for t, _, lat, lon, alt in fixes]


def rotated_track(track, yaw):
    """The Trajectory `track` (odom frame) turned into ENU by the yaw offset (to_enu)."""
    points = [to_enu(x, y, yaw) for x, y in zip(track.x, track.y)]
    return ev.make_trajectory(track.t, [p[0] for p in points], [p[1] for p in points])


def state_tracks(csv_path, yaw_state, error_states, prefix=""):
    """(position, predicted fix, final yaw) of a GPS node whose state holds the yaw offset
    (column x<yaw_state>) and the offset of the fixes from its odom origin (east: the sum of
    the states error_states[0], north: of error_states[1]): its pose turned into ENU, that
    plus the offset (what it predicts the next fix to be), and the last yaw [rad]. `prefix`:
    the columns of another track of the CSV (smoothed_ of --smooth)."""
    east, north = ([prefix + "x%d" % i for i in axis] for axis in error_states)
    names = [prefix + "pose_x", prefix + "pose_y", prefix + "x%d" % yaw_state] + east + north
    t, c = ev.read_csv_columns(csv_path, names)
    rows = [r for r in zip(t, *(c[n] for n in names)) if all(map(math.isfinite, r))]
    if not rows:
        raise ValueError("%s: no finite row" % csv_path)
    times, pe, pn, fe, fn = [], [], [], [], []
    for r in rows:
        e, n = to_enu(r[1], r[2], r[3])
        times.append(r[0])
        pe.append(e)
        pn.append(n)
        fe.append(e + sum(r[4:4 + len(east)]))
        fn.append(n + sum(r[4 + len(east):]))
    return (ev.make_trajectory(times, pe, pn), ev.make_trajectory(times, fe, fn), rows[-1][3])


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
                 replay_args=(), params=None, yaw_state=YAW_STATE, error_states=ERROR_STATES):
        self.node, self.baseline_node, self.fix_topic = node, baseline_node, fix_topic
        # the GPS node's state indices of the yaw offset and of the fixes' error (east,
        # north); yaw_state None: a node without them, given the fitted ~gps_yaw_offset
        self.yaw_state, self.error_states = yaw_state, tuple(map(tuple, error_states))
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


def _rows(tracks, fused_pts, held_pts, truth_pts):
    """One dict per (label, track, compare_with_truth): label, track, n (held-out fixes
    compared), rmse, max, final, fused_rmse [m] and truth_rmse [m] (None without truth)."""
    rows = []
    for label, track, position in tracks:
        errors = holdout_errors(track, held_pts)
        rmse, emax, final = gr.error_stats(errors)
        truth_rmse = None
        if truth_pts and position:
            truth_rmse = ev.rmse(holdout_errors(track, truth_pts))
        rows.append({"label": label, "track": track, "n": len(errors), "rmse": rmse,
                     "max": emax, "final": final, "truth_rmse": truth_rmse,
                     "fused_rmse": ev.rmse(holdout_errors(track, fused_pts))})
    return rows


def _replay_gps_node(bag, lib_dir, out_dir, fused, setup, yaw_offset):
    """Replays the GPS node on the bag without the held-out fixes; (left_out, summary, CSV
    path). Without a yaw state the node is given the fitted yaw offset (gps_params)."""
    reduced = os.path.join(out_dir, "fused_fixes.bag")
    left_out = write_reduced_bag(bag, reduced, [f[0] for f in fused], setup.fix_topic)
    args = (["--params", setup.params] if setup.params else []) + setup.replay_args
    if setup.yaw_state is None:
        params = os.path.join(out_dir, "gps.yaml")
        gps_params(params, yaw_offset, setup.params)
        args = ["--params", params] + setup.replay_args
    gps_csv = os.path.join(out_dir, setup.node + ".csv")
    summary = pioneer_nodes.replay(os.path.join(lib_dir, setup.node), reduced, gps_csv, args)
    return left_out, summary, gps_csv


def evaluate_holdout(bag, lib_dir, out_dir, every=5, calibration=10.0, setup=None, truth=None):
    """Replays and compares as described above (`setup`: a HoldoutSetup, the shipped Husky
    nodes by default; `truth`: the true track in ENU about the start, or None). Returns a
    dict: fixes (valid), fused and held ([(t, east, north)] about the datum), left_out
    (messages left out of the copy), yaw_offset [rad] (fitted, see above), yaw_state [rad]
    (the GPS node's final yaw state, None without), summary (the GPS node's replay output)
    and rows (_rows)."""
    setup = setup or HoldoutSetup()
    fused, held = split_fixes(gr.read_fixes(bag, setup.fix_topic), every)
    frame = gr.LocalFrame(fused[0][2], fused[0][3], fused[0][4])
    fused_pts, held_pts = enu_points(frame, fused), enu_points(frame, held)
    user = (["--params", setup.params] if setup.params else []) + setup.replay_args

    base_csv = os.path.join(out_dir, setup.baseline_node + ".csv")
    pioneer_nodes.replay(os.path.join(lib_dir, setup.baseline_node), bag, base_csv, user)
    base = ev.load_result_csv(base_csv)
    yaw_offset = calibrate_yaw_offset(base, fused_pts, calibration)
    left_out, summary, gps_csv = _replay_gps_node(bag, lib_dir, out_dir, fused, setup,
                                                  yaw_offset)
    node = "`%s`" % setup.node
    if setup.yaw_state is None:
        gps = [("GPS node (%s)" % node, rotated_track(ev.load_result_csv(gps_csv), yaw_offset),
                True)]
        final_yaw = None
    else:
        position, predicted, final_yaw = state_tracks(gps_csv, setup.yaw_state,
                                                      setup.error_states)
        gps = [("GPS node, predicted fix (%s)" % node, predicted, False),
               ("GPS node, position (%s)" % node, position, True)]
    truth_pts = None
    if truth is not None:
        truth_pts = [(t,) + ev.interpolate(truth, t)[:2] for t, _, _ in fused_pts + held_pts
                     if ev.interpolate(truth, t) is not None]
    tracks = gps + [("no GPS, same frame (`%s`)" % setup.baseline_node,
                     rotated_track(base, yaw_offset), True),
                    ("no GPS, best fit on the fused fixes", best_fit_track(base, fused_pts),
                     False),
                    ("fused fixes held", held_track(fused_pts), False)]
    return {"fixes": len(fused) + len(held), "fused": fused_pts, "held": held_pts,
            "left_out": left_out, "yaw_offset": yaw_offset, "yaw_state": final_yaw,
            "summary": summary, "rows": _rows(tracks, fused_pts, held_pts, truth_pts)}


def _parser():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    parser.add_argument("--bag", default=os.path.join(REPO, "bags", "husky_gps.bag"))
    parser.add_argument("--every", type=int, default=5, help="fuse every N-th fix (default 5)")
    parser.add_argument("--calibration", type=float, default=10.0,
                        help="seconds of fused fixes the yaw offset is fitted on (default 10)")
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
    parser.add_argument("--yaw-state", type=int, default=YAW_STATE,
                        help="the GPS node's state index of the yaw offset (default %(default)s)")
    parser.add_argument("--error-states", type=_indices, nargs=2, default=list(ERROR_STATES),
                        metavar=("EAST", "NORTH"),
                        help="its state indices whose sum is the fixes' offset from its odom "
                        "origin, east and north (default 9,11 10,12)")
    parser.add_argument("--fitted-yaw", action="store_true",
                        help="a GPS node without these states: give it the fitted yaw offset")
    parser.add_argument("--truth-topic", help="the bag's true pose (a simulated recording)")
    parser.add_argument("--truth-heading", type=float, default=0.0,
                        help="the heading [deg] in ENU of the true pose's x axis")
    return parser


def _indices(text):
    try:
        return tuple(int(v) for v in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError("expected state indices I[,J...], found %r" % text)


def _print_table(rows):
    truth = any(r["truth_rmse"] is not None for r in rows)
    print("| track | held-out fixes | RMSE [m] | max [m] | final [m] | RMSE on fused fixes [m] |"
          + (" RMSE against truth [m] |" if truth else ""))
    print("| --- " * (7 if truth else 6) + "|")
    for row in rows:
        line = "| %s | %d | %.2f | %.2f | %.2f | %.2f |" % (
            row["label"], row["n"], row["rmse"], row["max"], row["final"], row["fused_rmse"])
        if truth:
            line += " %s |" % ("%.2f" % row["truth_rmse"] if row["truth_rmse"] is not None
                               else "")
        print(line)


def main(argv=None):
    parser = _parser()
    args = parser.parse_args(argv)
    try:
        setup = HoldoutSetup(args.node, args.baseline_node, args.fix_topic,
                             replay_args(args.remap, args.static_transform), args.params,
                             None if args.fitted_yaw else args.yaw_state, args.error_states)
    except ValueError as e:
        parser.error(str(e))
    truth = None
    if args.truth_topic:
        truth = rotated_track(ev.load_truth(args.bag, args.truth_topic),
                              math.radians(args.truth_heading))

    # tmp keeps a temporary out_dir until main returns.
    lib_dir, out_dir, tmp = pioneer_nodes.husky_dirs(args.lib_dir, args.out_dir)  # noqa: F841
    if not lib_dir:
        return 2

    result = evaluate_holdout(args.bag, lib_dir, out_dir, args.every, args.calibration, setup,
                              truth)
    print("# %s: %d valid fixes, %d fused (every %d), %d held out; %d %s messages left out "
          "of the replayed copy" % (os.path.basename(args.bag), result["fixes"],
                                    len(result["fused"]), args.every, len(result["held"]),
                                    result["left_out"], args.fix_topic))
    print("# yaw offset fitted on the fused fixes of the first %g s: %.2f deg%s" % (
        args.calibration, math.degrees(result["yaw_offset"]),
        "" if result["yaw_state"] is None else
        " (a diagnostic; the GPS node's yaw state ends at %.2f deg)"
        % math.degrees(result["yaw_state"])))
    covariances = gr.covariance_summary(gr.read_covariances(args.bag, args.fix_topic))
    print("# fix covariances: %s; %d with entries off the diagonal, %d with unequal east and "
          "north variances" % (", ".join("%d %s" % (n, t) for t, n in
                                         sorted(covariances["types"].items())),
                               covariances["off_diagonal"], covariances["unequal_en"]))
    print("# %s replay: %s" % (args.node, result["summary"].replace("\n", "\n#   ")))
    print()
    _print_table(result["rows"])
    if args.plot:
        plot(args.plot, [(r["label"], r["track"]) for r in result["rows"]], result["fused"],
             result["held"])
    return 0


def plot(path, rows, fused_pts, held_pts):
    plt = ev._pyplot()
    fig, ax = plt.subplots(figsize=(7, 6))
    for label, track in rows:
        if label == "fused fixes held":
            continue
        ax.plot(track.x, track.y, label=label.replace("`", ""))
    ax.plot([p[1] for p in held_pts], [p[2] for p in held_pts], "k.", ms=4, label="held-out fixes")
    ax.plot([p[1] for p in fused_pts], [p[2] for p in fused_pts], "rs", ms=6, mfc="none",
            label="fused fixes")
    ax.set_xlabel("east [m]")
    ax.set_ylabel("north [m]")
    ax.set_aspect("equal")
    ax.grid(True)
    ax.legend(fontsize=8, loc="lower left")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())
