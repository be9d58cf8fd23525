#!/usr/bin/python3
"""Tunes the attitude filter's options (sf_estimation_broad_attitude) on a subset of the BROAD
trials by a coordinate search in log scale: each option in turn is multiplied and divided by
a factor while that lowers the mean RMSE over the subset; the factor halves (in log) once no
option improves. Prints every trial evaluation and, at the end, the options found.

The subset of doc/broad.md is the default: one or two trials of each motion and disturbance
kind that the stored snapshot holds (02, 07, 08, 11, 15, 16, 21, 25, 27, 30, 33)."""

import argparse
import math
import os
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data"))
import broad_trial  # noqa: E402
import broad_attitude_run  # noqa: E402

SUBSET = ("02", "07", "08", "11", "15", "16", "21", "25", "27", "30", "33")
# The options searched and where the search starts.
START = {"--gyro-noise": 0.00125, "--bias-walk": 1e-5, "--accelerometer-noise": 0.2,
         "--acceleration-inflation": 100.0, "--acceleration-gate": 100.0, "--acceleration-time-constant": 3.0,
         "--magnetometer-noise": 1.0, "--field-norm-gate": 0.1, "--field-dip-gate": 0.0873}


def options_of(values):
    return [str(x) for pair in sorted(values.items()) for x in (pair[0], "%.6g" % pair[1])]


def mean_rmse(trials, binary, values, jobs):
    options = options_of(values)
    with ThreadPoolExecutor(jobs) as pool:
        errors = list(pool.map(lambda t: broad_trial.rmse_deg(t, broad_attitude_run.run(t, binary, options)), trials))
    print("%.3f  %s  %s" % (np.mean(errors), " ".join("%.2f" % e for e in errors), " ".join(options)), flush=True)
    return float(np.mean(errors))


def search(trials, binary, values, jobs, factor, rounds, cost=None):
    """The coordinate search from `values`: (best mean RMSE, its values). `cost(values)` is the
    mean RMSE of a candidate (default: the attitude filter's over `trials`)."""
    cost = cost or (lambda candidate: mean_rmse(trials, binary, candidate, jobs))
    best = cost(values)
    for _ in range(rounds):
        improved = False
        for name in sorted(values):
            for step in (factor, 1.0 / factor):
                trial_values = dict(values, **{name: values[name] * step})
                value = cost(trial_values)
                if value < best:
                    best, values, improved = value, trial_values, True
                    break
        if not improved:
            factor = math.sqrt(factor)
            if factor < 1.2:
                break
    return best, values


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("data", help="directory with the BROAD trials")
    parser.add_argument("--binary", default=broad_attitude_run.DEFAULT_BINARY)
    parser.add_argument("--subset", nargs="*", default=SUBSET, help="trial numbers")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--rounds", type=int, default=6)
    args = parser.parse_args()
    paths = [p for p in broad_trial.find_trials(args.data) if os.path.basename(p)[:2] in args.subset]
    trials = [broad_trial.load(p) for p in paths]
    print("tuning on", " ".join(t.name for t in trials))
    best, values = search(trials, args.binary, dict(START), args.jobs, 4.0, args.rounds)
    print("best %.3f deg: %s" % (best, " ".join(options_of(values))))


if __name__ == "__main__":
    main()
