#!/usr/bin/python3
"""Round three's attacks replayed (issue 38 D1-D9): each reproduction of the issue is run again,
as a careless user and a faulty robot would, and its outcome checked against what the fix
promises (doc/reliability.md). Prints a table - attack, expected outcome, observed, PASS/FAIL -
and exits 1 when an attack is not handled as expected (2 when a node is not built).

Offline through sf_diff_drive_odom_imu (config/diff_drive_odom_imu.h), sf_husky_skid_steer_gps
(config/husky_skid_steer_gps.h on a copy of bags/husky_gps.bag) and sf_test_pose_block
(test/configs/pose_block_kf.h); online (D6, D7) through sf_diff_drive_odom_imu started under a
ROS master of this script's own on a free port. The bags and files are made in a temporary
directory with the helpers of the replay tests (test/robots). References: the input files byte
for byte; the replay of the Husky recording without the faulty fixes; a Kalman filter stepped
by hand (test/kalman_2d.py); the lines the node logged against the burst's duration.

Run by hand (7 s on a 2-core machine beside other builds):
  SF_LIB_DIR=$WS/devel/lib/sf_pkg /usr/bin/python3 test/attacks/attack_round_three.py
The test command runs it with --junit (CMakeLists.txt, attack_round_three).
"""

import argparse
import math
import os
import resource
import socket
import stat
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TEST = os.path.dirname(HERE)
REPO = os.path.dirname(TEST)
sys.dont_write_bytecode = True
for folder in (os.path.join(TEST, "robots"), os.path.join(TEST, "eval"), TEST):
    sys.path.insert(0, folder)
import replay_helpers  # noqa: E402
from kalman_2d import update  # noqa: E402
from run_unittests import write_junit  # noqa: E402
from test_gps_faults_replay import FAULTS as LATER_FIX_FAULTS  # noqa: E402
from test_gps_faults_replay import write_bags as write_gps_bags  # noqa: E402
from test_replay_faults import write_small_bag  # noqa: E402
from test_tool_faults import write_nan_bag  # noqa: E402

NODE = "sf_diff_drive_odom_imu"
GPS_NODE = "sf_husky_skid_steer_gps"
BLOCK_NODE = "sf_test_pose_block"
SHIPPED = os.path.join(REPO, "bags", "diff_drive_seed1.bag")
# D2: first fixes off the Earth, each in turn (the fourth fix is then the datum)
FIRST_FIX_FAULTS = {0: ("latitude", 91.0), 1: (("latitude", "longitude"), (-100.0, 500.0)),
                    2: ("altitude", 1e30)}
# What a refusal may use at most: on a tool without the size check the 100 MB file took 12.3 GB
# and 105 s (issue 38 D9), which must not take the machine down with it.
CHILD_MEMORY = 2 << 30  # bytes of address space
CHILD_CPU = 60  # s


class Attacks:
    """One method per attack: `attack_*` returns (observed, passed); its docstring's first line is
    the attack, its second the expected outcome."""

    def __init__(self, lib_dir, tmp):
        self.lib_dir, self.tmp = lib_dir, tmp
        self.bag = self.path("in.bag")
        write_small_bag(self.bag)

    def path(self, name):
        return os.path.join(self.tmp, name)

    def run(self, exe_name, *args):
        return subprocess.run([os.path.join(self.lib_dir, exe_name)] + list(args),
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              universal_newlines=True, errors="replace", timeout=120)

    @staticmethod
    def contents(path):
        with open(path, "rb") as f:
            return f.read()

    @staticmethod
    def first_error(proc):
        lines = proc.stderr.strip().splitlines()
        return lines[0].split(": ", 1)[-1] if lines else "(nothing on stderr)"

    # -- D1: --tune --out onto its input or onto what is not a file

    def refused_out(self, target, still, why):
        """`--tune in.bag --out target`: (observed, refused with `why` and `still` holds)."""
        before = self.contents(self.bag)
        proc = self.run(NODE, "--tune", self.bag, "--out", target)
        ok = (proc.returncode == 1 and why in proc.stderr and still()
              and self.contents(self.bag) == before and not os.path.lexists(target + ".partial"))
        return "exit %d, %s" % (proc.returncode, self.first_error(proc)), ok

    def attack_d1_out_is_the_input(self):
        """D1 `--tune in.bag --out in.bag`, and `--out sub/../in.bag`
        exit 1 'is the input bag', in.bag byte for byte as before"""
        os.makedirs(self.path("sub"), exist_ok=True)
        observed, ok = [], True
        for target in (self.bag, os.path.join(self.tmp, "sub", "..", "in.bag")):
            text, passed = self.refused_out(target, lambda: True, "is the input bag")
            observed.append(text)
            ok = ok and passed
        return "; ".join(observed), ok

    def attack_d1_out_is_not_a_file(self):
        """D1 `--tune in.bag --out` a FIFO, a symlink to a file, a device node (as root)
        exit 1 'it is a FIFO/symbolic link/device', each left what it was, the link's file kept"""
        fifo, link, elsewhere, device = (self.path(n) for n in ("fifo", "link", "kept", "null"))
        os.mkfifo(fifo)
        with open(elsewhere, "w") as f:
            f.write("kept: 1\n")
        os.symlink(elsewhere, link)
        cases = [(fifo, stat.S_ISFIFO, "a FIFO"), (link, stat.S_ISLNK, "a symbolic link")]
        try:  # a /dev/null of the attack's own: a bug must not replace the real one
            os.mknod(device, 0o600 | stat.S_IFCHR, os.makedev(1, 3))
            cases.append((device, stat.S_ISCHR, "a device"))
        except OSError:
            pass
        observed, ok = [], True
        for target, kind, why in cases:
            text, passed = self.refused_out(
                target, lambda t=target, k=kind: k(os.lstat(t).st_mode), "it is " + why)
            observed.append(text)
            ok = ok and passed
        ok = ok and self.contents(elsewhere) == b"kept: 1\n"
        return "; ".join(observed), ok

    # -- D2, D3: GPS fixes not on the Earth, a jump

    def gps_replay(self, faults, name, *extra):
        """The Husky recording with `faults` and without those fixes replayed: (faulty process,
        its rows or None, the rows without the fixes)."""
        faulty, removed = self.path(name + ".bag"), self.path(name + "_removed.bag")
        write_gps_bags(faulty, removed, faults)
        runs = []
        for bag in (faulty, removed):
            csv_path = bag[:-4] + ".csv"
            proc = self.run(GPS_NODE, "--replay", bag, "--csv", csv_path, *extra)
            runs.append((proc, replay_helpers.read_rows(csv_path) if proc.returncode == 0
                         else None))
        return runs[0][0], runs[0][1], runs[1][1]

    @staticmethod
    def largest_difference(rows, reference):
        """The largest position difference [m] between two replays, inf when they differ in
        length or one failed."""
        if not rows or not reference or len(rows) != len(reference):
            return math.inf
        return max(math.hypot(a["x0"] - b["x0"], a["x1"] - b["x1"])
                   for a, b in zip(rows, reference))

    def attack_d2_first_fixes_off_the_earth(self):
        """D2 first fixes latitude 91, then latitude -100 with longitude 500, then altitude 1e30
        the three dropped as not on the Earth, the fourth the datum: estimates as without them"""
        proc, rows, reference = self.gps_replay(FIRST_FIX_FAULTS, "first_fixes")
        gap = self.largest_difference(rows, reference)
        counted = "3 dropped as not on the Earth" in proc.stdout
        return ("exit %d, %s, largest difference to the recording without them %.3g m"
                % (proc.returncode, "3 counted as not on the Earth" if counted else
                   "not counted as not on the Earth", gap),
                proc.returncode == 0 and counted and gap < 1e-9)

    def attack_d2_datum_parameter(self):
        """D2 `--params` with `datum: [43, -79, 1.0e30]`
        refused, exit 2, naming the altitude"""
        params = self.path("datum.yaml")
        with open(params, "w") as f:
            f.write("datum: [43, -79, 1.0e30]\n")
        proc = self.run(GPS_NODE, "--replay", replay_helpers.HUSKY_BAG, "--params", params)
        return ("exit %d, %s" % (proc.returncode, self.first_error(proc)),
                proc.returncode == 2 and "altitude 1e+30 outside" in proc.stderr)

    def attack_d3_later_fixes(self):
        """D3 fix 1 latitude 91, 20 longitude 500, 40 altitude 1e30, 60 a 1000 km jump; --strict
        3 dropped, the jump gated, counted; estimates as without them; --strict exit 1"""
        proc, rows, reference = self.gps_replay(LATER_FIX_FAULTS, "later_fixes")
        gap = self.largest_difference(rows, reference)
        strict = self.run(GPS_NODE, "--replay", self.path("later_fixes.bag"), "--strict")
        counted = ("3 dropped as not on the Earth" in proc.stdout and "1 gated" in proc.stdout)
        return ("exit %d, %s, largest difference %.3g m; --strict exit %d (%s)" % (
            proc.returncode, "dropped and gated counted" if counted else "not counted", gap,
            strict.returncode, self.first_error(strict)),
            proc.returncode == 0 and counted and gap < 1e-9 and strict.returncode == 1)

    # -- D4: a covariance block asymmetric in the last bit

    def attack_d4_asymmetric_block(self):
        """D4 21 poses whose covariance pair is 0.1 against nextafter(0.1) (20 estimated periods)
        all 20 used, each with the pair's mean: the Kalman filter stepped by hand"""
        import genpy
        import rosbag
        from geometry_msgs.msg import PoseWithCovarianceStamped

        upper = math.nextafter(0.1, 1.0)
        mean = (0.1 + upper) / 2
        bag, csv_path = self.path("block.bag"), self.path("block.csv")
        x, P, expected = [0.0, 0.0], [[1.0, 0.0], [0.0, 1.0]], []
        with rosbag.Bag(bag, "w") as out:
            # one a period (ESTIMATION_PERIOD 100 ms); the 21st ends the 20th's period
            for k in range(21):
                m = PoseWithCovarianceStamped()
                m.header.stamp = genpy.Time(1700000000) + genpy.Duration(0, 100000000 * k)
                m.header.frame_id = "odom"
                m.pose.pose.position.x, m.pose.pose.position.y = 1.0 + 0.01 * k, -0.5
                m.pose.pose.orientation.w = 1.0
                m.pose.covariance = [0.0] * 36
                m.pose.covariance[0] = m.pose.covariance[7] = 1.0
                m.pose.covariance[1], m.pose.covariance[6] = upper, 0.1
                out.write("pose", m, m.header.stamp)
                x, P = update(x, P, [m.pose.pose.position.x, -0.5], [[1.0, mean], [mean, 1.0]])
                expected.append(x)
        proc = self.run(BLOCK_NODE, "--replay", bag, "--csv", csv_path)
        if proc.returncode != 0:
            return "exit %d, %s" % (proc.returncode, self.first_error(proc)), False
        rows = replay_helpers.read_rows(csv_path)
        error = max([abs(r["x0"] - e[0]) + abs(r["x1"] - e[1]) for r, e in zip(rows, expected)]
                    or [math.inf])
        used = "21 received, 20 used, dropped: none" in proc.stdout
        return ("exit 0, %s, %d estimates, at most %.3g off the hand computation" % (
            "20 of 20 used" if used else "not all used", len(rows), error),
            used and len(rows) == 20 and error < 1e-12)

    # -- D5: a remap onto another configured topic of another type

    def attack_d5_remap_type_clash(self):
        """D5 `--replay bags/diff_drive_seed1.bag odom:=imu/data --strict`
        exit 1 naming both types, no CSV"""
        csv_path = self.path("remap.csv")
        proc = self.run(NODE, "--replay", SHIPPED, "odom:=imu/data", "--strict", "--csv", csv_path)
        named = "one read as nav_msgs/Odometry, the other as sensor_msgs/Imu" in proc.stderr
        return ("exit %d, %s" % (proc.returncode, self.first_error(proc)),
                proc.returncode == 1 and named and not os.path.exists(csv_path))

    # -- D8: --tune with nothing to identify

    def attack_d8_tune_identifies_nothing(self):
        """D8 `--tune` on a bag of one message per topic, and on one whose values are all NaN
        exit 1 'identifies nothing', no tuned file written"""
        one, nan = self.path("one_each.bag"), self.path("nan.bag")
        write_small_bag(one, count=1)
        write_nan_bag(nan)
        observed, ok = [], True
        for bag in (one, nan):
            out = self.path("tuned.yaml")
            proc = self.run(NODE, "--tune", bag, "--out", out)
            observed.append("exit %d%s" % (proc.returncode, ", a file written"
                                           if os.path.exists(out) else ""))
            ok = ok and (proc.returncode == 1 and "identifies nothing" in proc.stderr
                         and not os.path.exists(out))
        return "; ".join(observed) + " (%s)" % self.first_error(proc), ok

    # -- D9: --params far larger than a node's parameters

    def attack_d9_huge_params(self):
        """D9 `--replay in.bag --params` a 100 MB YAML file (a list of numbers)
        exit 2 'larger than 256 KiB', without reading it: peak memory far below its size"""
        params = self.path("huge.yaml")
        line = "  - [" + ", ".join(["1.25"] * 16) + "]\n"
        chunk = (line * (1024 * 1024 // len(line))).encode()
        with open(params, "wb") as f:
            f.write(b"huge:\n")
            while f.tell() < 100 * 1000 * 1000:
                f.write(chunk)
        small = self.path("small.yaml")
        with open(small, "w") as f:
            f.write("estimation_period: 0.02\n")
        baseline, baseline_status, _ = self.peak_memory(small)
        peak, status, stderr = self.peak_memory(params)
        refused = status == 2 and "larger than 256 KiB" in stderr
        size = os.path.getsize(params)
        # The peak includes this script's memory at the fork (Linux keeps the high-water mark of
        # the forked image), the same for both runs; reading the file in would add its size.
        return ("exit %d, peak memory %.0f MB, %.0f MB with a 24-byte file, for a %.0f MB file"
                % (status, peak / 1e6, baseline / 1e6, size / 1e6),
                refused and baseline_status == 0 and peak < baseline + size / 4)

    def peak_memory(self, params):
        """`--replay in.bag --params params`: (peak resident bytes, exit status, stderr)."""
        stderr_path = self.path("peak.err")
        with open(stderr_path, "w") as err:
            child = subprocess.Popen([os.path.join(self.lib_dir, NODE), "--replay", self.bag,
                                      "--params", params, "--csv", self.path("peak.csv")],
                                     stdout=subprocess.DEVNULL, stderr=err, preexec_fn=bounded)
            _, status, usage = os.wait4(child.pid, 0)
        child.returncode = os.waitstatus_to_exitcode(status)
        with open(stderr_path) as err:
            return usage.ru_maxrss * 1024, child.returncode, err.read()

    # -- D6, D7: set_pose, through a running node

    def attack_d6_d7_set_pose(self):
        """D6, D7 set_pose: 1000 valid then 1000 refused service calls as fast as they go, x = 1e300
        at most one log line a second of each kind; x = 1e300 refused as ~initial_state is"""
        with OnlineNode(self.lib_dir, NODE, self.tmp) as node:
            valid = node.pose(1.0, 2.0, 0.2)
            refused = node.pose(1.0, 2.0, -1.0)  # a negative variance
            valid_took = node.burst(valid, 1000)
            refused_took = node.burst(refused, 1000)
            huge = node.call(node.pose(1e300, 0.0, 0.1))
            # the service answers after the node handled (and logged) each call
            set_lines, refused_lines = node.lines("pose set to"), node.lines("pose refused")
        ok_log = (1 <= set_lines <= 1 + valid_took and 1 <= refused_lines <= 1 + refused_took)
        ok_huge = (not huge.success and "magnitude at most 1e100" in huge.message)
        return ("%d 'pose set' lines in %.2f s, %d 'pose refused' lines in %.2f s; x = 1e300: %s"
                % (set_lines, valid_took, refused_lines, refused_took,
                   "refused (%s)" % huge.message if not huge.success else "set"),
                ok_log and ok_huge)


def bounded():
    """In the child before exec: CHILD_MEMORY and CHILD_CPU at most."""
    resource.setrlimit(resource.RLIMIT_AS, (CHILD_MEMORY, CHILD_MEMORY))
    resource.setrlimit(resource.RLIMIT_CPU, (CHILD_CPU, CHILD_CPU))


class OnlineNode:
    """A ROS master on a free port and `exe_name` under it (its output in a file), plus this
    process as a rospy node; the set_pose service of the node. Both stopped on exit."""

    def __init__(self, lib_dir, exe_name, tmp):
        self.exe = os.path.join(lib_dir, exe_name)
        self.tmp = tmp
        self.processes = []

    def __enter__(self):
        try:
            return self.start_all()
        except BaseException:
            self.__exit__()  # no master or node left behind
            raise

    def start_all(self):
        with socket.socket() as s:
            s.bind(("127.0.0.1", 0))
            port = s.getsockname()[1]
        os.environ.update(ROS_MASTER_URI="http://127.0.0.1:%d" % port, ROS_HOSTNAME="127.0.0.1",
                          ROS_LOG_DIR=os.path.join(self.tmp, "ros_log"))
        os.environ.pop("ROS_IP", None)
        self.start(["rosmaster", "--core", "-p", str(port)], "master.out")
        import rosgraph
        import rospy
        import rosservice
        from node_test_helpers import wait_for
        from roslib.message import get_service_class

        if not wait_for(lambda: rosgraph.is_master_online(), 30.0):
            raise RuntimeError("the ROS master did not start")
        self.output = os.path.join(self.tmp, "node.out")
        # stdout line by line (redirected, it is buffered): a line is in the file once the
        # service call that logged it has returned
        self.start(["stdbuf", "-oL", self.exe, "__name:=attacked"], "node.out")

        rospy.init_node("attack_round_three", disable_signals=True)
        rospy.wait_for_service("/attacked/set_pose", timeout=30.0)
        kind = get_service_class(rosservice.get_service_type("/attacked/set_pose"))
        self.service = rospy.ServiceProxy("/attacked/set_pose", kind, persistent=True)
        return self

    def start(self, command, output):
        with open(os.path.join(self.tmp, output), "w") as out:
            self.processes.append(subprocess.Popen(command, stdout=out, stderr=subprocess.STDOUT))

    def __exit__(self, *exc):
        import rospy

        if rospy.core.is_initialized():
            rospy.signal_shutdown("attacks done")
        for process in reversed(self.processes):
            process.terminate()
            try:
                process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()

    @staticmethod
    def pose(x, y, variance):
        from geometry_msgs.msg import PoseWithCovarianceStamped

        m = PoseWithCovarianceStamped()
        m.header.frame_id = "odom"
        m.pose.pose.position.x, m.pose.pose.position.y = x, y
        m.pose.pose.orientation.w = 1.0
        m.pose.covariance = [0.0] * 36
        m.pose.covariance[0] = m.pose.covariance[7] = variance
        m.pose.covariance[35] = 0.1
        return m

    def call(self, message):
        return self.service(pose=message)

    def burst(self, message, count):
        """`count` calls one after another; the seconds they took."""
        start = time.monotonic()
        for _ in range(count):
            self.call(message)
        return time.monotonic() - start

    def lines(self, text):
        with open(self.output, errors="replace") as f:
            return sum(1 for line in f if text in line)


def attack_methods():
    return [getattr(Attacks, name) for name in dir(Attacks) if name.startswith("attack_")]


def print_table(rows):
    """rows: (attack, expected, observed, verdict)."""
    print("| attack | expected | observed | result |")
    print("| --- | --- | --- | --- |")
    for row in rows:
        print("| %s |" % " | ".join(row))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--junit", help="also write the outcomes as a JUnit XML file")
    args = parser.parse_args()
    try:
        lib_dir = replay_helpers.built_lib_dir(NODE, GPS_NODE, BLOCK_NODE)
    except Exception as e:  # unittest.SkipTest: a node not built
        print("attack_round_three: %s" % e, file=sys.stderr)
        return 2
    rows, records = [], []
    with tempfile.TemporaryDirectory(prefix="sf_attacks_") as tmp:
        attacks = Attacks(lib_dir, tmp)
        for method in attack_methods():
            attack, expected = (line.strip() for line in method.__doc__.splitlines()[:2])
            start = time.monotonic()
            try:
                observed, passed = method(attacks)
            except Exception as e:  # an attack that crashed the script is a failed one
                observed, passed = "%s: %s" % (type(e).__name__, e), False
            rows.append((attack, expected, observed, "PASS" if passed else "FAIL"))
            records.append(("attack_round_three." + method.__name__, "",
                            "passed" if passed else "failure",
                            "" if passed else "%s\nexpected: %s\nobserved: %s" % (
                                attack, expected, observed), time.monotonic() - start))
    print_table(rows)
    failed = sum(1 for row in rows if row[3] == "FAIL")
    print("\n%d attacks, %d handled as expected, %d not" % (len(rows), len(rows) - failed, failed))
    if args.junit:
        write_junit(args.junit, records, "attack_round_three")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
