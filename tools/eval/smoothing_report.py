#!/usr/bin/python3
"""Filtered, fixed-lag and smoothed tracks of the shipped nodes on the shipped bags with ground
truth: position and heading RMSE per track, as the table of doc/smoothing.md ("Results").

  smoothing_report.py [--lib-dir DIR] [--lags L1,L2,...] [--markdown] [--only LABEL ...]

Per case it replays the node three ways on its bag: `--smooth` (the filtered columns and the
full Rauch-Tung-Striebel pass's smoothed_* columns), `--smooth-lag L` for each lag L in
seconds (the lagged_* columns; 0.01, 0.05, 0.2 and 1 s for the soccer KF, whose period is
1 ms, 0.1, 0.5, 2 and 10 s for the robots; --lags sets them for all), and `--smooth batch` when the node offers it (the batch
maximum-a-posteriori track; a node without it gets "-"). Every track is compared with the
bag's ground truth (tools/eval/evaluate.py) on the same periods: those up to the recording's
end minus the largest lag, where every lagged track has a value. Prints one row per case and
track kind (position RMSE [m], heading RMSE [deg] where the node has a heading).
"""

import argparse
import math
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import evaluate  # noqa: E402
import pioneer_nodes  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# (label, node, bag, pose columns without their prefix, lags [s]): the shipped bags that have
# ground truth, each with the node made for it (doc/bags.md). The soccer KF has no heading;
# its period is 1 ms, so its lags are shorter (a lag costs O(lag) per period).
SOCCER_LAGS = (0.01, 0.05, 0.2, 1.0)
ROBOT_LAGS = (0.1, 0.5, 2.0, 10.0)
POSE = ("pose_x", "pose_y", "pose_heading")
CASES = [
    ("soccer KF, soccer_seed1", "sf_soccer_kf", "bags/soccer_seed1.bag", ("x0", "x1"),
     SOCCER_LAGS),
    ("soccer KF, soccer_lost_vision", "sf_soccer_kf", "bags/soccer_lost_vision.bag",
     ("x0", "x1"), SOCCER_LAGS),
    ("soccer KF, soccer_lost_vision_ideal", "sf_soccer_kf", "bags/soccer_lost_vision_ideal.bag",
     ("x0", "x1"), SOCCER_LAGS),
    ("diff-drive EKF, diff_drive_seed1", "sf_diff_drive_odom_imu", "bags/diff_drive_seed1.bag",
     POSE, ROBOT_LAGS),
    ("Pioneer skid-steer EKF, pioneer_seed1", "sf_pioneer_skid_steer_ekf",
     "bags/pioneer_seed1.bag", POSE, ROBOT_LAGS),
    ("Pioneer nav3ctrl EKF, pioneer_seed1", "sf_nav3ctrl_ekf", "bags/pioneer_seed1.bag", POSE,
     ROBOT_LAGS),
]


def columns(prefix, pose):
    """The pose columns of a track: filtered (no prefix), smoothed_, lagged_."""
    return [prefix + c for c in pose]


def cut(track, end):
    """The part of `track` up to time `end`."""
    keep = [k for k, t in enumerate(track.t) if t <= end]
    pick = lambda values: [values[k] for k in keep] if values is not None else None
    return evaluate.make_trajectory(pick(track.t), pick(track.x), pick(track.y),
                                    pick(track.heading))


def tracks_of(exe, bag, pose, lags, tmp):
    """{kind: Trajectory} of one node on one bag: filtered, lag L, smoothed, batch MAP."""
    full = os.path.join(tmp, "smooth.csv")
    pioneer_nodes.replay(exe, bag, full, ["--smooth"], timeout=600)
    tracks = {"filtered": evaluate.load_result_csv(full, columns("", pose))}
    for lag in lags:
        path = os.path.join(tmp, "lag.csv")
        pioneer_nodes.replay(exe, bag, path, ["--smooth-lag", repr(lag)], timeout=600)
        tracks["lag %g s" % lag] = evaluate.load_result_csv(path, columns("lagged_", pose))
    tracks["smoothed (RTS)"] = evaluate.load_result_csv(full, columns("smoothed_", pose))
    batch = os.path.join(tmp, "batch.csv")
    try:
        pioneer_nodes.replay(exe, bag, batch, ["--smooth", "batch"], timeout=1200)
        tracks["batch MAP"] = evaluate.load_result_csv(batch, columns("smoothed_", pose))
    except RuntimeError as e:
        print("note: %s: no batch MAP track (%s)" % (os.path.basename(exe),
                                                     str(e).splitlines()[-1]), file=sys.stderr)
    return tracks


def case_rows(label, tracks, truth, max_lag):
    """Rows (label, track, n, position RMSE, heading RMSE) on the periods every track has."""
    end = tracks["filtered"].t[-1] - max_lag
    rows = []
    for kind, track in tracks.items():
        e = evaluate.evaluate(cut(track, end), truth)
        rows.append((label, kind, e.n_used, e.rmse_pos, e.rmse_heading_deg))
    return rows


def fmt(value, digits):
    return "-" if value is None or math.isnan(value) else "%.*f" % (digits, value)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lib-dir", help="where the sf_* executables are (default: the "
                        "sourced devel space's)")
    parser.add_argument("--lags", help="fixed lags in seconds for every case, comma-separated")
    parser.add_argument("--only", nargs="+", metavar="LABEL",
                        help="cases whose label contains one of these")
    parser.add_argument("--markdown", action="store_true", help="a markdown table")
    args = parser.parse_args(argv)
    lib_dir = args.lib_dir or pioneer_nodes.find_lib_dir("sf_soccer")
    if not lib_dir:
        parser.error("no --lib-dir and no sourced devel space with the nodes")
    rows = []
    for label, node, bag, pose, lags in CASES:
        if args.lags:
            lags = [float(v) for v in args.lags.split(",") if v]
        if args.only and not any(o in label for o in args.only):
            continue
        bag_path = os.path.join(REPO, bag)
        with tempfile.TemporaryDirectory(prefix="sf_smoothing_") as tmp:
            tracks = tracks_of(os.path.join(lib_dir, node), bag_path, pose, lags, tmp)
        rows += case_rows(label, tracks, evaluate.load_truth(bag_path), max(lags, default=0.0))
    header = ("case", "track", "periods", "position RMSE [m]", "heading RMSE [deg]")
    body = [(r[0], r[1], str(r[2]), fmt(r[3], 4), fmt(r[4], 3)) for r in rows]
    if args.markdown:
        print("| " + " | ".join(header) + " |")
        print("|" + " --- |" * len(header))
        for r in body:
            print("| " + " | ".join(r) + " |")
    else:
        widths = [max(len(x[i]) for x in [header] + body) for i in range(len(header))]
        for r in [header] + body:
            print("  ".join(x.ljust(w) for x, w in zip(r, widths)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
