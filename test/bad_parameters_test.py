#!/usr/bin/python3
"""Bad private parameters of a fusion node (test/bad_parameters.test): sf_train_kf
(config/train_kf.h: n = 2 states, m = 2 inputs, KF) is started once per case with one bad
parameter under its own name; each must be refused at start with exit status 1 and a fatal
message naming the parameter and what was expected (size or type), and no crash. A control
case with valid overrides of the same parameters must start and keep running. A remap of one
configured topic onto another of another type is refused the same way.
"""

import os
import signal
import subprocess
import sys
import time
import unittest

import rospy
import rostest

EXE_NAME = "sf_train_kf"

# (parameter, value, words the fatal line must contain)
CASES = [
    ("process_noise_covariance", [0.001, 0.0, 0.01],
     "parameter ~process_noise_covariance: expected 4 numbers (2x2, row-major), found 3"),
    ("process_noise_covariance", [[0.001, 0.0], [0.0]],
     "parameter ~process_noise_covariance: row 1 must be a list of 2 numbers, found a list of 1"),
    ("process_noise_covariance", [[0.001, 0.0], [0.0, [0.01]]],
     "parameter ~process_noise_covariance row 1 entry 1: expected a number, found a list of 1"),
    ("process_noise_covariance", "0.001 0 0 0.01",
     "parameter ~process_noise_covariance: expected a list of 4 numbers (2x2, row-major), "
     "found a string"),
    ("measurement_noise_covariance", [0.25, 0.0, 0.0, "x"],
     "parameter ~measurement_noise_covariance entry 3: expected a number, found a string"),
    ("initial_state", [0.0, 1.0, 2.0],
     "parameter ~initial_state: expected 2 numbers (2x1, row-major), found 3"),
    ("estimation_period", "fast",
     "parameter ~estimation_period: expected a number, found a string (\"fast\")"),
    ("estimation_period", [100],
     "parameter ~estimation_period: expected a number, found a list of 1"),
    # time parameters in seconds (REP-103), refused outside their plausible range with the
    # unit named, and the old unit's hint where it fits
    ("estimation_period", 0, "parameter ~estimation_period must be 0.0001 .. 10 s, found 0"),
    ("estimation_period", 50, "parameter ~estimation_period must be 0.0001 .. 10 s, found 50 "
     "(seconds, not milliseconds: 50 ms is 0.05 s)"),
    ("estimation_period", 1.0e13, "parameter ~estimation_period must be 0.0001 .. 10 s, "
     "found 1e+13"),
    ("estimation_period", 1.0e-6, "parameter ~estimation_period must be 0.0001 .. 10 s, "
     "found 1e-06"),
    ("frequency", 0.01, "parameter ~frequency: must be 0.1 .. 10000 Hz, found 0.01"),
    ({"frequency": 20, "estimation_period": 0.05}, None,
     "parameters ~estimation_period and ~frequency are both set: give one of them"),
    ("max_measurement_lag", 40, "parameter ~max_measurement_lag must be 0 (none) or 0 .. 10 s, "
     "found 40 (seconds, not milliseconds: 40 ms is 0.04 s)"),
    ("max_future_stamp", 500, "parameter ~max_future_stamp must be 0 (none) or 0 .. 60 s, "
     "found 500 (seconds, not milliseconds: 500 ms is 0.5 s)"),
    ("input_timeout", [0, 500], "parameter ~input_timeout entry 1: timeout must be 0 (none) or "
     "0.0001 .. 60 s, found 500 (seconds, not milliseconds: 500 ms is 0.5 s)"),
    # gates in standard deviations as an alternative to the chi-square threshold
    ({"input_gate": [0, 9.0], "input_gate_sigma": [0, 3.0]}, None,
     "parameters ~input_gate (chi-square) and ~input_gate_sigma (standard deviations) are "
     "both set"),
    ("input_gate_sigma", [0, -3.0], "parameter ~input_gate_sigma entry 1: expected a number of "
     "standard deviations from 0 (no gate) to 1e6"),
    # numbers at the edge and settings that would flood or freeze the node
    ("process_noise_covariance", [1e308, 0.0, 0.0, 0.01],
     "parameter ~process_noise_covariance row 0 column 0: 1e+308 is not a finite number of "
     "magnitude at most 1e100"),
    ("measurement_noise_covariance", [0.25, 0.0, 0.0, 1e101],
     "parameter ~measurement_noise_covariance row 1 column 1: 1e+101 is not a finite number"),
    ("initial_error_covariance", [[1e200, 0], [0, 1]],
     "parameter ~initial_error_covariance row 0 column 0: 1e+200 is not a finite number"),
    ("nis_tolerance", 0.5, "parameter ~nis_tolerance: expected a factor from 1 (the "
     "chi-square band alone) to 100, found 0.5"),
    ("diagnostic_period", 1e-9, "parameter ~diagnostic_period: expected a number of seconds "
     "from 0.01 to 3600"),
    ("frame_id", "", "parameter ~frame_id: '' is not a tf2 frame name"),
    ("child_frame_id", "", "parameter ~child_frame_id: '' is not a tf2 frame name"),
    ("random_seed", 1.5, "parameter ~random_seed: expected an integer, found a number"),
    ("random_seed", -3, "parameter ~random_seed: must not be negative"),
    ("input_gate", [1.0], "parameter ~input_gate: expected 2 entries (one per TOPICS_IN entry), "
     "found 1"),
    ("input_alignment", "LAST", "parameter ~input_alignment: expected a list of 2 entries "
     "(one per TOPICS_IN entry), found a string"),
    ("align_by_stamp", [False, "yes"], "parameter ~align_by_stamp entry 1: expected true or false"),
    # A map names inputs by INPUTS record name or index; this header has no records.
    ("input_gate", {"gyro": 1.0}, "parameter ~input_gate entry gyro: input 'gyro' is neither an "
     "input index nor an input name (this header has no INPUTS records)"),
    ("input_gate", {"5": 1.0}, "parameter ~input_gate entry 5: input index out of range, "
     "expected 0 to 1"),
    ("frame_id", 5, "parameter ~frame_id: expected a string, found an integer (5)"),
    ("publish_tf", "no", "parameter ~publish_tf: expected a boolean, found a string"),
    ("queue_size", "big", "parameter ~queue_size: expected an integer, found a string"),
    ("queue_size", 0, "parameter ~queue_size: expected 1 to 1000000 messages, found 0"),
]


def find_executable(name):
    from catkin.find_in_workspaces import find_in_workspaces

    found = find_in_workspaces(["libexec"], project="sf_pkg", path=name)
    if not found:
        raise RuntimeError("%s not found in the catkin workspaces" % name)
    return found[0]


class BadParametersTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.exe = find_executable(EXE_NAME)

    def start(self, name, params, *remaps):
        for key, value in params.items():
            rospy.set_param("/%s/%s" % (name, key), value)
        return subprocess.Popen([self.exe, "__name:=" + name] + list(remaps),
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                universal_newlines=True)

    def test_remap_onto_another_configured_topic_of_another_type_is_refused(self):
        # Issue 38 D5: checked after resolution, as in the replay: train/velocity (Float64)
        # remapped onto train/acceleration (Vector3Stamped) would leave one of them nothing.
        proc = self.start("remapped", {}, "train/velocity:=train/acceleration")
        try:
            out, err = proc.communicate(timeout=20)
        except subprocess.TimeoutExpired:
            proc.send_signal(signal.SIGINT)
            proc.communicate(timeout=10)
            self.fail("the node started with train/velocity remapped onto train/acceleration")
        self.assertEqual(proc.returncode, 1, out + err)
        self.assertIn("/remapped: refusing to start: topic /train/acceleration: two configured "
                      "topics resolve onto it (a remap?), one read as std_msgs/Float64, the "
                      "other as geometry_msgs/Vector3Stamped; a topic holds one message type",
                      err)

    def test_each_bad_parameter_is_refused_at_start(self):
        for k, (param, value, words) in enumerate(CASES):
            with self.subTest(param=str(param), value=value):
                name = "bad_%d" % k
                proc = self.start(name, param if isinstance(param, dict) else {param: value})
                try:
                    out, err = proc.communicate(timeout=20)
                except subprocess.TimeoutExpired:
                    proc.send_signal(signal.SIGINT)
                    proc.communicate(timeout=10)
                    self.fail("the node started with ~%s = %r" % (param, value))
                self.assertEqual(proc.returncode, 1, out + err)
                fatal = [line for line in err.splitlines() if "refusing to start" in line]
                self.assertEqual(len(fatal), 1, err)
                self.assertIn("/%s: refusing to start: %s" % (name, words), fatal[0])

    def test_valid_overrides_start(self):
        proc = self.start("good", {
            "process_noise_covariance": [[0.001, 0], [0, 0.01]],
            "measurement_noise_covariance": [0.25, 0.0, 0.0, 0.04],
            "initial_state": [0, 1], "estimation_period": 0.05, "random_seed": 3,
            "input_gate": [0, 9.0], "input_alignment": ["AVERAGE", "LAST"],
            "align_by_stamp": [False, True], "frame_id": "map", "publish_tf": False})
        time.sleep(5.0)
        if proc.poll() is not None:
            self.fail("the node exited: " + "".join(proc.communicate()))
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=20)
        self.assertNotIn("refusing to start", err)


if __name__ == "__main__":
    rospy.init_node("bad_parameters_test")
    rostest.rosrun("sf_pkg", "bad_parameters", BadParametersTest, sys.argv)
