#!/usr/bin/python3
"""The soccer robot's fusion block offline (thesis section 4.2.1, Figure 4.2; the vision/radar
paper's decentralised filters fused by weights): the same chain of nodes as
launch/soccer_fusion_block.launch, without a ROS master.

  1. the bag is replayed through the per-sensor filters, each writing its output bag
       sf_soccer_vision_kf   (config/soccer_vision_kf.h)   vision_kf/position/{x,y}
       sf_soccer_encoder_kf  (config/soccer_encoder_kf.h)  encoder_kf/position/{x,y}
  2. both output bags are replayed as one recording (--replay with two bags: merged in time
     order) through the confidence-weighted averaging of each axis
       sf_soccer_cwa_x, sf_soccer_cwa_y (config/soccer_fusion_cwa.h)  fused/position/{x,y}
  3. the two axes are joined into fusion_block.csv (time,x0,x1,var0,var1,present_inputs) and every
     position is merged into fusion_block.bag (python3-rosbag), the recording of the whole
     block.

It prints each stage's summary line and the position errors of the vision filter, the
encoder filter and the fused position against the bag's ground_truth/pose.

Usage: fusion_block.py [--bag BAG] [--out-dir DIR] [--lib-dir DIR]
       fusion_block.py --recording RECORDING.bag
The devel space must be sourced (or give --lib-dir). Default bag: bags/soccer_seed1.bag.
--recording evaluates a recording of launch/soccer_fusion_block.launch instead (the
per-sensor filters' and the fused positions, paired by stamp, against its ground truth).
"""

import argparse
import csv
import heapq
import math
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import evaluate  # noqa: E402
import pioneer_nodes  # noqa: E402  (replay runner and devel-space lookup)

DEFAULT_BAG = os.path.join(REPO, "bags", "soccer_seed1.bag")
# (executable, label) of the per-sensor filters, each with its position columns x0, x1.
SENSOR_FILTERS = [("sf_soccer_vision_kf", "vision_kf"), ("sf_soccer_encoder_kf", "encoder_kf")]
# (executable, axis) of the confidence-weighted averaging nodes.
AXIS_FUSION = [("sf_soccer_cwa_x", "x"), ("sf_soccer_cwa_y", "y")]
EXECUTABLES = [e for e, _ in SENSOR_FILTERS + AXIS_FUSION]


def merge_bags(inputs, output, keep=lambda topic: not topic.endswith("/state")):
    """Writes the messages of the bags `inputs` into the bag `output` in order of their bag
    time (rosbag itself reads messages of equal time in the order of their connections,
    whatever the order they were written in; each topic keeps its own order). Only topics
    for which `keep(topic)` is true are written; by default every topic but the states
    (each replay writes its whole state on /<name>/state). Returns {topic: count} of what
    was written. Raises ValueError when two inputs hold the same topic: the merged stream
    would interleave two publishers on one topic."""
    import rosbag  # Debian: python3-rosbag

    owner = {}
    bags = [rosbag.Bag(path) for path in inputs]
    try:
        for path, bag in zip(inputs, bags):
            for topic in bag.get_type_and_topic_info().topics:
                if not keep(topic):
                    continue
                if topic in owner:
                    raise ValueError("topic %s is in both %s and %s" % (topic, owner[topic], path))
                owner[topic] = path

        def stream(k, bag):
            for seq, (topic, msg, t) in enumerate(bag.read_messages(raw=True)):
                if topic in owner:
                    yield (t, k, seq, topic, msg)

        counts = {}
        with rosbag.Bag(output + ".partial", "w") as out:
            for t, _, _, topic, msg in heapq.merge(*[stream(k, b) for k, b in enumerate(bags)],
                                                   key=lambda m: m[:3]):
                out.write(topic, msg, t, raw=True)
                counts[topic] = counts.get(topic, 0) + 1
    finally:
        for bag in bags:
            bag.close()
    os.replace(output + ".partial", output)
    return counts


def join_axes(x_csv, y_csv, output):
    """fusion_block.csv (time,x0,x1,var0,var1,present_inputs) from the CWA replays of the x
    and the y axis (each time,x0,var0,present_inputs; present_inputs is the x axis's, both
    read the same stamps); returns the number of rows written. Estimates with
    an infinite variance on both axes (periods before the first input: nothing was fused;
    the CWA then reports 0 with variance inf) are left out. Raises ValueError when the two
    replays' estimate times differ: both run the same schedule on the same merged bag."""
    def rows(path):
        with open(path, newline="") as f:
            return [(r["time"], r["x0"], r["var0"], r["present_inputs"])
                    for r in csv.DictReader(f)]

    xs, ys = rows(x_csv), rows(y_csv)
    if len(xs) != len(ys) or any(a[0] != b[0] for a, b in zip(xs, ys)):
        raise ValueError("%s and %s have different estimate times" % (x_csv, y_csv))
    written = 0
    with open(output, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["time", "x0", "x1", "var0", "var1", "present_inputs"])
        for (t, x, vx, present), (_, y, vy, _) in zip(xs, ys):
            if math.isinf(float(vx)) and math.isinf(float(vy)):
                continue
            w.writerow([t, x, y, vx, vy, present])
            written += 1
    return written


def is_position(topic):
    """The per-sensor filters' topics that the CWA nodes read (their other outputs, such as
    the vision filter's velocity, stay out of the merged bag)."""
    return "/position/" in topic


def run_chain(bag, lib_dir, work_dir, timeout=120, log=print, record=False):
    """Runs the fusion block on `bag`; returns {label: csv path} of the vision filter, the
    encoder filter and the fused position ("fusion_block"), and the summaries (stage label
    -> replay summary line). With `record`, every position of the block is also merged into
    work_dir/fusion_block.bag (what launch/soccer_fusion_block.launch records online)."""
    os.makedirs(work_dir, exist_ok=True)
    exe = lambda name: os.path.join(lib_dir, name)
    csvs, summaries, stage_bags = {}, {}, []
    for name, label in SENSOR_FILTERS:
        csvs[label] = os.path.join(work_dir, label + ".csv")
        stage_bags.append(os.path.join(work_dir, label + ".bag"))
        output = pioneer_nodes.replay(exe(name), bag, csvs[label],
                                      ["--bag", stage_bags[-1], "--name", label], timeout)
        summaries[label] = evaluate.summary_line(output)
        log("  %-12s %s" % (label, summaries[label]))
    axis_csvs, axis_bags = [], []
    for name, axis in AXIS_FUSION:
        label = "cwa_" + axis
        axis_csvs.append(os.path.join(work_dir, label + ".csv"))
        axis_bags.append(os.path.join(work_dir, label + ".bag"))
        output = pioneer_nodes.replay(exe(name), stage_bags, axis_csvs[-1],
                                      ["--bag", axis_bags[-1], "--name", label], timeout)
        summaries[label] = evaluate.summary_line(output)
        log("  %-12s %s" % (label, summaries[label]))
    csvs["fusion_block"] = os.path.join(work_dir, "fusion_block.csv")
    join_axes(axis_csvs[0], axis_csvs[1], csvs["fusion_block"])
    if record:
        merge_bags(stage_bags + axis_bags, os.path.join(work_dir, "fusion_block.bag"),
                   keep=is_position)
    return csvs, summaries


def output_entity_class():
    """sf_msgs/OutputEntityStamped as a rospy message class, generated from
    sf_msgs/msg/OutputEntityStamped.msg (no devel space needed: for writing test bags)."""
    import genpy.dynamic
    from std_msgs.msg import Header

    with open(os.path.join(REPO, "sf_msgs", "msg", "OutputEntityStamped.msg")) as f:
        text = f.read()
    full = text + "\n" + "=" * 80 + "\nMSG: std_msgs/Header\n" + Header._full_text
    name = "sf_msgs/OutputEntityStamped"
    return genpy.dynamic.generate_dynamic(name, full)[name]


def load_recording(bag_path, namespace="/fusion_block"):
    """{label: trajectory} of the block's positions in a recording of
    launch/soccer_fusion_block.launch: vision_kf, encoder_kf and fusion_block, each from its
    x and y OutputEntityStamped topics paired by header.stamp (stamps with only one axis
    recorded are left out: the recorder can lose messages at 1 kHz; so are estimates with an
    infinite variance, the CWA's output for a period in which it had nothing to fuse, as in
    join_axes)."""
    import rosbag  # Debian: python3-rosbag

    prefixes = {"vision_kf": "vision_kf", "encoder_kf": "encoder_kf", "fusion_block": "fused"}
    axes = {label: ({}, {}) for label in prefixes}
    topics = {}
    for label, prefix in prefixes.items():
        for k, axis in enumerate("xy"):
            topics["%s/%s/position/%s" % (namespace, prefix, axis)] = (label, k)
    with rosbag.Bag(bag_path) as bag:
        for topic, msg, _ in bag.read_messages(topics=list(topics)):
            if math.isinf(msg.variance):
                continue
            label, k = topics[topic]
            axes[label][k][msg.header.stamp.to_sec()] = msg.value
    out = {}
    for label, (xs, ys) in axes.items():
        stamps = sorted(set(xs) & set(ys))
        if not stamps:
            raise ValueError("%s: no %s positions below %s" % (bag_path, label, namespace))
        out[label] = evaluate.make_trajectory(stamps, [xs[t] for t in stamps],
                                              [ys[t] for t in stamps])
    return out


def find_executables(lib_dir=None):
    """lib/sf_pkg holding the fusion block's executables; raises RuntimeError naming the
    missing ones."""
    lib_dir = lib_dir or pioneer_nodes.find_lib_dir("sf_soccer_cwa")
    missing = [e for e in EXECUTABLES
               if not (lib_dir and os.access(os.path.join(lib_dir, e), os.X_OK))]
    if missing:
        raise RuntimeError("%s not found: build them (CMakeLists.txt "
                           "SF_SOCCER_FUSION_BLOCK_CONFIGS) and source devel/setup.bash, or "
                           "give --lib-dir" % ", ".join(missing))
    return lib_dir


def main(argv=None):
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    parser.add_argument("--bag", default=DEFAULT_BAG, help="soccer bag (default %(default)s)")
    parser.add_argument("--out-dir", help="output directory (default: $SF_WS/results/fusion_block)")
    parser.add_argument("--lib-dir", help="where the sf_soccer_* nodes are (default: lib/sf_pkg "
                        "of the sourced devel space)")
    parser.add_argument("--timeout", type=int, default=120, help="s per replay (default 120)")
    parser.add_argument("--recording", help="instead of running the chain: evaluate a "
                        "recording of launch/soccer_fusion_block.launch against its "
                        "ground_truth/pose")
    args = parser.parse_args(argv)

    t_start = time.monotonic()
    if args.recording:
        try:
            truth = evaluate.load_truth(args.recording)
            rows = [(label, evaluate.evaluate(tr, truth), None)
                    for label, tr in load_recording(args.recording).items()]
        except (ValueError, OSError) as exc:
            print("error: %s: %s" % (args.recording, exc), file=sys.stderr)
            return 1
        print(evaluate.format_table(rows))
        return 0
    try:
        lib_dir = find_executables(args.lib_dir)
    except RuntimeError as exc:
        print("error: %s" % exc, file=sys.stderr)
        return 2
    out_dir = args.out_dir or os.path.join(os.environ.get("SF_WS", os.getcwd()), "results",
                                           "fusion_block")
    work_dir = os.path.join(out_dir, os.path.splitext(os.path.basename(args.bag))[0])
    try:
        csvs, _ = run_chain(args.bag, lib_dir, work_dir, args.timeout, record=True)
        truth = evaluate.load_truth(args.bag)
        rows = [(label, evaluate.evaluate(evaluate.load_result_csv(path, ["x0", "x1"]), truth),
                 None) for label, path in csvs.items()]
    except (RuntimeError, ValueError, OSError) as exc:
        print("error: %s: %s" % (args.bag, exc), file=sys.stderr)
        return 1
    print()
    print(evaluate.format_table(rows))
    print("results in %s (fusion_block.csv, fusion_block.bag, one CSV and bag per node)" % work_dir)
    print("fusion block done in %.1f s" % (time.monotonic() - t_start))
    return 0


if __name__ == "__main__":
    sys.exit(main())
