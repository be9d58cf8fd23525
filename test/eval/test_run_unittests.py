"""The JUnit file of run_unittests.py: every failure counted, subtests included (a test whose
subTest failed used to be left out of the file, so catkin_test_results saw one passed test
fewer and no failure)."""

import os
import subprocess
import sys
import tempfile
import textwrap
import unittest
import xml.etree.ElementTree as ET

RUNNER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "run_unittests.py")

MODULE = textwrap.dedent('''
    import unittest

    class Sample(unittest.TestCase):
        def test_passes(self):
            pass

        def test_second_subtest_fails(self):
            for name in ("a.yaml", "b.yaml"):
                with self.subTest(file=name):
                    self.assertEqual(name, "a.yaml")

        def test_subtest_errs(self):
            with self.subTest(step=1):
                raise RuntimeError("broken")
    ''')


class RunUnittestsJunitTest(unittest.TestCase):
    def test_failed_subtests_are_failures_in_the_junit_file(self):
        with tempfile.TemporaryDirectory(prefix="sf_run_unittests_") as tmp:
            tests = os.path.join(tmp, "tests")
            os.mkdir(tests)
            with open(os.path.join(tests, "test_sample.py"), "w") as f:
                f.write(MODULE)
            junit = os.path.join(tmp, "out.xml")
            run = subprocess.run([sys.executable, RUNNER, "--start-dir", tests, "--junit", junit],
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            self.assertEqual(run.returncode, 1, run.stdout)
            suite = ET.parse(junit).getroot()
            self.assertEqual((suite.get("tests"), suite.get("failures"), suite.get("errors")),
                             ("3", "1", "1"))
            cases = {c.get("name"): [e.tag for e in c] for c in suite.iter("testcase")}
            self.assertEqual(cases, {
                "test_passes": [],
                "test_second_subtest_fails (file='b.yaml')": ["failure"],
                "test_subtest_errs (step=1)": ["error"],
            })


if __name__ == "__main__":
    unittest.main()
