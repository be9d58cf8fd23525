#!/usr/bin/python3
"""Soccer-robot comparison (issue 5, Wang et al.'s set-up on the shipped bags): replays each
soccer bag through the centralised Kalman filter config/soccer_kf.h with the alignment
policies of Wang et al.'s Table II rows and Armesto's multi-rate sampler, and through the
fusion block (tools/eval/fusion_block.py), evaluates every position against the bag's
ground_truth/pose, and writes the section `soccer_comparison` of the page (default
doc/multirate_experiments.md).

Runs (inputs of soccer_kf.h: 0, 1 vision x, y at 32 Hz; 2, 3 encoder x, y at 1 kHz):
  Kalman filter      the header: every input AVERAGE at 1 ms, so vision corrects the filter
                     only in the periods a frame arrives in (Wang's "Kalman filter" row)
  SAMPLED            every input SAMPLED (Armesto's multi-rate sampler)
  multi-rate hold    vision HOLD BEZIER 4 (Wang's N_m = 5 stored samples), substitutes with
                     R x 10 (their R_m = 1 against R_K = 0.1, footnotes 3-4), and with R
  filling            vision FILL 0.001 5 (omega 1 ms, N = 5, R: footnote 2)
  fusion block       vision filter + encoder filter -> confidence-weighted average per axis
and the sensors alone: each per-sensor filter of the block, the latest vision frame held at
every 1 ms, the raw encoder.

Usage: soccer_comparison.py [--bag BAG]... [--page FILE] [--work-dir DIR] [--lib-dir DIR]
The devel space must be sourced (or give --lib-dir).
"""

import collections
import filecmp
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import chapter5_report  # noqa: E402  (machine description, git revision)
import doc_section  # noqa: E402
import evaluate  # noqa: E402
import fusion_block  # noqa: E402
import pioneer_nodes  # noqa: E402
import soccer_report  # noqa: E402  (vision gaps, zero-order hold of vision)

DEFAULT_BAGS = [os.path.join(REPO, "bags", b)
                for b in ("soccer_seed1.bag", "soccer_lost_vision.bag")]
DEFAULT_PAGE = os.path.join(REPO, "doc", "multirate_experiments.md")
SECTION = "soccer_comparison"
EXE = "sf_soccer_kf"
VISION_R = 1.2544e-4  # m^2, R of the vision inputs in soccer_kf.h
VISION, ALL = [0, 1], [0, 1, 2, 3]


def align(inputs, policy):
    out = []
    for i in inputs:
        out += ["--align", "%d=%s" % (i, policy)]
    return out


# label -> soccer_kf replay arguments
KF_RUNS = collections.OrderedDict([
    ("Kalman filter (soccer_kf.h)", []),
    ("SAMPLED", align(ALL, "SAMPLED")),
    ("multi-rate hold, R x 10", align(VISION, "HOLD BEZIER 4 %g" % (10 * VISION_R))),
    ("multi-rate hold, R", align(VISION, "HOLD BEZIER 4")),
    ("filling", align(VISION, "FILL 0.001 5")),
])
FUSION_BLOCK = "fusion block"
# The rows of the table, and the ones that are methods (the rest: sensors alone).
METHODS = list(KF_RUNS) + [FUSION_BLOCK]
SENSORS_ALONE = ["vision filter alone", "encoder filter alone", "vision held", "encoder"]

# The gap tables list the stretches of lost vision (more than this many frame periods between
# two frames), not the single frames a realistic bag loses at random.
LONG_GAP_PERIODS = 10
BagResult = collections.namedtuple("BagResult", "name duration evaluations timings gaps identical")


def run_bag(bag, lib_dir, work_dir, timeout, log=print):
    """Every run on one bag; a BagResult."""
    name = os.path.splitext(os.path.basename(bag))[0]
    out = os.path.join(work_dir, name)
    os.makedirs(out, exist_ok=True)
    csvs, timings = collections.OrderedDict(), {}
    for label, extra in KF_RUNS.items():
        csvs[label] = os.path.join(out, pioneer_nodes.slug(label) + ".csv")
        summary = pioneer_nodes.replay(os.path.join(lib_dir, EXE), bag, csvs[label], extra,
                                       timeout)
        timings[label] = evaluate.parse_summary_timing(summary)
        log("  %-22s %-28s %s" % (name, label, evaluate.summary_line(summary)))
    chain, summaries = fusion_block.run_chain(bag, lib_dir, os.path.join(out, "fusion_block"),
                                              timeout, log=lambda s: log("  %-22s %s" % (name, s)))
    # time of one estimate of the block: its four nodes' steps
    steps = [evaluate.parse_summary_timing(s) for s in summaries.values()]
    timings[FUSION_BLOCK] = sum(steps) if all(v is not None for v in steps) else None
    csvs[FUSION_BLOCK] = chain["fusion_block"]
    csvs["vision filter alone"] = chain["vision_kf"]
    csvs["encoder filter alone"] = chain["encoder_kf"]

    truth = evaluate.load_truth(bag)
    trajectories = collections.OrderedDict(
        (label, evaluate.load_result_csv(path, ["x0", "x1"])) for label, path in csvs.items())
    vision = evaluate.load_pose_bag(bag, soccer_report.VISION_TOPIC, with_heading=False)
    trajectories["vision held"] = soccer_report.zero_order_hold(
        soccer_report.load_arrivals(bag, soccer_report.VISION_TOPIC), trajectories[METHODS[0]].t)
    trajectories["encoder"] = evaluate.load_pose_bag(bag, soccer_report.ENCODER_TOPIC,
                                                     with_heading=False)
    evaluations = collections.OrderedDict(
        (label, evaluate.evaluate(tr, truth)) for label, tr in trajectories.items())
    identical = [label for label in KF_RUNS
                 if label != METHODS[0]
                 and filecmp.cmp(csvs[label], csvs[METHODS[0]], shallow=False)]
    return BagResult(name, truth.t[-1] - truth.t[0], evaluations, timings,
                     soccer_report.gaps(vision.t, LONG_GAP_PERIODS), identical)


def max_error(ev, start=None, end=None):
    errors = [e for t, e in zip(ev.times, ev.pos_errors)
              if (start is None or t > start) and (end is None or t < end)]
    return max(errors) if errors else None


def table(results):
    """Markdown lines: one row per run, RMSE and max error per bag, and the time per step."""
    head = "| run |"
    rule = "| --- |"
    for r in results:
        head += " %s RMSE [m] | max [m] |" % r.name
        rule += " ---: | ---: |"
    head += " time/step [us] |"
    rule += " ---: |"
    lines = [head, rule]
    for label in METHODS + SENSORS_ALONE:
        row = "| %s |" % ("**%s**" % label if label in METHODS else label)
        for r in results:
            ev = r.evaluations[label]
            row += " %.4f | %.4f |" % (ev.rmse_pos, max_error(ev))
        us = results[0].timings.get(label)
        row += " %s |" % ("-" if us is None else "%.2f" % us)
        lines.append(row)
    return lines


def gap_table(result):
    """Markdown lines: per lost-vision stretch of one bag, each method's largest error."""
    labels = METHODS + ["vision filter alone", "encoder filter alone", "vision held"]
    lines = ["| vision lost [s] | " + " | ".join(labels) + " |",
             "| --- |" + " ---: |" * len(labels)]
    t0 = result.evaluations[METHODS[0]].times[0]
    for a, b in result.gaps:
        cells = [max_error(result.evaluations[l], a, b) for l in labels]
        lines.append("| %.3f to %.3f | %s |" % (a - t0, b - t0,
                                                " | ".join("%.4f" % c for c in cells)))
    return lines


def verdicts(results):
    """Sentences computed from the numbers: which method wins per bag, the block against the
    centralised filter, the lost-vision stretches."""
    out = []
    kf = METHODS[0]
    for r in results:
        ranked = sorted(METHODS, key=lambda l: r.evaluations[l].rmse_pos)
        best = ranked[0]
        out.append("- `%s`: lowest position RMSE **%s** (%.4f m); then %s." % (
            r.name, best, r.evaluations[best].rmse_pos, ", ".join(
                "%s %.4f m" % (l, r.evaluations[l].rmse_pos) for l in ranked[1:])))
        fb, vis = r.evaluations[FUSION_BLOCK], r.evaluations["vision filter alone"]
        out.append("  The fusion block's RMSE is %.1f times the centralised filter's and "
                   "%.0f %% of its own vision filter's (%.4f m)." % (
                       fb.rmse_pos / r.evaluations[kf].rmse_pos,
                       100.0 * fb.rmse_pos / vis.rmse_pos, vis.rmse_pos))
        if r.identical:
            out.append("  %s: the same CSV as the header's run, byte for byte." % (
                ", ".join(r.identical)))
        for a, b in r.gaps:
            worst = {l: max_error(r.evaluations[l], a, b) for l in METHODS}
            order = sorted(METHODS, key=lambda l: worst[l])
            out.append("  Vision lost for %.2f s: largest error in the gap %s." % (
                b - a, ", ".join("%s %.4f m" % (l, worst[l]) for l in order)))
    return out


def page_section(results, seconds, machine, revision):
    lines = ["## Soccer robot: Kalman filter, multi-rate sampler, hold, filling, fusion block",
             "",
             "`tools/eval/soccer_comparison.py` replays %s through `sf_soccer_kf` "
             "(config/soccer_kf.h) with the policies of Wang et al.'s Table II rows "
             "(`--align`), and through the fusion block ([fusion_block.md](fusion_block.md)). "
             "Position error against `ground_truth/pose` at every 1 ms estimate: RMSE and "
             "largest error over the run (2-D). *time/step*: mean time of one estimation "
             "step in the first bag's replay (fusion block: its four nodes' steps added; one "
             "run on the shared machine). Bold: the methods; the rest are the sensors alone "
             "(the block's per-sensor filters, the latest vision frame held, the raw encoder)."
             % ", ".join("`%s.bag` (%.0f s)" % (r.name, r.duration) for r in results), ""]
    lines += table(results)
    for r in results:
        if r.gaps:
            lines += ["", "Largest position error [m] while vision is lost in `%s.bag` (from "
                      "the last frame before to the first after; stretches longer than %d "
                      "frame periods):" % (r.name, LONG_GAP_PERIODS), ""]
            lines += gap_table(r)
    lines += ["", "Computed from the tables:", ""]
    lines += verdicts(results)
    lines += ["", "Command, machine: `tools/eval/soccer_comparison.py` (%.0f s) on %s, "
              "revision %s." % (seconds, machine, revision)]
    return lines


def main(argv=None):
    parser = doc_section.command_parser(__doc__, DEFAULT_PAGE)
    parser.add_argument("--bag", action="append", help="soccer bag (repeatable; default: "
                        "soccer_seed1.bag and soccer_lost_vision.bag)")
    parser.add_argument("--work-dir",
                        help="replay outputs (default: $SF_WS/results/soccer_comparison)")
    parser.add_argument("--lib-dir",
                        help="where the sf_soccer_* nodes are (default: the devel space)")
    parser.add_argument("--timeout", type=int, default=300, help="s per replay (default 300)")
    args = parser.parse_args(argv)

    t_start = time.monotonic()
    try:
        lib_dir = fusion_block.find_executables(args.lib_dir)
        if not os.access(os.path.join(lib_dir, EXE), os.X_OK):
            raise RuntimeError("%s not found in %s" % (EXE, lib_dir))
    except RuntimeError as exc:
        print("error: %s" % exc, file=sys.stderr)
        return 2
    work_dir = args.work_dir or doc_section.default_work_dir("soccer_comparison")
    results = []
    try:
        for bag in args.bag or DEFAULT_BAGS:
            results.append(run_bag(bag, lib_dir, work_dir, args.timeout))
    except (RuntimeError, ValueError, OSError) as exc:
        print("error: %s" % exc, file=sys.stderr)
        return 1
    section = page_section(results, time.monotonic() - t_start,
                           chapter5_report.machine_description(), chapter5_report.git_revision())
    doc_section.publish(args.page, SECTION, section)
    return 0


if __name__ == "__main__":
    sys.exit(main())
