#!/usr/bin/python3
"""Builds sf_estimation with clang under AddressSanitizer + UndefinedBehaviorSanitizer and
runs either its unit tests or its libFuzzer target, writing a JUnit file for
catkin_test_results.

One build directory serves both commands: it is configured with the sanitizers, the unit
tests and the fuzz target (-DSF_ESTIMATION_FUZZ=ON, which instruments the library for
libFuzzer's coverage as well), build type Sanitize (-O0 with line tables, Eigen assertions
on), and without the library's generated fixed-size instances
(-DSF_ESTIMATION_EXPLICIT_INSTANCES=OFF): the tests and the fuzzer instantiate the same
templates for the sizes they use, which costs 30 % less CPU than compiling the whole size
grid under the sanitizers. The library's sources are compiled once for both
(doc/build_cost.md, "Round seven").

  sanitizer_checks.py unit-tests --build-dir DIR [--junit FILE]
      builds sf_estimation_tests in DIR and runs every test but the few of SLOW_AT_O0; any
      sanitizer report aborts the test binary and fails the check.

  sanitizer_checks.py fuzz --build-dir DIR [--seconds 60] [--corpus DIR] [--junit FILE]
      builds sf_estimation_fuzz in DIR and runs it for the given time on
      the corpus directory (default DIR/corpus, kept between runs so it grows) plus the
      inputs that once failed (sf_estimation/fuzz/regressions); prints the
      executions, the corpus size and the coverage libFuzzer reports. A crash, hang (10 s per
      input), leak, sanitizer report or an exception other than estimation::EstimationError
      fails the check; libFuzzer then leaves the input as DIR/crash-* (or leak-*, timeout-*).

  sanitizer_checks.py build --build-dir DIR [--make MAKE]
      builds both programs and stops. The package's test command builds it with the other
      tests (CMake target sf_sanitizer_builds, a dependency of `tests`), so that no compiler
      competes with the timing-sensitive rostests; the checks then find the tree up to date.
      --make "$(MAKE)" from a make recipe: the build joins that make's job server. Both
      checks may run at the same time on one DIR: configuring and building take a lock on DIR.

All need clang and libclang-rt-14-dev (scripts/run_tests.sh installs them).
"""

import argparse
import fcntl
import os
import re
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(HERE)  # sf_estimation/
# Inputs that once failed (fixed since), read as seeds; new inputs go to the first corpus.
REGRESSIONS = os.path.join(SOURCE, "fuzz", "regressions")
SANITIZER_ENV = {
    "ASAN_OPTIONS": "abort_on_error=1:detect_leaks=1:strict_string_checks=1",
    "UBSAN_OPTIONS": "print_stacktrace=1:halt_on_error=1",
}


def run(cmd, **kwargs):
    print("$ " + " ".join(cmd), flush=True)
    return subprocess.run(cmd, **kwargs)


CONFIGURE_OPTIONS = ["-DCMAKE_BUILD_TYPE=Sanitize", "-DCMAKE_CXX_COMPILER=clang++",
                     "-DSF_ESTIMATION_SANITIZE=ON", "-DSF_ESTIMATION_FUZZ=ON",
                     "-DSF_ESTIMATION_BUILD_TESTS=ON", "-DSF_ESTIMATION_EXPLICIT_INSTANCES=OFF"]
# Tests whose length is statistics, not code paths: at -O0 under the sanitizers they take
# minutes (LinearisedProposal's 2 x 3000 steps of 1000 particles: 123 s, against 0.45 s in the
# normal build, which runs them). The code they run is the sanitizers' all the same, in the
# shorter tests of the same filter (the proposal's one-step and refusal tests, the shared
# dead reckoning's). The long statistical loops of a few other tests run a short count in
# this tree instead (sf_estimation/test/statistical_steps.hpp; the regular build runs the
# full count and asserts their statistics).
SLOW_AT_O0 = ["LinearisedProposal.UnobservableBiasKeepsTheKalmanFiltersValue"]

TARGETS = {"unit-tests": ["sf_estimation_tests"], "fuzz": ["sf_estimation_fuzz"],
           "build": ["sf_estimation_tests", "sf_estimation_fuzz"]}


def jobserver_fds():
    """The read and write ends of the calling make's job server (--jobserver-auth=R,W in
    MAKEFLAGS, GNU make 4.2 and later), or None when there is none to join."""
    match = re.search(r"--jobserver-(?:auth|fds)=(\d+),(\d+)", os.environ.get("MAKEFLAGS", ""))
    if not match:
        return None
    fds = (int(match.group(1)), int(match.group(2)))
    try:
        for fd in fds:
            os.fstat(fd)
    except OSError:
        return None
    return fds


def build(build_dir, targets, jobs, make=None):
    """Configures and builds under an exclusive lock on build_dir: the unit tests and the
    fuzz run of the test command start together on one tree. With make (run from a make
    recipe), the build joins that make's job server instead of running its own jobs."""
    os.makedirs(build_dir, exist_ok=True)
    with open(os.path.join(build_dir, ".sanitizer_checks.lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        configure = ["cmake", "-S", SOURCE, "-B", build_dir, "-G", "Unix Makefiles"]
        if run(configure + CONFIGURE_OPTIONS, stdout=subprocess.DEVNULL).returncode != 0:
            return False
        fds = jobserver_fds() if make else None
        if fds:
            return run([make, "-C", build_dir] + targets, pass_fds=fds).returncode == 0
        return run(["cmake", "--build", build_dir, "-j", str(jobs), "--target"]
                   + targets).returncode == 0


def write_junit(path, suite_name, cases):
    """cases: (name, ok, message, seconds)."""
    if not path:
        return
    suite = ET.Element("testsuite", name=suite_name, tests=str(len(cases)),
                       failures=str(sum(1 for c in cases if not c[1])), errors="0", skipped="0")
    for name, ok, message, seconds in cases:
        case = ET.SubElement(suite, "testcase", classname=suite_name, name=name,
                             time="%.1f" % seconds)
        if not ok:
            ET.SubElement(case, "failure", message=message.splitlines()[0]).text = message
        else:
            ET.SubElement(case, "system-out").text = message
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    ET.ElementTree(suite).write(path, encoding="utf-8", xml_declaration=True)


def unit_tests(args):
    start = time.time()
    env = dict(os.environ, **SANITIZER_ENV)
    if not build(args.build_dir, TARGETS["unit-tests"], args.jobs):
        write_junit(args.junit, "estimation_sanitized_tests",
                    [("build", False, "sanitizer build of sf_estimation_tests failed", 0.0)])
        return 1
    built = time.time()
    xml = os.path.join(args.build_dir, "sanitized_tests.xml")
    proc = run([os.path.join(args.build_dir, "sf_estimation_tests"), "--gtest_output=xml:" + xml,
                "--gtest_filter=-" + ":".join(SLOW_AT_O0)],
               cwd=os.path.join(SOURCE, "test"), env=env, stdout=subprocess.PIPE,
               stderr=subprocess.STDOUT, universal_newlines=True)
    print(proc.stdout[-20000:])
    elapsed = time.time() - built
    summary = "build %.0f s, tests %.0f s, exit %d" % (built - start, elapsed, proc.returncode)
    print(summary)
    if args.junit:
        if proc.returncode == 0 and os.path.exists(xml):
            # gtest's own file, one testcase per test, renamed for the suite.
            tree = ET.parse(xml)
            tree.getroot().set("name", "estimation_sanitized_tests")
            os.makedirs(os.path.dirname(os.path.abspath(args.junit)), exist_ok=True)
            tree.write(args.junit, encoding="utf-8", xml_declaration=True)
        else:
            report = proc.stdout[-4000:]
            write_junit(args.junit, "estimation_sanitized_tests",
                        [("sf_estimation_tests", False, summary + "\n" + report, elapsed)])
    return 0 if proc.returncode == 0 else 1


def fuzz(args):
    if not build(args.build_dir, TARGETS["fuzz"], args.jobs):
        write_junit(args.junit, "estimation_fuzz",
                    [("build", False, "build of sf_estimation_fuzz failed", 0.0)])
        return 1
    corpus = args.corpus or os.path.join(args.build_dir, "corpus")
    os.makedirs(corpus, exist_ok=True)
    env = dict(os.environ, **SANITIZER_ENV)
    cmd = [os.path.join(args.build_dir, "sf_estimation_fuzz"), "-max_total_time=%d" % args.seconds,
           "-timeout=10", "-rss_limit_mb=2048", "-max_len=4096", "-print_final_stats=1",
           "-artifact_prefix=" + os.path.join(args.build_dir, ""), corpus, REGRESSIONS]
    start = time.time()
    proc = run(cmd, cwd=args.build_dir, env=env, stdout=subprocess.PIPE,
               stderr=subprocess.STDOUT, universal_newlines=True)
    elapsed = time.time() - start
    out = proc.stdout
    execs = re.findall(r"stat::number_of_executed_units:\s*(\d+)", out)
    cov = re.findall(r"cov: (\d+) ft: (\d+) corp: (\d+)/(\S+)", out)
    files = len(os.listdir(corpus))
    summary = "%.0f s, %s executions, corpus %d inputs%s, exit %d" % (
        elapsed, execs[-1] if execs else "?", files,
        " (cov %s, ft %s, %s/%s in the last report)" % cov[-1] if cov else "", proc.returncode)
    # The start of a crash report says what failed, the end what was running.
    print(out if len(out) < 12000 else out[:6000] + "\n[...]\n" + out[-6000:])
    print("fuzzing: " + summary)
    ok = proc.returncode == 0
    write_junit(args.junit, "estimation_fuzz",
                [("sf_estimation_fuzz", ok, "fuzzing: " + summary + ("" if ok else "\n" + out[:8000]),
                  elapsed)])
    return 0 if ok else 1


def build_only(args):
    return 0 if build(args.build_dir, TARGETS["build"], args.jobs, args.make) else 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    for name in ("unit-tests", "fuzz", "build"):
        p = sub.add_parser(name)
        p.add_argument("--build-dir", required=True)
        p.add_argument("-j", "--jobs", type=int, default=2)
        if name == "build":
            p.add_argument("--make", help="the calling make (a recipe's $(MAKE)): join its "
                           "job server when MAKEFLAGS names one")
        else:
            p.add_argument("--junit")
        if name == "fuzz":
            p.add_argument("--seconds", type=int, default=60)
            p.add_argument("--corpus")
    args = parser.parse_args()
    args.build_dir = os.path.abspath(args.build_dir)
    return {"unit-tests": unit_tests, "fuzz": fuzz, "build": build_only}[args.command](args)


if __name__ == "__main__":
    sys.exit(main())
