"""Unit tests of tools/data/filter_real_bag.py on a hand-made bag: only the chosen topics are
kept, each message with its bag time, serialised bytes and connection header (callerid,
latching) unchanged, bz2-compressed, and the same input gives the same file."""

import io
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(REPO, "tools", "data"))

try:
    import rosbag
    import rospy
    from std_msgs.msg import Float64, String
    import filter_real_bag as fb
except ImportError:  # pragma: no cover - Debian's python3-rosbag is a package dependency
    rosbag = None

# (topic, value, bag time [s], callerid)
MESSAGES = [
    ("/a", 1.5, 10.0, "/node_a"),
    ("/b", "x", 10.05, "/node_b"),
    ("/c", 2.5, 10.1, "/node_c"),
    ("/a", -3.25, 10.2, "/node_a"),
    ("/b", "yy", 10.2, "/node_b"),
    ("/c", 7.0, 10.3, "/node_c"),
]


def write_input(path):
    with rosbag.Bag(path, "w") as bag:
        for topic, value, t, caller in MESSAGES:
            msg = String(data=value) if isinstance(value, str) else Float64(data=value)
            header = {"callerid": caller, "latching": "1" if topic == "/b" else "0",
                      "topic": topic, "type": msg._type, "md5sum": msg._md5sum,
                      "message_definition": msg._full_text}
            bag.write(topic, msg, rospy.Time.from_sec(t), connection_header=header)


@unittest.skipIf(rosbag is None, "python3-rosbag missing")
class FilterTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.inp = os.path.join(self.tmp.name, "in.bag")
        write_input(self.inp)

    def tearDown(self):
        self.tmp.cleanup()

    def out(self, name):
        return os.path.join(self.tmp.name, name)

    def test_keeps_only_the_chosen_topics_unchanged(self):
        counts = fb.filter_bag(self.inp, self.out("o.bag"), ("/a", "/b"))
        self.assertEqual(counts, {"/a": 2, "/b": 2})
        with rosbag.Bag(self.out("o.bag")) as bag:
            got = [(topic, raw[1], t.to_nsec(), hdr["callerid"], hdr.get("latching"))
                   for topic, raw, t, hdr in bag.read_messages(raw=True,
                                                                return_connection_header=True)]
            self.assertEqual(bag.get_compression_info().compression, "bz2")
        want = []
        for topic, value, t, caller in MESSAGES:
            if topic in ("/a", "/b"):
                msg = String(data=value) if isinstance(value, str) else Float64(data=value)
                buf = io.BytesIO()
                msg.serialize(buf)
                # rosbag returns the stored connection header fields as bytes
                want.append((topic, buf.getvalue(), rospy.Time.from_sec(t).to_nsec(),
                             caller.encode(), b"1" if topic == "/b" else b"0"))
        self.assertEqual(got, want)

    def test_deterministic(self):
        fb.filter_bag(self.inp, self.out("1.bag"), ("/a", "/c"))
        fb.filter_bag(self.inp, self.out("2.bag"), ("/a", "/c"))
        with open(self.out("1.bag"), "rb") as f1, open(self.out("2.bag"), "rb") as f2:
            self.assertEqual(f1.read(), f2.read())

    def test_missing_topic_is_an_error(self):
        with self.assertRaises(ValueError):
            fb.filter_bag(self.inp, self.out("m.bag"), ("/a", "/nope"))


if __name__ == "__main__":
    unittest.main()
