#!/usr/bin/python3
"""Checks the compile-time validation of the sf_filter configuration headers.

Every *.h file of this directory (except the message stand-ins fake_*.h) is a configuration
header whose first lines say what compiling it must give:

  // EXPECT: OK                  must compile without errors and without warnings
  // EXPECT: WARNING <text>      must compile; the output must contain <text>
  // EXPECT: <text>              must fail; the FIRST error printed must contain <text>
                                 (several EXPECT lines: it must contain each of them)
  // MAX_ERRORS: <k>             (optional) at most k errors in total, default 1
  // REQUIRES: <path>            (optional, repeatable) skip the case unless <path> exists
                                 (a skip is reported as skipped, in the summary and in the
                                 JUnit file, never as a pass)

Each header is compiled like the node's generated translation unit:

  g++ -std=c++17 -fsyntax-only -Wall -Wextra -I<sf_filter/include> -I<sf_estimation/include> -isystem <eigen> -I<this dir>
      -include config_prelude.hpp -include <header> config_tu.cpp

config_prelude.hpp (the standard, Eigen and Boost.Preprocessor headers, which no
configuration changes) is precompiled once per run into a temporary directory; a compiler
that cannot precompile it (--no-prelude, or a failed precompilation) parses it in every case.

The error that deliberately ends a compilation after a fatal configuration error
("SF_CONFIGURATION_ERROR__...: No such file or directory") is not counted.

Usage: check_config_errors.py [--cxx g++] [--eigen /usr/include/eigen3] [-j N] [-v] [header ...]
Prints one line per case and "N passed, N failed, N skipped"; exits 1 on any failure.
"""

import argparse
import concurrent.futures
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
INCLUDE = os.path.join(REPO, "sf_filter", "include")
# The estimation library: QUATERNION_STATES's layout and rotation helpers come from it.
ESTIMATION_INCLUDE = os.path.join(REPO, "sf_estimation", "include")
TU = os.path.join(HERE, "config_tu.cpp")
STOP_MARKER = "SF_CONFIGURATION_ERROR__"
PASS, FAIL, SKIP = "pass", "fail", "skip"
ERROR_RE = re.compile(r"(?:^|: )(?:fatal )?error: ")
WARNING_RE = re.compile(r"(?:^|: )warning: ")


def read_directives(path):
    expects, max_errors, requires = [], 1, []
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.strip()
            if not line.startswith("//"):
                break
            body = line[2:].strip()
            if body.startswith("EXPECT:"):
                expects.append(body[len("EXPECT:"):].strip())
            elif body.startswith("MAX_ERRORS:"):
                max_errors = int(body[len("MAX_ERRORS:"):].strip())
            elif body.startswith("REQUIRES:"):
                requires.append(body[len("REQUIRES:"):].strip())
    return expects, max_errors, requires


PRELUDE = os.path.join(HERE, "config_prelude.hpp")
FLAGS = ["-std=c++17", "-Wall", "-Wextra", "-fdiagnostics-color=never"]
ENV = dict(os.environ, LC_ALL="C", LANG="C")  # plain ASCII quotes in the diagnostics


def precompile_prelude(cxx, eigen, directory):
    """Precompiles config_prelude.hpp into `directory` and returns the path to force-include
    (GCC then reads its .gch beside it), or the prelude itself when that fails."""
    copy = os.path.join(directory, os.path.basename(PRELUDE))
    shutil.copyfile(PRELUDE, copy)
    cmd = [cxx] + FLAGS + ["-isystem", eigen, "-x", "c++-header", copy, "-o", copy + ".gch"]
    try:
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              universal_newlines=True, env=ENV)
    except OSError as e:
        print("note: the prelude was not precompiled (%s); each case parses it" % e)
        return PRELUDE
    if proc.returncode != 0:
        print("note: the prelude was not precompiled (%s); each case parses it" %
              (proc.stdout.strip().splitlines() or ["exit %d" % proc.returncode])[-1])
        return PRELUDE
    return copy


def compile_header(cxx, eigen, header, prelude=PRELUDE):
    # -Winvalid-pch: a precompiled prelude the compiler cannot use is a warning, which fails
    # the cases expected to compile cleanly, instead of a silent slowdown.
    cmd = ([cxx, "-fsyntax-only", "-Winvalid-pch"] + FLAGS +
           ["-I" + INCLUDE, "-I" + ESTIMATION_INCLUDE, "-isystem", eigen, "-I" + HERE,
            "-include", prelude, "-include", header, TU])
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, env=ENV)
    return proc.returncode, proc.stdout, cmd


def check(cxx, eigen, header, verbose, prelude=PRELUDE):
    name = os.path.basename(header)
    expects, max_errors, requires = read_directives(header)
    expect = expects[0] if expects else None
    if expect is None:
        return FAIL, "FAIL %s: no '// EXPECT:' line" % name
    missing = [r for r in requires if not os.path.exists(r)]
    if missing:
        return SKIP, "SKIP %s (missing %s)" % (name, ", ".join(missing))
    rc, out, cmd = compile_header(cxx, eigen, header, prelude)
    lines = out.splitlines()
    errors = [l for l in lines if ERROR_RE.search(l) and STOP_MARKER not in l]
    warnings = [l for l in lines if WARNING_RE.search(l)]
    detail = ""
    if verbose:
        detail = "\n    $ " + " ".join(cmd) + "\n" + "\n".join("    " + l for l in lines)

    if expect == "OK":
        if rc != 0:
            first = errors[0] if errors else "exit code %d" % rc
            return FAIL, "FAIL %s: expected to compile, got: %s%s" % (name, first, detail)
        if warnings:
            return FAIL, "FAIL %s: expected no warnings, got: %s%s" % (name, warnings[0], detail)
        return PASS, "PASS %s (compiles)%s" % (name, detail)

    if expect.startswith("WARNING "):
        text = expect[len("WARNING "):]
        if rc != 0:
            first = errors[0] if errors else "exit code %d" % rc
            return FAIL, "FAIL %s: expected to compile, got: %s%s" % (name, first, detail)
        if text not in out:
            return FAIL, "FAIL %s: warning '%s' not printed%s" % (name, text, detail)
        return PASS, "PASS %s (warns: %s)%s" % (name, text, detail)

    expect = "' and '".join(expects)
    if rc == 0:
        return FAIL, "FAIL %s: expected an error containing '%s', but it compiled%s" % (
            name, expect, detail)
    if not errors:
        return FAIL, "FAIL %s: compiler failed without an error line%s" % (name, detail)
    if not all(e in errors[0] for e in expects):
        later = any(all(e in error for e in expects) for error in errors[1:])
        where = "a later error" if later else "no error"
        return FAIL, "FAIL %s: first error is\n    %s\n  expected it to contain '%s' (%s has it)%s" % (
            name, errors[0], expect, where, detail)
    if len(errors) > max_errors:
        return FAIL, "FAIL %s: %d errors, at most %d expected; the second is\n    %s%s" % (
            name, len(errors), max_errors, errors[1], detail)
    return PASS, "PASS %s (%d error%s)%s" % (name, len(errors), "" if len(errors) == 1 else "s",
                                             detail)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cxx", default=os.environ.get("CXX", "g++"))
    parser.add_argument("--eigen", default="/usr/include/eigen3")
    parser.add_argument("-v", "--verbose", action="store_true", help="print compiler output")
    parser.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 1,
                        help="parallel compilations (default: number of CPUs)")
    parser.add_argument("--junit", help="also write the results as a JUnit XML file")
    parser.add_argument("--no-prelude", action="store_true",
                        help="do not precompile config_prelude.hpp (parse it in every case)")
    parser.add_argument("headers", nargs="*", help="headers to check (default: all *.h here)")
    args = parser.parse_args()

    headers = args.headers or sorted(
        h for h in glob.glob(os.path.join(HERE, "*.h"))
        if not os.path.basename(h).startswith("fake_"))
    counts = {PASS: 0, FAIL: 0, SKIP: 0}
    cases = []
    scratch = tempfile.TemporaryDirectory(prefix="sf_config_errors_")
    prelude = PRELUDE if args.no_prelude else precompile_prelude(args.cxx, args.eigen,
                                                                  scratch.name)
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        results = pool.map(
            lambda h: check(args.cxx, args.eigen, os.path.abspath(h), args.verbose, prelude),
            headers)
        for header, (status, message) in zip(headers, results):
            print(message, flush=True)
            cases.append((os.path.basename(header), status, message))
            counts[status] += 1
    print("%d passed, %d failed, %d skipped" % (counts[PASS], counts[FAIL], counts[SKIP]))
    if args.junit:
        write_junit(args.junit, cases)
    return 1 if counts[FAIL] else 0


def write_junit(path, cases):
    """One testcase per header, so catkin_test_results counts them like gtest cases."""
    import xml.etree.ElementTree as ET
    suite = ET.Element("testsuite", name="config_errors", tests=str(len(cases)),
                       failures=str(sum(1 for c in cases if c[1] == FAIL)), errors="0",
                       skipped=str(sum(1 for c in cases if c[1] == SKIP)))
    for name, status, message in cases:
        case = ET.SubElement(suite, "testcase", classname="config_errors", name=name)
        if status == FAIL:
            ET.SubElement(case, "failure", message=message.splitlines()[0]).text = message
        elif status == SKIP:
            ET.SubElement(case, "skipped", message=message.splitlines()[0]).text = message
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    ET.ElementTree(suite).write(path, encoding="utf-8", xml_declaration=True)


if __name__ == "__main__":
    sys.exit(main())
