#!/usr/bin/python3
"""Madgwick's gradient-descent filter and Mahony's complementary filter, written here from
their papers (Madgwick, Harrison, Vaidyanathan 2011, eqs. 25-33; Mahony, Hamel, Pflimlin
2008, explicit complementary filter), for the BROAD comparison (doc/broad.md).

Both keep the quaternion q of the sensor frame relative to an earth frame whose x axis is
the horizontal magnetic field and z is up (north-west-up); q_enu = q_z(90 deg) * q. Both start
from the orientation of the first accelerometer and magnetometer sample, as the benchmark's
evaluation does, and return the estimate after each sample.

`field_halved` reproduces the x-io C code that the benchmark's published figures were run
with: it takes the earth field's reference (bx, bz) at half its magnitude (the benchmark's
issue 1), so that the magnetometer's residual never vanishes."""

import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data"))
import broad_trial  # noqa: E402

NWU_TO_ENU = np.array([math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5)])


def rotation_to_quat(R):
    """Unit quaternion (w, x, y, z, w >= 0) of the rotation matrix R (Shepperd's method)."""
    t = np.trace(R)
    if t > max(R[0, 0], R[1, 1], R[2, 2]):
        w = 0.5 * math.sqrt(1.0 + t)
        q = [w, (R[2, 1] - R[1, 2]) / (4 * w), (R[0, 2] - R[2, 0]) / (4 * w), (R[1, 0] - R[0, 1]) / (4 * w)]
    else:
        i = int(np.argmax(np.diag(R)))
        j, k = (i + 1) % 3, (i + 2) % 3
        s = 2.0 * math.sqrt(1.0 + R[i, i] - R[j, j] - R[k, k])
        q = [0.0] * 4
        q[0] = (R[k, j] - R[j, k]) / s
        q[1 + i] = 0.25 * s
        q[1 + j] = (R[j, i] + R[i, j]) / s
        q[1 + k] = (R[k, i] + R[i, k]) / s
    q = np.array(q)
    return q if q[0] >= 0 else -q


def earth_axes(acc, mag):
    """East, north and up in the sensor frame from one accelerometer (specific force, up at
    rest) and one magnetometer sample."""
    up = acc / np.linalg.norm(acc)
    east = np.cross(mag, up)
    east /= np.linalg.norm(east)
    return east, np.cross(up, east), up


def initial_enu(acc, mag):
    """Sensor-to-ENU quaternion of one accelerometer and magnetometer sample."""
    east, north, up = earth_axes(acc, mag)
    return rotation_to_quat(np.vstack([east, north, up]))  # rows: ENU axes in the sensor frame


def initial_benchmark_nwu(acc, mag):
    """The initial state the benchmark's evaluation gives both filters: the matrix whose
    columns are south, east, up in the sensor frame, taken as sensor to north-west-up. It is
    the transpose of a rotation to south-east-up and differs from initial_enu by a few
    degrees of tilt and heading on BROAD's trials; a filter converges from it, but Mahony's
    integral keeps what it gathers meanwhile."""
    east, north, up = earth_axes(acc, mag)
    return rotation_to_quat(np.column_stack([-north, east, up]))


def predicted(q, d):
    """R(q)^T d (an earth vector seen from the sensor) and its Jacobian (3x4 nested lists)
    with respect to the four unconstrained components of q, as Madgwick's objective uses."""
    w, x, y, z = q
    dx, dy, dz = d
    p = (dx * (1 - 2 * (y * y + z * z)) + dy * 2 * (x * y + w * z) + dz * 2 * (x * z - w * y),
         dx * 2 * (x * y - w * z) + dy * (1 - 2 * (x * x + z * z)) + dz * 2 * (y * z + w * x),
         dx * 2 * (x * z + w * y) + dy * 2 * (y * z - w * x) + dz * (1 - 2 * (x * x + y * y)))
    J = ((2 * (z * dy - y * dz), 2 * (y * dy + z * dz), 2 * (-2 * y * dx + x * dy - w * dz), 2 * (-2 * z * dx + w * dy + x * dz)),
         (2 * (x * dz - z * dx), 2 * (y * dx - 2 * x * dy + w * dz), 2 * (x * dx + z * dz), 2 * (-w * dx - 2 * z * dy + y * dz)),
         (2 * (y * dx - x * dy), 2 * (z * dx - w * dy - 2 * x * dz), 2 * (w * dx + z * dy - 2 * y * dz), 2 * (x * dx + y * dy)))
    return p, J


def add_gradient(g, q, d, measured):
    """g += J^T (R(q)^T d - measured)."""
    p, J = predicted(q, d)
    for i in range(3):
        r = p[i] - measured[i]
        for k in range(4):
            g[k] += J[i][k] * r


def unit(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v) if n > 0 else None


def rotate(q, v):
    """R(q) v (sensor to earth)."""
    w, x, y, z = q
    return (v[0] * (1 - 2 * (y * y + z * z)) + v[1] * 2 * (x * y - w * z) + v[2] * 2 * (x * z + w * y),
            v[0] * 2 * (x * y + w * z) + v[1] * (1 - 2 * (x * x + z * z)) + v[2] * 2 * (y * z - w * x),
            v[0] * 2 * (x * z - w * y) + v[1] * 2 * (y * z + w * x) + v[2] * (1 - 2 * (x * x + y * y)))


def field_reference(q, m, halved):
    """Madgwick's earth field reference (bx, 0, bz): the measured direction rotated to earth,
    its horizontal part put on the x axis."""
    h = rotate(q, m)
    s = 0.5 if halved else 1.0
    return (s * math.hypot(h[0], h[1]), 0.0, s * h[2])


def integrate(q, qdot, dt):
    q = [q[k] + qdot[k] * dt for k in range(4)]
    n = math.sqrt(sum(c * c for c in q))
    return [c / n for c in q]


def rate_of(q, w):
    """0.5 q * (0, w)."""
    a, b, c, d = q
    return [0.5 * (-b * w[0] - c * w[1] - d * w[2]), 0.5 * (a * w[0] + c * w[2] - d * w[1]),
            0.5 * (a * w[1] - b * w[2] + d * w[0]), 0.5 * (a * w[2] + b * w[1] - c * w[0])]


def madgwick_step(q, gyr, acc, mag, beta, dt, field_halved=False):
    """One step: q + (0.5 q (0, w) - beta grad/|grad|) dt, normalised; mag None for 6D."""
    qdot = rate_of(q, gyr)
    a = unit(acc)
    if a is not None:
        g = [0.0] * 4
        add_gradient(g, q, (0.0, 0.0, 1.0), a)
        m = unit(mag) if mag is not None else None
        if m is not None:
            add_gradient(g, q, field_reference(q, m, field_halved), m)
        n = math.sqrt(sum(c * c for c in g))
        if n > 0:
            qdot = [qdot[k] - beta * g[k] / n for k in range(4)]
    return integrate(q, qdot, dt)


def cross(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def mahony_step(q, integral, gyr, acc, mag, kp, ki, dt):
    """One step: w + kp e + ki int e, e = a x v (+ m x w) between measured and predicted
    directions; returns (q, integral)."""
    a = unit(acc)
    w = list(gyr)
    if a is not None:
        e = cross(a, predicted(q, (0.0, 0.0, 1.0))[0])
        m = unit(mag) if mag is not None else None
        if m is not None:
            em = cross(m, predicted(q, field_reference(q, m, False))[0])
            e = tuple(e[k] + em[k] for k in range(3))
        integral = [integral[k] + ki * e[k] * dt for k in range(3)] if ki > 0 else [0.0] * 3
        w = [w[k] + kp * e[k] + integral[k] for k in range(3)]
    return integrate(q, rate_of(q, w), dt), integral


def initial_nwu(trial, benchmark_start):
    acc, mag = trial.imu_acc[0], trial.imu_mag[0]
    if benchmark_start:
        return list(initial_benchmark_nwu(acc, mag))
    return list(broad_trial.quat_product(broad_trial.quat_conjugate(NWU_TO_ENU), initial_enu(acc, mag)))


def run(trial, algorithm, use_mag=True, benchmark_start=False, **params):
    """Sensor-to-ENU estimates ((N, 4)) of `algorithm` ('madgwick' with beta and optionally
    field_halved, 'mahony' with kp, ki) over the trial; benchmark_start: start from the
    benchmark's initial state (initial_benchmark_nwu)."""
    dt = 1.0 / trial.rate
    q, integral = initial_nwu(trial, benchmark_start), [0.0] * 3
    gyr, acc, mag = trial.imu_gyr.tolist(), trial.imu_acc.tolist(), trial.imu_mag.tolist()
    out = np.empty((len(gyr), 4))
    for i in range(len(gyr)):
        m = mag[i] if use_mag else None
        if algorithm == "madgwick":
            q = madgwick_step(q, gyr[i], acc[i], m, params["beta"], dt, params.get("field_halved", False))
        else:
            q, integral = mahony_step(q, integral, gyr[i], acc[i], m, params["kp"], params["ki"], dt)
        out[i] = q
    return broad_trial.quat_product(NWU_TO_ENU, out)


# The configurations of doc/broad.md: name -> (algorithm, use_mag, benchmark_start,
# parameters). beta 0.12 and Kp 0.74, Ki 0.0012 are the benchmark's parameters tuned over all
# 39 trials (its TAGP). The "_benchmark" rows run as the benchmark's evaluation did (its
# initial state; Madgwick with the C code's halved field reference), so that they reproduce
# its published per-trial figures.
BASELINES = {
    "madgwick9_benchmark": ("madgwick", True, True, dict(beta=0.12, field_halved=True)),
    "madgwick9": ("madgwick", True, False, dict(beta=0.12)),
    "madgwick6": ("madgwick", False, False, dict(beta=0.12)),
    "mahony9_benchmark": ("mahony", True, True, dict(kp=0.74, ki=0.0012)),
    "mahony9": ("mahony", True, False, dict(kp=0.74, ki=0.0012)),
    "mahony6": ("mahony", False, False, dict(kp=0.74, ki=0.0012)),
}


def run_baseline(trial, name):
    algorithm, use_mag, benchmark_start, params = BASELINES[name]
    return run(trial, algorithm, use_mag, benchmark_start, **params)


def main():
    import argparse
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("data", help="directory with the BROAD trials (or a checkout of the benchmark)")
    parser.add_argument("--only", nargs="*", default=sorted(BASELINES), help="baselines to run")
    args = parser.parse_args()
    for path in broad_trial.find_trials(args.data):
        trial = broad_trial.load(path)
        row = ["%-45s" % trial.name]
        for name in args.only:
            row.append("%s %.3f" % (name, broad_trial.rmse_deg(trial, run_baseline(trial, name))))
        print("  ".join(row), flush=True)


if __name__ == "__main__":
    main()
