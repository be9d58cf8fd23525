"""Unit tests of the fusion block's offline plumbing (tools/eval/fusion_block.py) and of the
generated doc sections (tools/eval/doc_section.py), on hand-made bags and texts with known
contents. No fusion node is needed: the nodes' part is test/robots/test_fusion_block_replay.py.
"""

import csv
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "tools", "eval"))
sys.dont_write_bytecode = True
import doc_section  # noqa: E402
import fusion_block  # noqa: E402

try:
    import rosbag
    import rospy
    from std_msgs.msg import Float64, String
except ImportError:  # pragma: no cover - Debian's python3-rosbag is a package dependency
    rosbag = None


def write_bag(path, messages):
    """messages: (topic, value, time [s]) written in the given order."""
    with rosbag.Bag(path, "w") as bag:
        for topic, value, t in messages:
            msg = String(data=value) if isinstance(value, str) else Float64(data=value)
            bag.write(topic, msg, rospy.Time.from_sec(t))


def read_bag(path):
    with rosbag.Bag(path) as bag:
        return [(topic, msg.data, round(t.to_sec(), 6)) for topic, msg, t in bag.read_messages()]


@unittest.skipIf(rosbag is None, "python3-rosbag missing")
class MergeBagsTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory(prefix="sf_merge_test_")
        self.path = lambda name: os.path.join(self.tmp.name, name)

    def tearDown(self):
        self.tmp.cleanup()

    def test_messages_in_time_order(self):
        write_bag(self.path("a.bag"), [("/a/x", 1.0, 10.001), ("/a/x", 2.0, 10.003),
                                       ("/a/y", 3.0, 10.003)])
        write_bag(self.path("b.bag"), [("/b/x", 4.0, 10.000), ("/b/x", 5.0, 10.003),
                                       ("/b/x", 6.0, 10.004)])
        counts = fusion_block.merge_bags([self.path("a.bag"), self.path("b.bag")],
                                         self.path("m.bag"))
        self.assertEqual(counts, {"/a/x": 2, "/a/y": 1, "/b/x": 3})
        merged = read_bag(self.path("m.bag"))
        # rosbag reads messages of equal time ordered by connection, not by write order, so
        # only the times' order and each topic's own order are the merge's to keep
        self.assertEqual([t for _, _, t in merged],
                         [10.0, 10.001, 10.003, 10.003, 10.003, 10.004])
        self.assertEqual(sorted(merged), sorted(read_bag(self.path("a.bag")) +
                                                read_bag(self.path("b.bag"))))
        for topic, values in (("/a/x", [1.0, 2.0]), ("/b/x", [4.0, 5.0, 6.0])):
            self.assertEqual([v for tp, v, _ in merged if tp == topic], values)
        self.assertFalse(os.path.exists(self.path("m.bag.partial")))

    def test_state_topics_left_out(self):
        # every replay writes /<name>/state; with the default name they would collide
        write_bag(self.path("a.bag"), [("/a/x", 1.0, 1.0), ("/sf_filter/state", "a", 1.0)])
        write_bag(self.path("b.bag"), [("/b/x", 2.0, 1.0), ("/sf_filter/state", "b", 1.0)])
        counts = fusion_block.merge_bags([self.path("a.bag"), self.path("b.bag")],
                                         self.path("m.bag"))
        self.assertEqual(counts, {"/a/x": 1, "/b/x": 1})

    def test_one_topic_in_two_inputs_is_refused(self):
        write_bag(self.path("a.bag"), [("/x", 1.0, 1.0)])
        write_bag(self.path("b.bag"), [("/x", 2.0, 2.0)])
        with self.assertRaisesRegex(ValueError, "topic /x is in both"):
            fusion_block.merge_bags([self.path("a.bag"), self.path("b.bag")], self.path("m.bag"))
        self.assertFalse(os.path.exists(self.path("m.bag")))


@unittest.skipIf(rosbag is None, "python3-rosbag missing")
class LoadRecordingTest(unittest.TestCase):
    def test_axes_paired_by_stamp(self):
        Entity = fusion_block.output_entity_class()
        with tempfile.TemporaryDirectory(prefix="sf_recording_test_") as tmp:
            path = os.path.join(tmp, "rec.bag")
            with rosbag.Bag(path, "w") as bag:
                for k, stamp in enumerate((5.001, 5.002, 5.003)):
                    for prefix in ("vision_kf", "encoder_kf", "fused"):
                        for axis, value in (("x", 1.0 + k), ("y", -1.0 - k)):
                            if prefix == "fused" and axis == "y" and k == 1:
                                continue  # a message the recorder lost
                            # the CWA's empty first period: value 0, variance inf
                            empty = prefix == "fused" and k == 0
                            msg = Entity(value=0.0 if empty else value,
                                         variance=float("inf") if empty else 0.1)
                            msg.header.stamp = rospy.Time.from_sec(stamp)
                            # recorded later than stamped, in another order
                            bag.write("/fusion_block/%s/position/%s" % (prefix, axis), msg,
                                      rospy.Time.from_sec(stamp + 0.0004))
            tr = fusion_block.load_recording(path)
        self.assertEqual(sorted(tr), ["encoder_kf", "fusion_block", "vision_kf"])
        self.assertEqual([round(t, 6) for t in tr["vision_kf"].t], [5.001, 5.002, 5.003])
        self.assertEqual(tr["vision_kf"].x, [1.0, 2.0, 3.0])
        self.assertEqual(tr["vision_kf"].y, [-1.0, -2.0, -3.0])
        self.assertEqual([round(t, 6) for t in tr["fusion_block"].t], [5.003])
        self.assertEqual(tr["fusion_block"].x, [3.0])


class JoinAxesTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory(prefix="sf_join_test_")
        self.path = lambda name: os.path.join(self.tmp.name, name)

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, name, rows):
        with open(self.path(name), "w") as f:
            f.write("time,x0,var0,present_inputs\n")
            for r in rows:
                f.write(",".join(r) + ",2\n")

    def test_columns_of_both_axes(self):
        # the first period had no input: value 0, variance inf on both axes, left out
        self.write("x.csv", [("1.000", "0", "inf"), ("1.001", "0.5", "0.01"),
                             ("1.002", "0.6", "0.02")])
        self.write("y.csv", [("1.000", "0", "inf"), ("1.001", "-1.5", "0.03"),
                             ("1.002", "-1.6", "0.04")])
        self.assertEqual(fusion_block.join_axes(self.path("x.csv"), self.path("y.csv"),
                                                self.path("xy.csv")), 2)
        with open(self.path("xy.csv")) as f:
            rows = list(csv.reader(f))
        self.assertEqual(rows, [["time", "x0", "x1", "var0", "var1", "present_inputs"],
                                ["1.001", "0.5", "-1.5", "0.01", "0.03", "2"],
                                ["1.002", "0.6", "-1.6", "0.02", "0.04", "2"]])

    def test_different_estimate_times_are_refused(self):
        self.write("x.csv", [("1.001", "0.5", "0.01")])
        self.write("y.csv", [("1.002", "-1.5", "0.03")])
        with self.assertRaisesRegex(ValueError, "different estimate times"):
            fusion_block.join_axes(self.path("x.csv"), self.path("y.csv"), self.path("xy.csv"))


class DocSectionTest(unittest.TestCase):
    def test_section_replaced_rest_kept(self):
        begin, end = doc_section.markers("s")
        text = "\n".join(["# Page", "intro", begin, "old 1", "old 2", end, "tail", ""])
        self.assertEqual(doc_section.replace_section(text, "s", ["new"]),
                         "\n".join(["# Page", "intro", begin, "new", end, "tail", ""]))

    def test_missing_section_appended(self):
        begin, end = doc_section.markers("s")
        self.assertEqual(doc_section.replace_section("# Page\n\n", "s", ["a", "b"]),
                         "\n".join(["# Page", "", begin, "a", "b", end, ""]))

    def test_other_sections_untouched(self):
        b1, e1 = doc_section.markers("one")
        b2, e2 = doc_section.markers("two")
        text = "\n".join([b1, "1", e1, b2, "2", e2])
        self.assertEqual(doc_section.replace_section(text, "two", ["II"]),
                         "\n".join([b1, "1", e1, b2, "II", e2]))

    def test_broken_markers_refused(self):
        begin, end = doc_section.markers("s")
        with self.assertRaisesRegex(ValueError, "section s"):
            doc_section.replace_section("\n".join([end, "x", begin]), "s", ["y"])
        with self.assertRaisesRegex(ValueError, "section s"):
            doc_section.replace_section("\n".join([begin, "x"]), "s", ["y"])


if __name__ == "__main__":
    unittest.main()
