#!/usr/bin/python3
"""Digest of a bag's message content, independent of how the file is laid out.

Hashes, in bag order, every message's topic, type, bag time and serialised bytes (MD5),
and prints one line per topic (count, first and last bag time, MD5 of that topic) and a
last line with the MD5 of the whole content. Two bags with equal digests hold the same
messages at the same times, whatever their compression or chunking.

  bag_digest.py bags/pioneer_seed1.bag [more.bag ...]
  bag_digest.py --dump bags/soccer_seed1.bag | head     # one text line per message
"""

import argparse
import hashlib
import sys

import rosbag


def digest(path, dump=None):
    total = hashlib.md5()
    topics = {}
    with rosbag.Bag(path) as bag:
        for topic, raw, t in bag.read_messages(raw=True):
            msg_type, data, md5sum = raw[0], raw[1], raw[2]
            stamp = "%d.%09d" % (t.secs, t.nsecs)
            line = b"%s %s %s %s " % (topic.encode(), msg_type.encode(), md5sum.encode(), stamp.encode())
            total.update(line + data + b"\n")
            entry = topics.setdefault(topic, [0, stamp, stamp, hashlib.md5(), msg_type])
            entry[0] += 1
            entry[2] = stamp
            entry[3].update(line + data + b"\n")
            if dump is not None:
                dump.write("%s %s %s %s\n" % (stamp, topic, msg_type, data.hex()))
    return topics, total.hexdigest()


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("bags", nargs="+")
    parser.add_argument("--dump", action="store_true", help="print every message instead of the digest")
    args = parser.parse_args(argv)
    for path in args.bags:
        if args.dump:
            digest(path, sys.stdout)
            continue
        topics, whole = digest(path)
        print("# %s" % path)
        for topic in sorted(topics):
            count, first, last, md5, msg_type = topics[topic]
            print("%-22s %-30s %7d  %s .. %s  %s" % (topic, msg_type, count, first, last, md5.hexdigest()))
        print("content-md5 %s" % whole)
    return 0


if __name__ == "__main__":
    sys.exit(main())
