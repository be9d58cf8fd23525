#!/usr/bin/python3
"""The library-level MR-EKF or MR-UKF (sf_estimation_armesto_fusion, doc/armesto.md) over the
samples a node of config/armesto_inertial_vision_*.h takes from a bag, so that the node and
the library filter are compared on the same data ("The node headers" in doc/armesto.md).

  armesto_bag_run.py BAG --binary BIN --filter ekf|ukf --csv OUT.csv [--gravity G]

The stream has a line per 10 ms period [k T - T, k T) from the bag's first message, as the
node's periods and SAMPLED inputs take it: the period's last imu/data message (the previous
one held when a period has none) and its last vision/pose; it starts at the first period with
a frame (the program starts from a frame). OUT.csv has the replay CSV's form for
tools/eval/pose3d_error.py: time (the period's end, as the node stamps its estimate), x0..x2 the
position, x3..x6 the quaternion w, x, y, z.
"""

import argparse
import math
import subprocess

PERIOD = 0.01
TOLERANCE = 1e-6


def period_of(offset):
    """The node's period of a message `offset` s after the first: k for [k T - T, k T), a time
    within the node's tolerance (1e-6 s, sf_filter's PeriodSchedule) of a period's end in the
    next period, as the node's schedule places a message on a period's end."""
    return int(math.floor((offset + TOLERANCE) / PERIOD)) + 1


def periods(bag_path):
    """{period: imu sample}, {period: vision frame} and the bag's first time [s]."""
    import rosbag  # Debian: python3-rosbag
    imu, vision, first = {}, {}, None
    with rosbag.Bag(bag_path) as bag:
        for topic, msg, t in bag.read_messages(topics=["imu/data", "vision/pose"]):
            first = t if first is None else first
            k = period_of((t - first).to_sec())  # from integer nanoseconds: exact at 1.7e9 s
            if topic == "imu/data":
                a, w = msg.linear_acceleration, msg.angular_velocity
                imu[k] = (a.x, a.y, a.z, w.x, w.y, w.z)
            else:
                p, q = msg.pose.pose.position, msg.pose.pose.orientation
                vision[k] = (p.x, p.y, p.z, q.w, q.x, q.y, q.z)
    start = first.to_sec()
    return imu, vision, start


def stream(imu, vision):
    """(period indices, the program's input lines) from the first period with a frame."""
    first = min(vision)
    held = imu[min(k for k in imu if k >= first)]
    ks, lines = [], []
    for k in range(first, max(imu) + 1):
        held = imu.get(k, held)
        frame = vision.get(k)
        values = list(held) + ([1] + list(frame) if frame else [0] * 8)
        ks.append(k)
        lines.append(",".join("%.10g" % v for v in values))
    return ks, "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("bag")
    parser.add_argument("--binary", required=True, help="sf_estimation_armesto_fusion")
    parser.add_argument("--filter", choices=("ekf", "ukf"), required=True)
    parser.add_argument("--csv", required=True)
    parser.add_argument("--gravity", type=float, default=9.80665,
                        help="m/s^2 (default 9.80665, the node headers'; the program's is 9.81)")
    args = parser.parse_args()
    imu, vision, start = periods(args.bag)
    ks, text = stream(imu, vision)
    done = subprocess.run([args.binary, "--filter", args.filter, "--gravity", repr(args.gravity)],
                          input=text, capture_output=True, text=True, check=True)
    with open(args.csv, "w") as out:
        out.write("time," + ",".join("x%d" % i for i in range(7)) + "\n")
        for k, line in zip(ks, done.stdout.split()):
            out.write("%.6f,%s\n" % (start + k * PERIOD, line))
    print(done.stderr.strip())


if __name__ == "__main__":
    main()
