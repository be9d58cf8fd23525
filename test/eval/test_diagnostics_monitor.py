"""Unit tests of tools/diagnostics_monitor.py's table on hand-built DiagnosticArrays (no master)."""

import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "tools"))
sys.dont_write_bytecode = True
import diagnostics_monitor as monitor  # noqa: E402

# python3-diagnostic-msgs is in scripts/common.sh's package list and package.xml
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus, KeyValue  # noqa: E402


def status(name, level, message, **values):
    return DiagnosticStatus(level=level, name=name, message=message, hardware_id="none",
                            values=[KeyValue(key=k, value=v) for k, v in values.items()])


def array(*statuses):
    return DiagnosticArray(status=list(statuses))


class FormatTableTest(unittest.TestCase):
    def setUp(self):
        self.latest = {}
        monitor.update(self.latest, array(
            status("/train_kf: estimation", DiagnosticStatus.OK, "ok", **{"NIS mean": "2.1"}),
            status("/train_kf: input 0 (train/velocity data)", DiagnosticStatus.WARN,
                   "3 values dropped", received="40"),
            status("/train_kf: input 1 (train/acceleration vector.x)", DiagnosticStatus.ERROR,
                   "all 4 values dropped")), received=100.0)

    def lines(self, *args, **kwargs):
        return monitor.format_table(self.latest, *args, **kwargs).splitlines()

    def test_one_line_per_name_sorted_with_level_message_and_age(self):
        lines = self.lines(101.25)
        self.assertEqual(lines[0].split(), ["LEVEL", "NAME", "REFRESHED", "MESSAGE"])
        self.assertEqual(len(lines), 5)
        self.assertTrue(lines[1].startswith("OK "))
        self.assertIn("/train_kf: estimation", lines[1])
        self.assertIn("1.2 s ago", lines[1])
        self.assertTrue(lines[1].rstrip().endswith("ok"))
        self.assertTrue(lines[2].startswith("WARN "))
        self.assertTrue(lines[2].rstrip().endswith("3 values dropped"))
        self.assertTrue(lines[3].startswith("ERROR "))
        self.assertEqual(lines[4], "3 statuses: 1 ERROR, 1 WARN, 1 OK")
        # the columns line up
        starts = {line.index("s ago") for line in lines[1:4]}
        self.assertEqual(len(starts), 1)

    def test_newer_array_replaces_a_name_and_keeps_the_others(self):
        monitor.update(self.latest, array(status("/train_kf: estimation", DiagnosticStatus.WARN,
                                                 "NIS mean 9.0 above [1.5, 2.5]")), received=104.0)
        lines = self.lines(104.5)
        self.assertTrue(lines[1].startswith("WARN "))
        self.assertIn("0.5 s ago", lines[1])
        self.assertIn("NIS mean 9.0", lines[1])
        self.assertIn("4.5 s ago", lines[2])

    def test_not_refreshed_is_stale(self):
        lines = self.lines(106.0, stale_after=5.0)
        self.assertTrue(all(line.startswith("STALE ") for line in lines[1:4]))
        self.assertEqual(lines[4], "3 statuses: 3 STALE")
        self.assertTrue(self.lines(106.0, stale_after=0)[1].startswith("OK "))

    def test_filter_keys_and_width(self):
        lines = self.lines(100.0, name_filter="input 1")
        self.assertEqual(len(lines), 3)
        self.assertIn("all 4 values dropped", lines[1])
        lines = self.lines(100.0, name_filter="estimation", keys=True)
        self.assertEqual(lines[2].strip(), "NIS mean: 2.1")
        self.assertEqual(self.lines(100.0, name_filter="nothing"), ["no status matches the filter"])
        narrow = self.lines(100.0, width=80)
        self.assertTrue(all(len(line) <= 80 for line in narrow[1:4]), narrow)
        self.assertTrue(narrow[3].endswith("..."))

    def test_empty_and_byte_levels(self):
        self.assertEqual(monitor.format_table({}, 0.0), "no diagnostics received yet")
        latest = monitor.update({}, array(status("a", b"\x02", "broken")), received=0.0)
        self.assertTrue(monitor.format_table(latest, 0.0).splitlines()[1].startswith("ERROR "))


if __name__ == "__main__":
    unittest.main()
