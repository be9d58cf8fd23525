#!/usr/bin/python3
"""Soccer-robot report (Wang et al.): replays soccer bags offline through sf_soccer_kf
(config/soccer_kf.h) and compares the fused position with each sensor alone, against the
bag's ground_truth/pose.

Per bag it prints the accuracy table (tools/eval/evaluate.py) of
  kf              the Kalman filter's position, every 1 ms estimate
  vision          the 32 Hz vision samples at their own stamps (the sensor's noise alone)
  vision held     the latest vision sample to have arrived (bag time) at every 1 ms estimate
                  time: what a 1 kHz controller gets from vision alone (noise plus the
                  motion since the frame, and its transport delay in a realistic bag)
  encoder         the 1 kHz encoder positions (the drifting bias alone)
and, for every stretch of lost vision frames (a gap in vision/pose longer than 1.5 frame
periods), the largest error of the filter and of the held vision inside it.

Output directory (--out-dir; default $SF_WS/results/soccer): replay/<bag>.csv and .txt,
table.txt, table.md and per bag <bag>_fig4.png: the position estimate against vision,
encoder and truth over one second (Wang Fig. 4), and the errors over the whole run with the
vision gaps shaded.

Usage: soccer_report.py [--bag BAG]... [--out-dir DIR] [--lib-dir DIR] [--exe EXE]
The devel space must be sourced (or give --lib-dir).
"""

import argparse
import bisect
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import evaluate  # noqa: E402
import pioneer_nodes  # noqa: E402  (replay runner and devel-space lookup)

DEFAULT_BAGS = [os.path.join(REPO, "bags", b) for b in ("soccer_seed1.bag", "soccer_lost_vision.bag")]
VISION_TOPIC = "vision/pose"
ENCODER_TOPIC = "encoder/pose"
GAP_FACTOR = 1.5  # a vision gap: consecutive frames more than this many periods apart


def load_arrivals(bag_path, topic):
    """The PointStamped samples of `topic` at their arrival (bag) times, not their header
    stamps: what a controller holding the latest frame has. With the transport delay of a
    realistic bag (soccer_sim.py --realistic wang) a frame arrives after its stamp; a frame
    recorded twice counts once, at its first arrival."""
    import rosbag
    t, x, y, seen = [], [], [], set()
    with rosbag.Bag(bag_path) as bag:
        for _, msg, stamp in bag.read_messages(topics=[topic]):
            key = (msg.header.seq, msg.header.stamp.to_nsec())
            if key in seen:
                continue
            seen.add(key)
            t.append(stamp.to_sec())
            x.append(msg.point.x)
            y.append(msg.point.y)
    return evaluate.make_trajectory(t, x, y)


def zero_order_hold(samples, times):
    """Trajectory at `times` holding the latest sample at or before each time (times before
    the first sample are left out)."""
    t, x, y = [], [], []
    for stamp in times:
        k = bisect.bisect_right(samples.t, stamp + evaluate.DEFAULT_TIME_TOLERANCE) - 1
        if k < 0:
            continue
        t.append(stamp)
        x.append(samples.x[k])
        y.append(samples.y[k])
    return evaluate.make_trajectory(t, x, y)


def gaps(stamps, factor=GAP_FACTOR):
    """(last stamp before, first stamp after) of every interval longer than `factor` times
    the median interval of the increasing `stamps`."""
    steps = [b - a for a, b in zip(stamps, stamps[1:])]
    if not steps:
        return []
    nominal = statistics.median(steps)
    return [(a, b) for a, b in zip(stamps, stamps[1:]) if b - a > factor * nominal]


def max_error_between(ev, start, end):
    """Largest position error of evaluation `ev` with start < stamp < end (None if none)."""
    errors = [e for t, e in zip(ev.times, ev.pos_errors) if start < t < end]
    return max(errors) if errors else None


def plot_fig4(path, truth, vision, encoder, kf, evaluations, vision_gaps, window, title):
    """Top: x over `window` (start, end) [s since start]: truth, vision, encoder, estimate
    (Wang Fig. 4). Bottom: position errors over the run, vision gaps shaded."""
    plt = evaluate._pyplot()
    t0 = truth.t[0]
    fig, (ax, ae) = plt.subplots(2, 1, figsize=(11, 8))

    def part(tr):
        ks = [k for k, t in enumerate(tr.t) if window[0] <= t - t0 <= window[1]]
        return [tr.t[k] - t0 for k in ks], [tr.x[k] for k in ks]

    ax.plot(*part(truth), "-", color="black", lw=2.5, alpha=0.35, label="ground truth")
    ax.plot(*part(encoder), "-", color="tab:blue", lw=1.0, label="encoder (1000 Hz)")
    ax.plot(*part(vision), "o", color="tab:green", markersize=4, label="vision (32 Hz)")
    ax.plot(*part(kf), "-", color="tab:red", lw=1.2, label="Kalman filter estimate (1 kHz)")
    ax.set_xlabel("time since start (s)")
    ax.set_ylabel("x (m)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="best")
    ax.set_title("position x (Wang et al. Fig. 4)")

    for label, ev in evaluations:
        ae.plot([t - t0 for t in ev.times], ev.pos_errors, "-", lw=1.0, label=label)
    for k, (a, b) in enumerate(vision_gaps):
        ae.axvspan(a - t0, b - t0, color="gray", alpha=0.25, label="vision lost" if k == 0 else None)
    ae.set_yscale("log")
    ae.set_xlabel("time since start (s)")
    ae.set_ylabel("position error (m)")
    ae.grid(True, alpha=0.3, which="both")
    ae.legend(fontsize=8, loc="best")
    ae.set_title("position error against ground truth")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def report_bag(bag, exe, replay_dir, out_dir, timeout):
    """Replays and evaluates one bag; returns (text lines, markdown lines)."""
    name = os.path.splitext(os.path.basename(bag))[0]
    csv_path = os.path.join(replay_dir, name + ".csv")
    summary = pioneer_nodes.replay(exe, bag, csv_path, [], timeout)
    with open(os.path.join(replay_dir, name + ".txt"), "w") as f:
        f.write(" ".join([exe, "--replay", bag, "--csv", csv_path]) + "\n" + summary + "\n")
    print("  %-20s %s" % (name, evaluate.summary_line(summary)))

    truth = evaluate.load_truth(bag)
    kf = evaluate.load_result_csv(csv_path, ["x0", "x1"])
    vision = evaluate.load_pose_bag(bag, VISION_TOPIC, with_heading=False)
    encoder = evaluate.load_pose_bag(bag, ENCODER_TOPIC, with_heading=False)
    held = zero_order_hold(load_arrivals(bag, VISION_TOPIC), kf.t)
    results = [("kf", kf), ("vision", vision), ("vision held", held), ("encoder", encoder)]
    evaluations = [(label, evaluate.evaluate(tr, truth)) for label, tr in results]
    timing = evaluate.parse_summary_timing(summary)
    rows = [(label, ev, timing if label == "kf" else None) for label, ev in evaluations]

    heading = "%s, %.1f s: position errors against ground_truth/pose" % (
        name, truth.t[-1] - truth.t[0])
    text = [heading, evaluate.format_table(rows)]
    md = ["**%s**" % heading, "", evaluate.format_table(rows, markdown=True)]
    vision_gaps = gaps(vision.t)
    by_label = dict(evaluations)
    if vision_gaps:
        text.append("vision gaps: start [s]  length [s]  frames lost  kf max error [m]  "
                    "kf max error before [m]  vision held max error [m]")
        md += ["", "| vision gap from [s] | length [s] | frames lost | kf max error in gap [m] "
               "| kf max error, same length before [m] | vision held max error in gap [m] |",
               "| ---: | ---: | ---: | ---: | ---: | ---: |"]
        period = statistics.median(b - a for a, b in zip(vision.t, vision.t[1:]))
        for a, b in vision_gaps:
            lost = round((b - a) / period) - 1
            inside = max_error_between(by_label["kf"], a, b)
            before = max_error_between(by_label["kf"], 2 * a - b, a)
            hold = max_error_between(by_label["vision held"], a, b)
            cells = (a - truth.t[0], b - a, lost, inside, before, hold)
            text.append("             %8.3f  %10.3f  %11d  %16.4f  %23.4f  %26.4f" % cells)
            md.append("| %.3f | %.3f | %d | %.4f | %.4f | %.4f |" % cells)
    mid = 0.5 * (truth.t[-1] - truth.t[0])
    fig = os.path.join(out_dir, name + "_fig4.png")
    plot_fig4(fig, truth, vision, encoder, kf, [(l, by_label[l]) for l in ("kf", "vision held",
                                                                          "encoder")],
              vision_gaps, (mid, mid + 1.0), "%s (offline replay of %s)" % (
                  name, os.path.basename(exe)))
    return text, md, fig


def main(argv=None):
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    parser.add_argument("--bag", action="append",
                        help="bag to replay (repeatable; default: bags/soccer_seed1.bag and "
                        "bags/soccer_lost_vision.bag)")
    parser.add_argument("--out-dir", help="output directory (default: $SF_WS/results/soccer)")
    parser.add_argument("--lib-dir", help="where sf_soccer_kf is (default: lib/sf_pkg of the "
                        "sourced devel space)")
    parser.add_argument("--exe", default="sf_soccer_kf", help="node to replay (default %(default)s)")
    parser.add_argument("--timeout", type=int, default=120, help="s per replay (default 120)")
    args = parser.parse_args(argv)

    t_start = time.monotonic()
    lib_dir = args.lib_dir or pioneer_nodes.find_lib_dir(args.exe)
    exe = args.exe if os.sep in args.exe else os.path.join(lib_dir or "", args.exe)
    if not os.access(exe, os.X_OK):
        print("error: %s not found: build it and source devel/setup.bash, or give --lib-dir"
              % args.exe, file=sys.stderr)
        return 2
    if args.out_dir:
        out_dir = args.out_dir
    elif os.environ.get("SF_WS"):
        out_dir = os.path.join(os.environ["SF_WS"], "results", "soccer")
    else:  # <workspace>/devel/lib/sf_pkg -> <workspace>/results/soccer
        out_dir = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
            os.path.abspath(os.path.dirname(exe))))), "results", "soccer")
    replay_dir = os.path.join(out_dir, "replay")
    os.makedirs(replay_dir, exist_ok=True)

    text, md, figures = [], [], []
    for bag in args.bag or DEFAULT_BAGS:
        try:
            t, m, fig = report_bag(bag, exe, replay_dir, out_dir, args.timeout)
        except (RuntimeError, ValueError, OSError) as exc:
            print("error: %s: %s" % (bag, exc), file=sys.stderr)
            return 1
        text += t + [""]
        md += m + [""]
        figures.append(fig)
    print()
    print("\n".join(text))
    with open(os.path.join(out_dir, "table.txt"), "w") as f:
        f.write("\n".join(text))
    with open(os.path.join(out_dir, "table.md"), "w") as f:
        f.write("\n".join(md))
    print("results in %s: table.txt, table.md, %s, replay/*.csv" % (
        out_dir, ", ".join(os.path.basename(p) for p in figures)))
    print("report done in %.1f s" % (time.monotonic() - t_start))
    return 0


if __name__ == "__main__":
    sys.exit(main())
