#!/usr/bin/python3
"""Dead reckoning by hand: wheel speed with the gyro's (or the wheels') yaw rate.

Usage:
  wheel_gyro_reference.py BAG OUT.csv [--yaw gyro|wheels] [options]

The reference a fusion filter has to beat on a real recording: the robot's forward speed
from the wheel odometry (nav_msgs/Odometry twist.twist.linear.x on --odom-topic) and its
yaw rate from the gyro (sensor_msgs/Imu angular_velocity.z on --imu-topic; --yaw wheels
takes the odometry's twist.twist.angular.z instead: the wheel odometry alone), integrated
with no filter at all. Both are taken at their header stamps.

Integration, at every odometry stamp t_k (the pose starts at (0, 0, 0) at the first one):
  heading  theta_k = theta_{k-1} + integral of the yaw rate over (t_{k-1}, t_k], the gyro
           interpolated linearly between its samples and held constant before the first
           and after the last (trapezoidal rule on the pieces between samples);
  position x_k = x_{k-1} + v_{k-1} (t_k - t_{k-1}) cos((theta_{k-1} + theta_k) / 2),
           y likewise with sin: the speed of the interval's start along the mid-interval
           heading.
--gyro-bias B subtracts a constant bias [rad/s] from the gyro. The output CSV has
time,pose_x,pose_y,pose_heading, the columns of a replay CSV, so tools/eval/gps_reference.py
and evaluate.py read it as they read a filter's output.

The integration functions are pure (no ROS) and unit-tested on a synthetic track in
test/eval/test_wheel_gyro_reference.py.
"""

import argparse
import math
import os
import sys


def yaw_increment(samples, t0, t1):
    """Integral of a piecewise-linear signal over (t0, t1]. samples: sorted (t, value)
    pairs; before the first and after the last sample the signal is held constant."""
    if t1 <= t0 or not samples:
        return 0.0

    def value(t):
        if t <= samples[0][0]:
            return samples[0][1]
        if t >= samples[-1][0]:
            return samples[-1][1]
        lo, hi = 0, len(samples) - 1
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if samples[mid][0] <= t:
                lo = mid
            else:
                hi = mid
        (ta, va), (tb, vb) = samples[lo], samples[hi]
        return va + (vb - va) * (t - ta) / (tb - ta)

    # Breakpoints: t0, the sample stamps inside (t0, t1), t1; trapezoid on each piece
    # (exact for a piecewise-linear signal).
    points = [t0] + [t for t, _ in samples if t0 < t < t1] + [t1]
    total = 0.0
    for a, b in zip(points, points[1:]):
        total += 0.5 * (value(a) + value(b)) * (b - a)
    return total


def dead_reckon(odom, yaw_samples, start=(0.0, 0.0, 0.0)):
    """odom: sorted (t, v) pairs; yaw_samples: sorted (t, yaw rate) pairs. Returns the lists
    (t, x, y, heading) at the odometry stamps (see the module's help)."""
    if not odom:
        raise ValueError("no odometry samples")
    t = [odom[0][0]]
    x, y, h = [float(start[0])], [float(start[1])], [float(start[2])]
    for k in range(1, len(odom)):
        t0, v0 = odom[k - 1]
        t1 = odom[k][0]
        h1 = h[-1] + yaw_increment(yaw_samples, t0, t1)
        mid = 0.5 * (h[-1] + h1)
        x.append(x[-1] + v0 * (t1 - t0) * math.cos(mid))
        y.append(y[-1] + v0 * (t1 - t0) * math.sin(mid))
        h.append(h1)
        t.append(t1)
    return t, x, y, h


def _stamp(msg, t_bag):
    s = msg.header.stamp.to_sec()
    return s if s > 0 else t_bag.to_sec()


def read_bag(path, odom_topic, imu_topic):
    """(odom [(t, v)], wheel yaw [(t, wz)], gyro [(t, wz)]) at header stamps, sorted."""
    import rosbag  # only here: the integration needs no ROS
    odom, wheel_yaw, gyro = [], [], []
    with rosbag.Bag(path) as bag:
        for topic, msg, t in bag.read_messages(topics=[odom_topic, imu_topic]):
            if topic == odom_topic:
                s = _stamp(msg, t)
                odom.append((s, msg.twist.twist.linear.x))
                wheel_yaw.append((s, msg.twist.twist.angular.z))
            else:
                gyro.append((_stamp(msg, t), msg.angular_velocity.z))
    for series in (odom, wheel_yaw, gyro):
        series.sort()
    if not odom:
        raise ValueError("%s: no messages on %s" % (path, odom_topic))
    return odom, wheel_yaw, gyro


def write_csv(path, track):
    with open(path, "w") as f:
        f.write("time,pose_x,pose_y,pose_heading\n")
        for row in zip(*track):
            f.write("%.9f,%.6f,%.6f,%.6f\n" % row)


def main(argv=None):
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    parser.add_argument("bag")
    parser.add_argument("out", help="output CSV (time,pose_x,pose_y,pose_heading)")
    parser.add_argument("--yaw", choices=["gyro", "wheels"], default="gyro",
                        help="source of the yaw rate (default %(default)s)")
    parser.add_argument("--odom-topic", default="/encoder")
    parser.add_argument("--imu-topic", default="/imu/data")
    parser.add_argument("--gyro-bias", type=float, default=0.0,
                        help="constant gyro bias subtracted [rad/s] (default 0)")
    args = parser.parse_args(argv)
    try:
        odom, wheel_yaw, gyro = read_bag(args.bag, args.odom_topic, args.imu_topic)
        if args.yaw == "gyro":
            if not gyro:
                raise ValueError("%s: no messages on %s" % (args.bag, args.imu_topic))
            yaw = [(t, w - args.gyro_bias) for t, w in gyro]
        else:
            yaw = wheel_yaw
        track = dead_reckon(odom, yaw)
        write_csv(args.out, track)
    except (ValueError, OSError) as exc:
        print("error: %s" % exc, file=sys.stderr)
        return 2
    print("%d poses, %.1f s, yaw rate from the %s: final pose (%.3f, %.3f) m, heading %.3f rad"
          % (len(track[0]), track[0][-1] - track[0][0], args.yaw, track[1][-1], track[2][-1],
             track[3][-1]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
