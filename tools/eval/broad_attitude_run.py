#!/usr/bin/python3
"""Runs the C++ attitude filter (sf_estimation_broad_attitude) over one BROAD trial: the
trial's IMU stream is piped to the program as CSV and its quaternions read back."""

import io
import subprocess

import numpy as np

DEFAULT_BINARY = "sf_estimation_broad_attitude"


def run(trial, binary=DEFAULT_BINARY, options=()):
    """Sensor-to-ENU estimates ((N, 4)) of the attitude filter over `trial`; `options` are
    extra command-line options of the program (e.g. ("--no-magnetometer",))."""
    stream = io.StringIO()
    np.savetxt(stream, np.hstack([trial.imu_gyr, trial.imu_acc, trial.imu_mag]), fmt="%.9g", delimiter=",")
    command = [binary, "--rate", repr(trial.rate)] + list(options)
    done = subprocess.run(command, input=stream.getvalue(), capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError("%s failed on %s: %s" % (" ".join(command), trial.name, done.stderr.strip()))
    out = np.loadtxt(io.StringIO(done.stdout), delimiter=",", ndmin=2)
    if out.shape != (len(trial.imu_gyr), 4):
        raise RuntimeError("%s on %s: %s rows for %d samples" % (binary, trial.name, out.shape, len(trial.imu_gyr)))
    return out
