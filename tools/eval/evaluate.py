#!/usr/bin/python3
"""Accuracy of filter results against a ground truth: RMSE and final errors, plots.

Usage:
  evaluate.py --truth TRUTH [options] RESULT [RESULT ...]

RESULT is LABEL=PATH or PATH (the label is then the file name without extension):
  *.csv   the CSV of a node's replay (`sf_<config> --replay IN.bag --csv OUT.csv`):
          columns time, x0.., var0.., [pose_x, pose_y, pose_heading,] present_inputs.
          The pose columns are used by default; --pose-columns picks others
          (e.g. x0,x1,x2 for a configuration without POSE_OUT).
  *.bag   a bag with nav_msgs/Odometry on /odometry/filtered (--odom-topic), e.g. the
          node's `--bag OUT.bag` or a `rosbag record` of the running node; PoseStamped
          and PointStamped topics work too (e.g. --odom-topic vision/pose: a raw sensor).

With --dead-reckoning the path of a CSV result is computed from logged velocities, as the
thesis did for a state without a pose (nav3red, the particle filter, the averaging; 5.2.2
and 5.2.4): the transition eqs. 5.1-5.3 and 5.5 applied to the logged values, from --start.
SPEC names the columns: v=x1,omega=x0 (velocities), a=x1,omega=x0 (an acceleration,
first integrated into v by eq. 5.6 from rest), wheels=x0,x1 (left and right wheel speeds in
mm/s, converted by eqs. 5.17-5.18 with --radius).

TRUTH is a bag with geometry_msgs/PoseStamped on ground_truth/pose (--truth-topic; the
simulated bags of bags/ have it), or a CSV with the columns time,x,y[,heading] (a header
line with these names, or no header and the columns in this order).

Per result it prints: the number of estimates used (those inside the truth's time range),
the RMSE of the position [m] (the truth interpolated linearly at each estimate's stamp),
the final position error [m] (the last estimate used against the truth at its stamp), the
final heading error [deg] (estimate - truth, wrapped to (-180, 180]), the RMSE of the
wrapped heading differences [deg], and the mean execution time per estimation step [us]
when given (--timing LABEL=US, or --summary LABEL=FILE with the replay's summary line
"... X us per estimation step ...").

With --plot-dir it writes (matplotlib, Agg backend):
  paths.png           the paths against the truth, start and final positions and the final
                      headings (like thesis figures 5.6, 5.7 and 5.9), right: the finals zoomed
  position_error.png  position error over time
  heading_error.png   heading error over time (when the truth and a result have headings)

The core functions (wrap_angle, interpolate, rmse, evaluate, ...) are pure and use only the
standard library; rosbag and matplotlib are imported only when needed.
"""

import argparse
import bisect
import collections
import csv
import math
import os
import re
import sys

# One trajectory: increasing times [s], positions [m], headings [rad] or None.
Trajectory = collections.namedtuple("Trajectory", "t x y heading")

# The evaluation of one result against the truth (see evaluate()).
Evaluation = collections.namedtuple(
    "Evaluation",
    "n_total n_used rmse_pos final_pos_err final_heading_err_deg rmse_heading_deg final_time "
    "times pos_errors heading_errors_deg")

DEFAULT_TIME_TOLERANCE = 1e-6  # s: stamps printed as 1700000000.0999999 still match 0.1 s


# -----------------------------------------------------------------------------
# Pure core
# -----------------------------------------------------------------------------
def wrap_angle(a):
    """a wrapped to (-pi, pi]."""
    w = math.fmod(a + math.pi, 2.0 * math.pi)
    if w <= 0.0:
        w += 2.0 * math.pi
    return w - math.pi


def angle_diff(a, b):
    """a - b wrapped to (-pi, pi]."""
    return wrap_angle(a - b)


def yaw_from_quaternion(x, y, z, w):
    """Yaw (rotation about z) of a quaternion, in (-pi, pi]."""
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def make_trajectory(t, x, y, heading=None):
    """Trajectory sorted by time; of samples with equal stamps the last one is kept."""
    n = len(t)
    if len(x) != n or len(y) != n or (heading is not None and len(heading) != n):
        raise ValueError("trajectory columns differ in length")
    order = sorted(range(n), key=lambda i: t[i])  # stable: equal stamps keep their order
    keep = []
    for i in order:
        if keep and t[keep[-1]] == t[i]:
            keep[-1] = i
        else:
            keep.append(i)
    return Trajectory([float(t[i]) for i in keep], [float(x[i]) for i in keep],
                      [float(y[i]) for i in keep],
                      None if heading is None else [float(heading[i]) for i in keep])


def interpolate(truth, stamp, tolerance=DEFAULT_TIME_TOLERANCE):
    """(x, y, heading) of `truth` at `stamp`, linear between its samples; the heading along
    the shorter way round (wrapped result; None without headings). None when `stamp` lies
    outside the truth's time range by more than `tolerance` (no extrapolation)."""
    t = truth.t
    if not t or stamp < t[0] - tolerance or stamp > t[-1] + tolerance:
        return None
    if stamp <= t[0]:
        i = 0
        f = 0.0
        j = 0
    elif stamp >= t[-1]:
        i = j = len(t) - 1
        f = 0.0
    else:
        j = bisect.bisect_right(t, stamp)  # t[j-1] <= stamp < t[j]
        i = j - 1
        f = (stamp - t[i]) / (t[j] - t[i])
    x = truth.x[i] + f * (truth.x[j] - truth.x[i])
    y = truth.y[i] + f * (truth.y[j] - truth.y[i])
    h = None
    if truth.heading is not None:
        h0 = truth.heading[i]
        h = wrap_angle(h0 + f * angle_diff(truth.heading[j], h0))
    return x, y, h


def rmse(values):
    """Root mean square of `values` (None for an empty sequence)."""
    values = list(values)
    if not values:
        return None
    return math.sqrt(sum(v * v for v in values) / len(values))


def evaluate(estimate, truth, tolerance=DEFAULT_TIME_TOLERANCE):
    """Evaluation of the trajectory `estimate` against `truth`.

    Only estimates whose stamp lies inside the truth's time range are used (n_used of
    n_total); the truth is interpolated at their stamps. Heading results are None when
    either side has no heading. Raises ValueError when no estimate can be matched."""
    times, pos_errors, heading_errors = [], [], []
    last = None
    use_heading = estimate.heading is not None and truth.heading is not None
    for k, stamp in enumerate(estimate.t):
        ref = interpolate(truth, stamp, tolerance)
        if ref is None:
            continue
        times.append(stamp)
        pos_errors.append(math.hypot(estimate.x[k] - ref[0], estimate.y[k] - ref[1]))
        if use_heading:
            heading_errors.append(math.degrees(angle_diff(estimate.heading[k], ref[2])))
        last = k
    if last is None:
        span = lambda tr: "[%.3f, %.3f]" % (tr.t[0], tr.t[-1]) if tr.t else "(empty)"
        raise ValueError("no estimate inside the truth's time range: estimates %s, truth %s"
                         % (span(estimate), span(truth)))
    return Evaluation(
        n_total=len(estimate.t), n_used=len(times), rmse_pos=rmse(pos_errors),
        final_pos_err=pos_errors[-1],
        final_heading_err_deg=heading_errors[-1] if use_heading else None,
        rmse_heading_deg=rmse(heading_errors) if use_heading else None,
        final_time=times[-1], times=times, pos_errors=pos_errors,
        heading_errors_deg=heading_errors if use_heading else None)


SUMMARY_TIME_RE = re.compile(r"([0-9.eE+-]+)\s*us per estimation step")


def summary_line(text):
    """The replay's summary line ("N messages, N estimates, ...") of its output; the per-input
    counter lines follow it. The last line when there is no summary line."""
    lines = text.splitlines()
    for line in lines:
        if " estimates, " in line:
            return line
    return lines[-1] if lines else ""


def parse_summary_timing(text):
    """Mean time per estimation step [us] from a replay summary line, or None."""
    found = SUMMARY_TIME_RE.findall(text)
    return float(found[-1]) if found else None


# -----------------------------------------------------------------------------
# Paths from logged velocities (thesis 5.2.2 and 5.2.4: "the position is calculated offline
# from the logged state variables v and omega")
# -----------------------------------------------------------------------------
def dead_reckon(t, v, omega, start=(0.0, 0.0, 0.0)):
    """Trajectory from logged velocities by the thesis's own transition eqs. 5.1-5.3 and 5.5
    (= 5.8-5.10 and 5.12), so that a path computed offline from a filter without a pose
    (nav3red, 5.2.4) is the path the full-state filters integrate:
        x_k = x_{k-1} + ds_{k-1} cos(theta_{k-1}),  y likewise with sin,
        theta_k = theta_{k-1} + omega_{k-1} dt_k,   ds_k = v_{k-1} dt_k,
    with dt_k = t_k - t_{k-1}, ds_0 = 0 and the start pose (x, y, heading) at t_0. A value
    that is not finite (an input not yet received) counts as 0 before the first finite one
    and as the previous one after."""
    n = len(t)
    if len(v) != n or len(omega) != n:
        raise ValueError("dead_reckon: t, v and omega differ in length")
    if n == 0:
        raise ValueError("dead_reckon: no samples")
    v = hold_finite(v)
    omega = hold_finite(omega)
    x, y, h = [float(start[0])], [float(start[1])], [float(start[2])]
    ds = 0.0
    for k in range(1, n):
        dt = t[k] - t[k - 1]
        x.append(x[-1] + ds * math.cos(h[-1]))
        y.append(y[-1] + ds * math.sin(h[-1]))
        h.append(h[-1] + omega[k - 1] * dt)
        ds = v[k - 1] * dt
    return make_trajectory(t, x, y, h)


def hold_finite(values):
    """values with every non-finite entry replaced by the previous finite one (0 at first)."""
    out, last = [], 0.0
    for a in values:
        a = float(a)
        if math.isfinite(a):
            last = a
        out.append(last)
    return out


def integrate_acceleration(t, a, v0=0.0):
    """Velocities from accelerations by eq. 5.6, forward Euler: v_k = v_{k-1} + a_{k-1} dt."""
    if len(a) != len(t):
        raise ValueError("integrate_acceleration: t and a differ in length")
    a = hold_finite(a)
    v = [float(v0)] if t else []
    for k in range(1, len(t)):
        v.append(v[-1] + a[k - 1] * (t[k] - t[k - 1]))
    return v


def wheel_velocities(left, right, radius):
    """(v [m/s], omega [rad/s]) from the wheel speeds in mm/s: eqs. 5.17-5.18 solved,
    v = (left + right) / 2, omega = (right - left) / (2 R)."""
    if len(left) != len(right):
        raise ValueError("wheel_velocities: left and right differ in length")
    if not radius > 0:
        raise ValueError("wheel_velocities: the radius must be > 0, got %r" % radius)
    v = [(l + r) / 2000.0 for l, r in zip(left, right)]
    omega = [(r - l) / (2000.0 * radius) for l, r in zip(left, right)]
    return v, omega


DEAD_RECKONING_FORMS = {
    frozenset(["v", "omega"]): "velocities",
    frozenset(["a", "omega"]): "acceleration",
    frozenset(["wheels"]): "wheels",
}


def parse_dead_reckoning(spec):
    """'v=x5,omega=x3' | 'a=x1,omega=x0' | 'wheels=x0,x1' -> (form, {name: column(s)}).
    form is 'velocities', 'acceleration' or 'wheels'; wheels maps to [left, right]."""
    parts = {}
    items = [p.strip() for p in spec.split(",") if p.strip()]
    k = 0
    while k < len(items):
        if "=" not in items[k]:
            raise ValueError("--dead-reckoning: expected NAME=COLUMN, got %r in %r"
                             % (items[k], spec))
        name, col = [a.strip() for a in items[k].split("=", 1)]
        if name == "wheels":  # wheels=LEFT,RIGHT: the next item is the right wheel
            if k + 1 >= len(items) or "=" in items[k + 1]:
                raise ValueError("--dead-reckoning: wheels needs two columns, "
                                 "wheels=LEFT,RIGHT; got %r" % spec)
            parts[name] = [col, items[k + 1]]
            k += 2
            continue
        if name in parts:
            raise ValueError("--dead-reckoning: %s given twice in %r" % (name, spec))
        parts[name] = col
        k += 1
    form = DEAD_RECKONING_FORMS.get(frozenset(parts))
    if form is None or any(not c for c in parts.values()):
        raise ValueError("--dead-reckoning: expected v=COL,omega=COL or a=COL,omega=COL or "
                         "wheels=LEFT,RIGHT; got %r" % spec)
    return form, parts


def dead_reckon_columns(t, columns, form, parts, radius=0.3, start=(0.0, 0.0, 0.0)):
    """Trajectory from the named columns (dict name -> list) of a result, see
    parse_dead_reckoning: velocities are integrated directly, an acceleration first into
    v (eq. 5.6, starting at rest), wheel speeds are converted by wheel_velocities()."""
    if form == "velocities":
        v, omega = columns[parts["v"]], columns[parts["omega"]]
    elif form == "acceleration":
        v, omega = integrate_acceleration(t, columns[parts["a"]]), columns[parts["omega"]]
    elif form == "wheels":
        left, right = (hold_finite(columns[c]) for c in parts["wheels"])
        v, omega = wheel_velocities(left, right, radius)
    else:
        raise ValueError("unknown dead-reckoning form %r" % form)
    return dead_reckon(t, v, omega, start)


def shift_trajectory(traj, dt):
    """traj with every stamp moved by dt [s] (dt < 0: earlier). Evaluating a shifted estimate
    measures how much of its error is a delay: the thesis's models move the pose with the
    previous period's velocities (eqs. 5.1-5.5), so their paths trail the truth."""
    return Trajectory([t + dt for t in traj.t], traj.x, traj.y, traj.heading)


def mean_spread(values):
    """(mean, sample standard deviation) of values; the deviation is 0 for one value,
    (None, None) for none. None entries are left out."""
    values = [float(a) for a in values if a is not None]
    if not values:
        return None, None
    mean = sum(values) / len(values)
    if len(values) == 1:
        return mean, 0.0
    return mean, math.sqrt(sum((a - mean) ** 2 for a in values) / (len(values) - 1))


def format_table(rows, markdown=False):
    """Text table. rows: list of (label, Evaluation, us_per_step or None)."""
    headers = ["filter", "estimates", "RMSE pos [m]", "final pos err [m]",
               "final heading err [deg]", "RMSE heading [deg]", "time/step [us]"]

    def num(v, fmt):
        return "-" if v is None else fmt % v

    body = []
    for label, ev, us in rows:
        used = "%d" % ev.n_used if ev.n_used == ev.n_total else "%d/%d" % (ev.n_used, ev.n_total)
        body.append([label, used, num(ev.rmse_pos, "%.4f"), num(ev.final_pos_err, "%.4f"),
                     num(ev.final_heading_err_deg, "%+.3f"), num(ev.rmse_heading_deg, "%.3f"),
                     num(us, "%.2f")])
    if markdown:
        lines = ["| " + " | ".join(headers) + " |",
                 "| --- |" + " ---: |" * (len(headers) - 1)]
        lines += ["| " + " | ".join(r) + " |" for r in body]
        return "\n".join(lines)
    widths = [max(len(r[i]) for r in [headers] + body) for i in range(len(headers))]
    fmt = lambda r: "  ".join(
        (c.ljust(widths[i]) if i == 0 else c.rjust(widths[i])) for i, c in enumerate(r))
    return "\n".join([fmt(headers)] + [fmt(r) for r in body])


# -----------------------------------------------------------------------------
# Loading
# -----------------------------------------------------------------------------
def _float(s):
    return float(s) if s.strip() != "" else float("nan")


def load_result_csv(path, pose_columns=None):
    """Trajectory from a replay CSV. pose_columns: (x, y[, heading]) column names; default
    pose_x, pose_y, pose_heading."""
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = [h.strip() for h in next(reader)]
        cols = list(pose_columns) if pose_columns else ["pose_x", "pose_y", "pose_heading"]
        missing = [c for c in ["time"] + cols if c not in header]
        if missing:
            raise ValueError("%s: no column %s (columns: %s)%s" % (
                path, ", ".join(missing), ",".join(header),
                "; a configuration without POSE_OUT needs --pose-columns, e.g. x0,x1,x2"
                if not pose_columns else ""))
        idx = [header.index(c) for c in ["time"] + cols]
        t, x, y, h = [], [], [], []
        for row in reader:
            if not row:
                continue
            v = [_float(row[i]) for i in idx]
            if any(math.isnan(a) for a in v[:3]):
                continue
            t.append(v[0])
            x.append(v[1])
            y.append(v[2])
            if len(cols) > 2:
                h.append(v[3])
    return make_trajectory(t, x, y, h if len(cols) > 2 else None)


def read_csv_columns(path, names):
    """{name: [float]} and the time column of a replay CSV, for the given column names."""
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = [h.strip() for h in next(reader)]
        missing = [c for c in ["time"] + list(names) if c not in header]
        if missing:
            raise ValueError("%s: no column %s (columns: %s)" % (
                path, ", ".join(missing), ",".join(header)))
        idx = {c: header.index(c) for c in ["time"] + list(names)}
        out = {c: [] for c in idx}
        for row in reader:
            if not row:
                continue
            for c, i in idx.items():
                out[c].append(_float(row[i]))
    return out.pop("time"), out


def load_result_dead_reckoned(path, spec, radius=0.3, start=(0.0, 0.0, 0.0)):
    """Trajectory dead-reckoned from the columns of a replay CSV (--dead-reckoning SPEC)."""
    form, parts = parse_dead_reckoning(spec)
    names = parts["wheels"] if form == "wheels" else list(parts.values())
    t, columns = read_csv_columns(path, names)
    return dead_reckon_columns(t, columns, form, parts, radius, start)


def load_truth_csv(path):
    """Trajectory from a CSV time,x,y[,heading] (header line optional)."""
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].lstrip().startswith("#")]
    if not rows:
        raise ValueError("%s: empty" % path)
    names = {"time": 0, "x": 1, "y": 2, "heading": 3}
    try:
        float(rows[0][0])
    except ValueError:
        header = [h.strip().lower() for h in rows[0]]
        aliases = {"t": "time", "stamp": "time", "yaw": "heading", "theta": "heading"}
        header = [aliases.get(h, h) for h in header]
        names = {k: header.index(k) for k in ("time", "x", "y", "heading") if k in header}
        if not all(k in names for k in ("time", "x", "y")):
            raise ValueError("%s: header needs time,x,y[,heading], got %s" % (path, rows[0]))
        rows = rows[1:]
    has_h = "heading" in names and all(len(r) > names["heading"] for r in rows)
    t = [_float(r[names["time"]]) for r in rows]
    x = [_float(r[names["x"]]) for r in rows]
    y = [_float(r[names["y"]]) for r in rows]
    h = [_float(r[names["heading"]]) for r in rows] if has_h else None
    return make_trajectory(t, x, y, h)


def _topic_variants(topic):
    bare = topic.lstrip("/")
    return [bare, "/" + bare]


class _Identity:
    x = y = z = 0.0
    w = 1.0


def _pose_of(msg):
    """(position, orientation) of a PoseStamped, Odometry or PoseWithCovarianceStamped; a
    PointStamped (a position sensor such as the soccer robot's vision) has the identity
    orientation."""
    if hasattr(msg, "point"):
        return msg.point, _Identity
    pose = msg.pose
    if hasattr(pose, "pose"):
        pose = pose.pose
    return pose.position, pose.orientation


def load_pose_bag(path, topic, with_heading=True):
    """Trajectory from the poses on `topic` (with or without the leading slash) of a bag,
    stamped with header.stamp. The heading is the yaw of the orientation; with_heading=None
    drops it when every orientation is the identity (position-only truth such as the
    soccer bags')."""
    import rosbag  # Debian: python3-rosbag

    t, x, y, h = [], [], [], []
    all_identity = True
    with rosbag.Bag(path) as bag:
        topics = _topic_variants(topic)
        for _, msg, stamp in bag.read_messages(topics=topics):
            if hasattr(msg, "header") and (msg.header.stamp.secs or msg.header.stamp.nsecs):
                stamp = msg.header.stamp
            p, q = _pose_of(msg)
            t.append(stamp.to_sec())
            x.append(p.x)
            y.append(p.y)
            h.append(yaw_from_quaternion(q.x, q.y, q.z, q.w))
            if (q.x, q.y, q.z, q.w) != (0.0, 0.0, 0.0, 1.0):
                all_identity = False
    if not t:
        raise ValueError("%s: no messages on %s" % (path, " or ".join(_topic_variants(topic))))
    keep_h = with_heading if with_heading is not None else not all_identity
    return make_trajectory(t, x, y, h if keep_h else None)


def load_result(path, pose_columns=None, odom_topic="/odometry/filtered"):
    if path.endswith(".bag"):
        return load_pose_bag(path, odom_topic, with_heading=pose_columns is None
                             or len(pose_columns) > 2)
    return load_result_csv(path, pose_columns)


def load_truth(path, topic="ground_truth/pose"):
    if path.endswith(".bag"):
        return load_pose_bag(path, topic, with_heading=None)
    return load_truth_csv(path)


def split_label(spec):
    """'label=path' -> (label, path); 'path' -> (file name without extension, path)."""
    if "=" in spec:
        label, path = spec.split("=", 1)
        if label and "/" not in label:
            return label, path
    return os.path.splitext(os.path.basename(spec))[0], spec


# -----------------------------------------------------------------------------
# Plots
# -----------------------------------------------------------------------------
def _pyplot():
    import matplotlib  # Debian: python3-matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _draw_finals(ax, truth, results, arrow_len):
    """Final positions (and headings as arrows) of the results and of the truth."""
    for label, traj, ev, color in results:
        k = traj.t.index(ev.final_time)
        ax.plot(traj.x[k], traj.y[k], "x", color=color, markersize=9, mew=2, zorder=5)
        if traj.heading is not None:
            ax.annotate("", xy=(traj.x[k] + arrow_len * math.cos(traj.heading[k]),
                                traj.y[k] + arrow_len * math.sin(traj.heading[k])),
                        xytext=(traj.x[k], traj.y[k]),
                        arrowprops=dict(arrowstyle="->", color=color, lw=1.5), zorder=5)
    tx, ty, th = truth.x[-1], truth.y[-1], None if truth.heading is None else truth.heading[-1]
    ax.plot(tx, ty, "*", color="black", markersize=14, zorder=6)
    if th is not None:
        ax.annotate("", xy=(tx + arrow_len * math.cos(th), ty + arrow_len * math.sin(th)),
                    xytext=(tx, ty), arrowprops=dict(arrowstyle="->", color="black", lw=1.5),
                    zorder=6)


def _colors(plt, n):
    """n distinguishable colours: the default cycle, or tab20 for more than 10 lines."""
    if n <= 10:
        cycle = plt.rcParams["axes.prop_cycle"].by_key()["color"]
        return [cycle[i % len(cycle)] for i in range(n)]
    cmap = plt.get_cmap("tab20")
    return [cmap(i % 20) for i in range(n)]


def plot_paths(path, truth, results, title=None, limit=None, dpi=110):
    """results: list of (label, Trajectory, Evaluation). limit [m]: the left panel shows the
    truth's extent plus `limit` (paths further out are cut) and the zoom on the final
    positions leaves out finals more than `limit` from the truth's (their errors stay in the
    legend); None shows everything."""
    plt = _pyplot()
    colors = _colors(plt, len(results))
    res = [(l, tr, ev, colors[i]) for i, (l, tr, ev) in enumerate(results)]
    fig, (ax, az) = plt.subplots(1, 2, figsize=(14, 6.5), gridspec_kw={"width_ratios": [3, 2]})

    # Left: the paths.
    ax.plot(truth.x, truth.y, "-", color="black", lw=2.5, alpha=0.35, label="ground truth")
    for label, tr, ev, color in res:
        ax.plot(tr.x, tr.y, "-", color=color, lw=1.2, label=label)
    xs = truth.x + ([] if limit else [v for _, tr, _, _ in res for v in tr.x])
    ys = truth.y + ([] if limit else [v for _, tr, _, _ in res for v in tr.y])
    span = max(max(xs) - min(xs), max(ys) - min(ys), 1e-3)
    ax.plot(truth.x[0], truth.y[0], "o", color="black", markersize=13, mfc="none", mew=1.5,
            label="start", zorder=6)
    _draw_finals(ax, truth, res, 0.05 * span)
    ax.plot([], [], "*", color="black", markersize=12, label="final actual position")
    ax.plot([], [], "x", color="gray", markersize=9, mew=2, label="final estimated positions")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    if limit:
        ax.set_xlim(min(xs) - limit, max(xs) + limit)
        ax.set_ylim(min(ys) - limit, max(ys) + limit)
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="best")
    ax.set_title("paths" + (" (cut %g m beyond the truth)" % limit if limit else ""))

    # Right: the final positions, zoomed (thesis Fig. 5.7/5.9, right graphs).
    zoomed = [r for r in res if not limit or r[2].final_pos_err <= limit]
    fx = [truth.x[-1]] + [tr.x[tr.t.index(ev.final_time)] for _, tr, ev, _ in zoomed]
    fy = [truth.y[-1]] + [tr.y[tr.t.index(ev.final_time)] for _, tr, ev, _ in zoomed]
    zspan = max(max(fx) - min(fx), max(fy) - min(fy), 0.02)
    cx, cy = (max(fx) + min(fx)) / 2, (max(fy) + min(fy)) / 2
    half = 0.5 * zspan * 1.6
    for label, tr, ev, color in res:
        az.plot(tr.x, tr.y, "-", color=color, lw=1.0, alpha=0.6)
    az.plot(truth.x, truth.y, "-", color="black", lw=2.5, alpha=0.35)
    _draw_finals(az, truth, res, 0.15 * zspan)
    az.plot([], [], "*", color="black", markersize=12, label="final actual position")
    for label, tr, ev, color in res:
        az.plot([], [], "x", color=color, markersize=9, mew=2,
                label="%s: %.3f m off" % (label, ev.final_pos_err))
    az.legend(fontsize=8, loc="best")
    az.set_xlim(cx - half, cx + half)
    az.set_ylim(cy - half, cy + half)
    az.set_aspect("equal", adjustable="box")
    az.set_xlabel("x (m)")
    az.set_ylabel("y (m)")
    az.grid(True, alpha=0.3)
    az.set_title("final positions (arrows: final headings)")
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    plt.close(fig)


def plot_errors(path, truth, results, heading=False, title=None, limit=None, dpi=110):
    """Position (or heading) error over time since the truth's start; limit caps the
    position error axis [m]."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(10, 4.5))
    t0 = truth.t[0]
    drawn = 0
    for label, tr, ev in results:
        values = ev.heading_errors_deg if heading else ev.pos_errors
        if values is None:
            continue
        ax.plot([t - t0 for t in ev.times], values, "-", lw=1.2, label=label)
        drawn += 1
    if heading:
        ax.axhline(0.0, color="black", lw=0.8)
    if limit and not heading:
        ax.set_ylim(0.0, limit)
    ax.set_xlabel("time since start (s)")
    ax.set_ylabel("heading error, estimate - truth (deg)" if heading else "position error (m)")
    ax.grid(True, alpha=0.3)
    if drawn:
        ax.legend(fontsize=8, loc="best")
    ax.set_title((title + ": " if title else "") + ("heading error" if heading else
                                                      "position error"))
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    return drawn


def write_plots(plot_dir, truth, results, title=None, limit=None):
    """paths.png, position_error.png and heading_error.png (if any headings) in plot_dir;
    returns the written paths. limit: see plot_paths()."""
    os.makedirs(plot_dir, exist_ok=True)
    written = []
    p = os.path.join(plot_dir, "paths.png")
    plot_paths(p, truth, results, title, limit)
    written.append(p)
    p = os.path.join(plot_dir, "position_error.png")
    plot_errors(p, truth, results, heading=False, title=title, limit=limit)
    written.append(p)
    if truth.heading is not None and any(ev.heading_errors_deg for _, _, ev in results):
        p = os.path.join(plot_dir, "heading_error.png")
        plot_errors(p, truth, results, heading=True, title=title)
        written.append(p)
    return written


# -----------------------------------------------------------------------------
# Command line
# -----------------------------------------------------------------------------
def parse_label_values(specs, what):
    out = {}
    for spec in specs or []:
        if "=" not in spec:
            raise SystemExit("%s: expected LABEL=VALUE, got %r" % (what, spec))
        label, value = spec.split("=", 1)
        out[label] = value
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    parser.add_argument("results", nargs="+", metavar="RESULT", help="LABEL=PATH or PATH")
    parser.add_argument("--truth", required=True, help="bag with ground_truth/pose, or a CSV")
    parser.add_argument("--truth-topic", default="ground_truth/pose")
    parser.add_argument("--odom-topic", default="/odometry/filtered",
                        help="topic of the results in bags (default %(default)s)")
    parser.add_argument("--pose-columns", help="CSV columns X,Y[,HEADING] "
                        "(default pose_x,pose_y,pose_heading)")
    parser.add_argument("--dead-reckoning", metavar="SPEC",
                        help="compute the path of CSV results from logged velocities instead "
                        "of pose columns: v=COL,omega=COL | a=COL,omega=COL | "
                        "wheels=LEFT,RIGHT (mm/s; --radius)")
    parser.add_argument("--radius", type=float, default=0.3,
                        help="effective skid-steer radius for wheels= [m] (default %(default)g)")
    parser.add_argument("--start", default="0,0,0", metavar="X,Y,HEADING",
                        help="start pose of --dead-reckoning [m, m, rad] (default %(default)s)")
    parser.add_argument("--timing", action="append", metavar="LABEL=US",
                        help="mean time per estimation step of a result [us] (repeatable)")
    parser.add_argument("--summary", action="append", metavar="LABEL=FILE",
                        help="file with the replay's summary line, for the timing (repeatable)")
    parser.add_argument("--time-tolerance", type=float, default=DEFAULT_TIME_TOLERANCE,
                        help="s an estimate may lie outside the truth's range (default %(default)g)")
    parser.add_argument("--plot-dir", help="write the PNG plots into this directory")
    parser.add_argument("--title", help="title of the plots")
    parser.add_argument("--plot-limit", type=float, metavar="M",
                        help="cut paths more than M metres beyond the truth's extent, and "
                        "cap the position error axis at M (for results that run away)")
    parser.add_argument("--markdown", action="store_true", help="print a Markdown table")
    args = parser.parse_args(argv)

    pose_columns = [c.strip() for c in args.pose_columns.split(",")] if args.pose_columns else None
    if pose_columns is not None and len(pose_columns) not in (2, 3):
        parser.error("--pose-columns needs 2 or 3 names")
    try:
        if args.dead_reckoning:
            parse_dead_reckoning(args.dead_reckoning)
        start = tuple(float(a) for a in args.start.split(","))
        if len(start) != 3:
            raise ValueError("--start: expected X,Y,HEADING, got %r" % args.start)
    except ValueError as exc:
        parser.error(str(exc))
    timing = {k: float(v) for k, v in parse_label_values(args.timing, "--timing").items()}
    for label, fname in parse_label_values(args.summary, "--summary").items():
        with open(fname) as f:
            us = parse_summary_timing(f.read())
        if us is None:
            print("warning: no 'us per estimation step' in %s" % fname, file=sys.stderr)
        else:
            timing[label] = us

    try:
        truth = load_truth(args.truth, args.truth_topic)
    except (ValueError, OSError) as exc:
        print("error: truth: %s" % exc, file=sys.stderr)
        return 2
    rows, plotted = [], []
    failed = False
    seen = collections.Counter()
    for spec in args.results:
        label, path = split_label(spec)
        seen[label] += 1
        if seen[label] > 1:  # the same label twice: keep both, told apart
            label = "%s (%d)" % (label, seen[label])
        try:
            if args.dead_reckoning and not path.endswith(".bag"):
                traj = load_result_dead_reckoned(path, args.dead_reckoning, args.radius, start)
            else:
                traj = load_result(path, pose_columns, args.odom_topic)
            ev = evaluate(traj, truth, args.time_tolerance)
        except (ValueError, OSError) as exc:
            print("error: %s: %s" % (label, exc), file=sys.stderr)
            failed = True
            continue
        rows.append((label, ev, timing.get(label)))
        plotted.append((label, traj, ev))
    if rows:
        print(format_table(rows, markdown=args.markdown))
    if args.plot_dir and plotted:
        for p in write_plots(args.plot_dir, truth, plotted, args.title, args.plot_limit):
            print("wrote %s" % p)
    return 1 if failed or not rows else 0


if __name__ == "__main__":
    sys.exit(main())
