"""The offline tools against what round three's attacks found (issue 38): D1, an output of
any tool (`--out` of `--tune` as well as `--csv`, `--bag`) that is an input file or not a
regular file; D8, `--tune` on a recording that identifies nothing; D9, a `--params` file far
larger than a node's parameters, or a directory; and tf2's TF_REPEATED_DATA, one line per
duplicated transform of overlapping bags.

Through sf_diff_drive_odom_imu (config/diff_drive_odom_imu.h) on the small bags of
test_replay_faults.py and bags/diff_drive_seed1.bag, and sf_tune_cart_kf
(test/configs/tune_cart_kf.h) on a bag of the cart simulator (tools/sim/cart_sim.py).
References: the input files byte for byte before and after; the number of transforms
duplicated, counted in the bags here; the replay of the bag without the duplicates; the cart
KF's structure (with only speed readings, the position's Q and R cannot enter the cost).

Run by hand:
  SF_LIB_DIR=$WS/devel/lib/sf_pkg test/eval/run_unittests.py --start-dir test/robots -v \\
      test_tool_faults.py
"""

import os
import stat
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
import simbag  # noqa: E402
from replay_helpers import built_lib_dir  # noqa: E402
from test_replay_faults import write_small_bag  # noqa: E402

NODE = "sf_diff_drive_odom_imu"
TUNE_NODE = "sf_tune_cart_kf"
SHIPPED = os.path.join(REPO, "bags", "diff_drive_seed1.bag")
LIMIT = 256 * 1024  # bytes of a --params file at most (yaml_parameters.hpp)


def write_nan_bag(path, count=100):
    """write_small_bag's 2 s bag with every odometry and IMU value NaN."""
    import rospy  # noqa: F401  (rosbag needs genpy's time types)
    import rosbag
    import genpy
    from nav_msgs.msg import Odometry
    from sensor_msgs.msg import Imu

    nan = float("nan")
    with rosbag.Bag(path, "w") as bag:
        t0 = genpy.Time(1700000000)
        for k in range(count):
            t = t0 + genpy.Duration(0, 20000000 * (k + 1))
            o = Odometry()
            o.header.stamp, o.header.frame_id = t, "odom"
            o.twist.twist.linear.x = o.twist.twist.angular.z = nan
            o.pose.pose.position.x = o.pose.pose.position.y = nan
            bag.write("odom", o, t)
            m = Imu()
            m.header.stamp, m.header.frame_id = t, "base_link"
            m.angular_velocity.z = m.linear_acceleration.x = nan
            bag.write("imu/data", m, t)


def write_speed_only_cart_bag(path, periods=300):
    """The cart simulator's readings of the speed alone (no cart/position topic)."""
    bag = simbag.BagBuilder()
    for k, _, _, _, z_v in cart_sim.simulate(1, periods):
        cart_sim.add_reading(bag, "cart/speed", k * cart_sim.PERIOD_NS, z_v)
    bag.write(path, compression="none")


def duplicate_tf(source, path, until_s):
    """A copy of `source` plus a second bag's worth of its /tf messages of the first
    `until_s` seconds (the overlap of two bags), each written twice. The number of
    transforms written twice."""
    import rosbag

    duplicated = 0
    with rosbag.Bag(source) as src, rosbag.Bag(path, "w") as dst:
        start = src.get_start_time()
        for topic, msg, t in src.read_messages():
            dst.write(topic, msg, t)
            if topic.lstrip("/") == "tf" and t.to_sec() - start < until_s:
                dst.write(topic, msg, t)
                duplicated += len(msg.transforms)
    return duplicated


class ToolFaultTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.exe = os.path.join(built_lib_dir(NODE), NODE)

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory(prefix="sf_tool_faults_")
        self.dir = self.tmp.name
        self.bag = self.path("in.bag")
        write_small_bag(self.bag)

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.dir, name)

    def run_node(self, *args, exe=None):
        return subprocess.run([exe or self.exe] + list(args), stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, universal_newlines=True,
                              errors="replace", timeout=300)

    def assertRefused(self, proc, *words, status=1, absent=()):
        """Exit status, one line on stderr with the program's name and `words` (status 2, a
        refused command line: then the usage); neither the files `absent` nor their .partial
        names exist."""
        self.assertEqual(proc.returncode, status, proc.stdout + proc.stderr)
        lines = proc.stderr.strip().splitlines()
        if status == 2:
            self.assertTrue(lines[1].startswith("usage: "), proc.stderr)
            lines = lines[:1]
        self.assertEqual(len(lines), 1, "expected one line on stderr:\n" + proc.stderr)
        self.assertTrue(lines[0].startswith(proc.args[0] + ": "), lines[0])
        for word in words:
            self.assertIn(word, lines[0])
        for path in absent:
            self.assertFalse(os.path.lexists(path), path + " left behind")
            self.assertFalse(os.path.lexists(path + ".partial"), path + ".partial left behind")
        return lines[0]

    def contents(self, path):
        with open(path, "rb") as f:
            return f.read()

    # -- D1: every output goes through one checked writer

    def test_tune_out_that_is_an_input_is_refused(self):
        # D1: `--tune in.bag --out in.bag` exited 0 and left in.bag a 771-byte YAML
        os.mkdir(self.path("sub"))
        os.link(self.bag, self.path("hardlink.bag"))
        params = self.path("params.yaml")
        with open(params, "w") as f:
            f.write("estimation_period: 0.02\n")
        bag_before, params_before = self.contents(self.bag), self.contents(params)
        for target, what in ((self.bag, "is the input bag " + self.bag),
                             (os.path.join(self.dir, "sub", "..", "in.bag"), "is the input bag"),
                             (self.path("hardlink.bag"), "is the input bag"),
                             (params, "is the input --params file " + params)):
            with self.subTest(target=target):
                proc = self.run_node("--tune", self.bag, "--params", params, "--out", target)
                self.assertRefused(proc, "--out " + target, what, "refusing to overwrite")
                self.assertEqual(self.contents(self.bag), bag_before)
                self.assertEqual(self.contents(params), params_before)
                self.assertFalse(os.path.exists(target + ".partial"))
                self.assertEqual(proc.stdout, "")  # refused before the bag was read

    def test_replay_output_that_is_the_params_file_is_refused(self):
        params = self.path("params.yaml")
        with open(params, "w") as f:
            f.write("estimation_period: 0.02\n")
        for option in ("--csv", "--bag"):
            with self.subTest(option=option):
                proc = self.run_node("--replay", self.bag, "--params", params, option, params)
                self.assertRefused(proc, option + " " + params, "is the input --params file")
                self.assertEqual(self.contents(params), b"estimation_period: 0.02\n")

    def non_regular_targets(self):
        """(path, what it is, check that it is still that) for a FIFO, a directory, a symbolic
        link to a file outside, and a device node of the test's own (where allowed)."""
        fifo, directory, link = self.path("fifo"), self.path("dir"), self.path("link.yaml")
        os.mkfifo(fifo)
        os.mkdir(directory)
        elsewhere = self.path("elsewhere.yaml")
        with open(elsewhere, "w") as f:
            f.write("kept: 1\n")
        os.symlink(elsewhere, link)
        cases = [(fifo, "a FIFO", stat.S_ISFIFO), (directory, "a directory", stat.S_ISDIR),
                 (link, "a symbolic link", stat.S_ISLNK)]
        device = self.path("null")  # a /dev/null of the test's own: a bug must not replace it
        try:
            os.mknod(device, 0o600 | stat.S_IFCHR, os.makedev(1, 3))
            cases.append((device, "a device", stat.S_ISCHR))
        except OSError:
            pass  # not allowed to make device nodes here
        return cases

    def test_every_output_refuses_what_is_not_a_regular_file(self):
        # D1: a FIFO, a symlink and (as root) a device node given to --out were replaced by a
        # regular file; --csv and --bag were fixed in round two, by the same checks
        for target, kind, still in self.non_regular_targets():
            for args in (["--tune", self.bag, "--out", target],
                         ["--replay", self.bag, "--csv", target],
                         ["--replay", self.bag, "--bag", target]):
                with self.subTest(args=args):
                    proc = self.run_node(*args)
                    self.assertRefused(proc, args[2] + " " + target, "it is " + kind)
                    self.assertTrue(still(os.lstat(target).st_mode), target + " replaced")
                    self.assertFalse(os.path.lexists(target + ".partial"))
        self.assertEqual(self.contents(self.path("elsewhere.yaml")), b"kept: 1\n")

    # -- D8: --tune with nothing to identify

    def test_tune_refuses_a_recording_without_an_innovation(self):
        # D8: exit 0, "cost start 0, tuned 0" and a "tuned" file
        one = self.path("one_each.bag")
        write_small_bag(one, count=1)
        nan = self.path("nan.bag")
        write_nan_bag(nan)
        for bag in (one, nan):
            with self.subTest(bag=bag):
                out = self.path("tuned.yaml")
                proc = self.run_node("--tune", bag, "--out", out)
                self.assertRefused(proc, "--tune: the recording identifies nothing: no period "
                                   "has a finite innovation", "nothing written", absent=[out])
        # the refusal is not about the file: without --out it fails the same way
        proc = self.run_node("--tune", one)
        self.assertRefused(proc, "the recording identifies nothing")

    def test_tune_refuses_a_flat_cost(self):
        # with speed readings alone the cart KF's S is P_vv + R_v, whose prediction and update
        # never read the position's entries: the cost cannot depend on Q.0 or R.0
        exe = os.path.join(built_lib_dir(TUNE_NODE), TUNE_NODE)
        bag = self.path("speed_only.bag")
        write_speed_only_cart_bag(bag)
        out = self.path("tuned.yaml")
        proc = self.run_node("--tune", bag, "--allow-missing-topics", "--free", "Q.0,R.0",
                             "--out", out, exe=exe)
        self.assertEqual(proc.returncode, 1, proc.stdout + proc.stderr)
        line = [x for x in proc.stderr.splitlines() if "--tune:" in x]
        self.assertEqual(len(line), 1, proc.stderr)
        self.assertIn("does not identify the free entries: the cost stayed within 0 (below "
                      "1e-4)", line[0])
        self.assertIn("nothing written", line[0])
        self.assertFalse(os.path.exists(out))
        # the speed's entries do enter it: the same bag tunes them
        proc = self.run_node("--tune", bag, "--allow-missing-topics", "--free", "Q.1,R.1",
                             "--out", out, exe=exe)
        self.assertEqual(proc.returncode, 0, proc.stdout + proc.stderr)
        self.assertTrue(os.path.exists(out))

    # -- D9: --params bounded, a directory named

    def params_of_size(self, size):
        """A valid parameter file of exactly `size` bytes: one parameter and comment lines."""
        path = self.path("big.yaml")
        head = "estimation_period: 0.02\n"
        line = "#" + "x" * 62 + "\n"
        body = line * ((size - len(head)) // len(line))
        body += "#" * (size - len(head) - len(body) - 1) + "\n"
        with open(path, "w") as f:
            f.write(head + body)
        self.assertEqual(os.path.getsize(path), size)
        return path

    def test_params_larger_than_the_limit_is_refused(self):
        # D9: a 100 MB YAML took 105 s and 12 GB and was accepted; the limit is 256 KiB
        csv = self.path("out.csv")
        at_limit = self.params_of_size(LIMIT)
        proc = self.run_node("--replay", self.bag, "--params", at_limit, "--csv", csv)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        over = self.params_of_size(LIMIT + 1)
        for mode in ("--replay", "--tune"):
            with self.subTest(mode=mode):
                proc = self.run_node(mode, self.bag, "--params", over)
                self.assertRefused(proc, "parameter file " + over + " is larger than 256 KiB, "
                                   "the limit for a node's private parameters", status=2)

    def test_params_directory_is_named(self):
        directory = self.path("params_dir")
        os.mkdir(directory)
        proc = self.run_node("--replay", self.bag, "--params", directory)
        self.assertRefused(proc, "parameter file " + directory + " is a directory", status=2)

    # -- tf2's TF_REPEATED_DATA: one line with a count

    def test_repeated_transforms_of_overlapping_bags_are_one_line(self):
        doubled = self.path("doubled.bag")
        duplicated = duplicate_tf(SHIPPED, doubled, 20.0)
        self.assertEqual(duplicated, 1000)  # /tf at 50 Hz
        csv, reference = self.path("doubled.csv"), self.path("reference.csv")
        proc = self.run_node("--replay", doubled, "--csv", csv)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        repeated = [x for x in proc.stderr.splitlines() if "TF_REPEATED_DATA" in x]
        self.assertEqual(repeated, [proc.args[0] + ": tf2: TF_REPEATED_DATA: %d transforms "
                                    "ignored, each with the stamp of one its frame already had "
                                    "(overlapping bags, or a transform recorded twice); the "
                                    "first is kept" % duplicated], proc.stderr[:2000])
        self.assertIn("(%d refused by tf2)" % duplicated, proc.stdout)
        # the first of each pair is kept: the estimates are those of the bag without them
        plain = self.run_node("--replay", SHIPPED, "--csv", reference)
        self.assertEqual(plain.returncode, 0, plain.stderr)
        self.assertNotIn("TF_REPEATED_DATA", plain.stderr)
        self.assertEqual(self.contents(csv), self.contents(reference))


if __name__ == "__main__":
    unittest.main()
