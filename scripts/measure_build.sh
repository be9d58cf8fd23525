#!/usr/bin/env bash
# Build cost of the package (doc/build_cost.md): per configuration header, the CPU time and
# peak memory of compiling its node's translation unit (GNU time, the package's own flags);
# the wall time of a clean build of every node (no tests); the wall time of rebuilding one
# node after touching its header. With --baseline REV the same translation units of another
# revision are compiled in the same run, for a before/after on one machine.
#
#   scripts/measure_build.sh [--baseline REV] [--baseline-clean] [--units-only] [--jobs N]
#                            [HEADER ...]
#
# HEADER: configuration headers relative to the repository (default: config/nav3ctrl_ekf.h,
# config/nav3ctrl_ukf.h, config/nav3ctrl_pf.h, config/soccer_kf.h). --baseline-clean also
# times the baseline's clean build (minutes); --units-only measures the translation units
# alone (no clean build, no header-touch rebuild). Needs the packages of scripts/common.sh
# and GNU time (/usr/bin/time, Debian package "time").
set -euo pipefail
export PATH="/usr/bin:/bin:${PATH}"
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd -P)"
baseline="" baseline_clean=0 units_only=0 jobs=2 headers=()
while (($#)); do
  case "$1" in
    --baseline) baseline="$2"; shift 2 ;;
    --baseline-clean) baseline_clean=1; shift ;;
    --units-only) units_only=1; shift ;;
    --jobs) jobs="$2"; shift 2 ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    *) headers+=("$1"); shift ;;
  esac
done
((${#headers[@]})) || headers=(config/nav3ctrl_ekf.h config/nav3ctrl_ukf.h config/nav3ctrl_pf.h
  config/soccer_kf.h)
[[ -x /usr/bin/time ]] || { echo "measure_build.sh: needs GNU time (apt-get install time)" >&2; exit 1; }

work="$(mktemp -d "${TMPDIR:-/tmp}/sf_measure_build.XXXXXX")"
trap 'rm -rf "$work"' EXIT

# configure <source tree> <workspace>: a workspace without tests, compile commands exported,
# the messages generated (every node's unit includes them).
# A tree with the message package sf_msgs/ gets its second link (scripts/common.sh); an older
# tree generated the messages in sf_pkg.
configure() {
  mkdir -p "$2/src"
  ln -s "$1" "$2/src/sf_pkg"
  local messages=sf_pkg_generate_messages_cpp
  if [[ -f "$1/sf_msgs/package.xml" ]]; then
    ln -s "$1/sf_msgs" "$2/src/sf_msgs"
    messages=sf_msgs_generate_messages_cpp
  fi
  catkin_make -C "$2" -j"$jobs" -DCMAKE_BUILD_TYPE=Release -DPYTHON_EXECUTABLE=/usr/bin/python3 \
    -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DCATKIN_ENABLE_TESTING=OFF \
    "$messages" >"$2/configure.log" 2>&1
}

# unit_cost <workspace> <header> [<source>]: "cpu_s peak_MB" of compiling the header's node
# unit (fusion_node_main), its smoothers' unit (fusion_node_smoothers), its step's unit
# (fusion_node_step; a header without QUATERNION_STATES, or a tree before one, has none: "n/a n/a")
# or its EKF Jacobians' (fusion_node_jacobians: an EKF's or a 3D header's; a tree before
# 2026-12-07 had it as fusion_node_observation, for the 3D headers only).
unit_cost() {
  local cmd
  cmd="$(/usr/bin/python3 - "$1/build/compile_commands.json" "$2" "${3:-fusion_node_main}" <<'EOF'
import json, sys
for entry in json.load(open(sys.argv[1])):
    # the node's unit is fusion_node_unit.cpp for a NODELET header
    names = [sys.argv[3]] + {'fusion_node_main': ['fusion_node_unit'],
                             'fusion_node_jacobians': ['fusion_node_observation']}.get(
                                 sys.argv[3], [])
    if (any(n in entry['file'] for n in names)
            and '/' + sys.argv[2] + '\\"' in entry['command']):
        print('cd %s && %s' % (entry['directory'], entry['command'].replace(
            entry['command'].split(' -o ')[1].split()[0], '/dev/null')))
        break
EOF
)"
  [[ -n "$cmd" ]] || { echo "n/a n/a"; return; }
  /usr/bin/time -f "%U %S %M" -o "$work/time.txt" bash -c "$cmd" >/dev/null 2>&1 || true
  awk '{printf "%.1f %.0f\n", $1 + $2, $3 / 1024}' "$work/time.txt"
}

clean_build() {  # wall seconds of building everything in a configured workspace
  local t0=$SECONDS
  catkin_make -C "$1" -j"$jobs" >"$1/build.log" 2>&1
  echo $((SECONDS - t0))
}

echo "machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(date -u +%F)"
echo "compiler: $(c++ --version | head -1)"
echo

configure "$repo" "$work/current"
if [[ -n "$baseline" ]]; then
  git -C "$repo" worktree add -q --detach "$work/baseline_src" "$baseline"
  trap 'git -C "$repo" worktree remove --force "$work/baseline_src"; rm -rf "$work"' EXIT
  configure "$work/baseline_src" "$work/baseline"
fi

# The clean build comes first, as a user's: make builds the precompiled prelude
# (cmake/sf_add_filter.cmake) beside the library's sources, before the units that need it.
if ((!units_only)); then
  wall=$(clean_build "$work/current")
  ((baseline_clean)) && [[ -n "$baseline" ]] && baseline_wall=$(clean_build "$work/baseline")
fi

# The prelude, rebuilt alone for its figures; a unit's figure is then its compile with the
# prelude in place, as in a build.
prelude_cost() {  # "cpu_s peak_MB" of building the prelude target, or nothing
  local target=sf_pkg_sf_filter_prelude
  # (no "make help | grep -q": with pipefail, grep's early exit fails the pipeline)
  [[ "$(make -C "$1/build" help 2>/dev/null)" == *"... $target"* ]] || return 0
  find "$1/build" -path "*/$target.dir/*.gch" -delete
  /usr/bin/time -f "%U %S %M" -o "$work/prelude.txt" make -C "$1/build" "$target" >/dev/null 2>&1
  awk '{printf "%.1f %.0f\n", $1 + $2, $3 / 1024}' "$work/prelude.txt"
}
read -r pcpu pmem < <(prelude_cost "$work/current") || true
if [[ -n "${pcpu:-}" ]]; then
  printf '%-28s %14s %14s\n' "precompiled prelude (once)" "$pcpu" "$pmem"
fi
if [[ -n "$baseline" ]]; then prelude_cost "$work/baseline" >/dev/null; fi

printf '%-28s %14s %14s' "translation unit (header)" "CPU s" "peak MB"
[[ -n "$baseline" ]] && printf ' %14s %14s' "CPU s ($baseline)" "peak MB ($baseline)"
echo
# Each header's node unit, then its smoothers', its step's and its Jacobians' unit (sf_add_filter
# compiles the step's only for the 3D headers, the Jacobians' for them and the EKF headers).
for h in "${headers[@]}"; do
  for source in fusion_node_main fusion_node_smoothers fusion_node_step fusion_node_jacobians; do
    label="$h"
    [[ "$source" == fusion_node_smoothers ]] && label="  + smoothers"
    [[ "$source" == fusion_node_step ]] && label="  + step"
    [[ "$source" == fusion_node_jacobians ]] && label="  + Jacobians"
    read -r cpu mem < <(unit_cost "$work/current" "$h" "$source")
    bcpu=n/a bmem=n/a
    [[ -n "$baseline" ]] && read -r bcpu bmem < <(unit_cost "$work/baseline" "$h" "$source")
    # a unit neither tree compiles for this header is not listed
    [[ "$source" != fusion_node_main && "$cpu" == n/a && "$bcpu" == n/a ]] && continue
    printf '%-28s %14s %14s' "$label" "$cpu" "$mem"
    [[ -n "$baseline" ]] && printf ' %14s %14s' "$bcpu" "$bmem"
    echo
  done
done
echo
((units_only)) && exit 0

echo "clean build, every node, no tests (-j$jobs): $wall s wall"
[[ -n "${baseline_wall:-}" ]] && echo "clean build at $baseline (-j$jobs): $baseline_wall s wall"

node="sf_$(basename "${headers[0]}" .h)"
touch "$repo/${headers[0]}"
t0=$(date +%s.%N)
make -C "$work/current/build" "$node" >/dev/null 2>&1
echo "touch ${headers[0]}, rebuild $node: $(awk "BEGIN { printf \"%.1f\", $(date +%s.%N) - $t0 }") s wall"
