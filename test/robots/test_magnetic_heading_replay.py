"""A magnetometer's heading (DERIVED_INPUTS MAGNETIC_YAW, doc/configuration.md "Magnetometer")
replayed offline through the node built from test/configs/magnetic_heading_ekf.h, on a tiny
synthetic bag written here: a robot standing still at true yaw 125 deg where magnetic north
lies 10 deg east of true north, so its magnetometer reads the field of a magnetic heading of
135 deg, b = 20 uT (sin 135, cos 135). With --params magnetic_declination: 10 deg the estimate
settles at 125 deg, without it at 135 deg (the magnetic heading); a declination out of
[-pi, pi] is refused naming the parameter (sf_filter/io/extractor_parameters.hpp, the same
code as the online node's).
The executable comes from $SF_LIB_DIR or the sourced devel space (skipped when not built).
"""

import math
import os
import subprocess
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from replay_helpers import built_lib_dir, read_rows  # noqa: E402

NODE = "sf_test_magnetic_heading"
TRUE_YAW = math.radians(125.0)
DECLINATION = math.radians(10.0)


def write_bag(path):
    """5 s of a still robot: the magnetometer and the gyro at 20 Hz."""
    import rosbag  # Debian: python3-rosbag
    import rospy
    from sensor_msgs.msg import Imu, MagneticField
    with rosbag.Bag(path, "w") as bag:
        for k in range(100):
            stamp = rospy.Time.from_sec(10.0 + 0.05 * k)
            mag = MagneticField()
            mag.header.stamp = stamp
            mag.header.frame_id = "base_link"
            mag.magnetic_field.x = 2e-5 * math.sin(TRUE_YAW + DECLINATION)
            mag.magnetic_field.y = 2e-5 * math.cos(TRUE_YAW + DECLINATION)
            mag.magnetic_field.z = -4e-5
            bag.write("imu/mag", mag, stamp)
            imu = Imu()
            imu.header.stamp = stamp
            bag.write("imu/data", imu, stamp)


class MagneticHeadingReplay(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.exe = os.path.join(built_lib_dir(NODE), NODE)
        cls.tmp = tempfile.TemporaryDirectory()
        cls.bag = os.path.join(cls.tmp.name, "magnetometer.bag")
        write_bag(cls.bag)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def replay(self, name, yaml_text=None):
        csv_path = os.path.join(self.tmp.name, name + ".csv")
        extra = []
        if yaml_text is not None:
            params = os.path.join(self.tmp.name, name + ".yaml")
            with open(params, "w") as f:
                f.write(yaml_text)
            extra = ["--params", params]
        proc = subprocess.run([self.exe, "--replay", self.bag, "--csv", csv_path] + extra,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              universal_newlines=True, timeout=120)
        rows = read_rows(csv_path) if proc.returncode == 0 else None
        return proc, rows

    def test_declination_gives_the_true_heading(self):
        proc, rows = self.replay("declination", "magnetic_declination: %.17g\n" % DECLINATION)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertGreater(len(rows), 40)
        self.assertAlmostEqual(rows[-1]["x0"], TRUE_YAW, places=3)
        self.assertNotIn("unknown private parameter", proc.stderr)

    def test_default_is_the_magnetic_heading(self):
        proc, rows = self.replay("default")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertAlmostEqual(rows[-1]["x0"], TRUE_YAW + DECLINATION, places=3)

    def test_declination_out_of_range_is_refused(self):
        proc, _ = self.replay("refused", "magnetic_declination: 4.0\n")
        self.assertNotEqual(proc.returncode, 0)
        self.assertIn("parameter ~magnetic_declination: expected radians in [-pi, pi]",
                      proc.stderr)


if __name__ == "__main__":
    unittest.main()
