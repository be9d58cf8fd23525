#!/usr/bin/python3
"""Figure of what the realistic error options change in a Pioneer bag (doc/bags.md).

Panels: the wheels' yaw rate against the gyro's (10 Hz pairs, yaw_agreement.py) for an
ideal bag, a realistic bag and optionally the real Husky recording; and the dead-reckoning
paths of the ideal and realistic bags (wheels only, and wheel speed with gyro heading)
against the true path. Prints the statistics and the final dead-reckoning errors (the
true path ends at its start).

  make_bags.sh --ideal --out /tmp/ideal
  plot_realistic.py --ideal /tmp/ideal/pioneer_seed1_ideal.bag --realistic bags/pioneer_seed1.bag \\
      [--husky husky_gps_data.bag] --out doc/img/bags/realistic_pioneer.png
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import yaw_agreement  # noqa: E402

R_EFF = 0.3   # pioneer_sim.R_EFF: the consumer's skid-steer radius [m]


def dead_reckoning(path):
    """Paths integrated from the bag: wheels only (v and omega from the wheel speeds) and
    wheel speed with the gyro's yaw rate; plus the true path. Each sample's interval runs to
    the next sample (times: bag time of the wheels, header stamps of the gyro)."""
    import rosbag
    left, right, gyro, truth = [], [], [], []
    with rosbag.Bag(path) as bag:
        for topic, msg, t in bag.read_messages():
            if topic == "velocity_wheel_left":
                left.append((t.to_sec(), msg.data * 1e-3))
            elif topic == "velocity_wheel_right":
                right.append((t.to_sec(), msg.data * 1e-3))
            elif topic == "angular_velocity":
                gyro.append((msg.header.stamp.to_sec(), msg.vector.z))
            elif topic == "ground_truth/pose":
                truth.append((msg.pose.position.x, msg.pose.position.y))
    n = min(len(left), len(right))
    gyro.sort()
    gt, gv = [t for t, _ in gyro], [v for _, v in gyro]
    paths = {"wheels": [(0.0, 0.0)], "wheels+gyro": [(0.0, 0.0)]}
    th_w = th_g = 0.0
    xw = yw = xg = yg = 0.0
    for i in range(n - 1):
        t, vl = left[i]
        vr = right[i][1]
        dt = left[i + 1][0] - t
        v, w = 0.5 * (vl + vr), (vr - vl) / (2.0 * R_EFF)
        g = yaw_agreement.interpolate(gt, gv, t)
        g = w if g is None else g
        xw += v * dt * math.cos(th_w + 0.5 * w * dt)
        yw += v * dt * math.sin(th_w + 0.5 * w * dt)
        th_w += w * dt
        xg += v * dt * math.cos(th_g + 0.5 * g * dt)
        yg += v * dt * math.sin(th_g + 0.5 * g * dt)
        th_g += g * dt
        paths["wheels"].append((xw, yw))
        paths["wheels+gyro"].append((xg, yg))
    paths["truth"] = truth
    return paths


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--ideal", required=True)
    parser.add_argument("--realistic", required=True)
    parser.add_argument("--husky", help="the real Husky recording (optional third scatter panel)")
    parser.add_argument("--out", required=True)
    args = parser.parse_args(argv)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    scatter = [("ideal: %s" % os.path.basename(args.ideal), args.ideal, "pioneer"),
               ("realistic: %s" % os.path.basename(args.realistic), args.realistic, "pioneer")]
    if args.husky:
        scatter.append(("real Husky recording", args.husky, "husky"))
    fig, axes = plt.subplots(1, len(scatter) + 1, figsize=(4.2 * (len(scatter) + 1), 4.2))
    for ax, (title, path, layout) in zip(axes, scatter):
        w, g = yaw_agreement.pair(*yaw_agreement.read_bag(path, layout))
        n, corr, resid, slope, resid_slope = yaw_agreement.statistics(w, g)
        print("%s: pairs=%d corr=%.3f resid_std=%.4f slope=%.3f resid_after_slope=%.4f"
              % (title, n, corr, resid, slope, resid_slope))
        ax.plot(g, w, ".", ms=2, alpha=0.5)
        lim = max(max(map(abs, g)), max(map(abs, w))) * 1.05
        ax.plot([-lim, lim], [-lim, lim], "k-", lw=0.8, label="wheels = gyro")
        ax.plot([-lim, lim], [-slope * lim, slope * lim], "r--", lw=0.8, label="slope %.2f" % slope)
        ax.set_xlim(-lim, lim)
        ax.set_ylim(-lim, lim)
        ax.set_aspect("equal")
        ax.set_xlabel("gyro yaw rate [rad/s]")
        ax.set_ylabel("wheels' yaw rate [rad/s]")
        ax.set_title("%s\ncorr %.3f, resid std %.3f rad/s" % (title, corr, resid), fontsize=9)
        ax.legend(fontsize=7, loc="upper left")
    ax = axes[-1]
    for label, path, style in (("ideal", args.ideal, ":"), ("realistic", args.realistic, "-")):
        paths = dead_reckoning(path)
        for name, colour in (("wheels", "tab:red"), ("wheels+gyro", "tab:green")):
            xy = paths[name]
            end = math.hypot(*xy[-1])
            print("%s %s: final dead-reckoning error %.2f m" % (label, name, end))
            ax.plot([p[0] for p in xy], [p[1] for p in xy], style, color=colour, lw=0.9,
                    label="%s, %s (end %.2f m off)" % (label, name, end))
        if label == "ideal":
            ax.plot([p[0] for p in paths["truth"]], [p[1] for p in paths["truth"]], "k-", lw=1.5, alpha=0.4,
                    label="truth")
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title("dead reckoning (start and true end at 0, 0)", fontsize=9)
    ax.legend(fontsize=6, loc="best")
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    fig.savefig(args.out, dpi=90)
    print("wrote %s" % args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
