"""The 3D replay tests' common part: a recording of tools/sim/rigid_body_sim.py made once per
test class in a temporary folder, its ground truth (tools/eval/pose3d_error.py), and the
replays of generated nodes on it, each run once per node, bag and arguments."""

import math
import os
import subprocess
import sys
import tempfile
import unittest

from replay_helpers import REPO, read_rows, replay_exe
import pose3d_error  # noqa: E402  (tools/eval, on the path through replay_helpers)

SIM = os.path.join(REPO, "tools", "sim", "rigid_body_sim.py")


def rms_deg(values):
    """Root mean square of angles in radians, in degrees."""
    return math.degrees(pose3d_error.rms(values))


def simulate(out, *args):
    """Writes rigid_body_sim.py's recording with `args` to the bag `out`."""
    subprocess.run([sys.executable, SIM] + list(args) + ["--out", out], check=True,
                   stdout=subprocess.PIPE)


class RigidBodyReplayCase(unittest.TestCase):
    """A test class on one simulated recording: `bag`, `truth` and `replay()`; SIM_ARGS are the
    simulator's options."""

    SIM_ARGS = ("--seed", "5", "--duration", "30")

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.bag = os.path.join(cls.tmp.name, "rigid_body.bag")
        simulate(cls.bag, *cls.SIM_ARGS)
        cls.truth = pose3d_error.load_truth(cls.bag)
        cls.replays = {}

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    @classmethod
    def replay(cls, node, *extra, bag=None):
        """The rows of `node`'s replay CSV on `bag` (default: the class's recording) with the
        replay's `extra` arguments; each such replay runs once per class."""
        key = (node, bag) + extra
        if key not in cls.replays:
            csv_path = os.path.join(cls.tmp.name, "%s_%d.csv" % (node, len(cls.replays)))
            replay_exe(node, bag or cls.bag, csv_path, *extra)
            cls.replays[key] = read_rows(csv_path)
        return cls.replays[key]
