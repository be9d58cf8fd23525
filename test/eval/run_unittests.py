#!/usr/bin/python3
"""Runs the unittest modules test_*.py of this directory (or --start-dir) and optionally writes a JUnit XML
file (one <testcase> per test method), so that `catkin_make run_tests` and
catkin_test_results count them like the gtest cases. Standard library only (Debian has
neither python3-nose's catkin integration nor xmlrunner here).

Usage: run_unittests.py [--start-dir DIR] [--suite-name NAME] [--junit FILE] [-v] [PATTERN]
Exits 1 when a test failed or errored, or when none ran.
"""

import argparse
import os
import sys
import time
import traceback
import unittest
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree


class RecordingResult(unittest.TextTestResult):
    """TextTestResult that also keeps (test id, outcome, detail, seconds) per test.

    A test whose subTest failed gets neither addSuccess nor addFailure from unittest, only
    addSubTest: each failed subtest is recorded as a case of its own (the test's name plus
    the subtest's parameters), so that the JUnit file counts it as failed instead of
    leaving the test out."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.records = []
        self._started = {}

    def startTest(self, test):
        self._started[test.id()] = time.monotonic()
        super().startTest(test)

    def _record(self, test, outcome, detail="", label=""):
        t0 = self._started.get(test.id(), time.monotonic())
        self.records.append((test.id(), label, outcome, detail, time.monotonic() - t0))

    def addSubTest(self, test, subtest, err):
        super().addSubTest(test, subtest, err)
        if err is not None:
            outcome = "failure" if issubclass(err[0], test.failureException) else "error"
            self._record(test, outcome, "".join(traceback.format_exception(*err)),
                         label=subtest._subDescription())

    def addSuccess(self, test):
        super().addSuccess(test)
        self._record(test, "passed")

    def addFailure(self, test, err):
        super().addFailure(test, err)
        self._record(test, "failure", "".join(traceback.format_exception(*err)))

    def addError(self, test, err):
        super().addError(test, err)
        self._record(test, "error", "".join(traceback.format_exception(*err)))

    def addSkip(self, test, reason):
        super().addSkip(test, reason)
        self._record(test, "skipped", reason)

    def addExpectedFailure(self, test, err):
        super().addExpectedFailure(test, err)
        self._record(test, "passed")

    def addUnexpectedSuccess(self, test):
        super().addUnexpectedSuccess(test)
        self._record(test, "failure", "unexpected success")


def write_junit(path, records, suite_name):
    count = lambda o: sum(1 for r in records if r[2] == o)
    suite = ET.Element("testsuite", name=suite_name, tests=str(len(records)),
                       failures=str(count("failure")), errors=str(count("error")),
                       skipped=str(count("skipped")),
                       time="%.3f" % sum(r[4] for r in records))
    for test_id, label, outcome, detail, seconds in records:
        classname, _, name = test_id.rpartition(".")
        case = ET.SubElement(suite, "testcase", classname=classname,
                             name=name + (" " + label if label else ""), time="%.3f" % seconds)
        if outcome in ("failure", "error"):
            last = detail.strip().splitlines()[-1] if detail.strip() else outcome
            ET.SubElement(case, outcome, message=last).text = detail
        elif outcome == "skipped":
            ET.SubElement(case, "skipped", message=detail)
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    ET.ElementTree(suite).write(path, encoding="utf-8", xml_declaration=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--junit", help="write a JUnit XML file")
    parser.add_argument("--suite-name", default="evaluate_tests")
    parser.add_argument("-v", "--verbose", action="store_true")
    parser.add_argument("--start-dir", default=HERE,
                        help="directory of the test_*.py modules (default: this one)")
    parser.add_argument("pattern", nargs="?", default="test_*.py")
    args = parser.parse_args()

    start = os.path.abspath(args.start_dir)
    suite = unittest.defaultTestLoader.discover(start, pattern=args.pattern, top_level_dir=start)
    runner = unittest.TextTestRunner(stream=sys.stdout, verbosity=2 if args.verbose else 1,
                                     resultclass=RecordingResult)
    result = runner.run(suite)
    if args.junit:
        write_junit(args.junit, result.records, args.suite_name)
    if not result.wasSuccessful() or result.testsRun == 0:
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
