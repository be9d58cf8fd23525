"""INPUTS records (doc/configuration.md, "One record per input") against the thesis syntax:
config/diff_drive_odom_imu.h and config/skid_steer_odom_imu.h rewritten one record per input
(test/configs/*_records.h) must

- generate the same tables: sizes, Q, R, x0, P0, the observation model at three states,
  every input's topic, type, field and options, frame alignment, outputs (printed by
  test/config_tables_dump.cpp built for each header);
- replay bags/diff_drive_seed1.bag to a byte-identical CSV;
- name their inputs by record name: in the replay's per-input lines, and in overrides
  (--gate NAME=..., a ~input_gate map in --params) that act exactly as the same override
  given by index to the original header's node.

The executables come from $SF_LIB_DIR or the sourced devel space (skipped when not built).
"""

import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(REPO, "tools", "eval"))
sys.path.insert(0, HERE)
import pioneer_nodes  # noqa: E402
from replay_helpers import replay_exe  # noqa: E402

SIM_BAG = os.path.join(REPO, "bags", "diff_drive_seed1.bag")
CONFIGS = ("diff_drive_odom_imu", "skid_steer_odom_imu")
# A chi-square threshold that gates a good part of the gyro's values on this bag: the
# override must visibly change the estimates for the equality below to mean anything.
TIGHT_GATE = "0.01"


def run_exe(exe_name, *args):
    lib_dir = os.environ.get("SF_LIB_DIR") or pioneer_nodes.find_lib_dir(exe_name)
    exe = os.path.join(lib_dir or "", exe_name)
    if not os.access(exe, os.X_OK):
        raise unittest.SkipTest("%s not built (set SF_LIB_DIR or source the devel space)" % exe_name)
    return subprocess.run([exe] + list(args), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True, timeout=120)


def replay_bytes(exe_name, *extra):
    """The CSV of a replay of the simulated bag, as bytes, and the replay's stdout."""
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "out.csv")
        proc = replay_exe(exe_name, SIM_BAG, path, *extra)
        with open(path, "rb") as f:
            return f.read(), proc.stdout


class GeneratedTablesAreIdentical(unittest.TestCase):
    def test_tables(self):
        for config in CONFIGS:
            with self.subTest(config=config):
                original = run_exe("sf_test_config_tables_%s_original" % config)
                records = run_exe("sf_test_config_tables_%s_records" % config)
                self.assertEqual(original.returncode, 0, original.stderr)
                self.assertEqual(records.returncode, 0, records.stderr)
                # The dump holds every table (not an empty or partial print).
                for key in ("\nR 3x3 ", "\nh(x) 3x1 ", "\ninput 2 topic imu/data ",
                            "\n  aligned angular_velocity z", "by_stamp 1 timeout 0.5"):
                    self.assertIn(key, original.stdout)
                self.assertEqual(original.stdout, records.stdout)


class ReplayIsByteIdentical(unittest.TestCase):
    def test_replays(self):
        for config in CONFIGS:
            with self.subTest(config=config):
                original, _ = replay_bytes("sf_%s" % config)
                records, _ = replay_bytes("sf_test_%s_records" % config)
                self.assertGreater(len(original), 10000)
                self.assertEqual(original, records)


class InputsAreNamedByRecord(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.plain, cls.stdout = replay_bytes("sf_test_diff_drive_odom_imu_records")

    def test_replay_lines_name_the_record(self):
        self.assertIn("gyro_yaw_rate: imu/data angular_velocity", self.stdout)
        self.assertIn("wheel_speed: odom twist.twist.linear.x", self.stdout)

    def test_gate_option_by_name(self):
        by_name, _ = replay_bytes("sf_test_diff_drive_odom_imu_records",
                                  "--gate", "gyro_yaw_rate=" + TIGHT_GATE)
        by_index, _ = replay_bytes("sf_diff_drive_odom_imu", "--gate", "2=" + TIGHT_GATE)
        self.assertNotEqual(by_name, self.plain, "the gate should change the estimates")
        self.assertEqual(by_name, by_index)

    def test_parameter_map_by_name(self):
        with tempfile.TemporaryDirectory() as tmp:
            named = os.path.join(tmp, "named.yaml")
            with open(named, "w") as f:
                f.write("input_gate: {gyro_yaw_rate: %s}\n" % TIGHT_GATE)
            listed = os.path.join(tmp, "listed.yaml")
            with open(listed, "w") as f:
                f.write("input_gate: [0, 0, %s]\n" % TIGHT_GATE)
            by_name, _ = replay_bytes("sf_test_diff_drive_odom_imu_records", "--params", named)
            by_list, _ = replay_bytes("sf_diff_drive_odom_imu", "--params", listed)
        self.assertNotEqual(by_name, self.plain, "the gate should change the estimates")
        self.assertEqual(by_name, by_list)

    def test_unknown_name_is_refused_with_the_names(self):
        proc = run_exe("sf_test_diff_drive_odom_imu_records", "--replay", SIM_BAG,
                       "--gate", "gyro=1")
        self.assertNotEqual(proc.returncode, 0)
        self.assertIn("input 'gyro' is neither an input index nor one of the input names "
                      "wheel_speed, wheel_yaw_rate, gyro_yaw_rate", proc.stdout + proc.stderr)


if __name__ == "__main__":
    unittest.main()
