"""The messages are the catkin package sf_msgs, found by the ROS tools in the devel space
(issue 17, item 4; the install space: test/install/test_install_space.py).

Run by `catkin_make run_tests` (evaluate_tests), which runs it in the workspace's devel
environment; outside a sourced workspace (no ROS_PACKAGE_PATH) it is skipped.
"""

import os
import subprocess
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
MESSAGES = ("OutputEntityStamped", "StateEstimateStamped")


def run(*cmd):
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True)
    if proc.returncode != 0:
        raise AssertionError("%s failed (exit %d):\n%s" % (" ".join(cmd), proc.returncode,
                                                          proc.stdout))
    return proc.stdout


def fields(msg_text):
    """The 'type name' lines of a .msg text or of rosmsg's top level, comments dropped."""
    out = []
    for line in msg_text.splitlines():
        line = line.split("#")[0].strip()
        if line and not line.startswith(" "):
            out.append(" ".join(line.split()))
    return out


@unittest.skipUnless(os.environ.get("ROS_PACKAGE_PATH"), "no sourced catkin workspace")
class DevelSpaceMessagesTest(unittest.TestCase):
    def test_rospack_finds_the_package_of_this_repository(self):
        found = run("/usr/bin/rospack", "find", "sf_msgs").strip()
        self.assertEqual(os.path.realpath(found),
                         os.path.realpath(os.path.join(REPO, "sf_msgs")))

    def test_rosmsg_shows_each_message_as_defined(self):
        for name in MESSAGES:
            with open(os.path.join(REPO, "sf_msgs", "msg", name + ".msg")) as f:
                defined = fields(f.read())
            shown = run("/usr/bin/rosmsg", "show", "sf_msgs/" + name)
            top = [line for line in shown.splitlines() if line and not line.startswith(" ")]
            self.assertEqual(fields("\n".join(top)), defined, name)

    def test_python_and_rosmsg_agree_on_the_md5(self):
        script = ("from sf_msgs.msg import %s\nprint(' '.join(c._md5sum for c in (%s)))"
                  % (", ".join(MESSAGES), ", ".join(MESSAGES)))
        python = run("/usr/bin/python3", "-c", script).split()
        rosmsg = [run("/usr/bin/rosmsg", "md5", "sf_msgs/" + n).strip() for n in MESSAGES]
        self.assertEqual(python, rosmsg)

    def test_the_old_namespace_is_gone(self):
        proc = subprocess.run(["/usr/bin/rosmsg", "show", "sf_pkg/OutputEntityStamped"],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        self.assertNotEqual(proc.returncode, 0)


if __name__ == "__main__":
    unittest.main()
