# shellcheck shell=bash
# Shared by the ROS benchmark scripts (measure_node_overhead.sh, soak_node.sh): a private
# roscore in an output directory and stopping what a script started, by pid. Source it after
# setting OUT (the output directory); it sets ROS_MASTER_URI, ROS_HOME and ROS_LOG_DIR.

# bench_exe <name>: the path of an sf_pkg executable of the sourced workspace.
bench_exe() { catkin_find --first-only --libexec sf_pkg "$1"; }

# bench_free_port: a TCP port nobody listens on.
bench_free_port() {
  python3 -c 'import socket; s = socket.socket(); s.bind(("localhost", 0)); print(s.getsockname()[1])'
}

# bench_stop <pid> <signal>: signal, wait up to 5 s, then SIGKILL.
bench_stop() {
  local pid=$1 sig=$2
  [[ -n "$pid" ]] && kill -0 "$pid" 2>/dev/null || return 0
  kill "-$sig" "$pid" 2>/dev/null || true
  for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || return 0; sleep 0.1; done
  kill -KILL "$pid" 2>/dev/null || true
}

# bench_start_roscore <port>: roscore on the port, logs in $OUT; sets ROSCORE_PID.
bench_start_roscore() {
  local port=$1
  if ss -ltn 2>/dev/null | awk '{print $4}' | grep -q ":${port}\$"; then
    echo "port $port is in use; pick another with --port" >&2
    exit 1
  fi
  export ROS_MASTER_URI=http://localhost:${port}
  export ROS_HOME=$OUT/ros_home
  export ROS_LOG_DIR=$OUT/log
  mkdir -p "$ROS_HOME" "$ROS_LOG_DIR"
  roscore -p "$port" >"$OUT/roscore.log" 2>&1 &
  ROSCORE_PID=$!
  for _ in $(seq 100); do
    rosparam get /rosdistro >/dev/null 2>&1 && return 0
    kill -0 "$ROSCORE_PID" 2>/dev/null || { echo "roscore failed, see $OUT/roscore.log" >&2; exit 1; }
    sleep 0.3
  done
  echo "roscore did not come up" >&2
  exit 1
}
