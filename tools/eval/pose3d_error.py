#!/usr/bin/python3
"""Orientation and position errors of a 3D replay CSV (a header with QUATERNION_STATES: its
quaternion w, x, y, z in four state columns) against a bag's geometry_msgs/PoseStamped ground
truth (tools/sim/rigid_body_sim.py, tools/data/broad_to_bag.py: ground_truth/pose).

Each estimate is compared with the truth sample nearest its time (within --max-gap s):
  orientation  the angle of q_truth^-1 q_estimate [deg] (sign-invariant: q and -q agree)
  tilt         the angle between the true and the estimated body up axis [deg]: roll and pitch
               only, what an accelerometer observes
  position     the Euclidean distance [m] (with --position)
--skip s leaves out the first s seconds (the filter settling from its initial belief);
--window A B compares only the estimates from A to B s after the truth bag's first message
instead (a window fixed in the recording, whatever the first row's time: a node's first row
is at its first /clock, a replay's one ~max_measurement_lag earlier);
--align-yaw removes the constant heading offset of the first compared sample from the
estimate (an IMU without a magnetometer has no heading of its own: the reference's world frame
is then unknown to it).

  pose3d_error.py --csv out.csv --truth bag.bag --quaternion 3 --position 0 [--skip 2]
Prints "<name> RMSE <value> <unit>, max <value>" per error.
"""

import argparse
import bisect
import csv
import math


def norm(v):
    return math.sqrt(sum(c * c for c in v))


def quat_multiply(a, b):
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return (w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
            w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2)


def quat_conjugate(q):
    return (q[0], -q[1], -q[2], -q[3])


def rotate(q, v):
    return quat_multiply(quat_multiply(q, (0.0,) + tuple(v)), quat_conjugate(q))[1:]


def angle_between(q1, q0):
    """The rotation angle of q0^-1 q1 [rad], the same for -q1."""
    d = quat_multiply(quat_conjugate(q0), q1)
    return 2.0 * math.atan2(norm(d[1:]), abs(d[0]))


def tilt_between(q1, q0):
    """The angle between the body's up axes (the world's z seen in each body frame) [rad]."""
    up1, up0 = rotate(quat_conjugate(q1), (0, 0, 1)), rotate(quat_conjugate(q0), (0, 0, 1))
    dot = sum(a * b for a, b in zip(up1, up0)) / (norm(up1) * norm(up0))
    return math.acos(max(-1.0, min(1.0, dot)))


def yaw_quaternion(yaw):
    return (math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2))


def heading(q):
    w, x, y, z = q
    return math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))


def load_truth(bag_path, topic="ground_truth/pose"):
    """Sorted times [s], quaternions (w, x, y, z) and positions of the PoseStamped topic."""
    import rosbag  # Debian: python3-rosbag
    times, quats, positions = [], [], []
    with rosbag.Bag(bag_path) as bag:
        for _, msg, _ in bag.read_messages(topics=[topic]):
            o, p = msg.pose.orientation, msg.pose.position
            times.append(msg.header.stamp.to_sec())
            quats.append((o.w, o.x, o.y, o.z))
            positions.append((p.x, p.y, p.z))
    order = sorted(range(len(times)), key=lambda i: times[i])
    return ([times[i] for i in order], [quats[i] for i in order], [positions[i] for i in order])


def errors(rows, truth, quaternion, position=None, skip=0.0, max_gap=0.02, align_yaw=False,
           window=None):
    """Lists of orientation, tilt [rad] and position [m] errors of the CSV rows (those from
    `skip` s after the first row on, or those in `window`, (start, end) times [s])."""
    times, quats, positions = truth
    out = {"orientation": [], "tilt": [], "position": []}
    offset = None
    start = rows[0]["time"] + skip if rows else 0.0
    end = float("inf")
    if window is not None:
        start, end = window
    for row in rows:
        if not start <= row["time"] <= end:
            continue
        k = bisect.bisect_left(times, row["time"])
        near = [j for j in (k - 1, k) if 0 <= j < len(times)]
        if not near:
            continue
        j = min(near, key=lambda j: abs(times[j] - row["time"]))
        if abs(times[j] - row["time"]) > max_gap:
            continue
        q = [row["x%d" % (quaternion + i)] for i in range(4)]
        q = tuple(c / norm(q) for c in q)
        if align_yaw:
            if offset is None:
                offset = yaw_quaternion(heading(quats[j]) - heading(q))
            q = quat_multiply(offset, q)
        out["orientation"].append(angle_between(q, quats[j]))
        out["tilt"].append(tilt_between(q, quats[j]))
        if position is not None:
            p = [row["x%d" % (position + i)] for i in range(3)]
            out["position"].append(norm([a - b for a, b in zip(p, positions[j])]))
    return out


def read_rows(csv_path):
    with open(csv_path, newline="") as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def rms(values):
    return math.sqrt(sum(v * v for v in values) / len(values)) if values else float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--csv", required=True, help="the replay's CSV (--csv)")
    parser.add_argument("--truth", required=True, help="bag with the ground truth")
    parser.add_argument("--truth-topic", default="ground_truth/pose")
    parser.add_argument("--quaternion", type=int, required=True, help="state index of w")
    parser.add_argument("--position", type=int, help="state index of the position's x")
    parser.add_argument("--skip", type=float, default=0.0, help="seconds left out at the start")
    parser.add_argument("--max-gap", type=float, default=0.02, help="s to the nearest truth")
    parser.add_argument("--align-yaw", action="store_true")
    parser.add_argument("--window", type=float, nargs=2, metavar=("A", "B"),
                        help="only the estimates A to B s after the truth bag's first message")
    args = parser.parse_args()
    window = None
    if args.window:
        import rosbag
        with rosbag.Bag(args.truth) as bag:
            window = tuple(bag.get_start_time() + a for a in args.window)
    e = errors(read_rows(args.csv), load_truth(args.truth, args.truth_topic), args.quaternion,
               args.position, args.skip, args.max_gap, args.align_yaw, window)
    print("compared %d estimates" % len(e["orientation"]))
    for name in ("orientation", "tilt"):
        deg = [math.degrees(v) for v in e[name]]
        print("%s RMSE %.3f deg, max %.3f deg" % (name, rms(deg), max(deg, default=float("nan"))))
    if args.position is not None:
        print("position RMSE %.4f m, max %.4f m" % (rms(e["position"]),
                                                   max(e["position"], default=float("nan"))))


if __name__ == "__main__":
    main()
