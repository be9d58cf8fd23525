"""Offline replay of bad files through sf_diff_drive_odom_imu (config/diff_drive_odom_imu.h,
topics odom: nav_msgs/Odometry, imu/data: sensor_msgs/Imu, plus /tf_static and /tf): each
fault ends the run with exit status 1 (130 for an interrupt), a single line on stderr
naming the problem and the file, and neither the output files nor their temporary
`<output>.partial` names left behind, also when the failure comes midway through the bag.

The faulty bags are made here: a truncated copy of bags/diff_drive_seed1.bag, a copy with
a chunk overwritten, a bag whose chunk index points outside its chunk (librosbag reads
outside its buffer and dies by a signal, which the replay contains), a text file, an empty
file, a missing file, and small bags written with python3-rosbag that lack a topic or hold
a topic with another message type.

Run by hand:
  SF_LIB_DIR=$WS/devel/lib/sf_pkg test/eval/run_unittests.py --start-dir test/robots -v \
      test_replay_faults.py
"""

import os
import resource
import signal
import stat
import struct
import subprocess
import sys
import tempfile
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "tools", "eval"))
sys.dont_write_bytecode = True
import pioneer_nodes  # noqa: E402  (devel-space lookup)

EXE_NAME = "sf_diff_drive_odom_imu"
SHIPPED = os.path.join(REPO, "bags", "diff_drive_seed1.bag")


def executable():
    lib_dir = os.environ.get("SF_LIB_DIR") or pioneer_nodes.find_lib_dir(EXE_NAME)
    exe = os.path.join(lib_dir or "", EXE_NAME)
    if not os.access(exe, os.X_OK):
        raise unittest.SkipTest("%s not built (set SF_LIB_DIR or source the devel space)" % EXE_NAME)
    return exe


def write_small_bag(path, odom=True, imu_type="sensor_msgs/Imu", count=100, compression="none",
                    early=None, odom_value=0.5):
    """A 2 s bag at 50 Hz in the node's topics: odom (nav_msgs/Odometry), imu/data as
    sensor_msgs/Imu, as another type (imu_type="geometry_msgs/Vector3Stamped"), as a
    sensor_msgs/Imu of another definition (imu_type="other md5sum"), or not at all
    (imu_type=None), and the static transform base_link -> imu_link. `early`: a time [s]
    of one more odom message long before the others; `odom_value`: their linear.x."""
    import rospy  # noqa: F401  (rosbag needs genpy's time types)
    import rosbag
    from geometry_msgs.msg import TransformStamped, Vector3Stamped
    from nav_msgs.msg import Odometry
    from sensor_msgs.msg import Imu
    from tf2_msgs.msg import TFMessage
    import genpy

    class OtherImu(Imu):
        """sensor_msgs/Imu as recorded by a build with another definition of it."""
        _md5sum = "0123456789abcdef0123456789abcdef"

    with rosbag.Bag(path, "w", compression=compression) as bag:
        t0 = genpy.Time(1700000000)
        static = TransformStamped()
        static.header.stamp = t0
        static.header.frame_id = "base_link"
        static.child_frame_id = "imu_link"
        static.transform.rotation.w = 1.0
        bag.write("/tf_static", TFMessage(transforms=[static]), t0)
        if early is not None:
            o = Odometry()
            o.header.stamp = genpy.Time.from_sec(early)
            o.header.frame_id = "odom"
            bag.write("odom", o, o.header.stamp)
        for k in range(count):
            t = t0 + genpy.Duration(0, 20000000 * (k + 1))
            if odom:
                o = Odometry()
                o.header.stamp = t
                o.header.frame_id = "odom"
                o.twist.twist.linear.x = odom_value
                o.twist.twist.angular.z = 0.1
                bag.write("odom", o, t)
            if imu_type in ("sensor_msgs/Imu", "other md5sum"):
                m = Imu() if imu_type == "sensor_msgs/Imu" else OtherImu()
                m.header.stamp = t
                m.header.frame_id = "imu_link"
                m.angular_velocity.z = 0.1
                bag.write("imu/data", m, t)
            elif imu_type == "geometry_msgs/Vector3Stamped":
                m = Vector3Stamped()
                m.header.stamp = t
                m.vector.z = 0.1
                bag.write("imu/data", m, t)


def corrupt_first_index_entry(path):
    """Points the first message of the bag's first chunk index (an IndexData record, op 0x04:
    entries of time sec, nsec and offset into the chunk, 4 bytes each) 2 GB past its chunk."""
    data = bytearray(open(path, "rb").read())
    op = data.find(b"\x04\x00\x00\x00op=\x04")
    assert op > 0, "no IndexData record"
    # walk back to the record's 4-byte header length, which covers the op field
    for start in range(op - 4, max(op - 200, 0), -1):
        header_len = struct.unpack_from("<I", data, start)[0]
        if start + 4 <= op < start + 4 + header_len and header_len < 200:
            fields_end = start + 4 + header_len
            break
    else:
        raise AssertionError("IndexData header not found")
    first_entry = fields_end + 4  # after the data length
    struct.pack_into("<I", data, first_entry + 8, 0x7FFFFFF0)
    open(path, "wb").write(data)


class ReplayFaultTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.exe = executable()

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory(prefix="sf_replay_faults_")
        self.dir = self.tmp.name
        self.csv = os.path.join(self.dir, "out.csv")
        self.bag = os.path.join(self.dir, "out.bag")

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.dir, name)

    def replay(self, bag, *extra, csv=None, out_bag=None, **popen):
        """--csv and --bag are the test's outputs unless given; "" leaves one out."""
        outputs = []
        for option, path, default in (("--csv", csv, self.csv), ("--bag", out_bag, self.bag)):
            path = default if path is None else path
            if path:
                outputs += [option, path]
        return subprocess.run(
            [self.exe, "--replay", bag] + outputs + list(extra), stdout=subprocess.PIPE,
            stderr=subprocess.PIPE, universal_newlines=True, errors="replace", timeout=120,
            **popen)

    def assertFails(self, proc, *words, status=1, outputs=None):
        """Exit status, one line on stderr with the program's name and `words`, no outputs."""
        self.assertEqual(proc.returncode, status, proc.stderr)
        lines = proc.stderr.strip().splitlines()
        self.assertEqual(len(lines), 1, "expected one line on stderr:\n" + proc.stderr)
        self.assertTrue(lines[0].startswith(self.exe + ": "), lines[0])
        for word in words:
            self.assertIn(word, lines[0])
        for out in outputs or (self.csv, self.bag):
            self.assertFalse(os.path.exists(out), out + " left behind")
            self.assertFalse(os.path.exists(out + ".partial"), out + ".partial left behind")
        return lines[0]

    def test_the_shipped_bag_replays(self):
        # the reference for every case below: the same command succeeds on the intact bag
        proc = self.replay(SHIPPED)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertTrue(os.path.getsize(self.csv) > 0 and os.path.getsize(self.bag) > 0)
        self.assertFalse(os.path.exists(self.csv + ".partial"))

    def test_truncated_bag(self):
        data = open(SHIPPED, "rb").read()
        for name, size in (("half.bag", len(data) // 2), ("head.bag", 20)):
            with self.subTest(name):
                open(self.path(name), "wb").write(data[:size])
                self.assertFails(self.replay(self.path(name)), self.path(name), "truncated")

    def test_garbage_in_a_chunk(self):
        # the shipped bag's chunks are bz2: garbage there fails the decompression midway
        data = bytearray(open(SHIPPED, "rb").read())
        data[len(data) // 2:len(data) // 2 + 4096] = b"\xa5" * 4096
        open(self.path("garbage.bag"), "wb").write(data)
        self.assertFails(self.replay(self.path("garbage.bag")), self.path("garbage.bag"),
                         "corrupt")

    def test_chunk_index_pointing_outside_its_chunk(self):
        bag = self.path("bad_index.bag")
        write_small_bag(bag)
        corrupt_first_index_entry(bag)
        self.assertFails(self.replay(bag), bag, "corrupt")

    def test_not_a_bag(self):
        open(self.path("notes.bag"), "w").write("not a bag\n" * 100)
        open(self.path("empty.bag"), "w").close()
        for name in ("notes.bag", "empty.bag"):
            with self.subTest(name):
                self.assertFails(self.replay(self.path(name)), self.path(name), "not a bag")

    def test_missing_file(self):
        self.assertFails(self.replay(self.path("none.bag")), self.path("none.bag"),
                         "No such file")

    def test_missing_topic_is_an_error(self):
        bag = self.path("no_imu.bag")
        write_small_bag(bag, imu_type=None)
        self.assertFails(self.replay(bag), bag, "no topic /imu/data", "--allow-missing-topics")

    def test_missing_topic_allowed(self):
        bag = self.path("no_imu.bag")
        write_small_bag(bag, imu_type=None)
        proc = self.replay(bag, "--allow-missing-topics")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("warning: bag %s has no topic /imu/data" % bag, proc.stderr)
        with open(self.csv) as f:
            rows = f.read().splitlines()
        # 100 odometry messages over 2 s at 20 ms periods: about 99 estimates, all with one
        # input present (odom carries inputs 0 and 1; present_inputs counts 2 of 3)
        self.assertGreater(len(rows) - 1, 90)
        self.assertTrue(all(r.endswith(",2") for r in rows[2:]), rows[:5])

    def test_no_configured_topic_even_when_allowed(self):
        bag = self.path("tf_only.bag")
        write_small_bag(bag, odom=False, imu_type=None)
        self.assertFails(self.replay(bag, "--allow-missing-topics"), bag, "none of its topics")

    def test_wrong_message_type(self):
        bag = self.path("wrong_type.bag")
        write_small_bag(bag, imu_type="geometry_msgs/Vector3Stamped")
        self.assertFails(self.replay(bag), bag, "/imu/data holds geometry_msgs/Vector3Stamped",
                         "sensor_msgs/Imu")

    def test_same_type_of_another_definition(self):
        bag = self.path("other_definition.bag")
        write_small_bag(bag, imu_type="other md5sum")
        self.assertFails(self.replay(bag), bag, "/imu/data holds sensor_msgs/Imu of another "
                         "definition (md5sum 0123456789abcdef0123456789abcdef")

    def test_unwritable_outputs(self):
        missing_dir = self.path("no/such/dir/out.csv")
        self.assertFails(self.replay(SHIPPED, csv=missing_dir), missing_dir,
                         outputs=[missing_dir, self.bag])
        os.mkdir(self.path("a_dir"))
        self.assertFails(self.replay(SHIPPED, out_bag=self.path("a_dir")), "is a directory",
                         outputs=[self.csv])
        self.assertFalse(os.path.exists(self.path("a_dir.partial")))

    def test_output_write_fails_midway(self):
        # a 64 KiB file size limit: the outputs (about 1 MB each) fail midway, with EFBIG
        def limit():
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
            resource.setrlimit(resource.RLIMIT_FSIZE, (65536, 65536))
        with self.subTest("csv"):
            self.assertFails(self.replay(SHIPPED, out_bag="", preexec_fn=limit),
                             "cannot write " + self.csv, "File too large")
        with self.subTest("bag"):
            # rosbag says "Error seeking" or "Error writing", not why
            self.assertFails(self.replay(SHIPPED, csv="", preexec_fn=limit),
                             "cannot write " + self.bag)

    # -- outputs that would destroy the input or something that is not a file (issue 15 D1, D2)

    def assertUnchanged(self, path, before):
        with open(path, "rb") as f:
            self.assertEqual(f.read(), before, path + " was changed")

    def test_output_that_is_the_input_is_refused(self):
        os.mkdir(self.path("sub"))
        source = self.path("in.bag")
        write_small_bag(source)
        os.link(source, self.path("hardlink.bag"))
        with open(source, "rb") as f:
            before = f.read()
        for option, target in (("--bag", source), ("--csv", source),
                               ("--csv", os.path.join(self.dir, "sub", "..", "in.bag")),
                               ("--bag", self.path("hardlink.bag"))):
            with self.subTest(option=option, target=target):
                proc = self.replay(source, csv=target if option == "--csv" else "",
                                   out_bag=target if option == "--bag" else "")
                self.assertFails(proc, option, "is the input bag", status=1,
                                 outputs=[target + ".partial"])
                self.assertUnchanged(source, before)

    def test_non_regular_targets_are_refused(self):
        fifo = self.path("fifo")
        os.mkfifo(fifo)
        directory = self.path("dir")
        os.mkdir(directory)
        cases = [(fifo, "a FIFO"), (directory, "a directory")]
        device = self.path("null")  # a /dev/null of the test's own: a bug must not replace it
        try:
            os.mknod(device, 0o600 | stat.S_IFCHR, os.makedev(1, 3))
            cases.append((device, "a device"))
        except OSError:
            pass  # not allowed to make device nodes here
        for target, kind in cases:
            with self.subTest(target=target):
                proc = self.replay(SHIPPED, csv=target, out_bag="")
                self.assertFails(proc, "--csv " + target, "it is " + kind,
                                 outputs=[target + ".partial"])
        self.assertTrue(stat.S_ISFIFO(os.lstat(fifo).st_mode))
        if os.path.lexists(device):
            self.assertTrue(stat.S_ISCHR(os.lstat(device).st_mode))

    def test_same_path_for_csv_and_bag_is_refused(self):
        for second in (self.csv, os.path.join(self.dir, ".", "out.csv")):
            with self.subTest(second=second):
                proc = self.replay(SHIPPED, csv=self.csv, out_bag=second)
                self.assertFails(proc, "--csv and --bag name the same file")

    # -- bounded work (D3) and the summary (D8)

    def test_a_gap_longer_than_the_limit_is_skipped(self):
        # one message at t = 1 s, the rest 1.7e9 s later: crossed like a clock jump online, in
        # one estimate, not by 8.5e10 empty 20 ms periods
        source = self.path("gap.bag")
        write_small_bag(source, early=1.0)
        proc = self.replay(source, out_bag="")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn(": 201 messages, ", proc.stdout)
        self.assertIn(", 1 gaps skipped, ", proc.stdout)
        with open(self.csv) as f:
            rows = sum(1 for _ in f) - 1
        # the bag's 2 s at a 20 ms period: 100 periods, plus the gap's one estimate
        self.assertLessEqual(rows, 102)
        self.assertGreaterEqual(rows, 99)

    def test_period_and_lag_in_seconds_with_bounds(self):
        for option, value, words in (
                ("--estimation-period", "1e-6", "--estimation-period must be 0.0001 .. 10 s"),
                ("--estimation-period", "50", "(seconds, not milliseconds: 50 ms is 0.05 s)"),
                ("--estimation-period", "1e13", "--estimation-period must be 0.0001 .. 10 s"),
                ("--estimation-period-ms", "1e-6", "--estimation-period-ms must be"),
                ("--max-lag", "40", "(seconds, not milliseconds: 40 ms is 0.04 s)")):
            with self.subTest(option=option, value=value):
                proc = self.replay(SHIPPED, option, value)
                self.assertEqual(proc.returncode, 2, proc.stderr)
                self.assertIn(words, proc.stderr.splitlines()[0])
                self.assertFalse(os.path.exists(self.csv))
        # --estimation-period 0.04 and --estimation-period-ms 40: the same estimates
        seconds = self.replay(SHIPPED, "--estimation-period", "0.04", out_bag="")
        self.assertEqual(seconds.returncode, 0, seconds.stderr)
        with open(self.csv) as f:
            by_seconds = f.read()
        ms = self.replay(SHIPPED, "--estimation-period-ms", "40", out_bag="")
        self.assertEqual(ms.returncode, 0, ms.stderr)
        with open(self.csv) as f:
            self.assertEqual(f.read(), by_seconds)
        first, second = [float(line.split(",")[0]) for line in by_seconds.splitlines()[1:3]]
        # times near 1.7e9 s: a double resolves 2**-22 s (2.4e-7 s) there
        self.assertAlmostEqual(second - first, 0.04, delta=2 * 2.0 ** -22)

    def test_strict_fails_on_dropped_values(self):
        source = self.path("nan.bag")
        write_small_bag(source, odom_value=float("nan"))
        lenient = self.replay(source, out_bag="")
        self.assertEqual(lenient.returncode, 0, lenient.stderr)
        self.assertIn(" 0 failed steps, 0 filter resets, ", lenient.stdout)
        self.assertIn(", 100 dropped values ", lenient.stdout)
        strict = self.replay(source, "--strict", csv="", out_bag="")
        self.assertEqual(strict.returncode, 1, strict.stderr)
        self.assertIn("--strict: 0 failed steps, 0 filter resets, 100 dropped values",
                      strict.stderr)
        clean = self.replay(SHIPPED, "--strict", csv="", out_bag="")
        self.assertEqual(clean.returncode, 0, clean.stdout + clean.stderr)

    def test_interrupted_midway(self):
        # The replay (a parent and the child that reads the bag, contained_run.hpp) is held
        # stopped whenever the test looks at it, so the interrupt lands while the output is
        # still being written however slowly this process runs: it is let run in slices of
        # 2 ms until the partial CSV exists, and SIGINT is sent before it may go on.
        proc = subprocess.Popen(
            [self.exe, "--replay", SHIPPED, "--csv", self.csv, "--bag", self.bag],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True,
            start_new_session=True, preexec_fn=default_interrupt)
        group = proc.pid
        deadline = time.monotonic() + 60
        while True:
            os.killpg(group, signal.SIGSTOP)
            wait_until_stopped(group)
            if os.path.exists(self.csv + ".partial") or proc.poll() is not None:
                break
            self.assertLess(time.monotonic(), deadline, "no partial output after 60 s")
            os.killpg(group, signal.SIGCONT)
            time.sleep(0.002)
        self.assertIsNone(proc.poll(), "the replay ended before it wrote a partial output")
        os.killpg(group, signal.SIGINT)
        os.killpg(group, signal.SIGCONT)
        out, err = proc.communicate(timeout=30)
        result = subprocess.CompletedProcess(proc.args, proc.returncode, out, err)
        self.assertFails(result, "interrupted", status=130)


def default_interrupt():
    """SIGINT as a terminal's Ctrl-C finds it. A program started in the background of a
    non-interactive shell inherits SIGINT ignored and, rightly, runs to its end when sent one
    (exit 0: the failures of this test in runs started so), so the test must not depend on
    how it was started."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def wait_until_stopped(group, timeout=10.0):
    """Waits until every live process of the process group is stopped (state T in /proc)."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        running = False
        for pid in os.listdir("/proc"):
            if not pid.isdigit():
                continue
            try:
                with open("/proc/%s/stat" % pid) as f:
                    fields = f.read().rsplit(")", 1)[1].split()
            except OSError:
                continue  # gone
            # fields[0]: state, fields[2]: process group
            if int(fields[2]) == group and fields[0] not in ("T", "t", "Z", "X"):
                running = True
                break
        if not running:
            return
        time.sleep(0.0005)
    raise AssertionError("process group %d did not stop" % group)

if __name__ == "__main__":
    unittest.main()
