#!/usr/bin/python3
"""The table of doc/real_robot.md: fusion headers and hand-made references on the real Husky
recording, each measured against its GPS track.

Usage:
  real_robot_report.py [--bag bags/husky_gps.bag] [--lib-dir DIR] [--out-dir DIR]
                       [--plot doc/img/real_robot_husky.png] [--grid]

Rows:
  encoder pose         the recording's own wheel odometry (/encoder pose, its driver's)
  wheels by hand       /encoder twist v and yaw rate integrated (wheel_gyro_reference.py --yaw wheels)
  wheels + gyro by hand  /encoder v with the gyro's yaw rate (wheel_gyro_reference.py)
  sf_husky_<header>_<method>  the replay of config/husky_<header>_<method>.h (the generic
                       headers with the bag's topics, period and IMU frame)
Each track is compared with the GPS fixes after its best rotation and shift
(gps_reference.py): RMSE, maximum and final error [m]. For the filters also:
  jump max / mean [mm]  per period, how far the estimated position moved off the
                       dead-reckoning step of the previous estimate, |p_k - p_{k-1} -
                       v T (cos, sin)(theta + omega T / 2)| with v, omega, theta of estimate
                       k - 1: zero when no innovation moves the position; what an update
                       moves it by through its covariances otherwise;
  heading std [deg]    the filter's own final heading standard deviation (sqrt P(2,2));
  b_g [rad/s]          the final gyro bias estimate;
  us/step              the replay's mean time per estimation step.
--grid also replays the Kalman filters with Q and R scaled by 0.1, 0.3, 1, 3, 10 each
(--scale-q, --scale-r: 25 runs per header) and prints the best RMSE of the grid beside the
shipped one: a coarse tuning, not an identification.

The executables are found as pioneer_report.py finds them (--lib-dir, else the sourced
devel space, else $SF_WS/devel). Needs python3-rosbag, and python3-matplotlib for --plot.
"""

import argparse
import csv
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import evaluate as ev  # noqa: E402
import gps_reference as gr  # noqa: E402
import pioneer_nodes  # noqa: E402
import wheel_gyro_reference as wg  # noqa: E402

FILTERS = ["husky_diff_drive_ekf", "husky_diff_drive_ukf", "husky_diff_drive_pf",
           "husky_skid_steer_ekf", "husky_skid_steer_ukf", "husky_skid_steer_pf"]
GRID = [0.1, 0.3, 1.0, 3.0, 10.0]


def read_rows(path):
    with open(path, newline="") as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def jumps(rows):
    """Per-period distance [m] between the estimated position step and the dead-reckoning
    step of the previous estimate (see the module's help)."""
    out = []
    for a, b in zip(rows, rows[1:]):
        dt = b["time"] - a["time"]
        h = a["x2"] + 0.5 * a["x4"] * dt
        ex = a["x0"] + a["x3"] * dt * math.cos(h)
        ey = a["x1"] + a["x3"] * dt * math.sin(h)
        out.append(math.hypot(b["x0"] - ex, b["x1"] - ey))
    return out


def replay(exe, bag, csv_path, extra=()):
    """Runs `exe --replay bag --csv csv_path extra...`; returns its summary (stdout)."""
    cmd = [exe, "--replay", bag, "--csv", csv_path] + list(extra)
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=120)
    if proc.returncode != 0:
        raise RuntimeError("%s: exit %d\n%s" % (" ".join(cmd), proc.returncode,
                                                proc.stdout.strip()))
    return proc.stdout


def step_time(summary):
    for part in summary.split(","):
        if "us per estimation step" in part:
            return float(part.split()[0])
    return float("nan")


def compare(track_fn, gps):
    est = track_fn()
    return gr.compare(est, gps), est


def main(argv=None):
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    parser.add_argument("--bag", default=os.path.join(REPO, "bags", "husky_gps.bag"))
    parser.add_argument("--lib-dir", help="where the sf_husky_* executables are")
    parser.add_argument("--out-dir", help="keep the CSVs here (default: a temporary directory)")
    parser.add_argument("--plot", help="write the tracks on the GPS (PNG)")
    parser.add_argument("--grid", action="store_true",
                        help="also the best RMSE over a Q/R scaling grid per Kalman filter")
    args = parser.parse_args(argv)

    lib_dir, out_dir, tmp = pioneer_nodes.husky_dirs(args.lib_dir, args.out_dir)
    if not lib_dir:
        return 2

    _, gps = gr.gps_track(gr.read_fixes(args.bag))
    results = []  # (label, compare result, trajectory, extra dict)

    enc = ev.load_result(args.bag, None, "/encoder")
    results.append(("encoder pose (driver)", gr.compare(enc, gps), enc, {}))
    odom, wheel_yaw, gyro = wg.read_bag(args.bag, "/encoder", "/imu/data")
    for label, yaw in (("wheels by hand", wheel_yaw), ("wheels + gyro by hand", gyro)):
        path = os.path.join(out_dir, pioneer_nodes.slug(label) + ".csv")
        wg.write_csv(path, wg.dead_reckon(odom, yaw))
        traj = ev.load_result_csv(path)
        results.append((label, gr.compare(traj, gps), traj, {}))

    for name in FILTERS:
        exe = os.path.join(lib_dir, "sf_" + name)
        if not os.access(exe, os.X_OK):
            print("note: %s not built, left out" % exe, file=sys.stderr)
            continue
        path = os.path.join(out_dir, name + ".csv")
        summary = replay(exe, args.bag, path)
        rows = read_rows(path)
        traj = ev.load_result_csv(path)
        j = jumps(rows)
        extra = {"jump_max": max(j), "jump_mean": sum(j) / len(j),
                 "heading_std": math.degrees(math.sqrt(max(rows[-1]["var2"], 0.0))),
                 "bias": rows[-1]["x5"], "us": step_time(summary)}
        if args.grid and not name.endswith("_pf"):
            best = None
            for sq in GRID:
                for sr in GRID:
                    gpath = os.path.join(out_dir, "%s_q%g_r%g.csv" % (name, sq, sr))
                    replay(exe, args.bag, gpath,
                                         ["--scale-q", str(sq), "--scale-r", str(sr)])
                    res = gr.compare(ev.load_result_csv(gpath), gps)
                    if best is None or res["rmse"] < best[0]:
                        best = (res["rmse"], sq, sr)
            extra["grid"] = best
        results.append(("sf_" + name, gr.compare(traj, gps), traj, extra))

    print("# %s against its GPS track (%d fixes), after each track's best rotation and shift"
          % (os.path.basename(args.bag), len(gps.t)))
    print()
    head = "| track | RMSE [m] | max [m] | final [m] | jump max / mean [mm] | heading std [deg] | b_g [rad/s] | us/step |"
    if args.grid:
        head += " best of Q/R grid: RMSE [m] (scale Q, R) |"
    print(head)
    print("|" + " --- |" * (head.count("|") - 1))
    for label, res, _, x in results:
        cells = ["`%s`" % label if label.startswith("sf_") else label,
                 "%.2f" % res["rmse"], "%.2f" % res["max"], "%.2f" % res["final"]]
        if x:
            cells += ["%.1f / %.2f" % (1000 * x["jump_max"], 1000 * x["jump_mean"]),
                      "%.1f" % x["heading_std"], "%+.4f" % x["bias"], "%.1f" % x["us"]]
        else:
            cells += ["-", "-", "-", "-"]
        if args.grid:
            g = x.get("grid") if x else None
            cells.append("%.2f (%g, %g)" % g if g else "-")
        print("| " + " | ".join(cells) + " |")

    if args.plot:
        import matplotlib  # Debian: python3-matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 6))
        ax.plot(gps.x, gps.y, "k.", markersize=5, label="GPS fixes")
        show = ["encoder pose (driver)", "wheels + gyro by hand", "sf_husky_diff_drive_ekf",
                "sf_husky_skid_steer_ekf", "sf_husky_skid_steer_ukf"]
        for label, res, traj, _ in results:
            if label not in show:
                continue
            moved = gr.apply_rigid_2d(res["transform"], list(zip(traj.x, traj.y)))
            ax.plot([p[0] for p in moved], [p[1] for p in moved],
                    label="%s (RMSE %.2f m)" % (label, res["rmse"]))
        ax.set_xlabel("east [m]")
        ax.set_ylabel("north [m]")
        ax.set_aspect("equal")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
        ax.set_title("%s: tracks after their best rotation and shift onto the GPS"
                     % os.path.basename(args.bag), fontsize=9)
        fig.tight_layout()
        fig.savefig(args.plot, dpi=90)
        print()
        print("plot: %s" % args.plot)
    if tmp:
        tmp.cleanup()
    return 0


if __name__ == "__main__":
    sys.exit(main())
