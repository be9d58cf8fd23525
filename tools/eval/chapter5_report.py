#!/usr/bin/python3
"""The thesis's chapter-5 experiments on the shipped Pioneer 3-AT bags: replays every bag
through the fusion nodes of config/nav*.h offline, evaluates them against the ground truth
(evaluate.py) and writes the report page (default doc/experiments.md) with its plots
(default doc/img/chapter5/).

The page has one section per comparison of the thesis: estimation versus averaging (5.2.2),
the models (5.2.3), the methods and their execution times (5.2.4, Table 5.3) and the tuning
(5.2.5: shorter period, R x 10, Q x 0.1 and x 0.01). Numbers are the mean and the sample
standard deviation over the bags (default: bags/pioneer_seed1..3.bag); plots show the first
bag. Every claim of the thesis that the page checks is decided from the measured numbers.

Usage: chapter5_report.py [--bag BAG]... [--out FILE] [--img-dir DIR] [--work-dir DIR]
The devel space with the sf_nav* executables must be sourced (or give --lib-dir); build
them with `catkin_make --make-args <the SF_PIONEER_CONFIGS of CMakeLists.txt, sf_ prefixed>`.
"""

import argparse
import collections
import datetime
import json
import os
import platform
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import chapter5_page  # noqa: E402
import evaluate  # noqa: E402
import pioneer_nodes  # noqa: E402

DEFAULT_BAGS = [os.path.join(REPO, "bags", "pioneer_seed%d.bag" % k) for k in (1, 2, 3)]
MODELS = ["nav1", "nav1ctrl", "nav2", "nav2ctrl", "nav3", "nav3ctrl", "nav3red"]
METHODS = ["kf", "ekf", "ukf", "pf"]
AVERAGING = ["nav1_moving_average", "nav2_moving_average"]
# Extra runs of shipped nodes with other settings: label -> (configuration, arguments).
VARIANTS = collections.OrderedDict([
    # 5.2.4: the particle filters with the variances of section 5.1.2, as in the thesis (the
    # headers weigh with them times 1000, see config/pioneer/common.h).
    ("nav3ctrl_pf thesis R", ("nav3ctrl_pf", ["--scale-r", "0.001"])),
    ("nav3red_pf thesis R", ("nav3red_pf", ["--scale-r", "0.001"])),
    ("nav3_pf thesis R", ("nav3_pf", ["--scale-r", "0.001"])),
    # 5.2.5 on the nav3ctrl UKF: (2) R x 10, (3) R x 10 at 10 ms (Fig. 5.10), Q x 0.1 and
    # x 0.01 at 10 ms (Fig. 5.11), and the period alone (Fig. 5.14).
    ("nav3ctrl_ukf R*10", ("nav3ctrl_ukf", ["--scale-r", "10"])),
    ("nav3ctrl_ukf R*10 10ms", ("nav3ctrl_ukf", ["--scale-r", "10", "--estimation-period", "0.01"])),
    ("nav3ctrl_ukf Q*0.1 10ms",
     ("nav3ctrl_ukf", ["--scale-q", "0.1", "--estimation-period", "0.01"])),
    ("nav3ctrl_ukf Q*0.01 10ms",
     ("nav3ctrl_ukf", ["--scale-q", "0.01", "--estimation-period", "0.01"])),
    ("nav3ctrl_ukf 200ms", ("nav3ctrl_ukf", ["--estimation-period", "0.2"])),
    ("nav3ctrl_ukf 50ms", ("nav3ctrl_ukf", ["--estimation-period", "0.05"])),
    ("nav3ctrl_ukf 20ms", ("nav3ctrl_ukf", ["--estimation-period", "0.02"])),
    ("nav3ctrl_ukf 10ms", ("nav3ctrl_ukf", ["--estimation-period", "0.01"])),
    # The same periods for nav3, whose model does not assume that cmd_vel is reached
    # within one period.
    ("nav3_ukf 20ms", ("nav3_ukf", ["--estimation-period", "0.02"])),
    ("nav3_ukf 10ms", ("nav3_ukf", ["--estimation-period", "0.01"])),
])

# Thesis Table 5.3: the runs whose time per estimation step is compared. Their replays are
# repeated (--timing-repeats) and the fastest counts: other processes on the machine only
# ever add time.
TIMED = ["nav3ctrl_ekf", "nav3ctrl_ukf", "nav3ctrl_pf", "nav3red_kf", "nav3red_ekf",
         "nav3red_ukf", "nav3red_pf", "nav3ctrl_pf thesis R", "nav3red_pf thesis R"]

# One replay of a bag: label, configuration name, extra arguments of the node.
Run = collections.namedtuple("Run", "label config extra")
# One path evaluated from a replay: its label, the run, and how the path is obtained
# ("pose": the CSV's pose columns, else an evaluate.py --dead-reckoning SPEC).
PathSpec = collections.namedtuple("PathSpec", "label run source")


def plan(available):
    """The runs and the paths evaluated from them, for the available configurations."""
    runs, paths = [], []
    configs = [m + "_" + k for m in MODELS for k in METHODS] + AVERAGING
    for config in configs:
        if config not in available:
            continue
        run = Run(config, config, [])
        runs.append(run)
        spec = pioneer_nodes.dead_reckoning_of(config)
        if spec:
            paths.append(PathSpec(config, config, spec))
        elif config.endswith("_pf"):
            # Thesis 5.2.4: the particle filter's own pose is a random walk; its path is
            # computed offline from the estimated v and omega.
            paths.append(PathSpec(config + " own pose", config, "pose"))
            paths.append(PathSpec(config, config, pioneer_nodes.VELOCITIES_OF_POSE_STATE))
        else:
            paths.append(PathSpec(config, config, "pose"))
    for label, (config, extra) in VARIANTS.items():
        if config not in available:
            continue
        runs.append(Run(label, config, extra))
        if config.endswith("_pf") or pioneer_nodes.dead_reckoning_of(config):
            spec = pioneer_nodes.dead_reckoning_of(config) or \
                pioneer_nodes.VELOCITIES_OF_POSE_STATE
            paths.append(PathSpec(label, label, spec))
        else:
            paths.append(PathSpec(label, label, "pose"))
    return runs, paths


def load_path(csv_path, source):
    if source == "pose":
        return evaluate.load_result_csv(csv_path)
    return evaluate.load_result_dead_reckoned(csv_path, source)


def read_truth_twist(bag_path):
    """(t, v, omega) of the bag's ground_truth/twist."""
    import rosbag  # Debian: python3-rosbag

    t, v, w = [], [], []
    with rosbag.Bag(bag_path) as bag:
        for _, msg, _ in bag.read_messages(topics=["ground_truth/twist", "/ground_truth/twist"]):
            t.append(msg.header.stamp.to_sec())
            v.append(msg.twist.linear.x)
            w.append(msg.twist.angular.z)
    return t, v, w


def machine_description():
    """One line: CPU model, cores, OS, compiler."""
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    osname = platform.platform()
    try:
        with open("/etc/debian_version") as f:
            osname = "Debian " + f.read().strip()
    except OSError:
        pass
    try:
        gxx = subprocess.run(["g++", "--version"], stdout=subprocess.PIPE,
                             universal_newlines=True).stdout.splitlines()[0]
    except (OSError, IndexError):
        gxx = "g++ (unknown version)"
    return "%s, %d vCPU, %s, %s, Release build" % (cpu, os.cpu_count() or 0, osname, gxx)


def git_revision():
    try:
        rev = subprocess.run(["git", "-C", REPO, "rev-parse", "--short", "HEAD"],
                             stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                             universal_newlines=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", REPO, "status", "--porcelain", "--untracked-files=no"],
                               stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                               universal_newlines=True).stdout.strip()
        return rev + ("+changes" if dirty else "") if rev else "unknown"
    except OSError:
        return "unknown"


def main(argv=None):
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    parser.add_argument("--bag", action="append",
                        help="bag to replay (repeatable; default: bags/pioneer_seed1..3.bag)")
    parser.add_argument("--out", default=os.path.join(REPO, "doc", "experiments.md"),
                        help="the report page (default: doc/experiments.md)")
    parser.add_argument("--img-dir", help="where the plots go (default: img/chapter5 beside "
                        "the page)")
    parser.add_argument("--work-dir", help="replay CSVs and summaries (default: a temporary "
                        "directory, removed afterwards)")
    parser.add_argument("--lib-dir", help="where the sf_nav* executables are "
                        "(default: lib/sf_pkg of the sourced devel space)")
    parser.add_argument("--json", help="also write the measured numbers to this file")
    parser.add_argument("--timeout", type=int, default=300, help="s per replay (default 300)")
    parser.add_argument("--timing-repeats", type=int, default=5,
                        help="replays of each Table 5.3 run per bag; the fastest time per "
                        "step counts (default %(default)s)")
    args = parser.parse_args(argv)

    t_start = time.monotonic()
    bags = args.bag or DEFAULT_BAGS
    for bag in bags:
        if not os.path.isfile(bag):
            print("error: bag %s not found" % bag, file=sys.stderr)
            return 2
    lib_dir = args.lib_dir or pioneer_nodes.find_lib_dir()
    if not lib_dir or not os.path.isdir(lib_dir):
        print("error: no devel space with lib/%s/sf_nav*: source devel/setup.bash or give "
              "--lib-dir" % pioneer_nodes.PACKAGE, file=sys.stderr)
        return 2
    available = {pioneer_nodes.config_of(n) for n in pioneer_nodes.list_nodes(lib_dir)}
    runs, paths = plan(available)
    expected = {m + "_" + k for m in MODELS for k in METHODS
                if not (k == "kf" and m != "nav3red")} | set(AVERAGING)
    missing = sorted(expected - available)
    if missing:
        print("error: not built: %s (in %s)" % (" ".join("sf_" + c for c in missing), lib_dir),
              file=sys.stderr)
        return 2
    out_path = os.path.abspath(args.out)
    img_dir = os.path.abspath(args.img_dir or os.path.join(os.path.dirname(out_path), "img",
                                                            "chapter5"))
    os.makedirs(img_dir, exist_ok=True)
    tmp = None
    if args.work_dir:
        work_dir = args.work_dir
        os.makedirs(work_dir, exist_ok=True)
    else:
        tmp = tempfile.TemporaryDirectory(prefix="sf_chapter5_")
        work_dir = tmp.name

    load_before = os.getloadavg()
    # Replays: per bag and run, the CSV and the time per estimation step.
    replays = collections.OrderedDict()
    for bag in bags:
        name = os.path.splitext(os.path.basename(bag))[0]
        replays[bag] = {}
        print("%s: %d replays" % (name, len(runs)), flush=True)
        for run in runs:
            csv_path = os.path.join(work_dir, "%s__%s.csv" % (name, pioneer_nodes.slug(run.label)))
            exe = os.path.join(lib_dir, "sf_" + run.config)
            try:
                summary = pioneer_nodes.replay(exe, bag, csv_path, run.extra, args.timeout)
                us = evaluate.parse_summary_timing(summary)
                if run.label in TIMED:
                    scratch = os.path.join(work_dir, "timing.csv")
                    for _ in range(args.timing_repeats - 1):
                        again = pioneer_nodes.replay(exe, bag, scratch, run.extra, args.timeout)
                        us = min(us, evaluate.parse_summary_timing(again))
            except RuntimeError as exc:
                print("error: %s" % exc, file=sys.stderr)
                return 1
            replays[bag][run.label] = (csv_path, us)
            print("  %-26s %s" % (run.label, evaluate.summary_line(summary)), flush=True)
    load_after = os.getloadavg()

    # Evaluations: per bag and path.
    truths, twists, trajectories, evaluations = {}, {}, {}, {}
    for bag in bags:
        truths[bag] = evaluate.load_truth(bag)
        twists[bag] = read_truth_twist(bag)
        trajectories[bag], evaluations[bag] = {}, {}
        for p in paths:
            traj = load_path(replays[bag][p.run][0], p.source)
            trajectories[bag][p.label] = traj
            evaluations[bag][p.label] = evaluate.evaluate(traj, truths[bag])

    measured = chapter5_page.Measurements(
        bags=bags, paths=paths, runs=runs, replays=replays, truths=truths, twists=twists,
        trajectories=trajectories, evaluations=evaluations)
    context = {
        "machine": machine_description(),
        "revision": git_revision(),
        "date": datetime.date.today().isoformat(),
        "load": (load_before, load_after),
        "timing_repeats": args.timing_repeats,
        "command": "python3 tools/eval/chapter5_report.py" + "".join(
            " " + a for a in (argv if argv is not None else sys.argv[1:])),
    }
    page, figures = chapter5_page.write(measured, context, out_path, img_dir)
    print("wrote %s and %d plots in %s" % (out_path, len(figures), img_dir))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(chapter5_page.numbers(measured), f, indent=1, sort_keys=True)
        print("wrote %s" % args.json)
    if tmp is not None:
        tmp.cleanup()
    print("report done in %.1f s" % (time.monotonic() - t_start))
    return 0


if __name__ == "__main__":
    sys.exit(main())
