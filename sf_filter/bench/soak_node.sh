#!/usr/bin/env bash
# Load / soak of a fusion node (doc/reliability.md, "Load and soak"): four inputs at 1 kHz and a
# command at 100 Hz for --sim-duration seconds of simulated time, as fast as the node keeps up.
#
# Starts a private roscore on a free port, sets use_sim_time, then sf_test_soak (built from
# test/configs/soak_four_inputs_kf.h: KF, 10 ms period, four inputs, one control) and
# sf_test_soak_driver (sf_filter/bench/soak_driver.cpp), which owns /clock, publishes the inputs
# in simulated time, waits for the node's estimates so that it never runs more than --window
# periods ahead, and measures the estimates' spacing and delay, the node's CPU and its VmRSS.
# At the end the node is stopped with SIGINT and logs its per-input counters; the script
# compares the values received per input with the messages published.
#
# Usage (in a sourced catkin workspace that built sf_test_soak and sf_test_soak_driver):
#   sf_filter/bench/soak_node.sh [--sim-duration 600] [--warmup S] [--window 1] [--port P]
#     [--out DIR] [--wall-clock]
# --wall-clock: no simulated time; the driver publishes at 1 kHz in wall time for
# --sim-duration wall seconds without waiting for the node, and reports the jitter of the
# estimates' arrival spacing against the 10 ms period (the node's ros::Timer).
# Prints key=value lines (also in DIR/report.txt; DIR/rss.csv holds the memory samples) and
# exits 0 when every published input value was received and the driver saw no stall.
set -euo pipefail
export PATH=/usr/bin:/bin:$PATH
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

SIM_DURATION=600
WARMUP=""
WINDOW=1
PORT=""
OUT=""
WALL_CLOCK=false
while [[ $# -gt 0 ]]; do
  case "$1" in
    --sim-duration) SIM_DURATION=$2; shift 2 ;;
    --warmup) WARMUP=$2; shift 2 ;;
    --window) WINDOW=$2; shift 2 ;;
    --port) PORT=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --wall-clock) WALL_CLOCK=true; shift ;;
    -h|--help) sed -n '2,21p' "$0"; exit 0 ;;
    *) echo "unknown argument: $1" >&2; exit 2 ;;
  esac
done
[[ -n "$WARMUP" ]] || WARMUP=$(awk -v d="$SIM_DURATION" 'BEGIN {print d / 10}')

if ! command -v catkin_find >/dev/null || ! catkin_find --first-only --libexec sf_pkg sf_test_soak >/dev/null 2>&1; then
  echo "source the catkin workspace first (devel/setup.bash) and build sf_test_soak, sf_test_soak_driver" >&2
  exit 1
fi
[[ -n "$OUT" ]] || OUT=$(mktemp -d /tmp/sf_soak.XXXXXX)
mkdir -p "$OUT"
# shellcheck source=ros_bench_lib.sh
source "$HERE/ros_bench_lib.sh"
NODE_EXE=$(bench_exe sf_test_soak)
DRIVER_EXE=$(bench_exe sf_test_soak_driver)
[[ -n "$PORT" ]] || PORT=$(bench_free_port)

ROSCORE_PID="" NODE_PID="" DRIVER_PID=""
cleanup() {
  bench_stop "$DRIVER_PID" INT
  bench_stop "$NODE_PID" INT
  bench_stop "$ROSCORE_PID" INT
  wait 2>/dev/null || true
}
trap cleanup EXIT
trap 'exit 130' INT TERM

echo "machine=$(lscpu | sed -n 's/^Model name: *//p' | tr ' ' _), $(nproc) CPUs, load $(cut -d' ' -f1-3 /proc/loadavg | tr ' ' ,)"
echo "out=$OUT"
bench_start_roscore "$PORT"
$WALL_CLOCK || rosparam set /use_sim_time true

"$NODE_EXE" __name:=sf_test_soak >"$OUT/node.log" 2>&1 &
NODE_PID=$!
sleep 1
kill -0 "$NODE_PID" 2>/dev/null || { echo "sf_test_soak failed, see $OUT/node.log" >&2; exit 1; }
"$DRIVER_EXE" _sim_duration:="$SIM_DURATION" _warmup:="$WARMUP" _window:="$WINDOW" \
  _node_pid:="$NODE_PID" _wall_clock:="$WALL_CLOCK" _report:="$OUT/driver.txt" _rss_csv:="$OUT/rss.csv" \
  >"$OUT/driver.log" 2>&1 &
DRIVER_PID=$!
DRIVER_STATUS=0
wait "$DRIVER_PID" || DRIVER_STATUS=$?
DRIVER_PID=""
sleep 1  # the values still in flight
bench_stop "$NODE_PID" INT
NODE_PID=""
[[ -s "$OUT/driver.txt" ]] || { echo "driver failed ($DRIVER_STATUS), see $OUT/driver.log" >&2; exit 1; }

# The node's counters against what was published.
python3 - "$OUT" "$DRIVER_STATUS" <<'PY'
import re, sys
out, driver_status = sys.argv[1], int(sys.argv[2])
report = dict(l.strip().split("=", 1) for l in open(out + "/driver.txt") if "=" in l)
line = [l for l in open(out + "/node.log") if "input counters at shutdown" in l]
extra = []
ok = driver_status == 0
if not line:
    extra.append("node_counters=missing (see node.log)")
    ok = False
else:
    counts = re.findall(r"input (\d+) \(([^)]*)\): received (\d+), used (\d+), dropped (\d+)", line[-1])
    names = ["position_a", "position_b", "velocity_a", "velocity_b"]
    lost = 0
    for (index, _topic, received, used, dropped) in counts:
        published = int(report["published_" + names[int(index)]])
        extra += ["node_received_%s=%s" % (names[int(index)], received),
                  "node_used_%s=%s" % (names[int(index)], used),
                  "node_dropped_%s=%s" % (names[int(index)], dropped)]
        lost += published - int(received)
    extra.append("lost_at_subscriber=%d" % lost)
    ok = ok and lost == 0 and len(counts) == 4
extra.append("result=%s" % ("ok" if ok else "FAILED"))
with open(out + "/report.txt", "w") as f:
    f.write("".join("%s=%s\n" % kv for kv in report.items()) + "\n".join(extra) + "\n")
print(open(out + "/report.txt").read(), end="")
sys.exit(0 if ok else 1)
PY
