#!/usr/bin/python3
"""Tunes the noise of the attitude node with its magnetometer (config/imu_attitude_mag.h) on
the BROAD subset of doc/broad.md by the coordinate search of tools/eval/broad_tune.py, through
the node's run-time parameters (Q, R and the accelerometer's gate; no rebuild): each knob in
turn is multiplied and divided by a factor while that lowers the mean RMSE over the subset.
Prints every evaluation and the parameters found, as YAML for broad_node_report.py --params.

    tools/eval/broad_node_tune.py /path/to/broad --bag-dir /tmp/broad_bags"""

import argparse
import json
import os
import sys
import tempfile
from multiprocessing import Pool

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "data"))
import broad_node_report  # noqa: E402
import broad_trial  # noqa: E402
import broad_tune  # noqa: E402

# The knobs and where the search starts: the header's own values at 285.7 Hz (T = 3.5 ms).
T = 0.0035
START = {"rotation_q": 1e-6 * T, "bias_q": 1e-10 * T, "field_q": 1e-4 * T,
         "accelerometer_r": 0.5, "field_r": 1e-12, "accelerometer_gate": 1e4}
STATES = 9  # stored: q (4), gyro bias (3), field (2)


def diagonal(entries):
    """An n x n matrix (list of rows) with `entries` on its diagonal."""
    return [[entries[i] if i == j else 0.0 for j in range(len(entries))] for i in range(len(entries))]


def parameters(values):
    """The node's parameters of the knob values: Q over the stored rows (the quaternion's w row
    zero, its tangent rows on x, y, z), R, the gate of the accelerometer's rows."""
    q = [0.0] + [values["rotation_q"]] * 3 + [values["bias_q"]] * 3 + [values["field_q"]] * 2
    r = [values["accelerometer_r"]] * 3 + [values["field_r"]] * 3
    return {"process_noise_covariance": diagonal(q), "measurement_noise_covariance": diagonal(r),
            "input_gate": [values["accelerometer_gate"]] * 3 + [0.0] * 3}


def trial_rmse(job):
    path, node, params, bag_dir = job
    bag = os.path.join(bag_dir, os.path.splitext(os.path.basename(path))[0] + ".bag")
    with tempfile.TemporaryDirectory(prefix="broad_tune_") as work:
        trial, estimates = broad_node_report.replay(path, node, params, work, bag)
    return broad_trial.rmse_deg(trial, estimates)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("data", help="directory with the BROAD trials")
    parser.add_argument("--node", default=broad_node_report.NODE, help="a name for rosrun or a path")
    parser.add_argument("--bag-dir", required=True, help="the subset's bags, converted once and reused")
    parser.add_argument("--subset", nargs="*", default=broad_tune.SUBSET, help="trial numbers")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--rounds", type=int, default=4)
    parser.add_argument("--factor", type=float, default=10.0)
    parser.add_argument("--start", type=json.loads, default={}, help="JSON of knob values replacing START's")
    parser.add_argument("--knobs", nargs="*", default=sorted(START), help="the knobs searched (the others stay)")
    args = parser.parse_args()
    paths = [p for p in broad_trial.find_trials(args.data) if os.path.basename(p)[:2] in args.subset]

    def cost(values):
        with Pool(args.jobs) as pool:
            errors = pool.map(trial_rmse, [(p, args.node, parameters(values), args.bag_dir) for p in paths])
        print("%.3f  %s  %s" % (np.mean(errors), " ".join("%.2f" % e for e in errors), json.dumps(values)), flush=True)
        return float(np.mean(errors))

    fixed = dict(START, **args.start)
    searched = {k: fixed.pop(k) for k in args.knobs}
    best, values = broad_tune.search(None, None, searched, args.jobs, args.factor, args.rounds,
                                     lambda v: cost(dict(fixed, **v)))
    values = dict(fixed, **values)
    print("best %.3f deg: %s" % (best, json.dumps(values)))
    print(json.dumps(parameters(values)))


if __name__ == "__main__":
    main()
