#!/usr/bin/env bash
# The package's main job on the shipped default: builds in the catkin
# workspace ($SF_WS), then runs the default job. Extra arguments are passed on
# to it.
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

# The default job: the thesis's moving-train example (RMSE table per method).
SF_DEFAULT_JOB=(rosrun sf_pkg sf_moving_train)

sf_prepare
sf_log "running: ${SF_DEFAULT_JOB[*]} $*"
exec "${SF_DEFAULT_JOB[@]}" "$@"
