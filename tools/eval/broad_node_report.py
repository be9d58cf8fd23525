#!/usr/bin/python3
"""Regenerates the node section of doc/broad.md: the orientation error of the shipped attitude
node with its magnetometer (config/imu_attitude_mag.h, sf_imu_attitude_mag) on every BROAD
trial found, beside the library's attitude filter, Madgwick's and Mahony's filters run here
(tools/eval/broad_report.py) and the figures the benchmark publishes.

Each trial is converted to a bag on demand (tools/data/broad_to_bag.py, into a temporary
directory), replayed by the node (`--replay trial.bag --csv out.csv`) and scored by
tools/data/broad_trial.py as the rest of the page is: the RMS of the error angle over the
movement phase, the reference's gaps left out, no alignment. The node estimates once per
period; a trial sample gets the node's latest estimate that can contain it (its row at or
within half a sample after the sample's time: the next sample comes a whole sample later).

The node runs at the IMU's rate (`frequency`), with the start the benchmark gives every filter
(the orientation of the first accelerometer and magnetometer sample, and that sample's field
as the state's field) and the header's noise unless --params adds a YAML file of node
parameters (the tuning: tools/eval/broad_node_report.py --params FILE --trials 02,07,... --page -).

Example (the page's own run):

    tools/eval/broad_node_report.py /path/to/broad --published /path/to/broad/example_code/out \\
        --binary build/sf_estimation_broad_attitude --baseline-cache broad_baselines.json"""

import json
import os
import subprocess
import sys
import tempfile
import time
from multiprocessing import Pool

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(REPO, "tools", "data"))
import attitude_baselines  # noqa: E402
import broad_report  # noqa: E402
import broad_to_bag  # noqa: E402
import broad_trial  # noqa: E402
import doc_section  # noqa: E402

NODE = "sf_imu_attitude_mag"
# The trials the node's noise was chosen on (doc/broad.md, "The node's attitude header"): the
# library filter's tuning subset (tools/eval/broad_tune.py), so that both hold out the same 19.
TUNING = broad_report.broad_tune.SUBSET
COLUMNS = [("node", "**node header**")] + [c for c in broad_report.COLUMNS
                                          if c[0] in ("ekf9", "madgwick9_benchmark", "pub_madgwick",
                                                      "madgwick9", "mahony9_benchmark", "pub_mahony", "mahony9")]


def start_parameters(trial):
    """The node's initial state from the trial's first sample: the sensor-to-ENU orientation
    of its accelerometer and magnetometer reading, no gyro bias, its field's horizontal and
    vertical components [uT] (the header's m_n, m_u)."""
    acc, mag = trial.imu_acc[0], trial.imu_mag[0]
    q = attitude_baselines.initial_enu(acc, mag)
    up = acc / np.linalg.norm(acc)
    vertical = float(np.dot(mag, up))
    horizontal = float(np.linalg.norm(mag - vertical * up))
    return {"frequency": trial.rate, "initial_state": [float(c) for c in q] + [0.0] * 3 + [horizontal, vertical]}


def estimates_at_samples(trial, times, quats, start_epoch):
    """(N, 4): per trial sample, the node's latest row at or before the sample's time plus
    half a sample (the first row before the node's first estimate)."""
    sample_times = start_epoch + np.arange(len(trial.imu_gyr)) / trial.rate
    index = np.searchsorted(times, sample_times + 0.5 / trial.rate, side="right") - 1
    return quats[np.clip(index, 0, len(quats) - 1)]


def replay(trial_path, node, extra_params, work, bag=None):
    """The Trial in `trial_path` and the node's estimates at its samples; `node`: a name for
    rosrun or the executable's path. The trial's bag is `bag`, converted when missing (default:
    in `work`)."""
    trial = broad_trial.load(trial_path)
    csv_path, params = os.path.join(work, "out.csv"), os.path.join(work, "params.yaml")
    epoch = 1700000000
    bag = bag or os.path.join(work, "trial.bag")
    if not os.path.exists(bag):
        broad_to_bag.main([trial_path, bag + ".partial", "--compression", "none", "--start-epoch", str(epoch)])
        os.replace(bag + ".partial", bag)
    values = start_parameters(trial)
    values.update(extra_params)
    with open(params, "w") as f:
        json.dump(values, f)  # JSON is YAML
    command = [node] if os.path.sep in node else ["rosrun", "sf_pkg", node]
    subprocess.run(command + ["--replay", bag, "--csv", csv_path, "--params", params], check=True,
                   stdout=subprocess.DEVNULL)
    rows = np.genfromtxt(csv_path, delimiter=",", names=True)
    quats = np.column_stack([rows["x%d" % i] for i in range(4)])
    return trial, estimates_at_samples(trial, rows["time"], quats, epoch)


def evaluate(job):
    """(trial name, {column: RMSE [deg]}): the node's, and broad_report's columns unless
    `binary` is None."""
    path, node, extra_params, binary, cached, bag_dir = job
    bag = os.path.join(bag_dir, os.path.splitext(os.path.basename(path))[0] + ".bag") if bag_dir else None
    with tempfile.TemporaryDirectory(prefix="broad_node_") as work:
        trial, estimates = replay(path, node, extra_params, work, bag)
    out = {"node": broad_trial.rmse_deg(trial, estimates)}
    if binary:
        out.update(broad_report.evaluate((path, binary, cached))[1])
    print("  %s node %.2f deg" % (trial.name, out["node"]), file=sys.stderr, flush=True)
    return trial.name, out


def groups(names):
    undisturbed = [n for n in names if int(n[:2]) <= broad_trial.UNDISTURBED_LAST]
    tuning = [n for n in names if n[:2] in TUNING]
    return [("all %d trials found" % len(names), names),
            ("%d undisturbed trials found" % len(undisturbed), undisturbed),
            ("%d disturbed trials found" % (len(names) - len(undisturbed)), [n for n in names if n not in undisturbed]),
            ("%d trials of the tuning" % len(tuning), tuning),
            ("%d trials held out" % (len(names) - len(tuning)), [n for n in names if n not in tuning])]


def body(results, args, seconds):
    names = sorted(results)
    columns = [c for c in COLUMNS if args.published or not c[0].startswith("pub_")]
    lines = ["RMSE [deg] over each trial's movement phase; node header = `%s` replayed on the trial's bag%s;"
             " EKF 9D = the library's attitude filter (options above)." % (args.node, " with `%s`" % args.params_text
                                                                           if args.params_text else ""), ""]
    lines += broad_report.table([(n, results[n]) for n in names], columns)
    lines += ["", "Means over the trials found (the mean of the trials' RMSE):", ""]
    lines += broad_report.table([(label, broad_report.group_means(results, members))
                                 for label, members in groups(names) if members], columns)
    lines += ["", "The paper's published Madgwick (beta 0.12) over all 39 trials: %.2f deg; over the 23 undisturbed: %.2f deg."
              % broad_report.PUBLISHED_GROUPS["madgwick"], "",
              "Command: `%s` (%.0f s with %d jobs)" % (" ".join(["tools/eval/broad_node_report.py"] + args.shown_argv),
                                                       seconds, args.jobs), "",
              "Machine: %s." % broad_report.machine()]
    return lines


def parse_args():
    parser = doc_section.command_parser(__doc__, "doc/broad.md")
    parser.add_argument("data", help="directory with the BROAD trials (its checkout, or data_hdf5/, data_mat/)")
    parser.add_argument("--node", default=NODE, help="the node: a name for rosrun or a path (default %(default)s)")
    parser.add_argument("--params", help="YAML (JSON) file of node parameters added to the start's")
    parser.add_argument("--trials", help="comma-separated trial numbers (default: every trial found)")
    parser.add_argument("--published", help="the benchmark's example_code/out directory")
    parser.add_argument("--binary", help="sf_estimation_broad_attitude: the library filter's and the baselines' "
                        "columns (left out without it)")
    parser.add_argument("--baseline-cache", help="JSON file of the baselines' figures (broad_report.py's)")
    parser.add_argument("--bag-dir", help="keep the trials' bags here and reuse them (default: each in a temporary "
                        "directory, deleted after its replay)")
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    args.shown_argv = ["BROAD"] + (["--published", "BROAD/example_code/out"] if args.published else []) + (
        ["--binary", "BUILD/sf_estimation_broad_attitude"] if args.binary else []) + (
        ["--baseline-cache", "broad_baselines.json"] if args.baseline_cache else []) + (
        ["--bag-dir", "BAGS"] if args.bag_dir else [])
    args.params_text = ""
    if args.params:
        with open(args.params) as f:
            args.params_text = " ".join(f.read().split())
    return parser, args


def main():
    parser, args = parse_args()
    paths = broad_trial.find_trials(args.data)
    if args.trials:
        wanted = set(args.trials.split(","))
        paths = [p for p in paths if os.path.basename(p)[:2] in wanted]
    if not paths:
        parser.error("no BROAD trial in %s" % args.data)
    extra = {}
    if args.params:
        import yaml
        with open(args.params) as f:
            extra = yaml.safe_load(f) or {}
    cache = {}
    if args.baseline_cache and os.path.exists(args.baseline_cache):
        with open(args.baseline_cache) as f:
            cache = json.load(f)
    started = time.time()
    jobs = [(p, args.node, extra, args.binary, cache.get(os.path.splitext(os.path.basename(p))[0], {}),
             args.bag_dir) for p in paths]
    with Pool(args.jobs) as pool:
        results = dict(pool.map(evaluate, jobs))
    if args.published:
        for name, values in broad_report.published(args.published).items():
            if name in results:
                results[name].update({"pub_" + k: v for k, v in values.items()})
    doc_section.publish(args.page, "broad-node", body(results, args, time.time() - started))


if __name__ == "__main__":
    main()
