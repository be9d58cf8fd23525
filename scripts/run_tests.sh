#!/usr/bin/env bash
# Every test of the package: builds in the catkin workspace ($SF_WS), runs
# `catkin_make run_tests` (gtest unit tests, rostests), then prints
# catkin_test_results' report and a last line "N passed, N failed, N skipped".
# Exits non-zero when a test fails or errors, or when no test ran.
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

# The package's own heavy checks (sanitizers, fuzzing, soak) are part of this command, and so
# are the benchmarks, built and installed (the install-space test checks them).
SF_CMAKE_ARGS=(-DSF_PKG_HEAVY_TESTS=ON -DSF_ESTIMATION_EXPLICIT_INSTANCES=ON
  -DSF_BUILD_BENCHMARKS=ON)
SF_DEB_PACKAGES+=("${SF_TEST_DEB_PACKAGES[@]}")
sf_prepare

results="${SF_WS}/build/test_results"
rm -rf "$results"

# Two steps, so that what measures wall-clock behaviour runs without a compiler beside it
# (doc/reliability.md, "Test order"): (1) one goal, sf_untimed_tests, builds every test
# executable and the sanitizer tree (`tests`) and runs the tests that do not depend on timing,
# each as soon as what it runs is built, two jobs at a time, the longest chains first (the
# sanitizer checks, the robot replay suite; CMakeLists.txt); (2) the rostests run two at a time
# (SF_ROSTEST_JOBS) but those playing a bag in real time alone, then the soak and the
# under-load check (which brings its own load, stress-ng) one at a time. Under a plain
# `catkin_make -j2 run_tests` a compiler or the fuzz run would compete with the 1 kHz nodes of
# the online tests, a load nobody chose and no test asserts against.
build_dir="${SF_WS}/build"
make_targets="$(make -C "$build_dir" help 2>/dev/null | sed -n 's/^\.\.\. \([^ ]*\).*$/\1/p')"
has_target() { grep -qx -- "$1" <<<"$make_targets"; }
# The timed groups are CMake's list (SF_PKG_TIMED_TEST_GROUPS in CMakeLists.txt).
read -r -a timed <<<"$(sed -n 's/^SF_PKG_TIMED_TEST_GROUPS:INTERNAL=//p' "${build_dir}/CMakeCache.txt" \
  | tr ';' ' ')"
# Each rostest has its own master and waits for events, not for time; two at a time took the
# rostests from 230 to 120 s on 2 cores with the same margins (doc/reliability.md). Those that
# play a bag in real time against the node's offline replay run alone (sf_online_rostests).
SF_ROSTEST_JOBS="${SF_ROSTEST_JOBS:-2}"
timed_targets=()
for name in "${timed[@]}"; do
  target="run_tests_${SF_PACKAGE}_${name}"
  if has_target "$target"; then timed_targets+=("$target"); fi
done
# Step 1: CMake's goal for sf_pkg (make runs the goals of a catkin build directory one after
# another, but a goal's prerequisites side by side), and the whole run_tests target of the
# workspace's other packages, if they have tests.
untimed=(sf_untimed_tests)
for target in $(grep -E "^run_tests_[A-Za-z0-9]+$" <<<"$make_targets"); do
  [[ "$target" == "run_tests_${SF_PACKAGE}" ]] || untimed+=("$target")
done

sf_log "running tests (log: ${SF_WS}/tests.log)"
t0=$SECONDS
base=(catkin_make -C "$SF_WS" -k -DCMAKE_BUILD_TYPE=Release -DPYTHON_EXECUTABLE=/usr/bin/python3
  "${SF_CMAKE_ARGS[@]}")
# Show the tests' own output, not catkin/CMake/make chatter.
filter() {
  if [[ "$SF_VERBOSE" == 1 ]]; then
    cat
  else
    awk '
    /^-- / || /^####/ || /^\[ *[0-9]+%\] (Built target|Linking|Building)/ { next }
    /^(Base path|Source space|Build space|Devel space|Install space):/ { next }
    /^(Removing test result files|Making|Generating)/ { next }
    { print; fflush() }'
  fi
}
run_steps() {
  local rc=0 t=$SECONDS
  sf_log "step 1: building the tests and running those that do not depend on timing" \
    "(${untimed[*]})"
  "${base[@]}" -j"${SF_JOBS}" "${untimed[@]}" || rc=$?
  sf_log "step 1 took $((SECONDS - t)) s"
  if ((${#timed_targets[@]})); then
    t=$SECONDS
    # The rostest group runs as CMake's two goals (CMakeLists.txt): those playing a bag in real
    # time against the node's offline replay alone, the others two at a time.
    local rostests=0 alone=() target
    for target in "${timed_targets[@]}"; do
      if [[ "$target" == "run_tests_${SF_PACKAGE}_rostest" ]]; then
        rostests=1
      else
        alone+=("$target")
      fi
    done
    if ((rostests)); then
      sf_log "step 2: the rostests, ${SF_ROSTEST_JOBS} at a time (sf_paired_rostests)," \
        "then those playing a bag in real time one at a time (sf_online_rostests)"
      "${base[@]}" -j"${SF_ROSTEST_JOBS}" sf_paired_rostests || rc=$?
      "${base[@]}" -j1 sf_online_rostests || rc=$?
    fi
    if ((${#alone[@]})); then
      sf_log "step 2, one at a time: ${alone[*]}"
      "${base[@]}" -j1 "${alone[@]}" || rc=$?
    fi
    sf_log "step 2 took $((SECONDS - t)) s"
  fi
  return "$rc"
}
run_steps 2>&1 | tee "${SF_WS}/tests.log" | filter && test_rc=0 || test_rc=$?
sf_log "tests finished in $((SECONDS - t0)) s"
if ((test_rc != 0)); then
  sf_log "ERROR: catkin_make run_tests failed (exit ${test_rc}); full log: ${SF_WS}/tests.log"
fi

echo
echo "==== test summary ===="
results_rc=0
if [[ -d "$results" ]]; then
  catkin_test_results "$results" || results_rc=$?
fi
summary_args=()
if ((test_rc != 0)); then
  summary_args+=(--failed-step "catkin_make run_tests (build or runner) failed, see ${SF_WS}/tests.log")
fi
summary_rc=0
/usr/bin/python3 "${SF_REPO_ROOT}/scripts/test_summary.py" "${summary_args[@]}" "$results" \
  || summary_rc=$?

if ((test_rc != 0 || results_rc != 0 || summary_rc != 0)); then
  exit 1
fi
