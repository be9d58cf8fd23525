#!/usr/bin/env bash
# CPU time of the fusion node on a recording, side by side (doc/node_benchmarks.md,
# "On a recording"): one `rosbag play --clock` of the bag at 1x to processes that are all
# subscribed before it starts:
#   floor    sf_subscribe_floor_node: the node's input subscriptions, doing nothing (roscpp's
#            cost for the traffic)
#   node     the fusion node as a process (default sf_husky_skid_steer_ekf)
#   nodelet  the same header's nodelet in a nodelet manager (the manager's CPU)
#   rl       robot_localization's ekf_localization_node, with --rl-ws (optional)
#   node_lib the node with the libsf_fusion_node.so of --compare-lib DIR (optional: another
#            build of the node library, e.g. an older commit's, for a before/after figure)
# CPU = utime + stime of /proc/<pid>/stat (all threads, 1/CLK_TCK s ticks), read before the
# player starts, when it has ended, and after --idle s more with the simulated clock stopped
# (the bag's last /clock stays the time). Also --before s of waiting for the first /clock.
#
# Usage (in a sourced catkin workspace that built the node, its nodelet and
# sf_subscribe_floor_node):
#   sf_filter/bench/measure_recording_cpu.sh [--bag bags/husky_gps.bag] [--runs 1]
#     [--node sf_husky_skid_steer_ekf] [--topics "/encoder /imu/data"] [--before 10]
#     [--idle 30] [--rl-ws DIR] [--compare-lib DIR] [--no-nodelet] [--node-args "A:=B ..."] [--port N]
#     [--out DIR]
# --rl-ws DIR: a catkin workspace with robot_localization built (DIR/devel/setup.bash); its
# EKF gets the node's inputs (odometry v and yaw rate, IMU yaw rate) at the node's period.
# --no-nodelet: leave the nodelet out (a header built without NODELET, e.g. the 3D ones).
# --node-args: extra arguments of the node, e.g. remaps of its relative topics onto the bag's
# (the node runs in the namespace /node).
# Prints one table per run; logs and reports in DIR (a fresh temporary directory by default).
# Everything started here is stopped on exit, by pid.
set -euo pipefail
export PATH=/usr/bin:/bin:$PATH

BAG=""
RUNS=1
NODE=sf_husky_skid_steer_ekf
TOPICS="/encoder /imu/data"
BEFORE=10
IDLE=30
RL_WS=""
COMPARE_LIB=""
PORT=""
OUT=""
NODELET=1
NODE_ARGS=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --bag) BAG=$2; shift 2 ;;
    --runs) RUNS=$2; shift 2 ;;
    --node) NODE=$2; shift 2 ;;
    --topics) TOPICS=$2; shift 2 ;;
    --before) BEFORE=$2; shift 2 ;;
    --idle) IDLE=$2; shift 2 ;;
    --rl-ws) RL_WS=$2; shift 2 ;;
    --compare-lib) COMPARE_LIB=$2; shift 2 ;;
    --port) PORT=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --no-nodelet) NODELET=0; shift ;;
    --node-args) NODE_ARGS=$2; shift 2 ;;
    -h|--help) sed -n '2,30p' "$0"; exit 0 ;;
    *) echo "unknown argument: $1" >&2; exit 2 ;;
  esac
done

if ! command -v catkin_find >/dev/null || ! catkin_find --first-only --libexec sf_pkg "$NODE" >/dev/null 2>&1; then
  echo "source the catkin workspace first (devel/setup.bash) and build $NODE" >&2
  exit 1
fi
[[ -n "$BAG" ]] || BAG="$(rospack find sf_pkg)/bags/husky_gps.bag"
[[ -f "$BAG" ]] || { echo "no bag $BAG" >&2; exit 1; }
[[ -n "$OUT" ]] || OUT=$(mktemp -d /tmp/sf_recording_cpu.XXXXXX)
mkdir -p "$OUT"
# shellcheck source=ros_bench_lib.sh
source "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/ros_bench_lib.sh"
NODE_EXE=$(bench_exe "$NODE")
FLOOR_EXE=$(bench_exe sf_subscribe_floor_node)
MANAGER_EXE=$(catkin_find --first-only --libexec nodelet nodelet 2>/dev/null || echo /usr/lib/nodelet/nodelet)
RL_EXE=""
if [[ -n "$RL_WS" ]]; then
  RL_EXE=$(find "$RL_WS/devel/lib/robot_localization" -name ekf_localization_node -type f | head -1)
  [[ -x "$RL_EXE" ]] || { echo "no ekf_localization_node in $RL_WS/devel" >&2; exit 1; }
fi
[[ -n "$PORT" ]] || PORT=$(bench_free_port)

declare -A PID=()
LOADER_PID=""
ROSCORE_PID=""
cleanup() {
  for name in "${!PID[@]}"; do bench_stop "${PID[$name]}" INT; done
  bench_stop "$LOADER_PID" INT
  bench_stop "$ROSCORE_PID" INT
  wait 2>/dev/null || true
}
trap cleanup EXIT
trap 'exit 130' INT TERM

cpu_seconds() { awk -v tck="$(getconf CLK_TCK)" '{sub(/^.*\) /, ""); print ($12 + $13) / tck}' "/proc/$1/stat"; }
now() { date +%s.%N; }

# subscribers_ready N: every topic in $TOPICS has at least N subscribing nodes.
subscribers_ready() {
  python3 - "$1" $TOPICS <<'EOF'
import sys, rosgraph
need, topics = int(sys.argv[1]), sys.argv[2:]
_, subscribers, _ = rosgraph.Master("/bench").getSystemState()
have = {t: len(nodes) for t, nodes in subscribers}
sys.exit(0 if all(have.get(t, 0) >= need for t in topics) else 1)
EOF
}

rl_params() {  # the node's inputs, period and frames for robot_localization's EKF
  cat <<EOF
frequency: 10
two_d_mode: true
publish_tf: true
odom_frame: rl_odom
base_link_frame: base_footprint
world_frame: rl_odom
odom0: /encoder
odom0_config: [false, false, false, false, false, false, true, false, false, false, false, true, false, false, false]
imu0: /imu/data
imu0_config: [false, false, false, false, false, false, false, false, false, false, false, true, false, false, false]
EOF
}

DURATION=$(rosbag info --yaml --key=duration "$BAG")
bench_start_roscore "$PORT"
rosparam set /use_sim_time true
echo "load before: $(cat /proc/loadavg)" | tee "$OUT/load.txt"

for run in $(seq "$RUNS"); do
  D="$OUT/run$run"
  mkdir -p "$D"
  PID=()
  # shellcheck disable=SC2086
  "$FLOOR_EXE" $TOPICS __name:=floor >"$D/floor.log" 2>&1 &
  PID[floor]=$!
  # shellcheck disable=SC2086
  ROS_NAMESPACE=node "$NODE_EXE" __name:=fusion $NODE_ARGS >"$D/node.log" 2>&1 &
  PID[node]=$!
  expected=2
  if [[ "$NODELET" == 1 ]]; then
    "$MANAGER_EXE" manager __name:=manager >"$D/manager.log" 2>&1 &
    PID[nodelet]=$!
    ROS_NAMESPACE=nodelet "$MANAGER_EXE" load "sf_pkg/$NODE" /manager __name:=fusion >"$D/loader.log" 2>&1 &
    LOADER_PID=$!
    expected=3
  fi
  if [[ -n "$COMPARE_LIB" ]]; then
    [[ -f "$COMPARE_LIB/libsf_fusion_node.so" ]] || { echo "no $COMPARE_LIB/libsf_fusion_node.so" >&2; exit 1; }
    ROS_NAMESPACE=node_lib LD_LIBRARY_PATH="$COMPARE_LIB:${LD_LIBRARY_PATH:-}" "$NODE_EXE" __name:=fusion >"$D/node_lib.log" 2>&1 &
    PID[node_lib]=$!
    expected=$((expected + 1))
  fi
  if [[ -n "$RL_EXE" ]]; then
    rl_params >"$D/rl.yaml"
    rosparam load "$D/rl.yaml" /rl_ekf
    "$RL_EXE" __name:=rl_ekf >"$D/rl.log" 2>&1 &
    PID[rl]=$!
    expected=$((expected + 1))
  fi
  for _ in $(seq 200); do subscribers_ready "$expected" && break; sleep 0.3; done
  subscribers_ready "$expected" || { echo "not all $expected processes subscribed to $TOPICS" >&2; exit 1; }
  declare -A C0=() C1=() C2=() C3=()
  for n in "${!PID[@]}"; do C0[$n]=$(cpu_seconds "${PID[$n]}"); done
  sleep "$BEFORE"
  for n in "${!PID[@]}"; do C1[$n]=$(cpu_seconds "${PID[$n]}"); done
  start=$(now)
  # -d 1: a second after advertising, so that every subscriber has connected before the first
  # message (roscpp drops what is published before a connection stands)
  rosbag play --clock -q -d 1 "$BAG" >"$D/play.log" 2>&1
  end=$(now)
  for n in "${!PID[@]}"; do C2[$n]=$(cpu_seconds "${PID[$n]}"); done
  sleep "$IDLE"
  for n in "${!PID[@]}"; do C3[$n]=$(cpu_seconds "${PID[$n]}"); done
  load=$(cat /proc/loadavg)
  play=$(awk -v a="$start" -v b="$end" 'BEGIN {printf "%.1f", b - a}')
  echo
  echo "run $run: $BAG ($DURATION s) played in $play s (1x, rosbag play --clock -d 1); load average after: $load"
  echo "CPU [s] while it played, % of a core over the recording's $DURATION s, then % of a core for"
  echo "$IDLE s with the clock stopped after it and for $BEFORE s before the first /clock"
  printf '%-8s %8s %10s %12s %14s %13s\n' process "CPU [s]" "% of core" "above floor" "clock stopped" "before clock"
  for n in floor node nodelet node_lib rl; do
    [[ -n "${PID[$n]:-}" ]] || continue
    awk -v n="$n" -v c0="${C0[$n]}" -v c1="${C1[$n]}" -v c2="${C2[$n]}" -v c3="${C3[$n]}" \
        -v f1="${C1[floor]}" -v f2="${C2[floor]}" -v dur="$DURATION" -v idle="$IDLE" -v before="$BEFORE" \
        'BEGIN {printf "%-8s %8.2f %10.2f %12.2f %14.2f %13.2f\n", n, c2 - c1, 100 * (c2 - c1) / dur,
                (c2 - c1) - (f2 - f1), 100 * (c3 - c2) / idle, 100 * (c1 - c0) / before}'
  done | tee "$D/table.txt"
  for n in "${!PID[@]}"; do bench_stop "${PID[$n]}" INT; done
  bench_stop "$LOADER_PID" INT
  LOADER_PID=""
  PID=()
  grep -h "messages received\|input counters" "$D"/*.log || true
done
echo "load after: $(cat /proc/loadavg)" | tee -a "$OUT/load.txt"
echo "logs: $OUT"
