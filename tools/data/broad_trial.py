#!/usr/bin/python3
"""Reads the trials of the BROAD benchmark (Laidig, Caruso, Cereatti, Seel: "BROAD - A
Benchmark for Robust Inertial Orientation Estimation", Data 6(7), 2021; CC BY 4.0) and
computes its orientation error.

A trial is one HDF5 (data_hdf5/NN_name.hdf5) or MATLAB v5 (data_mat/NN_name.mat) file of
the benchmark's repository; both hold the same arrays (checked on the 22 trials present in
both forms): imu_gyr [rad/s], imu_acc [m/s^2], imu_mag [uT] at 285.7 Hz, the optical
reference opt_quat (w, x, y, z; sensor to ENU, NaN in the reference's gaps) and opt_pos [m],
and the boolean movement over which the benchmark's errors are taken."""

import glob
import os
import re

import numpy as np

ARRAYS = ("imu_gyr", "imu_acc", "imu_mag", "opt_quat", "opt_pos", "movement")
# The benchmark's trial groups: the first 23 trials are undisturbed, 24..39 disturbed.
UNDISTURBED_LAST = 23
TRIAL_NAME = re.compile(r"^(\d\d)_([A-Za-z0-9_]+)\.(hdf5|mat)$")


class Trial:
    """The arrays of one trial, `rate` in Hz and `name` (e.g. 02_undisturbed_slow_rotation_B)."""

    def __init__(self, name, rate, arrays):
        self.name, self.rate = name, float(rate)
        for key in ARRAYS:
            setattr(self, key, arrays[key])
        n = len(self.imu_gyr)
        for key in ARRAYS:
            if len(arrays[key]) != n:
                raise ValueError("trial %s: %s has %d rows, imu_gyr %d" % (name, key, len(arrays[key]), n))

    @property
    def number(self):
        return int(self.name[:2])

    @property
    def undisturbed(self):
        return self.number <= UNDISTURBED_LAST

    def times(self):
        return np.arange(len(self.imu_gyr)) / self.rate


def load(path):
    """The Trial in the .hdf5 or .mat file `path`."""
    name, ext = os.path.splitext(os.path.basename(path))
    if ext == ".hdf5":
        import h5py
        with h5py.File(path, "r") as f:
            arrays = {k: np.array(f[k]) for k in ARRAYS}
            rate = float(f.attrs["sampling_rate"])
    elif ext == ".mat":
        import scipy.io
        m = scipy.io.loadmat(path)
        arrays = {k: np.asarray(m[k]) for k in ARRAYS}
        rate = float(np.asarray(m["sampling_rate"]).ravel()[0])
    else:
        raise ValueError("%s: a BROAD trial is a .hdf5 or .mat file" % path)
    arrays["movement"] = arrays["movement"].ravel().astype(bool)
    for k in ARRAYS[:5]:
        arrays[k] = np.ascontiguousarray(arrays[k], dtype=float)
    return Trial(name, rate, arrays)


def find_trials(directory):
    """Paths of the trials in `directory` (searched with its data_hdf5/ and data_mat/),
    one per trial number, sorted; the HDF5 form when both are there. Files that are not
    real data (Git LFS pointers of a few hundred bytes) are skipped."""
    found = {}
    for sub in ("", "data_hdf5", "data_mat"):
        for path in sorted(glob.glob(os.path.join(directory, sub, "*"))):
            match = TRIAL_NAME.match(os.path.basename(path))
            if not match or os.path.getsize(path) < 100000:
                continue
            key = match.group(1) + "_" + match.group(2)
            if key not in found or path.endswith(".hdf5"):
                found[key] = path
    return [found[k] for k in sorted(found)]


def quat_product(p, q):
    """Row-wise Hamilton product of (N, 4) or (4,) arrays (w, x, y, z)."""
    p, q = np.asarray(p, float), np.asarray(q, float)
    pw, px, py, pz = np.moveaxis(p, -1, 0)
    qw, qx, qy, qz = np.moveaxis(q, -1, 0)
    return np.stack([pw * qw - px * qx - py * qy - pz * qz,
                     pw * qx + px * qw + py * qz - pz * qy,
                     pw * qy - px * qz + py * qw + pz * qx,
                     pw * qz + px * qy - py * qx + pz * qw], axis=-1)


def quat_conjugate(q):
    return np.asarray(q, float) * np.array([1.0, -1.0, -1.0, -1.0])


def error_angles(estimate, reference):
    """Angle [rad] of the rotation between the estimate and the reference (both sensor to
    ENU), per row: 2 acos|w| of estimate * reference^-1, the benchmark's total error. The
    earth-frame error quaternion has the same angle as the body-frame one; NaN where the
    reference has a gap."""
    e = estimate / np.linalg.norm(estimate, axis=1)[:, None]
    r = reference / np.linalg.norm(reference, axis=1)[:, None]
    d = quat_product(e, quat_conjugate(r))
    d = d / np.linalg.norm(d, axis=1)[:, None]
    return 2.0 * np.arccos(np.clip(np.abs(d[:, 0]), 0.0, 1.0))


def rmse_deg(trial, estimate):
    """The benchmark's total orientation RMSE [deg] of `estimate` ((N, 4), sensor to ENU) over
    the trial's movement phase, the reference's gaps left out."""
    angles = error_angles(estimate, trial.opt_quat)[trial.movement]
    return float(np.degrees(np.sqrt(np.nanmean(angles ** 2))))
