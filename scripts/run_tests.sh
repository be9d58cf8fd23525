#!/usr/bin/env bash
# Every test of the package: builds in the catkin workspace ($SF_WS), runs
# `catkin_make run_tests` (gtest unit tests, rostests), then prints
# catkin_test_results' report and a last line "N passed, N failed, N skipped".
# Exits non-zero when a test fails or errors, or when no test ran.
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

# The package's own heavy checks (sanitizers, fuzzing, soak) are part of this command.
SF_CMAKE_ARGS=(-DSF_PKG_HEAVY_TESTS=ON)
sf_prepare

results="${SF_WS}/build/test_results"
rm -rf "$results"

sf_log "running tests (log: ${SF_WS}/tests.log)"
t0=$SECONDS
cmd=(catkin_make -C "$SF_WS" -j"${SF_JOBS}" -k
  -DCMAKE_BUILD_TYPE=Release -DPYTHON_EXECUTABLE=/usr/bin/python3 -DSF_PKG_HEAVY_TESTS=ON run_tests)
if [[ "$SF_VERBOSE" == 1 ]]; then
  "${cmd[@]}" 2>&1 | tee "${SF_WS}/tests.log" && test_rc=0 || test_rc=$?
else
  # Show the tests' own output, not catkin/CMake/make chatter.
  "${cmd[@]}" 2>&1 | tee "${SF_WS}/tests.log" | awk '
    /^-- / || /^####/ || /^\[ *[0-9]+%\] (Built target|Linking|Building)/ { next }
    /^(Base path|Source space|Build space|Devel space|Install space):/ { next }
    /^(Removing test result files|Making|Generating)/ { next }
    { print; fflush() }' && test_rc=0 || test_rc=$?
fi
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
