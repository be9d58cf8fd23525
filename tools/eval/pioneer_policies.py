#!/usr/bin/python3
"""Alignment policies on the Pioneer 3-AT bags (issue 5): replays every bag through the
nav3ctrl UKF (config/nav3ctrl_ukf.h) at a 10 ms period with AVERAGE, LAST and SAMPLED for
all inputs and for each sensor alone, and HOLD and FILL for the 10 Hz wheel speeds, plus
the header's 100 ms with LAST for the 100 Hz sensors (the thesis's own question, section
4.3.4); evaluates each run against the bag's ground truth and writes the section
`pioneer_policies` of the page (default doc/multirate_experiments.md).

Inputs of nav3ctrl (config/pioneer/common.h): 0 gyroscope (100 Hz), 1 accelerometer
(100 Hz), 2 and 3 the wheel speeds (10 Hz); cmd_vel is a control.

Usage: pioneer_policies.py [--bag BAG]... [--page FILE] [--work-dir DIR] [--lib-dir DIR]
The devel space with sf_nav3ctrl_ukf must be sourced (or give --lib-dir).
"""

import collections
import concurrent.futures
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import chapter5_report  # noqa: E402  (machine description, git revision)
import doc_section  # noqa: E402
import evaluate  # noqa: E402
import pioneer_nodes  # noqa: E402

DEFAULT_BAGS = [os.path.join(REPO, "bags", "pioneer_seed%d.bag" % k) for k in (1, 2, 3)]
DEFAULT_PAGE = os.path.join(REPO, "doc", "multirate_experiments.md")
SECTION = "pioneer_policies"
EXE = "sf_nav3ctrl_ukf"
SENSORS = collections.OrderedDict([("gyroscope", [0]), ("accelerometer", [1]),
                                   ("wheels", [2, 3])])
ALL_INPUTS = [0, 1, 2, 3]
WHEEL_R = 2.0  # (mm/s)^2, R of the wheel speeds (config/pioneer/common.h)
TEN_MS = ["--estimation-period", "0.01"]

# One run: label, the sensor group it is about (None: all inputs), the policy, the node's
# arguments.
Variant = collections.namedtuple("Variant", "label period sensor policy args")


def align(inputs, policy):
    """--align options giving every input of `inputs` the policy `policy`."""
    out = []
    for i in inputs:
        out += ["--align", "%d=%s" % (i, policy)]
    return out


def variants():
    """Every run of the comparison, in the order of the page's table."""
    v = [Variant("100 ms, AVERAGE (header)", 100, None, "AVERAGE", [])]
    v.append(Variant("100 ms, all LAST", 100, None, "LAST", align(ALL_INPUTS, "LAST")))
    for sensor in ("gyroscope", "accelerometer"):
        v.append(Variant("100 ms, %s LAST" % sensor, 100, sensor, "LAST",
                         align(SENSORS[sensor], "LAST")))
    v.append(Variant("10 ms, AVERAGE", 10, None, "AVERAGE", TEN_MS))
    for policy in ("LAST", "SAMPLED"):
        v.append(Variant("10 ms, all %s" % policy, 10, None, policy,
                         TEN_MS + align(ALL_INPUTS, policy)))
    for sensor, inputs in SENSORS.items():
        for policy in ("LAST", "SAMPLED"):
            v.append(Variant("10 ms, %s %s" % (sensor, policy), 10, sensor, policy,
                             TEN_MS + align(inputs, policy)))
    wheel_policies = [
        ("HOLD LAGRANGE 0", "zero-order hold"),
        ("HOLD LAGRANGE 0 %g" % (10 * WHEEL_R), "zero-order hold, variance 10 R"),
        ("HOLD LAGRANGE 1", "first-order hold"),
        ("HOLD BEZIER 2", "Bezier hold, order 2"),
        ("HOLD TAYLOR 1", "Taylor hold, order 1"),
        ("FILL 0.001 5", "filling, omega 1 ms"),
        ("FILL 0.1 5", "filling, omega 100 ms"),
    ]
    for policy, what in wheel_policies:
        v.append(Variant("10 ms, wheels %s (%s)" % (policy, what), 10, "wheels", policy,
                         TEN_MS + align(SENSORS["wheels"], policy)))
    return v


def run_one(exe, bag, variant, work_dir, timeout):
    """Replays `bag` with `variant`; (evaluation, us per step, summary line)."""
    name = "%s_%s.csv" % (os.path.splitext(os.path.basename(bag))[0],
                          pioneer_nodes.slug(variant.label))
    csv_path = os.path.join(work_dir, name)
    summary = pioneer_nodes.replay(exe, bag, csv_path, variant.args, timeout)
    ev = evaluate.evaluate(evaluate.load_result_csv(csv_path), evaluate.load_truth(bag))
    return ev, evaluate.parse_summary_timing(summary), evaluate.summary_line(summary)


def mean_sd(values):
    values = [v for v in values if v is not None]
    if not values:
        return None, None
    return statistics.mean(values), (statistics.stdev(values) if len(values) > 1 else 0.0)


def fmt(stat, digits=3):
    m, s = stat
    return "-" if m is None else "%.*f ± %.*f" % (digits, m, digits, s)


def metrics(evs):
    """label -> (mean, sd) over the bags of the final position error, the position RMSE and
    the |final heading error|."""
    return {"final": mean_sd([e.final_pos_err for e in evs]),
            "rmse": mean_sd([e.rmse_pos for e in evs]),
            "heading": mean_sd([abs(e.final_heading_err_deg) for e in evs])}


def best_per_sensor(results, all_variants, period=10):
    """{sensor: (best variant, its metrics, the AVERAGE metrics, whether every candidate gave
    the same RMSE to 0.1 mm)} by mean position RMSE among the runs at `period` ms changing
    only that sensor (AVERAGE included)."""
    base = next(v for v in all_variants if v.period == period and v.sensor is None
                and v.policy == "AVERAGE")
    out = collections.OrderedDict()
    for sensor in SENSORS:
        candidates = [base] + [v for v in all_variants
                               if v.period == period and v.sensor == sensor]
        if len(candidates) < 2:
            continue
        rmses = [round(results[v.label]["rmse"][0], 4) for v in candidates]
        best = min(candidates, key=lambda v: results[v.label]["rmse"][0])
        out[sensor] = (best, results[best.label], results[base.label], len(set(rmses)) == 1)
    return out


def identical_groups(results, all_variants, digits=4):
    """Groups (lists of labels, 2 or more) of runs whose mean final error and RMSE agree to
    `digits` decimals: the policies that coincide on these bags."""
    groups = collections.OrderedDict()
    for v in all_variants:
        r = results[v.label]
        key = (v.period, round(r["final"][0], digits), round(r["rmse"][0], digits))
        groups.setdefault(key, []).append(v.label)
    return [g for g in groups.values() if len(g) > 1]


def page_section(results, timings, all_variants, bags, seconds, machine, revision):
    lines = []
    w = lines.append
    names = ", ".join("`%s`" % os.path.basename(b) for b in bags)
    w("## Pioneer 3-AT: alignment policies of the nav3ctrl UKF")
    w("")
    w("`tools/eval/pioneer_policies.py` replays %s through `sf_nav3ctrl_ukf` "
      "(config/nav3ctrl_ukf.h) with the policies below (`--estimation-period`, `--align "
      "INPUT=POLICY`; inputs 0 gyroscope and 1 accelerometer at 100 Hz, 2 and 3 the wheel "
      "speeds at 10 Hz) and evaluates each run against the ground truth. Mean ± sample "
      "standard deviation over the %d bags; *final*: distance of the last estimate from the "
      "true final position; *RMSE*: position error along the path; *heading*: |final "
      "heading error|; *us/step*: mean time of one estimation step in the first bag's "
      "replay (one run, the machine shared). Runs not named change nothing against the "
      "header (AVERAGE for every input)." % (names, len(bags)))
    w("")
    w("| run | final [m] | RMSE [m] | heading [deg] | us/step |")
    w("| --- | ---: | ---: | ---: | ---: |")
    for v in all_variants:
        r = results[v.label]
        us = timings.get(v.label)
        w("| %s | %s | %s | %s | %s |" % (v.label, fmt(r["final"]), fmt(r["rmse"]),
                                          fmt(r["heading"], 2),
                                          "-" if us is None else "%.2f" % us))
    w("")
    w("Computed from the table:")
    w("")
    for period in (100, 10):
        for sensor, (best, r, base, tie) in best_per_sensor(results, all_variants,
                                                             period).items():
            if tie:
                w("- %s at %d ms: every policy tried gives the same RMSE (%s m) and final "
                  "error (%s m) as AVERAGE." % (sensor.capitalize(), period, fmt(base["rmse"]),
                                                fmt(base["final"])))
                continue
            if best.policy == "AVERAGE":
                others = [v for v in all_variants if v.period == period and v.sensor == sensor]
                w("- Best policy for the %s at %d ms (lowest mean RMSE among the runs changing "
                  "only it): **AVERAGE**, RMSE %s m, final %s m (%s)." % (
                      sensor, period, fmt(r["rmse"]), fmt(r["final"]), "; ".join(
                          "%s: RMSE %s m, final %s m" % (v.policy, fmt(results[v.label]["rmse"]),
                                                         fmt(results[v.label]["final"]))
                          for v in others)))
                continue
            change = 100.0 * (r["rmse"][0] - base["rmse"][0]) / base["rmse"][0]
            w("- Best policy for the %s at %d ms (lowest mean RMSE among the runs changing "
              "only it): **%s**, RMSE %s m, final %s m (AVERAGE: RMSE %s m, final %s m; RMSE "
              "%+.1f %%)." % (sensor, period, best.policy, fmt(r["rmse"]), fmt(r["final"]),
                              fmt(base["rmse"]), fmt(base["final"]), change))
    overall = min(all_variants, key=lambda v: results[v.label]["rmse"][0])
    w("- Lowest RMSE of all runs: **%s** (%s m, final %s m)." % (
        overall.label, fmt(results[overall.label]["rmse"]), fmt(results[overall.label]["final"])))
    for group in identical_groups(results, all_variants):
        w("- Same mean final error and RMSE (to 0.1 mm): %s." % "; ".join(group))
    w("")
    w("Command, machine: `tools/eval/pioneer_policies.py` (%d replays, %.0f s) on %s, "
      "revision %s." % (len(all_variants) * len(bags), seconds, machine, revision))
    return lines


def main(argv=None):
    parser = doc_section.command_parser(__doc__, DEFAULT_PAGE)
    parser.add_argument("--bag", action="append", help="bag (repeatable; default: the three "
                        "pioneer_seed bags)")
    parser.add_argument("--work-dir", help="replay CSVs (default: $SF_WS/results/pioneer_policies)")
    parser.add_argument("--lib-dir", help="where sf_nav3ctrl_ukf is (default: the devel space)")
    parser.add_argument("--jobs", type=int, default=2, help="parallel replays (default 2)")
    parser.add_argument("--timeout", type=int, default=300, help="s per replay (default 300)")
    args = parser.parse_args(argv)

    t_start = time.monotonic()
    bags = args.bag or DEFAULT_BAGS
    lib_dir = args.lib_dir or pioneer_nodes.find_lib_dir(EXE)
    exe = os.path.join(lib_dir or "", EXE)
    if not os.access(exe, os.X_OK):
        print("error: %s not found: build it and source devel/setup.bash, or give --lib-dir"
              % EXE, file=sys.stderr)
        return 2
    work_dir = args.work_dir or doc_section.default_work_dir("pioneer_policies")
    os.makedirs(work_dir, exist_ok=True)
    all_variants = variants()
    evs = collections.defaultdict(list)
    timings = {}
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            jobs = {(v.label, b): pool.submit(run_one, exe, b, v, work_dir, args.timeout)
                    for v in all_variants for b in bags}
            for v in all_variants:
                for b in bags:
                    ev, us, line = jobs[(v.label, b)].result()
                    evs[v.label].append(ev)
                    if b == bags[0]:
                        timings[v.label] = us
                    print("  %-58s %-18s final %.4f m, RMSE %.4f m" % (
                        v.label, os.path.basename(b), ev.final_pos_err, ev.rmse_pos))
    except (RuntimeError, ValueError, OSError) as exc:
        print("error: %s" % exc, file=sys.stderr)
        return 1
    results = {label: metrics(e) for label, e in evs.items()}
    seconds = time.monotonic() - t_start
    section = page_section(results, timings, all_variants, bags, seconds,
                           chapter5_report.machine_description(), chapter5_report.git_revision())
    doc_section.publish(args.page, SECTION, section)
    return 0


if __name__ == "__main__":
    sys.exit(main())
