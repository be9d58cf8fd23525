#!/usr/bin/python3
"""Count test cases in the JUnit XML files under a directory.

Usage: test_summary.py [--failed-step TEXT]... RESULTS_DIR

--failed-step counts one failure for a step that failed outside the result
files (e.g. the test build), so that the last line never reads as a success.

Prints failing test cases, then one last line of the form
    N passed, N failed, N skipped
("failed" includes errors). Exit status: 0 when at least one test ran and none
failed, 1 otherwise.

Handles the files catkin's run_tests writes:
  * gtest-<target>.xml from catkin_add_gtest (GoogleTest's own report);
  * rostest-<name>.xml, one test case per <test> of a .test launch file, next to
    rosunit-<test-name>.xml with that test node's own cases. A wrapper case is
    counted only when its detailed file is missing, or when it failed while the
    detailed file shows no failure (crash, time limit), so nothing counts twice;
  * the placeholder failure catkin writes when a test produced no result file.
"""
import os
import sys
import xml.etree.ElementTree as ET


def case_outcome(case):
    """'failed', 'skipped' or 'passed' for one <testcase>."""
    if case.find("failure") is not None or case.find("error") is not None:
        return "failed"
    if (
        case.find("skipped") is not None
        or case.get("status") == "notrun"
        or case.get("result") in ("skipped", "suppressed")
    ):
        return "skipped"
    return "passed"


def case_label(path, case):
    name = case.get("name", "?")
    cls = case.get("classname")
    return "%s: %s" % (os.path.basename(path), "%s.%s" % (cls, name) if cls else name)


def suite_error_count(root):
    """failures+errors declared on suites (used when a file lists no cases)."""
    suites = [root] if root.tag == "testsuite" else list(root.iter("testsuite"))
    total = 0
    for suite in suites:
        for attr in ("failures", "errors"):
            try:
                total += int(suite.get(attr, "0"))
            except ValueError:
                total += 1
    return total


def summarize(results_dir):
    counts = {"passed": 0, "failed": 0, "skipped": 0}
    failures = []
    files = []
    for dirpath, _, names in os.walk(results_dir):
        files.extend(os.path.join(dirpath, n) for n in sorted(names) if n.endswith(".xml"))

    parsed = {}
    for path in sorted(files):
        try:
            parsed[path] = ET.parse(path).getroot()
        except ET.ParseError as exc:
            counts["failed"] += 1
            failures.append("%s: unreadable result file (%s)" % (os.path.basename(path), exc))

    for path, root in parsed.items():
        cases = list(root.iter("testcase"))
        detail_dir = os.path.dirname(path)
        is_rostest = os.path.basename(path).startswith("rostest-")
        for case in cases:
            outcome = case_outcome(case)
            if is_rostest:
                name = case.get("name", "")
                test_name = name[4:] if name.startswith("test") else name
                detail = os.path.join(detail_dir, "rosunit-%s.xml" % test_name)
                if detail in parsed:
                    detail_failed = any(
                        case_outcome(c) == "failed" for c in parsed[detail].iter("testcase")
                    ) or suite_error_count(parsed[detail]) > 0
                    if outcome != "failed" or detail_failed:
                        continue
            counts[outcome] += 1
            if outcome == "failed":
                failures.append(case_label(path, case))
        if not cases and suite_error_count(root) > 0:
            counts["failed"] += 1
            failures.append("%s: suite reports failures but lists no test cases"
                            % os.path.basename(path))
    return counts, failures, len(files)


def main(argv):
    args = argv[1:]
    failed_steps = []
    while len(args) >= 2 and args[0] == "--failed-step":
        failed_steps.append(args[1])
        args = args[2:]
    if len(args) != 1:
        sys.stderr.write(__doc__)
        return 2
    results_dir = args[0]
    if os.path.isdir(results_dir):
        counts, failures, nfiles = summarize(results_dir)
    else:
        print("no test results directory: %s" % results_dir)
        counts, failures, nfiles = {"passed": 0, "failed": 0, "skipped": 0}, [], 0
    for step in failed_steps:
        counts["failed"] += 1
        failures.append(step)
    for line in failures:
        print("FAILED %s" % line)
    if counts["passed"] + counts["failed"] == 0:
        print("no test ran (%d result files in %s)" % (nfiles, results_dir))
    print("%d passed, %d failed, %d skipped" % (counts["passed"], counts["failed"], counts["skipped"]))
    ok = counts["failed"] == 0 and counts["passed"] > 0
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
