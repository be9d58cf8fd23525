#!/usr/bin/python3
"""Regression tests of check_config_errors.py: a case whose REQUIRES path is missing is a skip,
in the summary and in the JUnit file, never a pass (it used to be counted as passed); the
precompiled prelude gives the verdicts of the plain compile, and is used.

Usage: test_check_config_errors.py (unittest; the prelude test needs g++ and Eigen)."""

import os
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
CHECKER = os.path.join(HERE, "check_config_errors.py")


class SkipIsNotAPass(unittest.TestCase):
    def test_a_missing_requirement_is_reported_as_skipped(self):
        with tempfile.TemporaryDirectory() as tmp:
            header = os.path.join(tmp, "needs_missing_file.h")
            with open(header, "w", encoding="utf-8") as f:
                f.write("// EXPECT: OK\n// REQUIRES: %s\n" % os.path.join(tmp, "absent.h"))
            junit = os.path.join(tmp, "out.xml")
            proc = subprocess.run([sys.executable, CHECKER, "--junit", junit, header],
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                  universal_newlines=True)
            self.assertEqual(proc.returncode, 0, proc.stdout)
            self.assertIn("SKIP needs_missing_file.h", proc.stdout)
            self.assertIn("0 passed, 0 failed, 1 skipped", proc.stdout)
            suite = ET.parse(junit).getroot()
            self.assertEqual(suite.get("tests"), "1")
            self.assertEqual(suite.get("skipped"), "1")
            self.assertEqual(suite.get("failures"), "0")
            case = suite.find("testcase")
            self.assertIsNotNone(case.find("skipped"))
            self.assertIsNone(case.find("failure"))


class PrecompiledPrelude(unittest.TestCase):
    CASES = ["frame_aligned_ok.h", "control_undeclared.h", "wrong_method.h"]

    def run_checker(self, *options):
        proc = subprocess.run([sys.executable, CHECKER, "-v", "-j", "2"] + list(options) +
                              [os.path.join(HERE, c) for c in self.CASES],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              universal_newlines=True)
        verdicts = sorted(l.split(" (")[0] for l in proc.stdout.splitlines()
                          if l.startswith(("PASS ", "FAIL ")))
        return proc, verdicts

    def test_the_prelude_gives_the_plain_verdicts_and_is_precompiled(self):
        plain, plain_verdicts = self.run_checker("--no-prelude")
        with_prelude, verdicts = self.run_checker()
        self.assertEqual(plain.returncode, 0, plain.stdout)
        self.assertEqual(with_prelude.returncode, 0, with_prelude.stdout)
        self.assertEqual(verdicts, plain_verdicts)
        self.assertEqual(len(verdicts), len(self.CASES))
        self.assertNotIn("not precompiled", with_prelude.stdout)
        # Each case force-includes the copy beside its .gch, not the source tree's prelude.
        commands = [l for l in with_prelude.stdout.splitlines() if l.strip().startswith("$ ")]
        self.assertEqual(len(commands), len(self.CASES))
        for command in commands:
            self.assertIn("-Winvalid-pch", command)
            self.assertIn("sf_config_errors_", command)
            self.assertNotIn(os.path.join(HERE, "config_prelude.hpp"), command)


if __name__ == "__main__":
    unittest.main()
