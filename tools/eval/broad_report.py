#!/usr/bin/python3
"""Regenerates the tables of doc/broad.md: the orientation error of the IMU attitude filter
(sf_estimation/attitude_filter.hpp, through sf_estimation_broad_attitude) and of Madgwick's
and Mahony's filters (tools/eval/attitude_baselines.py) on every BROAD trial found, beside
the figures the benchmark publishes for the same trials.

The error is the benchmark's: the RMS over the trial's movement phase of the angle of
q_estimate q_reference^-1, in degrees, per trial; a group's figure is the mean of its trials'
figures, as the benchmark averages them. --published takes the benchmark's example_code/out
directory (results_madgwick.mat, results_mahony.mat: every trial at every parameter of its
grid); without it the published columns are left out.

Example (the page's own run):

    tools/eval/broad_report.py /path/to/broad --published /path/to/broad/example_code/out \\
        --binary build/sf_estimation_broad_attitude"""

import json
import os
import platform
import subprocess
import sys
from multiprocessing import Pool

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "data"))
import attitude_baselines  # noqa: E402
import broad_attitude_run  # noqa: E402
import broad_trial  # noqa: E402
import broad_tune  # noqa: E402
import doc_section  # noqa: E402

# The attitude filter's options on BROAD, found by tools/eval/broad_tune.py on its subset.
TUNED = ["--acceleration-time-constant", "3", "--accelerometer-noise", "0.2", "--acceleration-inflation", "1.5625",
         "--acceleration-gate", "100", "--gyro-noise", "0.005", "--bias-walk", "2.5e-06", "--magnetometer-noise", "1",
         "--field-norm-gate", "0.4", "--field-dip-gate", "1.3968"]
OURS = {"ekf9": TUNED, "ekf6": TUNED + ["--no-magnetometer"]}
BASELINES = ("madgwick9_benchmark", "madgwick9", "madgwick6", "mahony9_benchmark", "mahony9", "mahony6")
PUBLISHED_TRIALS = 39
PUBLISHED_GROUPS = {"madgwick": (4.96, 4.29)}  # the paper's Madgwick beta 0.12: all, undisturbed


def evaluate(job):
    """{column: RMSE [deg]} of one trial; the baselines' figures are taken from `cached`
    ({baseline: RMSE}) where present."""
    path, binary, cached = job
    trial = broad_trial.load(path)
    out = {name: broad_trial.rmse_deg(trial, broad_attitude_run.run(trial, binary, options))
           for name, options in OURS.items()}
    for name in BASELINES:
        out[name] = cached[name] if name in cached else broad_trial.rmse_deg(trial, attitude_baselines.run_baseline(trial, name))
    print("  %s done" % trial.name, file=sys.stderr, flush=True)
    return trial.name, out


def published(directory):
    """{trial name: {'madgwick': RMSE, 'mahony': RMSE}} at beta 0.12 and Kp 0.74, Ki 0.0012,
    read from the benchmark's result files."""
    import scipy.io
    out = {}
    for name, wanted in (("madgwick", {"beta": 0.12}), ("mahony", {"Kp": 0.74, "Ki": 0.0012})):
        results = scipy.io.loadmat(os.path.join(directory, "results_%s.mat" % name), squeeze_me=True)
        values = results["param_values"]
        names = list(np.atleast_1d(results["param_names"]))
        index = tuple(int(np.argmin(np.abs(np.atleast_1d(values[p].item()) - wanted[p]))) for p in names)
        table = results["total_rmse_deg"]
        for field in table.dtype.names:
            errors = np.atleast_1d(table[field].item())
            out.setdefault(field[len("trial_"):], {})[name] = float(errors[index] if errors.ndim == len(index) else errors[index[0]])
    return out


def fmt(value):
    return "" if value is None else "%.2f" % value


COLUMNS = [("ekf9", "**EKF 9D**"), ("ekf6", "EKF 6D"), ("madgwick9_benchmark", "Madgwick 9D as published"),
           ("pub_madgwick", "published Madgwick"), ("madgwick9", "Madgwick 9D"), ("madgwick6", "Madgwick 6D"),
           ("mahony9_benchmark", "Mahony 9D as published"), ("pub_mahony", "published Mahony"),
           ("mahony9", "Mahony 9D"), ("mahony6", "Mahony 6D")]


def table(rows, columns):
    lines = ["| trial | " + " | ".join(title for _, title in columns) + " |",
             "| --- | " + " | ".join("---:" for _ in columns) + " |"]
    for name, values in rows:
        lines.append("| %s | %s |" % (name, " | ".join(fmt(values.get(key)) for key, _ in columns)))
    return lines


def group_means(results, names):
    keys = set.intersection(*(set(results[n]) for n in names))
    return {k: float(np.mean([results[n][k] for n in names])) for k in keys}


def machine():
    cpu = "unknown CPU"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return "%s, %s, Python %s" % (cpu, platform.platform(), platform.python_version())


def reproduction(results, names):
    """How closely the runs made as the benchmark's evaluation made them give its figures."""
    lines = []
    for ours, theirs, title in (("madgwick9_benchmark", "pub_madgwick", "Madgwick"), ("mahony9_benchmark", "pub_mahony", "Mahony")):
        pairs = [(results[n][ours], results[n][theirs]) for n in names if theirs in results[n]]
        if pairs:
            worst = max(abs(a - b) for a, b in pairs)
            lines += ["", "%s as published against the published figure: largest difference %.4f deg over %d trials."
                      % (title, worst, len(pairs))]
    return lines


def body(results, args):
    names = sorted(results)
    undisturbed = [n for n in names if int(n[:2]) <= broad_trial.UNDISTURBED_LAST]
    columns = [c for c in COLUMNS if args.published or not c[0].startswith("pub_")]
    lines = ["Trials found: %d of the benchmark's %d (%s)." % (len(names), PUBLISHED_TRIALS, ", ".join(n[:2] for n in names)),
             "", "RMSE [deg] over each trial's movement phase; EKF = this package's attitude filter, options `%s`"
             " (6D: and `--no-magnetometer`)." % " ".join(TUNED), ""]
    lines += table([(n, results[n]) for n in names], columns)
    lines += ["", "Means over the trials found (the benchmark's group figure: the mean of its trials' RMSE):", ""]
    tuning = [n for n in names if n[:2] in broad_tune.SUBSET]
    held_out = [n for n in names if n not in tuning]
    groups = [("all %d trials found" % len(names), names), ("%d undisturbed trials found" % len(undisturbed), undisturbed),
              ("%d disturbed trials found" % (len(names) - len(undisturbed)), [n for n in names if n not in undisturbed]),
              ("%d trials of the EKF's tuning" % len(tuning), tuning), ("%d trials held out" % len(held_out), held_out)]
    lines += table([(label, group_means(results, members)) for label, members in groups], columns)
    lines += reproduction(results, names)
    lines += ["", "The paper's published Madgwick (beta 0.12) over all 39 trials: %.2f deg; over the 23 undisturbed: %.2f deg."
              % PUBLISHED_GROUPS["madgwick"], "",
              "Command: `%s`" % " ".join(["tools/eval/broad_report.py"] + args.shown_argv), "",
              "Machine: %s." % machine()]
    return lines


def main():
    parser = doc_section.command_parser(__doc__, "doc/broad.md")
    parser.add_argument("data", help="directory with the BROAD trials (its checkout, or data_hdf5/, data_mat/)")
    parser.add_argument("--published", help="the benchmark's example_code/out directory")
    parser.add_argument("--binary", default=broad_attitude_run.DEFAULT_BINARY, help="sf_estimation_broad_attitude")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--baseline-cache", help="JSON file of the baselines' figures, read if present and "
                        "written: the baselines (the slow part) are then run once; delete it after changing them")
    args = parser.parse_args()
    args.shown_argv = ["BROAD"] + (["--published", "BROAD/example_code/out"] if args.published else []) + [
        "--binary", "BUILD/sf_estimation_broad_attitude"]
    paths = broad_trial.find_trials(args.data)
    if not paths:
        parser.error("no BROAD trial in %s" % args.data)
    cache = {}
    if args.baseline_cache and os.path.exists(args.baseline_cache):
        with open(args.baseline_cache) as f:
            cache = json.load(f)
    with Pool(args.jobs) as pool:
        jobs = [(p, args.binary, cache.get(os.path.splitext(os.path.basename(p))[0], {})) for p in paths]
        results = dict(pool.map(evaluate, jobs))
    if args.baseline_cache:
        with open(args.baseline_cache, "w") as f:
            json.dump({n: {k: v for k, v in r.items() if k in BASELINES} for n, r in results.items()}, f, indent=1)
    if args.published:
        for name, values in published(args.published).items():
            if name in results:
                results[name].update({"pub_" + k: v for k, v in values.items()})
    doc_section.publish(args.page, "broad-results", body(results, args))


if __name__ == "__main__":
    main()
