# shellcheck shell=bash
# Shared helper for scripts/run_default.sh and scripts/run_tests.sh.
# Source it; it defines functions and variables and changes nothing else.
#
# Environment:
#   SF_WS       catkin workspace to build in (default: $HOME/.cache/sf_pkg_ws).
#               Created if missing; $SF_WS/src/sf_pkg is a symlink to this repo,
#               $SF_WS/src/sf_msgs one to its sf_msgs/ folder (the message package).
#   SF_JOBS     parallel build jobs (default: 2)
#   SF_VERBOSE  1 = stream the full build output (default: log file only)
#   SF_CMAKE_ARGS  (array, set by the calling script) extra CMake arguments of the build

# Debian's ROS lives in /usr; `python3` earlier on PATH (e.g. a pyenv shim)
# lacks the ROS Python modules.
export PATH="/usr/bin:/bin:${PATH}"

SF_REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd -P)"
SF_WS="${SF_WS:-${HOME}/.cache/sf_pkg_ws}"
SF_JOBS="${SF_JOBS:-2}"
SF_VERBOSE="${SF_VERBOSE:-0}"
SF_CMAKE_ARGS=()
SF_PACKAGE=sf_pkg

# Debian packages needed to build and run the package (and its gtest and rostest tests; the
# test command adds SF_TEST_DEB_PACKAGES below).
# rosbash provides rosrun (ros-core only recommends it); make, which cmake only recommends, is
# not on a minimal Debian 12 (checked in a fresh debootstrap, doc/build_cost.md "Round seven").
# python3-diagnostic-msgs: the Python messages of /diagnostics, for `rostopic echo
# /diagnostics`, tools/diagnostics_monitor.py and its test (ros-diagnostic-msgs has only the
# .msg files). tf2-tools: tf2_ros's executables, `rosrun tf2_ros static_transform_publisher`
# (launch/diff_drive_odom_imu.launch's imu_mount, doc/spatial_alignment.md).
# libgeographiclib-dev: the WGS84 geodesy of the GPS inputs (GeographicLib::LocalCartesian).
# python3-rosservice, python3-rostopic: the rostests that look up the type of a
# running service or topic (set_pose, covariance_block).
# libceres-dev: the batch MAP reference of the smoother tests (sf_estimation_ceres_tests,
# optional in CMake; neither the library nor the nodes link Ceres; doc/smoothing.md).
SF_DEB_PACKAGES=(
  ros-core-dev catkin libroscpp-dev librosbag-dev python3-rostest rosbash
  libtf2-ros-dev libtf2-geometry-msgs-dev
  ros-std-msgs ros-geometry-msgs ros-nav-msgs ros-sensor-msgs ros-diagnostic-msgs
  libdiagnostic-updater-dev libtopic-tools-dev ros-message-generation ros-message-runtime
  libeigen3-dev libboost-dev libyaml-cpp-dev libgtest-dev libgmock-dev libbenchmark-dev
  libnlopt-dev libnlopt-cxx-dev
  libceres-dev
  python3-rosbag python3-nav-msgs python3-sensor-msgs python3-tf2-msgs python3-tf2 python3-matplotlib
  python3-h5py python3-scipy
  python3-diagnostic-msgs tf2-tools python3-rosservice python3-rostopic
  libgeographiclib-dev
  libnodelet-dev libnodeletlib-dev libnodeletlib-tools pluginlib-dev
  cmake make g++
)
# Only the test command's (scripts/run_tests.sh): clang and libclang-rt-14-dev build
# sf_estimation's sanitizer and libFuzzer checks (sf_estimation/scripts/sanitizer_checks.py),
# stress-ng is the load of the under-load check: 320 of the 1654 MB a fresh Debian 12 installs,
# which the main job does not need (doc/build_cost.md, "Round seven").
# shellcheck disable=SC2034  # read by scripts/run_tests.sh
SF_TEST_DEB_PACKAGES=(clang libclang-rt-14-dev stress-ng)

sf_log() { printf '[sf_pkg] %s\n' "$*" >&2; }
sf_die() { printf '[sf_pkg] ERROR: %s\n' "$*" >&2; exit 1; }

# (a) Install missing Debian packages (root), or say how to (non-root).
sf_ensure_packages() {
  local missing=() pkg
  for pkg in "${SF_DEB_PACKAGES[@]}"; do
    if [[ "$(dpkg-query -W -f='${db:Status-Status}' "$pkg" 2>/dev/null)" != installed ]]; then
      missing+=("$pkg")
    fi
  done
  if ((${#missing[@]} == 0)); then return 0; fi

  if [[ "$(id -u)" -eq 0 ]]; then
    sf_log "installing missing Debian packages: ${missing[*]}"
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" \
      || sf_die "apt-get install failed"
  else
    sf_log "missing Debian packages: ${missing[*]}"
    sf_log "install them with (run 'sudo apt-get update' first on a fresh machine):"
    printf 'sudo apt-get install -y --no-install-recommends %s\n' "${missing[*]}"
    exit 1
  fi
}

# (b) Workspace with src/sf_pkg -> repository root and src/sf_msgs -> its sf_msgs/ folder:
# sf_msgs is a catkin package of its own, and catkin does not look for packages below a
# folder that has a package.xml (the repository root's).
sf_link_into_workspace() {
  local target="$1" link="$2"
  if [[ -L "$link" ]]; then
    if [[ "$(readlink -f "$link")" != "$target" ]]; then
      sf_log "re-pointing ${link} -> ${target}"
      ln -sfn "$target" "$link"
    fi
  elif [[ -e "$link" ]]; then
    sf_die "${link} exists and is not a symlink; set SF_WS to another workspace"
  else
    ln -s "$target" "$link"
  fi
}

sf_setup_workspace() {
  SF_WS="$(realpath -m "${SF_WS}")"
  case "$SF_WS/" in
    "$SF_REPO_ROOT"/*) sf_die "SF_WS (${SF_WS}) must be outside the source tree ${SF_REPO_ROOT}" ;;
  esac
  mkdir -p "${SF_WS}/src"
  SF_WS="$(cd "${SF_WS}" && pwd -P)"
  sf_link_into_workspace "$SF_REPO_ROOT" "${SF_WS}/src/${SF_PACKAGE}"
  sf_link_into_workspace "$SF_REPO_ROOT/sf_msgs" "${SF_WS}/src/sf_msgs"
  # Debian's catkin snapshots the environment of the tests (build/catkin_generated/
  # setup_cached.sh) at the first configure and puts only folders that exist then on
  # PYTHONPATH; sf_msgs' Python module is generated later, so without this folder every test
  # that imports sf_msgs fails in a fresh workspace ("No module named 'sf_msgs'").
  mkdir -p "${SF_WS}/devel/lib/python3/dist-packages"
}

# Run catkin_make in the workspace. The output goes to $SF_WS/<logname>;
# compiler warnings/errors are echoed, and the log tail is shown on failure.
#   sf_catkin_make <logname> [catkin_make args / make targets...]
sf_catkin_make() {
  local log="${SF_WS}/$1"
  shift
  local cmd=(catkin_make -C "$SF_WS" -j"${SF_JOBS}"
    -DCMAKE_BUILD_TYPE=Release -DPYTHON_EXECUTABLE=/usr/bin/python3 "${SF_CMAKE_ARGS[@]}" "$@")
  local rc=0
  if [[ "$SF_VERBOSE" == 1 ]]; then
    "${cmd[@]}" 2>&1 | tee "$log" || rc=$?
  else
    "${cmd[@]}" >"$log" 2>&1 || rc=$?
    grep -E '(warning|error):' "$log" >&2 || true
  fi
  if ((rc != 0)); then
    [[ "$SF_VERBOSE" == 1 ]] || tail -n 60 "$log" >&2
    sf_die "catkin_make $* failed (exit ${rc}); full log: ${log}"
  fi
}

# (c) Debian's ROS has no /opt/ros/<distro>/setup.bash: the workspace's own
# devel/setup.bash (which also runs /etc/catkin/profile.d hooks) is the one to
# source. It is not `set -u` clean, hence the guard.
sf_source_devel() {
  local setup="${SF_WS}/devel/setup.bash"
  [[ -f "$setup" ]] || sf_die "${setup} not found (build first)"
  local had_u=0
  [[ $- == *u* ]] && had_u=1
  set +u
  # shellcheck disable=SC1090
  source "$setup"
  if ((had_u)); then set -u; fi
  # setup.bash sets this via /etc/catkin/profile.d/10.roslaunch.sh; keep a
  # default in case it ever doesn't. rostest starts its own master anyway.
  export ROS_MASTER_URI="${ROS_MASTER_URI:-http://localhost:11311}"
  export PATH="/usr/bin:/bin:${PATH}"
}

# (d) Everything a script needs before doing its job: packages, workspace,
# a (Release) build, the devel environment. With arguments, only those make targets are
# built (the main job builds just the nodes it runs); without, every target.
sf_prepare() {
  sf_ensure_packages
  sf_setup_workspace
  sf_log "building ${SF_PACKAGE}${1:+ targets $*} in ${SF_WS} (log: ${SF_WS}/build.log)"
  local t0=$SECONDS
  sf_catkin_make build.log "$@"
  sf_log "build done in $((SECONDS - t0)) s"
  sf_source_devel
}
