#!/usr/bin/env bash
# End-to-end overhead of a fusion node under ROS (doc/node_benchmarks.md, "Fusion node").
#
# Starts a private roscore on a free port, then per run: the fusion node (default
# sf_nav3ctrl_ukf, renamed to that name so its state topic is /sf_nav3ctrl_ukf/state) and
# sf_node_load_driver, which publishes angular_velocity + acceleration at 100 Hz,
# velocity_wheel_left/right + cmd_vel at 10 Hz in wall time, records the publication delay of
# /pose/x and of the state topic (receive wall time - header.stamp, the period end) and the
# node's CPU time (/proc/<pid>/stat utime+stime, and /proc/<pid>/task/*/schedstat) over the
# measurement window. Optionally first measures the node idle (no inputs) and the estimator's
# own time per step (sf_fusion_core_benchmark, UKF_nav3ctrl_step), which is subtracted to give
# the CPU per period spent outside the estimator (ROS deserialisation, callbacks, alignment,
# serialisation and publication of the outputs, timers, tf, rosout logging).
#
# Usage (in a sourced catkin workspace that built sf_nav3ctrl_ukf, sf_node_load_driver,
# sf_fusion_core_benchmark and, for --reference, sf_ros_floor_node):
#   sf_filter/bench/measure_node_overhead.sh [--duration 60] [--warmup 5] [--runs 1]
#     [--port 11399] [--idle 0] [--tcp-nodelay] [--node sf_nav3ctrl_ukf] [--no-estimator-bench]
#     [--reference] [--out DIR]
# --reference: after each run of the node, the same run with sf_ros_floor_node (the same ROS
# traffic without FusionCore or estimator), to separate roscpp's cost from the node's own.
# Results: one key=value report per run in DIR (a fresh temporary directory by default) and a
# summary on stdout. Everything started here is stopped on exit, by pid.
set -euo pipefail
export PATH=/usr/bin:/bin:$PATH

DURATION=60
WARMUP=5
RUNS=1
PORT=11399
IDLE=0
TCP_NODELAY=false
REFERENCE=false
NODE=sf_nav3ctrl_ukf
ESTIMATOR_BENCH=true
OUT=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --duration) DURATION=$2; shift 2 ;;
    --warmup) WARMUP=$2; shift 2 ;;
    --runs) RUNS=$2; shift 2 ;;
    --port) PORT=$2; shift 2 ;;
    --idle) IDLE=$2; shift 2 ;;
    --tcp-nodelay) TCP_NODELAY=true; shift ;;
    --reference) REFERENCE=true; shift ;;
    --node) NODE=$2; shift 2 ;;
    --no-estimator-bench) ESTIMATOR_BENCH=false; shift ;;
    --out) OUT=$2; shift 2 ;;
    -h|--help) sed -n '2,23p' "$0"; exit 0 ;;
    *) echo "unknown argument: $1" >&2; exit 2 ;;
  esac
done

if ! command -v catkin_find >/dev/null || ! catkin_find --first-only --libexec sf_pkg "$NODE" >/dev/null 2>&1; then
  echo "source the catkin workspace first (devel/setup.bash) and build $NODE, sf_node_load_driver" >&2
  exit 1
fi
[[ -n "$OUT" ]] || OUT=$(mktemp -d /tmp/sf_node_overhead.XXXXXX)
mkdir -p "$OUT"
# shellcheck source=ros_bench_lib.sh
source "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/ros_bench_lib.sh"
exe() { bench_exe "$1"; }
DRIVER_EXE=$(exe sf_node_load_driver)
BENCH_EXE=$(exe sf_fusion_core_benchmark 2>/dev/null || true)

ROSCORE_PID=""
NODE_PID=""
DRIVER_PID=""
stop() { bench_stop "$@"; }
cleanup() {
  stop "$DRIVER_PID" INT
  stop "$NODE_PID" INT
  stop "$ROSCORE_PID" INT  # roscore stops its rosmaster and rosout
  wait 2>/dev/null || true
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# Node CPU seconds: utime+stime from /proc/<pid>/stat and the live threads' schedstat.
cpu_stat() { awk -v tck="$(getconf CLK_TCK)" '{sub(/^.*\) /, ""); print ($12 + $13) / tck}' "/proc/$1/stat"; }
cpu_sched() { cat /proc/"$1"/task/*/schedstat | awk '{s += $1} END {printf "%.6f\n", s / 1e9}'; }

echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) CPUs, load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "results in $OUT"

# Estimator alone, for the subtraction (CPU time per step, median of 5 repetitions).
ESTIMATOR_US=""
if $ESTIMATOR_BENCH && [[ -n "$BENCH_EXE" ]]; then
  "$BENCH_EXE" --benchmark_filter='^UKF_nav3ctrl_step$' --benchmark_repetitions=5 \
    --benchmark_out="$OUT/estimator_step.json" --benchmark_out_format=json >/dev/null 2>&1
  ESTIMATOR_US=$(python3 -c '
import json, sys
runs = [b for b in json.load(open(sys.argv[1]))["benchmarks"] if b.get("aggregate_name") == "median"]
print("%.3f" % (runs[0]["cpu_time"] / 1000.0))' "$OUT/estimator_step.json")
  echo "estimator step alone (UKF_nav3ctrl_step, CPU time, median of 5): $ESTIMATOR_US us"
fi

bench_start_roscore "$PORT"

# measure <executable name> <report tag>: one node under the driver's load.
measure() {
  local name=$1 tag=$2 exe
  exe=$(exe "$name")
  "$exe" __name:="$name" >"$OUT/node_$tag.log" 2>&1 &
  NODE_PID=$!
  sleep 2
  kill -0 "$NODE_PID" 2>/dev/null || { echo "$name failed, see $OUT/node_$tag.log" >&2; exit 1; }
  if [[ "$IDLE" != 0 ]]; then
    local s0 s1 q0 q1
    s0=$(cpu_stat "$NODE_PID"); q0=$(cpu_sched "$NODE_PID")
    sleep "$IDLE"
    s1=$(cpu_stat "$NODE_PID"); q1=$(cpu_sched "$NODE_PID")
    awk -v s="$s0" -v S="$s1" -v q="$q0" -v Q="$q1" -v t="$IDLE" 'BEGIN {
      printf "idle_window_s=%s\nidle_cpu_stat_percent=%.3f\nidle_cpu_sched_percent=%.3f\nidle_cpu_sched_us_per_period=%.1f\n",
        t, 100 * (S - s) / t, 100 * (Q - q) / t, (Q - q) / (t / 0.1) * 1e6 }' >"$OUT/$tag.txt"
  else
    : >"$OUT/$tag.txt"
  fi
  "$DRIVER_EXE" _duration:="$DURATION" _warmup:="$WARMUP" _node_pid:="$NODE_PID" \
    _tcp_nodelay:="$TCP_NODELAY" _state_topic:="/$name/state" _report:="$OUT/$tag.driver.txt" \
    >"$OUT/driver_$tag.log" 2>&1 &
  DRIVER_PID=$!
  wait "$DRIVER_PID" || { echo "driver failed, see $OUT/driver_$tag.log" >&2; exit 1; }
  DRIVER_PID=""
  stop "$NODE_PID" INT
  NODE_PID=""
  cat "$OUT/$tag.driver.txt" >>"$OUT/$tag.txt"
  echo "load_after=$(cut -d' ' -f1-3 /proc/loadavg | tr ' ' ,)" >>"$OUT/$tag.txt"
}

for run in $(seq "$RUNS"); do
  measure "$NODE" "node_$run"
  if [[ -n "$ESTIMATOR_US" ]]; then
    awk -F= -v e="$ESTIMATOR_US" '
      $1 == "node_cpu_stat_us_per_period" { s = $2 }
      $1 == "node_cpu_sched_us_per_period" { q = $2 }
      END { printf "estimator_us_per_period=%s\noutside_estimator_stat_us_per_period=%.1f\noutside_estimator_sched_us_per_period=%.1f\n", e, s - e, q - e }' \
      "$OUT/node_$run.txt" >>"$OUT/node_$run.txt"
  fi
  echo "--- run $run: $NODE"
  cat "$OUT/node_$run.txt"
  if $REFERENCE; then
    measure sf_ros_floor_node "floor_$run"
    echo "--- run $run: sf_ros_floor_node (same ROS traffic, no FusionCore, no estimator)"
    cat "$OUT/floor_$run.txt"
  fi
done

# Summary over the runs: median (min..max) of the main figures.
python3 - "$OUT" "$RUNS" <<'PY'
import statistics, sys
out, runs = sys.argv[1], int(sys.argv[2])
def load(path):
    try:
        return dict(l.strip().split("=", 1) for l in open(path) if "=" in l)
    except FileNotFoundError:
        return None
keys = ["node_cpu_stat_percent", "node_cpu_sched_percent", "node_cpu_sched_us_per_period",
        "idle_cpu_sched_us_per_period", "outside_estimator_sched_us_per_period",
        "output.delay_mean_us", "output.delay_median_us", "output.delay_p99_us",
        "output.delay_max_us", "state.delay_median_us", "state.delay_p99_us",
        "output.missed_periods"]
for tag in ("node", "floor"):
    reports = [r for r in (load(f"{out}/{tag}_{i}.txt") for i in range(1, runs + 1)) if r]
    if not reports:
        continue
    print(f"=== summary {tag}: {len(reports)} run(s), median (min .. max)")
    for k in keys:
        v = [float(r[k]) for r in reports if k in r]
        if v:
            print(f"  {k:40s} {statistics.median(v):10.1f}  ({min(v):.1f} .. {max(v):.1f})")
PY
