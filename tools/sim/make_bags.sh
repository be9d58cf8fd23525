#!/usr/bin/env bash
# Regenerates every bag shipped in bags/ from the simulators in tools/sim/ (see
# doc/bags.md). The runs are seeded, so the same command gives the same bags, byte for
# byte.
#
#   tools/sim/make_bags.sh             write bags/*.bag and print rosbag info of each
#   tools/sim/make_bags.sh --check     generate every bag twice into temporary folders and
#                                      check that both runs, and the shipped bags/, agree
#                                      (bytes and message content); bags/ is not touched
#   tools/sim/make_bags.sh --out DIR   write the bags into DIR instead of bags/
#   tools/sim/make_bags.sh --ideal --out DIR
#                                      write the ideal (error-free) Pioneer and soccer runs
#                                      that are not shipped (*_ideal.bag), for comparisons
#
# The shipped Pioneer and soccer bags carry the realistic errors (--realistic husky, wang;
# tools/sim/sensor_errors.py); soccer_lost_vision_ideal.bag and diff_drive_seed1.bag are the
# ideal runs kept because tests need their closed-form truth (doc/bags.md says which).
#
# Needs Debian's python3-rosbag, python3-std-msgs, python3-geometry-msgs, python3-nav-msgs,
# python3-sensor-msgs and python3-tf2-msgs (and rosbag
# for `rosbag info`); it uses /usr/bin/python3 so that a pyenv/virtualenv python3 on PATH
# does not hide the ROS modules.
set -euo pipefail

export PATH="/usr/bin:/bin:${PATH}"
PY=/usr/bin/python3
SIM="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd -P)"
ROOT="$(cd "${SIM}/../.." && pwd -P)"

BAGS=(pioneer_seed1.bag pioneer_seed2.bag pioneer_seed3.bag soccer_seed1.bag soccer_lost_vision.bag
  soccer_lost_vision_ideal.bag diff_drive_seed1.bag)
IDEAL_BAGS=(pioneer_seed1_ideal.bag pioneer_seed2_ideal.bag pioneer_seed3_ideal.bag soccer_seed1_ideal.bag)

# generate DIR: write every shipped bag into DIR
generate() {
  local dir="$1"
  mkdir -p "${dir}"
  # the Pioneer 3-AT runs of thesis chapter 5 with the realistic error set calibrated on a
  # real skid-steer recording (skid-steer slip, radius and load, encoder ticks, gyro bias
  # walk and scale, tilt, latency, losses, duplicates; sensor_errors.py, doc/bags.md)
  "${PY}" "${SIM}/pioneer_sim.py" --seed 1 --duration 90 --realistic husky --out "${dir}/pioneer_seed1.bag"
  "${PY}" "${SIM}/pioneer_sim.py" --seed 2 --duration 120 --realistic husky --out "${dir}/pioneer_seed2.bag"
  "${PY}" "${SIM}/pioneer_sim.py" --seed 3 --duration 150 --realistic husky --out "${dir}/pioneer_seed3.bag"
  # the soccer robot of Wang et al. with its vision delay, jitter, random frame losses and
  # duplicates and encoder ticks (--realistic wang)
  "${PY}" "${SIM}/soccer_sim.py" --seed 1 --duration 60 --realistic wang --out "${dir}/soccer_seed1.bag"
  # seed 1 again, 10 s longer, with lost vision frames: 80 frames (2.5 s) from 30 s, and
  # 45 frames from 63.5 s as in Wang et al. section VI-B. Shares trajectory and noise
  # with soccer_seed1.bag over the first 60 s.
  "${PY}" "${SIM}/soccer_sim.py" --seed 1 --duration 70 --drop 30:80 --drop 63.5:45 --realistic wang \
    --out "${dir}/soccer_lost_vision.bag"
  # the same run without the realistic errors: the tests of the soccer filters' consistency
  # and of the fusion block need vision frames whose only error is the white noise of the
  # filters' model (doc/bags.md, "Ideal bags")
  "${PY}" "${SIM}/soccer_sim.py" --seed 1 --duration 70 --drop 30:80 --drop 63.5:45 \
    --out "${dir}/soccer_lost_vision_ideal.bag"
  # generic differential-drive robot (/odom, /imu/data, IMU mounted on its side, gyro bias);
  # ideal: its tests check the closed-form gyro bias and mounting
  "${PY}" "${SIM}/diff_drive_sim.py" --seed 1 --duration 60 --out "${dir}/diff_drive_seed1.bag"
}

# generate_ideal DIR: the error-free Pioneer and soccer runs (not shipped)
generate_ideal() {
  local dir="$1"
  mkdir -p "${dir}"
  "${PY}" "${SIM}/pioneer_sim.py" --seed 1 --duration 90 --out "${dir}/pioneer_seed1_ideal.bag"
  "${PY}" "${SIM}/pioneer_sim.py" --seed 2 --duration 120 --out "${dir}/pioneer_seed2_ideal.bag"
  "${PY}" "${SIM}/pioneer_sim.py" --seed 3 --duration 150 --out "${dir}/pioneer_seed3_ideal.bag"
  "${PY}" "${SIM}/soccer_sim.py" --seed 1 --duration 60 --out "${dir}/soccer_seed1_ideal.bag"
}

mode=write
out="${ROOT}/bags"
while (($#)); do
  case "$1" in
    --check) mode=check ;;
    --ideal) mode=ideal ;;
    --out) out="$2"; shift ;;
    -h|--help) sed -n '2,22p' "$0"; exit 0 ;;
    *) echo "unknown argument: $1" >&2; exit 2 ;;
  esac
  shift
done

if [[ "${mode}" == ideal ]]; then
  if [[ "${out}" == "${ROOT}/bags" ]]; then
    echo "--ideal needs --out DIR (the ideal Pioneer and soccer runs are not shipped)" >&2
    exit 2
  fi
  generate_ideal "${out}"
  for bag in "${IDEAL_BAGS[@]}"; do
    rosbag info "${out}/${bag}"
    echo
  done
  exit 0
fi

if [[ "${mode}" == write ]]; then
  generate "${out}"
  for bag in "${BAGS[@]}"; do
    rosbag info "${out}/${bag}"
    echo
  done
  exit 0
fi

tmp="$(mktemp -d "${TMPDIR:-/tmp}/sf_bags_check.XXXXXX")"
trap 'rm -rf "${tmp}"' EXIT
generate "${tmp}/a" >/dev/null
generate "${tmp}/b" >/dev/null
fail=0
for bag in "${BAGS[@]}"; do
  a="${tmp}/a/${bag}" b="${tmp}/b/${bag}" shipped="${ROOT}/bags/${bag}"
  "${PY}" "${SIM}/bag_digest.py" "${a}" | tail -n +2 >"${tmp}/a.digest"
  "${PY}" "${SIM}/bag_digest.py" "${b}" | tail -n +2 >"${tmp}/b.digest"
  rosbag info "${a}" | grep -v '^path:' >"${tmp}/a.info"
  rosbag info "${b}" | grep -v '^path:' >"${tmp}/b.info"
  verdict="identical bytes"
  if ! cmp -s "${a}" "${b}"; then verdict="bytes differ"; fail=1; fi
  if ! cmp -s "${tmp}/a.digest" "${tmp}/b.digest"; then verdict+=", content differs"; fail=1; fi
  if ! cmp -s "${tmp}/a.info" "${tmp}/b.info"; then verdict+=", rosbag info differs"; fail=1; fi
  if [[ -f "${shipped}" ]]; then
    "${PY}" "${SIM}/bag_digest.py" "${shipped}" | tail -n +2 >"${tmp}/s.digest"
    if cmp -s "${a}" "${shipped}"; then
      verdict+="; shipped bag identical"
    elif cmp -s "${tmp}/a.digest" "${tmp}/s.digest"; then
      verdict+="; shipped bag: same content, different bytes"
    else
      verdict+="; shipped bag DIFFERS"; fail=1
    fi
  else
    verdict+="; no shipped bag"
  fi
  printf '%-24s %s  %s\n' "${bag}" "$(tail -n 1 "${tmp}/a.digest")" "${verdict}"
done
if ((fail)); then
  echo "make_bags --check: FAILED" >&2
  exit 1
fi
echo "make_bags --check: all bags reproducible"
