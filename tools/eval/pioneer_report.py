#!/usr/bin/python3
"""Pioneer 3-AT dead-reckoning report: replays a bag offline through the fusion nodes,
then prints the accuracy table and writes the plots (tools/eval/evaluate.py).

Every sf_nav* executable of the devel space (sf_nav3ctrl_ekf, sf_nav3ctrl_ukf, ...) replays
the bag with its shipped configuration (`--replay BAG --csv OUT.csv`, no ROS master
needed); unless --no-tuning, the UKF also runs with the tuned settings of thesis
Fig. 5.10: (2) R x 10 and (3) R x 10 with a 10 ms estimation period. The truth is the bag's
ground_truth/pose (the simulated bags of bags/ have it; a real recording has not).

Output directory (--out-dir; default $SF_WS/results, else <workspace>/results next to
the devel space): replay/<label>.csv and .txt (the node's CSV and its summary line),
table.txt and table.md, paths.png, position_error.png, heading_error.png.

Usage: pioneer_report.py [--bag BAG] [--out-dir DIR] [--exe NAME]... [--variant SPEC]...
The devel space must be sourced (or give --lib-dir).
"""

import argparse
import os
import re
import shlex
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import evaluate  # noqa: E402

PACKAGE = "sf_pkg"
# Thesis Fig. 5.10: (1) the configuration of section 5.1 (100 ms), (2) R x 10 (eq. 5.21),
# (3) R x 10 and a 10 ms period.
TUNING = [("R*10", ["--scale-r", "10"]),
          ("R*10 10ms", ["--scale-r", "10", "--estimation-period", "10"])]


def find_lib_dir(exe_prefix="sf_nav"):
    """lib/sf_pkg of the first CMAKE_PREFIX_PATH entry (the sourced devel space) holding an
    executable named exe_prefix*, else the one of $SF_WS/devel."""
    prefixes = [p for p in os.environ.get("CMAKE_PREFIX_PATH", "").split(":") if p]
    if os.environ.get("SF_WS"):
        prefixes.append(os.path.join(os.environ["SF_WS"], "devel"))
    for prefix in prefixes:
        d = os.path.join(prefix, "lib", PACKAGE)
        if os.path.isdir(d) and any(n.startswith(exe_prefix) for n in os.listdir(d)):
            return d
    return None


def has_replay_mode(exe):
    """True when the executable was built with the offline replay (an older build would
    start a ROS node and wait for a master instead)."""
    try:
        with open(exe, "rb") as f:
            return b"--replay" in f.read()
    except OSError:
        return False


def slug(label):
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", label).strip("_")


def parse_variant(spec):
    """'LABEL=EXE [ARGS...]' -> (label, exe, args)."""
    if "=" not in spec:
        raise SystemExit("--variant: expected 'LABEL=EXE [ARGS...]', got %r" % spec)
    label, rest = spec.split("=", 1)
    words = shlex.split(rest)
    if not label or not words:
        raise SystemExit("--variant: expected 'LABEL=EXE [ARGS...]', got %r" % spec)
    return label, words[0], words[1:]


def replay(exe, bag, csv_path, extra, timeout):
    """Runs one replay; returns its summary line (stdout). Raises RuntimeError."""
    cmd = [exe, "--replay", bag, "--csv", csv_path] + extra
    try:
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              universal_newlines=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        raise RuntimeError("%s: no result within %d s" % (" ".join(cmd), timeout))
    if proc.returncode != 0:
        raise RuntimeError("%s: exit %d\n%s" % (" ".join(cmd), proc.returncode,
                                                proc.stdout.strip()))
    return proc.stdout.strip()


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
    parser.add_argument("--exe", action="append",
                        help="executable to replay with its shipped configuration "
                        "(repeatable; default: every sf_nav* executable)")
    parser.add_argument("--variant", action="append", metavar="'LABEL=EXE [ARGS...]'",
                        help="an extra run, e.g. 'ukf Q*0.1=sf_nav3ctrl_ukf --scale-q 0.1'")
    parser.add_argument("--no-tuning", action="store_true",
                        help="leave out the UKF's tuned runs of thesis Fig. 5.10")
    parser.add_argument("--seed", type=int, help="passed to every node (particle filters)")
    parser.add_argument("--timeout", type=int, default=60, help="s per replay (default 60)")
    parser.add_argument("--title", help="plot title (default: the bag's name)")
    args = parser.parse_args(argv)

    t_start = time.monotonic()
    lib_dir = args.lib_dir or find_lib_dir()
    if not lib_dir or not os.path.isdir(lib_dir):
        print("error: no devel space with lib/%s/sf_nav*: source devel/setup.bash or give "
              "--lib-dir" % PACKAGE, file=sys.stderr)
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

    # The runs: (label, executable path, extra arguments).
    def resolve(name):
        return name if os.sep in name else os.path.join(lib_dir, name)

    names = args.exe or sorted(n for n in os.listdir(lib_dir)
                               if n.startswith("sf_nav") and os.access(os.path.join(lib_dir, n),
                                                                       os.X_OK))
    runs = []
    for name in names:
        label = os.path.basename(name)[3:] if os.path.basename(name).startswith("sf_") else name
        runs.append((label, resolve(name), []))
        if not args.no_tuning and label.endswith("_ukf"):
            runs += [("%s %s" % (label, suffix), resolve(name), extra) for suffix, extra in TUNING]
    for spec in args.variant or []:
        label, name, extra = parse_variant(spec)
        runs.append((label, resolve(name), extra))
    if not runs:
        print("error: no sf_nav* executable in %s" % lib_dir, file=sys.stderr)
        return 2

    bag_name = os.path.splitext(os.path.basename(args.bag))[0]
    print("replaying %s through %d runs (executables in %s)" % (args.bag, len(runs), lib_dir))
    results, timing, errors = [], {}, []
    for label, exe, extra in runs:
        if not os.access(exe, os.X_OK):
            errors.append("%s: %s is not an executable" % (label, exe))
            continue
        if not has_replay_mode(exe):
            errors.append("%s: %s has no --replay mode (not a fusion node, or built "
                          "before the replay mode: rebuild the workspace)"
                          % (label, exe))
            continue
        if args.seed is not None:
            extra = extra + ["--seed", str(args.seed)]
        csv_path = os.path.join(replay_dir, slug(label) + ".csv")
        try:
            summary = replay(exe, args.bag, csv_path, extra, args.timeout)
        except RuntimeError as exc:
            errors.append("%s: %s" % (label, exc))
            continue
        with open(os.path.join(replay_dir, slug(label) + ".txt"), "w") as f:
            f.write(" ".join([exe, "--replay", args.bag, "--csv", csv_path] + extra) + "\n")
            f.write(summary + "\n")
        print("  %-24s %s" % (label, summary.splitlines()[-1] if summary else ""))
        us = evaluate.parse_summary_timing(summary)
        if us is not None:
            timing[label] = us
        results.append((label, csv_path))

    truth_path = args.truth or args.bag
    truth = evaluate.load_truth(truth_path)
    rows, plotted = [], []
    for label, csv_path in results:
        try:
            traj = evaluate.load_result_csv(csv_path)
            ev = evaluate.evaluate(traj, truth)
        except (ValueError, OSError) as exc:
            errors.append("%s: %s" % (label, exc))
            continue
        rows.append((label, ev, timing.get(label)))
        plotted.append((label, traj, ev))

    for e in errors:
        print("error: %s" % e, file=sys.stderr)
    if not rows:
        return 1
    title = args.title or "%s (offline replay)" % bag_name
    heading = ("Pioneer 3-AT dead reckoning, %s, %.1f s: errors against ground_truth/pose "
               "(heading errors: estimate - truth, wrapped)" % (
                   bag_name, truth.t[-1] - truth.t[0]))
    table = evaluate.format_table(rows)
    print()
    print(heading)
    print(table)
    with open(os.path.join(out_dir, "table.txt"), "w") as f:
        f.write(heading + "\n" + table + "\n")
    with open(os.path.join(out_dir, "table.md"), "w") as f:
        f.write(heading + "\n\n" + evaluate.format_table(rows, markdown=True) + "\n")
    written = evaluate.write_plots(out_dir, truth, plotted, title)
    print()
    print("results in %s: table.txt, table.md, %s, replay/*.csv" % (
        out_dir, ", ".join(os.path.basename(p) for p in written)))
    print("report done in %.1f s" % (time.monotonic() - t_start))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
