#!/usr/bin/python3
"""Armesto, Tornero and Vincze's inertial+vision set-up ("Fast ego-motion estimation with
multi-rate fusion of inertial and vision") made from a BROAD trial, and its cost functions
(doc/armesto.md).

The stream has one line per period T = 10 ms: the IMU linearly interpolated at k T, and every
8th line (80 ms) a "vision" frame: the optical reference at the sample nearest k T with noise of
the paper's R (position variance r_pos per axis; the rotation by a body-frame rotation vector
of variance 4 r_quat per axis, i.e. r_quat per quaternion component), seeded and drawn for every
frame, the reference's gaps included, so that a frame's noise does not depend on the gaps
before it. A frame in a gap is not sent (a natural vision dropout). The stream starts at the
first frame with a reference. `run` pipes it through sf_estimation_armesto_fusion (MR-EKF or
MR-UKF); `vision_held` is the last frame held; the costs are the paper's eq. 24."""

import io
import subprocess

import numpy as np

DEFAULT_BINARY = "sf_estimation_armesto_fusion"
PERIOD = 0.01
VISION_EVERY = 8  # 80 ms
PAPER_R = dict(acc=1e-3, gyro=1e-4, pos=1e-7, quat=1e-6)


class Stream:
    """The 10 ms stream of one trial: imu (N, 6: acc, gyro), seen (N bool: a frame sent),
    vision (N, 7: p, q; NaN where none), the reference ref_p (N, 3), ref_q (N, 4) (NaN in its
    gaps) and movement (N bool), all at k T from the first line."""

    def __init__(self, imu, seen, vision, ref_p, ref_q, movement):
        self.imu, self.seen, self.vision = imu, seen, vision
        self.ref_p, self.ref_q, self.movement = ref_p, ref_q, movement

    def csv(self):
        if getattr(self, "_csv", None) is None:
            self._csv = self._table()
        return self._csv

    def _table(self):
        seen = self.seen.astype(float)[:, None]
        table = np.hstack([self.imu, seen, np.where(seen > 0, self.vision, np.nan)])
        out = io.StringIO()
        np.savetxt(out, table, fmt="%.10g", delimiter=",")
        return out.getvalue()


def rotation_vector_to_quat(v):
    """(N, 3) rotation vectors to (N, 4) unit quaternions (w, x, y, z)."""
    v = np.atleast_2d(v)
    angle = np.linalg.norm(v, axis=1)
    half = np.where(angle > 1e-12, np.sin(angle / 2) / np.maximum(angle, 1e-300), 0.5)
    return np.column_stack([np.cos(angle / 2), v * half[:, None]])


def quat_product(p, q):
    pw, px, py, pz = np.moveaxis(np.asarray(p, float), -1, 0)
    qw, qx, qy, qz = np.moveaxis(np.asarray(q, float), -1, 0)
    return np.stack([pw * qw - px * qx - py * qy - pz * qz, pw * qx + px * qw + py * qz - pz * qy,
                     pw * qy - px * qz + py * qw + pz * qx, pw * qz + px * qy - py * qx + pz * qw], axis=-1)


def add_vision_noise(p, q, r_pos, r_quat, rng):
    """The frames (p, q) with the paper's R: position noise of variance r_pos, a body-frame
    rotation of variance 4 r_quat per axis (r_quat per quaternion component)."""
    n = len(p)
    noise = rng.standard_normal((n, 6))
    noisy_q = quat_product(q, rotation_vector_to_quat(noise[:, 3:] * np.sqrt(4.0 * r_quat)))
    return p + noise[:, :3] * np.sqrt(r_pos), noisy_q / np.linalg.norm(noisy_q, axis=1)[:, None]


def from_trial(trial, seed=1, r_pos=PAPER_R["pos"], r_quat=PAPER_R["quat"]):
    """The Stream of a broad_trial.Trial (see the top)."""
    t = np.arange(0.0, (len(trial.imu_gyr) - 1) / trial.rate, PERIOD)
    source = np.arange(len(trial.imu_gyr)) / trial.rate
    imu = np.column_stack([np.interp(t, source, c) for c in np.hstack([trial.imu_acc, trial.imu_gyr]).T])
    nearest = np.minimum(np.round(t * trial.rate).astype(int), len(source) - 1)
    ref_p, ref_q = trial.opt_pos[nearest], trial.opt_quat[nearest]
    ref_q = ref_q / np.linalg.norm(ref_q, axis=1)[:, None]
    valid = np.all(np.isfinite(ref_p), axis=1) & np.all(np.isfinite(ref_q), axis=1)
    ticks = np.arange(len(t)) % VISION_EVERY == 0
    rng = np.random.default_rng(seed)
    frames = np.full((len(t), 7), np.nan)
    # In a gap the frame is drawn from a stand-in pose and never sent: only its noise is used up.
    at = valid[ticks][:, None]
    noisy_p, noisy_q = add_vision_noise(np.where(at, ref_p[ticks], 0.0), np.where(at, ref_q[ticks], [1.0, 0, 0, 0]),
                                        r_pos, r_quat, rng)
    frames[ticks] = np.hstack([noisy_p, noisy_q])
    seen = ticks & valid
    first = int(np.flatnonzero(seen)[0])
    cut = slice(first, None)
    return Stream(imu[cut], seen[cut], frames[cut], ref_p[cut], ref_q[cut], trial.movement[nearest][cut])


def run(stream, filter_kind="ekf", binary=DEFAULT_BINARY, options=()):
    """(positions (N, 3), quaternions (N, 4), CPU us per step) of the filter over `stream`;
    None for the estimates when the filter refused a step (diverged)."""
    command = [binary, "--filter", filter_kind] + [str(o) for o in options]
    done = subprocess.run(command, input=stream.csv(), capture_output=True, text=True)
    if done.returncode == 3:
        return None, None, float("nan")
    if done.returncode != 0:
        raise RuntimeError("%s failed: %s" % (" ".join(command), done.stderr.strip()))
    out = np.loadtxt(io.StringIO(done.stdout), delimiter=",", ndmin=2)
    if len(out) != len(stream.imu):
        raise RuntimeError("%s: %d lines for %d" % (binary, len(out), len(stream.imu)))
    cpu = float(done.stderr.split("cpu_per_step_us")[-1].split()[0])
    return out[:, :3], out[:, 3:7], cpu


def noise_options(r=None, q=None):
    """Command-line options of the program for R entries (acc, gyro, pos, quat) and Q entries
    (jerk, alpha, bias)."""
    options = []
    for key, value in sorted((r or {}).items()):
        options += ["--r-" + key, repr(float(value))]
    for key, value in sorted((q or {}).items()):
        options += ["--q-" + key, repr(float(value))]
    return options


def vision_held(stream):
    """The last frame held: (positions, quaternions) at every line."""
    index = np.maximum.accumulate(np.where(stream.seen, np.arange(len(stream.seen)), 0))
    return stream.vision[index, :3], stream.vision[index, 3:]


def costs(stream, p, q):
    """The paper's eq. 24 over the movement phase where the reference exists: J_p = mean of
    |p_ref - p|^2 [m^2], J_q = mean of |q_ref - q|^2 over the 4 components, q's sign taken as
    the reference's (q and -q are one rotation). (inf, inf) for a diverged run."""
    if p is None:
        return float("inf"), float("inf")
    kept = stream.movement & np.all(np.isfinite(stream.ref_p), axis=1) & np.all(np.isfinite(stream.ref_q), axis=1)
    sign = np.where(np.sum(q * stream.ref_q, axis=1) < 0, -1.0, 1.0)[:, None]
    jp = np.sum((stream.ref_p - p) ** 2, axis=1)[kept]
    jq = np.sum((stream.ref_q - sign * q) ** 2, axis=1)[kept]
    return float(np.mean(jp)), float(np.mean(jq))
