#!/usr/bin/python3
"""What the report tools know about the Pioneer 3-AT fusion nodes (config/nav*.h): where the
executables are, how to replay a bag through one, and how to get a path from its CSV.

Most nodes publish a pose (POSE_OUT): the CSV's pose columns are the path. Three kinds have
no pose in their state, and the path is computed offline from the logged state as the
thesis did (evaluate.py --dead-reckoning):
  nav3red_*             (omega, v, a): v = x1, omega = x0 (5.2.4)
  nav1_moving_average   averaged gyro and accelerometer: a = x1, omega = x0 ("raw", 5.2.2)
  nav2_moving_average   averaged wheel speeds: wheels x0, x1 (wheel odometry, 5.2.2)
The particle filters' own pose is useless (random walk of the pose noise, thesis 5.2.4);
their path is also computed from their v = x5 and omega = x3 (VELOCITIES_OF_POSE_STATE).
"""

import os
import re
import subprocess
import sys
import tempfile

PACKAGE = "sf_pkg"
# Columns of v and omega in the states (x, y, theta, omega, delta_s, v[, a]).
VELOCITIES_OF_POSE_STATE = "v=x5,omega=x3"
# Paths of the nodes without a pose: name pattern -> evaluate.py --dead-reckoning SPEC.
PATH_FROM_STATE = [
    (re.compile(r"^nav3red_"), "v=x1,omega=x0"),
    (re.compile(r"^nav1_moving_average$"), "a=x1,omega=x0"),
    (re.compile(r"^nav2_moving_average$"), "wheels=x0,x1"),
]


def dead_reckoning_of(config):
    """The --dead-reckoning SPEC for a node (config name, e.g. nav3red_kf) without a pose,
    None for a node whose CSV has pose columns."""
    for pattern, spec in PATH_FROM_STATE:
        if pattern.search(config):
            return spec
    return None


def config_of(exe):
    """Configuration name of an executable: sf_nav3ctrl_ukf -> nav3ctrl_ukf."""
    name = os.path.basename(exe)
    return name[3:] if name.startswith("sf_") else name


def find_lib_dir(exe_prefix="sf_nav"):
    """lib/sf_pkg of the first CMAKE_PREFIX_PATH entry (the sourced devel space) having
    executables named exe_prefix*, else $SF_WS/devel/lib/sf_pkg; None when there is none."""
    prefixes = [p for p in os.environ.get("CMAKE_PREFIX_PATH", "").split(":") if p]
    if os.environ.get("SF_WS"):
        prefixes.append(os.path.join(os.environ["SF_WS"], "devel"))
    for prefix in prefixes:
        d = os.path.join(prefix, "lib", PACKAGE)
        if os.path.isdir(d) and any(n.startswith(exe_prefix) for n in os.listdir(d)):
            return d
    return None


def husky_dirs(lib_dir, out_dir):
    """(lib_dir, out_dir, tmp) of the real-recording reports: lib_dir or the devel space's
    sf_husky_* executables (None, after an error on stderr, when there are none); out_dir
    (created) or a temporary directory, kept alive by `tmp` (None for a given out_dir)."""
    lib_dir = lib_dir or find_lib_dir("sf_husky")
    if not lib_dir:
        print("error: no sf_husky_* executables found (build them, source the devel space or "
              "give --lib-dir)", file=sys.stderr)
        return None, None, None
    tmp = None
    if not out_dir:
        tmp = tempfile.TemporaryDirectory()
        out_dir = tmp.name
    os.makedirs(out_dir, exist_ok=True)
    return lib_dir, out_dir, tmp


def list_nodes(lib_dir):
    """Sorted names of the sf_nav* executables in lib_dir."""
    return sorted(n for n in os.listdir(lib_dir)
                  if n.startswith("sf_nav") and os.access(os.path.join(lib_dir, n), os.X_OK))


def has_replay_mode(exe):
    """True when the executable was built with the offline replay (an older build would
    start a ROS node and wait for a master instead)."""
    try:
        with open(exe, "rb") as f:
            data = f.read()
    except OSError:
        return False
    # Since the node split the replay lives in libsf_fusion_node.so, which every node links.
    return b"--replay" in data or b"libsf_fusion_node.so" in data


def slug(label):
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", label).strip("_")


def replay(exe, bag, csv_path, extra=(), timeout=120):
    """Runs `exe --replay bag --csv csv_path extra...`; returns its summary (stdout). `bag`:
    a path, or a list of paths read as one recording. Raises RuntimeError naming the command
    when it fails or times out."""
    bags = [bag] if isinstance(bag, str) else list(bag)
    cmd = [exe, "--replay"] + bags + ["--csv", csv_path] + list(extra)
    if not os.access(exe, os.X_OK):
        raise RuntimeError("%s is not an executable" % exe)
    if not has_replay_mode(exe):
        raise RuntimeError("%s has no --replay mode (not a fusion node, or built before the "
                           "replay mode: rebuild the workspace)" % exe)
    try:
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              universal_newlines=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        raise RuntimeError("%s: no result within %d s" % (" ".join(cmd), timeout))
    if proc.returncode != 0:
        raise RuntimeError("%s: exit %d\n%s" % (" ".join(cmd), proc.returncode,
                                                proc.stdout.strip()))
    return proc.stdout.strip()
