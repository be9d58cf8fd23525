"""The offline replay of a recording held in several bags (`--replay A.bag B.bag ...`, also
`--tune`): their messages are read as one recording, merged in recorded-time order, as
`rosbag play A.bag B.bag` plays them.

Reference: the replay of the whole bag. bags/diff_drive_seed1.bag (odom, imu/data, /tf and
/tf_static; config/diff_drive_odom_imu.h, which rotates the IMU by the bag's transforms) is
split in two at mid-time, as `rosbag record --split` would, and by topic (the IMU in one bag,
the rest in the other); each replay of the parts must write the same CSV, byte for byte. The
noise identification of test/configs/tune_cart_kf.h on a simulated cart bag split in two must
write the same tuned file. A topic stored under two spellings ("odom" and "/odom") is read
under both. Refused: a bag given twice, a part holding a configured topic of
another type (named with its bag), and a topic that none of the bags holds.
"""

import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(REPO, "tools", "sim"))
sys.dont_write_bytecode = True
import cart_sim  # noqa: E402
from replay_helpers import built_lib_dir  # noqa: E402
from test_replay_faults import write_small_bag  # noqa: E402

BAG = os.path.join(REPO, "bags", "diff_drive_seed1.bag")
NODE = "sf_diff_drive_odom_imu"
TUNE_NODE = "sf_tune_cart_kf"


def split_bag(source, parts):
    """Copies every message of `source` (raw, with its connection header) into the first bag
    of `parts` [(path, predicate(topic, time_s))] whose predicate holds."""
    import rosbag

    outputs = [(rosbag.Bag(path, "w"), keep) for path, keep in parts]
    try:
        with rosbag.Bag(source) as bag:
            for topic, raw, t, header in bag.read_messages(raw=True,
                                                           return_connection_header=True):
                out = next(b for b, keep in outputs if keep(topic, t.to_sec()))
                out.write(topic, raw, t, raw=True, connection_header=header)
    finally:
        for out, _ in outputs:
            out.close()


def time_span(path):
    import rosbag

    with rosbag.Bag(path) as bag:
        return bag.get_start_time(), bag.get_end_time()


class SeveralBagsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.exe = os.path.join(built_lib_dir(NODE), NODE)

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory(prefix="sf_several_bags_")

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.tmp.name, name)

    def run_node(self, exe, *args):
        return subprocess.run([exe] + list(args), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              universal_newlines=True, timeout=300)

    def replay_csv(self, bags, name):
        csv_path = self.path(name)
        proc = self.run_node(self.exe, "--replay", *bags, "--csv", csv_path)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(csv_path) as f:
            return f.read()

    def test_split_at_mid_time_replays_as_the_whole_bag(self):
        start, end = time_span(BAG)
        middle = (start + end) / 2
        first, second = self.path("part_0.bag"), self.path("part_1.bag")
        split_bag(BAG, [(first, lambda topic, t: t < middle), (second, lambda topic, t: True)])
        whole = self.replay_csv([BAG], "whole.csv")
        self.assertGreater(whole.count("\n"), 1000)
        self.assertEqual(self.replay_csv([first, second], "parts.csv"), whole)
        # the order of the bags on the command line does not matter: time orders them
        self.assertEqual(self.replay_csv([second, first], "reversed.csv"), whole)

    def test_topics_in_separate_bags_replay_as_the_whole_bag(self):
        imu, rest = self.path("imu.bag"), self.path("rest.bag")
        split_bag(BAG, [(imu, lambda topic, t: "imu" in topic), (rest, lambda topic, t: True)])
        self.assertEqual(self.replay_csv([imu, rest], "parts.csv"),
                         self.replay_csv([BAG], "whole.csv"))

    def test_tuning_over_split_bags_equals_tuning_over_the_whole(self):
        exe = os.path.join(built_lib_dir(TUNE_NODE), TUNE_NODE)
        whole = self.path("cart.bag")
        cart_sim.write_bag(whole, cart_sim.simulate(1, 1000))
        start, end = time_span(whole)
        middle = (start + end) / 2
        first, second = self.path("cart_0.bag"), self.path("cart_1.bag")
        split_bag(whole, [(first, lambda topic, t: t < middle), (second, lambda topic, t: True)])
        tuned = []
        for name, bags in (("whole.yaml", [whole]), ("parts.yaml", [first, second])):
            proc = self.run_node(exe, "--tune", *bags, "--out", self.path(name))
            self.assertEqual(proc.returncode, 0, proc.stderr)
            with open(self.path(name)) as f:
                lines = f.read().splitlines()
            # the file's second line is the command that wrote it, with its bags
            self.assertIn(" ".join(bags), lines[1])
            tuned.append(lines[:1] + lines[2:])
        self.assertIn("measurement_noise_covariance:", "\n".join(tuned[0]))
        self.assertEqual(tuned[1], tuned[0])

    def test_a_topic_under_two_spellings_is_read_whole(self):
        # a recorder may store a name with or without its leading slash; the recording read
        # as one holds both spellings of odom (the shipped bag stores "odom")
        import rosbag

        respelled = self.path("respelled.bag")
        with rosbag.Bag(BAG) as bag, rosbag.Bag(respelled, "w") as out:
            count = 0
            for topic, raw, t, header in bag.read_messages(raw=True,
                                                           return_connection_header=True):
                if topic == "odom":
                    count += 1
                    if count % 2:
                        topic = "/odom"
                        header = dict(header, topic="/odom")
                out.write(topic, raw, t, raw=True, connection_header=header)
        self.assertGreater(count, 100)
        self.assertEqual(self.replay_csv([respelled], "respelled.csv"),
                         self.replay_csv([BAG], "whole.csv"))

    def test_a_bag_given_twice_is_refused(self):
        proc = self.run_node(self.exe, "--replay", BAG, BAG, "--csv", self.path("out.csv"))
        self.assertEqual(proc.returncode, 1)
        self.assertIn("bag %s is given twice" % BAG, proc.stderr)
        self.assertFalse(os.path.exists(self.path("out.csv")))

    def test_a_part_with_another_type_is_named(self):
        good, bad = self.path("good.bag"), self.path("bad.bag")
        write_small_bag(good)
        write_small_bag(bad, imu_type="geometry_msgs/Vector3Stamped")
        proc = self.run_node(self.exe, "--replay", good, bad, "--csv", self.path("out.csv"))
        self.assertEqual(proc.returncode, 1)
        self.assertIn("bag %s: topic /imu/data holds geometry_msgs/Vector3Stamped" % bad,
                      proc.stderr)
        self.assertFalse(os.path.exists(self.path("out.csv")))

    def test_a_topic_in_none_of_the_bags_is_refused(self):
        first, second = self.path("no_imu_0.bag"), self.path("no_imu_1.bag")
        write_small_bag(first, imu_type=None)
        write_small_bag(second, imu_type=None)
        proc = self.run_node(self.exe, "--replay", first, second)
        self.assertEqual(proc.returncode, 1)
        self.assertIn("bags %s, %s have no topic /imu/data" % (first, second), proc.stderr)

    def test_the_bags_are_given_once(self):
        proc = self.run_node(self.exe, "--replay", BAG, "--csv", self.path("out.csv"), "--replay",
                             BAG)
        self.assertEqual(proc.returncode, 2)
        self.assertIn("--replay: the bags are given once", proc.stderr)


if __name__ == "__main__":
    unittest.main()
