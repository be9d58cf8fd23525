#!/usr/bin/python3
"""Copies a real recording into a smaller bag that keeps only the topics a fusion node or
an evaluation uses, with every message's bag time, serialised content and connection
header unchanged, bz2-compressed.

  filter_real_bag.py IN.bag OUT.bag                 the default topics (below)
  filter_real_bag.py IN.bag OUT.bag --topic /fix    only the named topics (repeatable)

The default topics are those of the Clearpath Husky recording of robot_pose_ekf's test data
(shipped as bags/husky_gps.bag, see doc/bags.md): /encoder, /imu/data, /fix, /gps,
/husky/cmd_vel and /tf. Messages are copied raw (never deserialised), in the input's
order, so the output holds byte-identical messages; the same input gives the same output
file, byte for byte.
"""

import argparse
import sys

import rosbag

DEFAULT_TOPICS = ("/encoder", "/imu/data", "/fix", "/gps", "/husky/cmd_vel", "/tf")


def filter_bag(in_path, out_path, topics=DEFAULT_TOPICS, compression="bz2"):
    """Writes the messages of `topics` from in_path into out_path; returns {topic: count}.
    Raises ValueError when a requested topic is not in the input."""
    counts = {t: 0 for t in topics}
    with rosbag.Bag(in_path) as src:
        present = set(src.get_type_and_topic_info().topics)
        missing = [t for t in topics if t not in present]
        if missing:
            raise ValueError("%s has no topic %s" % (in_path, ", ".join(missing)))
        with rosbag.Bag(out_path, "w", compression=compression) as dst:
            for topic, raw, t, header in src.read_messages(
                    topics=list(topics), raw=True, return_connection_header=True):
                dst.write(topic, raw, t, raw=True, connection_header=header)
                counts[topic] += 1
    return counts


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input")
    parser.add_argument("output")
    parser.add_argument("--topic", action="append", dest="topics",
                        help="topic to keep (repeatable; default: %s)" % " ".join(DEFAULT_TOPICS))
    parser.add_argument("--compression", default="bz2", choices=("bz2", "lz4", "none"))
    args = parser.parse_args(argv)
    counts = filter_bag(args.input, args.output, tuple(args.topics or DEFAULT_TOPICS),
                        args.compression)
    for topic, n in counts.items():
        print("%-16s %6d messages" % (topic, n))
    return 0


if __name__ == "__main__":
    sys.exit(main())
