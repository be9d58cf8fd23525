#!/usr/bin/env bash
# The package's main job on the shipped default: builds in the catkin workspace
# ($SF_WS), then runs the default job. Extra arguments are passed on to the
# Pioneer report (tools/eval/pioneer_report.py --help), e.g. --bag bags/pioneer_seed2.bag.
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

# Only what the job runs: the default Pioneer nodes and the moving train (with --all or
# --exe, every target, as the report may then run any node). The default nodes are read
# from the report's source, not imported: its modules need packages sf_prepare installs.
# The packages first: on a fresh machine even /usr/bin/python3, which reads the default nodes
# below, comes with them.
sf_ensure_packages
targets=(sf_moving_train)
if [[ " $* " != *" --all "* && " $* " != *" --exe "* ]]; then
  mapfile -t -O 1 targets < <(/usr/bin/python3 -c '
import ast, sys
for node in ast.parse(open(sys.argv[1]).read()).body:
    if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", "") == "DEFAULT_CONFIGS":
        print("\n".join("sf_" + c for c in ast.literal_eval(node.value)))
' "${SF_REPO_ROOT}/tools/eval/pioneer_report.py")
  ((${#targets[@]} > 1)) \
    || sf_die "no default nodes read from tools/eval/pioneer_report.py (DEFAULT_CONFIGS)"
  # Ten nodes built once: each compiles the fixed-size steps of its own sizes, instead of the
  # library compiling the whole size grid for every node to come (doc/build_cost.md, "The main
  # job's build"). run_tests.sh and --all turn the grid back on.
  SF_CMAKE_ARGS=(-DSF_ESTIMATION_EXPLICIT_INSTANCES=OFF)
else
  targets=()
  SF_CMAKE_ARGS=(-DSF_ESTIMATION_EXPLICIT_INSTANCES=ON)
fi
sf_prepare "${targets[@]}"

# The default job, after the build (SF_WS is final only after sf_prepare):
# 1. the thesis's Pioneer 3-AT dead reckoning (chapter 5): bags/pioneer_seed1.bag replayed
#    offline through a default set of eight sf_nav* nodes (--all: every one) plus the nav3ctrl
#    UKF's tuned runs of Fig. 5.10; prints the accuracy table against the bag's ground truth
#    and writes the table, the plots and the replayed CSVs to $SF_WS/results/;
# 2. the moving-train example (RMSE table per estimation method).
SF_RESULTS_DIR="${SF_WS}/results"
SF_DEFAULT_JOB=(/usr/bin/python3 "${SF_REPO_ROOT}/tools/eval/pioneer_report.py"
  --bag "${SF_REPO_ROOT}/bags/pioneer_seed1.bag" --out-dir "${SF_RESULTS_DIR}")
SF_SECOND_JOB=(rosrun sf_pkg sf_moving_train)

sf_log "running: ${SF_DEFAULT_JOB[*]} $*"
report_rc=0
"${SF_DEFAULT_JOB[@]}" "$@" || report_rc=$?
if ((report_rc == 0)); then
  sf_log "Pioneer report done: table, plots and CSVs in the results directory printed above"
else
  sf_log "ERROR: the Pioneer report failed (exit ${report_rc}); running the moving train anyway"
fi

echo
sf_log "running: ${SF_SECOND_JOB[*]}"
if ((report_rc != 0)); then
  "${SF_SECOND_JOB[@]}" || true
  exit "${report_rc}"
fi
exec "${SF_SECOND_JOB[@]}"
