#!/usr/bin/python3
"""Pioneer 3-AT dead-reckoning report: replays a bag offline through fusion nodes, then
prints the accuracy table and writes the plots (tools/eval/evaluate.py).

The default set of nodes (DEFAULT_CONFIGS) covers the thesis's main comparisons in a table
that stays readable: nav3ctrl with EKF, UKF and particle filter, nav3red's Kalman filter,
three other models with the UKF, the wheel odometry of 5.2.2, and the package's recommended
configuration for this skid-steer robot (config/pioneer_skid_steer_ekf.h, not a thesis model:
a line under the table says why the two differ); --all replays every sf_nav* executable of the
devel space and the recommended one instead (24 + 1 with the shipped config/). Each replays
the bag with its shipped configuration (`--replay BAG --csv OUT.csv`, no ROS master
needed); unless --no-tuning, the nav3ctrl UKF also runs with the tuned settings of thesis
Fig. 5.10: (2) R x 10 and (3) R x 10 with a 10 ms estimation period. Nodes without a pose
(nav3red, the averaging) and the particle filters get a path computed from their logged
velocities (pioneer_nodes.py); a particle filter's own pose is listed too. The truth is the
bag's ground_truth/pose (the simulated bags of bags/ have it; a real recording has not).
The full chapter-5 comparison over all bags is tools/eval/chapter5_report.py.

Output directory (--out-dir; default $SF_WS/results, else <workspace>/results next to
the devel space): replay/<label>.csv and .txt (the node's CSV and its summary line),
table.txt and table.md, paths.png, position_error.png, heading_error.png.

Usage: pioneer_report.py [--bag BAG] [--out-dir DIR] [--all | --exe NAME...] [--variant SPEC]...
The devel space must be sourced (or give --lib-dir).
"""

import argparse
import os
import shlex
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import evaluate  # noqa: E402
import pioneer_nodes  # noqa: E402

# The default set: the thesis's best model with every method, the reduced model's Kalman
# filter, three models with less information, and plain wheel odometry (5.2.2).
# Last, the package's recommended configuration for this robot (config/pioneer_skid_steer_ekf.h).
DEFAULT_CONFIGS = ["nav3ctrl_ukf", "nav3ctrl_ekf", "nav3ctrl_pf", "nav3red_kf", "nav3_ukf",
                   "nav2ctrl_ukf", "nav1ctrl_ukf", "nav2_moving_average", "pioneer_skid_steer_ekf"]
RECOMMENDED_CONFIG = "pioneer_skid_steer_ekf"
RECOMMENDED_NOTE = (
    "%s is the package's recommended configuration for a skid-steer base like this one "
    "(config/pioneer_skid_steer_ekf.h): the gyro carries the yaw rate and the slipping wheels' "
    "turn counts only at standstill, where it teaches the gyro's bias; the thesis's models "
    "observe the wheels' turn as exact, so the slip goes into their heading." % RECOMMENDED_CONFIG)
# Thesis Fig. 5.10: (1) the configuration of section 5.1 (100 ms), (2) R x 10 (eq. 5.21),
# (3) R x 10 and a 10 ms period; applied to TUNED_CONFIG.
TUNED_CONFIG = "nav3ctrl_ukf"
TUNING = [("R*10", ["--scale-r", "10"]),
          ("R*10 10ms", ["--scale-r", "10", "--estimation-period", "0.01"])]
# Paths further than this beyond the truth are cut in the plots (nav1 runs away by tens of
# metres; a particle filter's own pose wanders off).
PLOT_LIMIT_M = 1.0


def parse_variant(spec):
    """'LABEL=EXE [ARGS...]' -> (label, exe, args)."""
    if "=" not in spec:
        raise SystemExit("--variant: expected 'LABEL=EXE [ARGS...]', got %r" % spec)
    label, rest = spec.split("=", 1)
    words = shlex.split(rest)
    if not label or not words:
        raise SystemExit("--variant: expected 'LABEL=EXE [ARGS...]', got %r" % spec)
    return label, words[0], words[1:]


def paths_of(label, config, csv_path):
    """[(row label, trajectory loader, plotted)] of one replay: the pose columns, or the path
    from the logged velocities for a node without a pose; a particle filter gets both, its
    own pose (a random walk, thesis 5.2.4) in the table only."""
    spec = pioneer_nodes.dead_reckoning_of(config)
    if spec:
        return [(label, lambda: evaluate.load_result_dead_reckoned(csv_path, spec), True)]
    own = lambda: evaluate.load_result_csv(csv_path)
    if config.endswith("_pf"):
        offline = pioneer_nodes.VELOCITIES_OF_POSE_STATE
        return [(label + " (own pose)", own, False),
                (label + " (v,w offline)",
                 lambda: evaluate.load_result_dead_reckoned(csv_path, offline), True)]
    return [(label, own, True)]


def main(argv=None):
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    parser.add_argument("--bag", default=os.path.join(REPO, "bags", "pioneer_seed1.bag"),
                        help="bag to replay (default: bags/pioneer_seed1.bag)")
    parser.add_argument("--truth", help="ground truth (default: the replayed bag)")
    parser.add_argument("--out-dir", help="output directory (default: $SF_WS/results)")
    parser.add_argument("--lib-dir", help="where the sf_nav* executables are "
                        "(default: lib/sf_pkg of the sourced devel space)")
    which = parser.add_mutually_exclusive_group()
    which.add_argument("--all", action="store_true",
                       help="replay every sf_nav* executable, not the default set")
    which.add_argument("--exe", action="append",
                       help="executable to replay with its shipped configuration "
                       "(repeatable; default: %s)" % " ".join("sf_" + c for c in DEFAULT_CONFIGS))
    parser.add_argument("--variant", action="append", metavar="'LABEL=EXE [ARGS...]'",
                        help="an extra run, e.g. 'ukf Q*0.1=sf_nav3ctrl_ukf --scale-q 0.1'")
    parser.add_argument("--no-tuning", action="store_true",
                        help="leave out the UKF's tuned runs of thesis Fig. 5.10")
    parser.add_argument("--seed", type=int, help="passed to every node (particle filters)")
    parser.add_argument("--timeout", type=int, default=60, help="s per replay (default 60)")
    parser.add_argument("--title", help="plot title (default: the bag's name)")
    args = parser.parse_args(argv)

    t_start = time.monotonic()
    lib_dir = args.lib_dir or pioneer_nodes.find_lib_dir()
    if not lib_dir or not os.path.isdir(lib_dir):
        print("error: no devel space with lib/%s/sf_nav*: source devel/setup.bash or give "
              "--lib-dir" % pioneer_nodes.PACKAGE, file=sys.stderr)
        return 2
    if not os.path.isfile(args.bag):
        print("error: bag %s not found" % args.bag, file=sys.stderr)
        return 2
    if args.out_dir:
        out_dir = args.out_dir
    elif os.environ.get("SF_WS"):
        out_dir = os.path.join(os.environ["SF_WS"], "results")
    else:  # <workspace>/devel/lib/sf_pkg -> <workspace>/results
        out_dir = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
            os.path.abspath(lib_dir)))), "results")
    replay_dir = os.path.join(out_dir, "replay")
    os.makedirs(replay_dir, exist_ok=True)

    # The runs: (label, configuration name, executable path, extra arguments).
    def resolve(name):
        return name if os.sep in name else os.path.join(lib_dir, name)

    errors = []
    def built(name):
        return os.access(os.path.join(lib_dir, name), os.X_OK)

    if args.all:
        names = pioneer_nodes.list_nodes(lib_dir) + [
            n for n in ["sf_" + RECOMMENDED_CONFIG] if built(n)]
    elif args.exe:
        names = args.exe
    else:
        names = [n for n in ("sf_" + c for c in DEFAULT_CONFIGS) if built(n)]
        missing = [n for n in ("sf_" + c for c in DEFAULT_CONFIGS) if not built(n)]
        if missing:
            errors.append("not built: %s (in %s)" % (" ".join(missing), lib_dir))
    runs = []
    for name in names:
        config = pioneer_nodes.config_of(name)
        runs.append((config, config, resolve(name), []))
        if not args.no_tuning and config == TUNED_CONFIG:
            runs += [("%s %s" % (config, suffix), config, resolve(name), extra)
                     for suffix, extra in TUNING]
    for spec in args.variant or []:
        label, name, extra = parse_variant(spec)
        runs.append((label, pioneer_nodes.config_of(name), resolve(name), extra))
    if not runs:
        print("error: no sf_nav* executable in %s" % lib_dir, file=sys.stderr)
        return 2

    bag_name = os.path.splitext(os.path.basename(args.bag))[0]
    print("replaying %s through %d runs (executables in %s)" % (args.bag, len(runs), lib_dir))
    results, timing = [], {}
    for label, config, exe, extra in runs:
        if args.seed is not None:
            extra = extra + ["--seed", str(args.seed)]
        csv_path = os.path.join(replay_dir, pioneer_nodes.slug(label) + ".csv")
        try:
            summary = pioneer_nodes.replay(exe, args.bag, csv_path, extra, args.timeout)
        except RuntimeError as exc:
            errors.append("%s: %s" % (label, exc))
            continue
        with open(os.path.join(replay_dir, pioneer_nodes.slug(label) + ".txt"), "w") as f:
            f.write(" ".join([exe, "--replay", args.bag, "--csv", csv_path] + extra) + "\n")
            f.write(summary + "\n")
        print("  %-24s %s" % (label, evaluate.summary_line(summary)))
        us = evaluate.parse_summary_timing(summary)
        for row_label, loader, plotted in paths_of(label, config, csv_path):
            if us is not None:
                timing[row_label] = us
            results.append((row_label, loader, plotted))

    truth_path = args.truth or args.bag
    truth = evaluate.load_truth(truth_path)
    rows, plotted = [], []
    for label, loader, in_plots in results:
        try:
            traj = loader()
            ev = evaluate.evaluate(traj, truth)
        except (ValueError, OSError) as exc:
            errors.append("%s: %s" % (label, exc))
            continue
        rows.append((label, ev, timing.get(label)))
        if in_plots:
            plotted.append((label, traj, ev))

    for e in errors:
        print("error: %s" % e, file=sys.stderr)
    if not rows:
        return 1
    title = args.title or "%s (offline replay)" % bag_name
    heading = ("Pioneer 3-AT dead reckoning, %s, %.1f s: errors against ground_truth/pose "
               "(heading errors: estimate - truth, wrapped; 'v,w offline': path computed "
               "from the logged velocities)" % (bag_name, truth.t[-1] - truth.t[0]))
    table = evaluate.format_table(rows)
    note = RECOMMENDED_NOTE if any(label == RECOMMENDED_CONFIG for label, _, _ in rows) else ""
    print()
    print(heading)
    print(table)
    if note:
        print(note)
    with open(os.path.join(out_dir, "table.txt"), "w") as f:
        f.write(heading + "\n" + table + "\n" + (note + "\n" if note else ""))
    with open(os.path.join(out_dir, "table.md"), "w") as f:
        f.write(heading + "\n\n" + evaluate.format_table(rows, markdown=True) + "\n" +
                ("\n" + note + "\n" if note else ""))
    written = evaluate.write_plots(out_dir, truth, plotted, title, limit=PLOT_LIMIT_M)
    print()
    print("results in %s: table.txt, table.md, %s, replay/*.csv" % (
        out_dir, ", ".join(os.path.basename(p) for p in written)))
    print("report done in %.1f s" % (time.monotonic() - t_start))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
