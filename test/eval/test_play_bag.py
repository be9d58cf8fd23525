"""tools/play_bag.py, the player of the shipped launch files, with stand-ins for rosbag and
roslaunch (no master, no bag): its arguments reach `rosbag play`, and after the bag it sends
SIGINT (roslaunch's Ctrl-C) to a parent roslaunch only when told to with --end-launch."""

import os
import subprocess
import sys
import tempfile
import textwrap
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
PLAY_BAG = os.path.join(REPO, "tools", "play_bag.py")

FAKE_ROSBAG = """\
#!/bin/sh
printf '%s\\n' "$@" > "$FAKE_DIR/rosbag_args"
for a in "$@"; do case "$a" in *.bag) [ -f "$a" ] && cp "$a" "$FAKE_DIR/played.bag";; esac; done
exit ${FAKE_ROSBAG_RC:-0}
"""

# Stands in for roslaunch: named roslaunch, starts play_bag.py as a child and notes whether
# the child sent it SIGINT.
FAKE_ROSLAUNCH = """\
import os, signal, subprocess, sys, time
got = []
signal.signal(signal.SIGINT, lambda *a: got.append(1))
child = subprocess.run([sys.executable] + sys.argv[1:])
deadline = time.time() + float(os.environ.get("FAKE_WAIT", "5"))
while not got and time.time() < deadline:
    time.sleep(0.05)
with open(os.path.join(os.environ["FAKE_DIR"], "launcher"), "w") as f:
    f.write("rc=%d sigint=%d\\n" % (child.returncode, len(got)))
"""


class PlayBagTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory(prefix="sf_play_bag_test_")
        self.dir = self.tmp.name
        rosbag = os.path.join(self.dir, "rosbag")
        with open(rosbag, "w") as f:
            f.write(FAKE_ROSBAG)
        os.chmod(rosbag, 0o755)
        with open(os.path.join(self.dir, "roslaunch"), "w") as f:
            f.write(textwrap.dedent(FAKE_ROSLAUNCH))
        self.env = dict(os.environ, FAKE_DIR=self.dir,
                        PATH=self.dir + os.pathsep + os.environ.get("PATH", ""))

    def tearDown(self):
        self.tmp.cleanup()

    def read(self, name):
        with open(os.path.join(self.dir, name)) as f:
            return f.read()

    def launch(self, *args, rc=0, wait=5, timeout=10):
        """The launcher's note: play_bag.py's exit code and whether SIGINT arrived within
        wait seconds of its exit."""
        env = dict(self.env, FAKE_ROSBAG_RC=str(rc), FAKE_WAIT=str(wait))
        subprocess.run([sys.executable, os.path.join(self.dir, "roslaunch"), PLAY_BAG] + list(args),
                       env=env, timeout=timeout, check=True)
        return self.read("launcher").strip()

    def test_bag_end_shuts_the_launch_down(self):
        self.assertEqual(self.launch("--end-launch", "--clock", "-r", "2", "a.bag",
                                     "__name:=player"), "rc=0 sigint=1")
        # everything but --end-launch reaches rosbag play, roslaunch's remappings included
        self.assertEqual(self.read("rosbag_args").split("\n")[:-1],
                         ["play", "--clock", "-r", "2", "a.bag", "__name:=player"])

    def test_without_end_launch_it_only_plays(self):
        self.assertEqual(self.launch("--clock", "a.bag", wait=1), "rc=0 sigint=0")

    def test_a_failed_play_ends_the_launch_with_rosbags_code(self):
        self.assertEqual(self.launch("--end-launch", "missing.bag", rc=1), "rc=1 sigint=1")

    def test_uncompressed_copy_of_the_played_part(self):
        # bags/pioneer_seed1.bag is bz2-compressed; with -s 5 -u 10 the player gets an
        # uncompressed copy of its first 16 s (start + duration + 1 s), message for message
        import rosbag
        shipped = os.path.join(REPO, "bags", "pioneer_seed1.bag")
        result = subprocess.run([sys.executable, PLAY_BAG, "--uncompressed", "--clock", "-s", "5",
                                 "-u", "10", shipped], env=self.env, timeout=120)
        self.assertEqual(result.returncode, 0)
        args = self.read("rosbag_args").split("\n")[:-1]
        self.assertEqual(args[:6], ["play", "--clock", "-s", "5", "-u", "10"])
        self.assertNotEqual(args[6], shipped)
        self.assertFalse(os.path.exists(args[6]), "the copy outlived the player")
        with rosbag.Bag(shipped) as original:
            end = original.get_start_time() + 16.0
            expected = [(topic, raw[1], t.to_nsec()) for topic, raw, t in
                        original.read_messages(raw=True) if t.to_sec() <= end]
            self.assertIn("bz2", str(original.get_compression_info()))
        with rosbag.Bag(os.path.join(self.dir, "played.bag")) as copy:
            self.assertEqual(copy.get_compression_info().compression, "none")
            got = [(topic, raw[1], t.to_nsec()) for topic, raw, t in
                   copy.read_messages(raw=True)]
        self.assertGreater(len(expected), 1000)
        self.assertEqual(got, expected)

    def test_a_parent_that_is_not_roslaunch_is_left_alone(self):
        # the parent here is this test runner: a signal would interrupt it
        result = subprocess.run([sys.executable, PLAY_BAG, "--end-launch", "a.bag"],
                                env=self.env, timeout=10)
        self.assertEqual(result.returncode, 0)


if __name__ == "__main__":
    unittest.main()
