"""The tuned parameter files shipped in config/tuned/ (doc/tuning.md, "The shipped headers'
own NIS check"): one per shipped header and the bag it is meant for, written by `--tune`.

For every file:
- it is what its own command writes: the command in its second comment line is rerun
  (except for the soccer file, whose identification replays a 60 s bag at 1 kHz 2460 times,
  12 min on a loaded machine) and must give the same matrices;
- the header's values replayed on the bag are inconsistent by the node's rule (the run's
  verdict, and every judged window of the node's default ~nis_window), so the check is able
  to fail on these bags;
- the file's values replayed on the bag pass it: the run's verdict is not "inconsistent" and
  no window of the default ~nis_window is flagged, i.e. the node's diagnostics would report
  OK for the NIS from the first full window to the end of the bag.
"""

import concurrent.futures
import glob
import os
import re
import shlex
import subprocess
import sys
import tempfile
import unittest

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "tools", "eval"))
sys.dont_write_bytecode = True
sys.path.insert(0, HERE)
from replay_helpers import built_exe as executable  # noqa: E402

TUNED_DIR = os.path.join(REPO, "config", "tuned")
SLOW_TO_TUNE = {"soccer_kf_on_soccer_seed1.yaml"}
NIS_ALL = re.compile(r"^(\S+): NIS all inputs: mean (\S+) over .*\]: (.+?); window of (\d+) "
                     r"periods inconsistent in (\d+) of (\d+) judged periods$", re.M)


def run(args):
    proc = subprocess.run(args, cwd=REPO, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True, timeout=900)
    if proc.returncode != 0:
        raise AssertionError("%s: exit %d\n%s%s" % (" ".join(args), proc.returncode,
                                                    proc.stdout, proc.stderr))
    return proc.stdout


def nis_all(stdout):
    """(verdict, window, flagged, judged) of the replay's "NIS all inputs" line."""
    m = NIS_ALL.search(stdout)
    if not m:
        raise AssertionError("no NIS line in:\n" + stdout)
    return m.group(3), int(m.group(4)), int(m.group(5)), int(m.group(6))


def run_all(commands):
    """run() of each command, two at a time (the replays and identifications are independent
    and single-threaded: at the end of the test command's first step the second core would
    idle), as a list of (stdout or the AssertionError) in the commands' order, so that every
    failure is reported by its own subTest."""
    def attempt(args):
        try:
            return run(args)
        except AssertionError as e:
            return e
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        return list(pool.map(attempt, commands))


def outcome(result):
    """The stdout of a run_all() result, or its error raised."""
    if isinstance(result, AssertionError):
        raise result
    return result


def tuned_files():
    files = sorted(glob.glob(os.path.join(TUNED_DIR, "*_on_*.yaml")))
    if not files:
        raise AssertionError("no tuned files in " + TUNED_DIR)
    return files


def command_of(path):
    """The `rosrun sf_pkg NODE --tune BAG --out FILE ...` of the file's comment, as a list."""
    with open(path) as f:
        lines = f.read().splitlines()
    assert lines[1].startswith("# rosrun sf_pkg "), (path, lines[1])
    return shlex.split(lines[1][2:])


def tune_command(path, directory):
    """The file's own command (command_of) writing into `directory` instead."""
    words = command_of(path)
    return ([executable(words[2]), "--tune", words[4], "--out",
             os.path.join(directory, os.path.basename(path))] + words[7:])


class TunedFilesTest(unittest.TestCase):
    def test_every_file_is_what_its_command_writes(self):
        with tempfile.TemporaryDirectory(prefix="sf_tuned_files_") as tmp:
            files = [p for p in tuned_files() if os.path.basename(p) not in SLOW_TO_TUNE]
            # Each file's command with its --out in tmp, run two at a time before the checks.
            ran = dict(zip(files, run_all([tune_command(p, tmp) for p in files])))
            for path in tuned_files():
                name = os.path.basename(path)
                words = command_of(path)
                node, bag = words[2], words[4]
                config, bag_name = name[:-len(".yaml")].split("_on_")
                with self.subTest(file=name):
                    self.assertEqual(node, "sf_" + config)
                    self.assertEqual(bag, "bags/%s.bag" % bag_name)
                    self.assertEqual(words[3], "--tune")
                    self.assertEqual(words[5:7], ["--out", "config/tuned/" + name])
                    if name in SLOW_TO_TUNE:
                        continue
                    out = os.path.join(tmp, name)
                    outcome(ran[path])
                    with open(path) as f:
                        shipped = yaml.safe_load(f)
                    with open(out) as f:
                        again = yaml.safe_load(f)
                    self.assertEqual(sorted(shipped), sorted(again))
                    for key, value in shipped.items():
                        self.assertEqual(again[key], value, key)

    def test_header_values_warn_and_tuned_values_pass_the_nis_check(self):
        paths = tuned_files()
        replays = []  # per file: the header's values, then the file's
        for path in paths:
            words = command_of(path)
            exe, bag = executable(words[2]), words[4]
            replays += [[exe, "--replay", bag], [exe, "--replay", bag, "--params", path]]
        results = run_all(replays)
        for k, path in enumerate(paths):
            name = os.path.basename(path)
            with self.subTest(file=name):
                verdict, window, flagged, judged = nis_all(outcome(results[2 * k]))
                self.assertTrue(verdict.startswith("inconsistent"), verdict)
                self.assertGreater(judged, 0)
                self.assertEqual(flagged, judged)
                verdict, window, flagged, judged = nis_all(outcome(results[2 * k + 1]))
                print("%s: tuned: %s; window of %d periods flagged in %d of %d" %
                      (name, verdict, window, flagged, judged))
                self.assertFalse(verdict.startswith("inconsistent"), verdict)
                self.assertGreater(judged, 0)
                self.assertEqual(flagged, 0)


if __name__ == "__main__":
    unittest.main()
