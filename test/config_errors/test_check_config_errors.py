#!/usr/bin/python3
"""Regression test of check_config_errors.py: a case whose REQUIRES path is missing is a skip,
in the summary and in the JUnit file, never a pass (it used to be counted as passed).

Usage: test_check_config_errors.py (unittest; no compiler needed: the only case is skipped)."""

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


if __name__ == "__main__":
    unittest.main()
