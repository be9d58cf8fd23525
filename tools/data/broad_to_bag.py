#!/usr/bin/python3
"""Converts one trial of the BROAD benchmark (HDF5 or MATLAB file; tools/data/broad_trial.py)
into a rosbag: the IMU, the magnetometer, the optical reference as ground truth and, as the
"vision" of Armesto's inertial+vision set-up, the reference sampled at a low rate with
added Gaussian noise (doc/bags.md, "BROAD").

| topic | type | rate | content |
| --- | --- | --- | --- |
| imu/data | sensor_msgs/Imu | 285.7 Hz | gyro [rad/s], accelerometer [m/s^2]; orientation_covariance[0] = -1 (none) |
| imu/mag | sensor_msgs/MagneticField | 285.7 Hz | field [T] (the trial's uT times 1e-6), covariance 0 (unknown) |
| ground_truth/pose | geometry_msgs/PoseStamped | 285.7 Hz | optical reference, sensor to ENU ("world"); left out in its gaps |
| vision/pose | geometry_msgs/PoseWithCovarianceStamped | 12.5 Hz | the reference at the sample nearest each 80 ms tick, position and rotation noise added (body frame), the noise's covariance; left out in the reference's gaps |

The noise is seeded (--seed) and drawn for every tick, gaps included, so that a given tick's
noise does not depend on the gaps before it. Times: --start-epoch + sample index / rate."""

import argparse
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "sim"))
import broad_trial  # noqa: E402


def rotation_vector_to_quat(v):
    angle = np.linalg.norm(v)
    if angle < 1e-12:
        return np.array([1.0, 0.5 * v[0], 0.5 * v[1], 0.5 * v[2]])
    axis = v / angle
    return np.concatenate([[math.cos(angle / 2)], math.sin(angle / 2) * axis])


def fill_pose(pose, position, quat):
    pose.position.x, pose.position.y, pose.position.z = (float(c) for c in position)
    pose.orientation.w, pose.orientation.x, pose.orientation.y, pose.orientation.z = (float(c) for c in quat)


def add_imu(builder, trial, k, t_ns, args):
    from sensor_msgs.msg import Imu, MagneticField
    imu = Imu()
    imu.header.stamp, imu.header.frame_id, imu.header.seq = builder.stamp(t_ns), args.imu_frame, builder.next_seq("imu/data")
    imu.orientation_covariance[0] = -1.0
    imu.angular_velocity.x, imu.angular_velocity.y, imu.angular_velocity.z = (float(c) for c in trial.imu_gyr[k])
    imu.linear_acceleration.x, imu.linear_acceleration.y, imu.linear_acceleration.z = (float(c) for c in trial.imu_acc[k])
    for i in range(3):
        imu.angular_velocity_covariance[4 * i] = args.gyro_std ** 2
        imu.linear_acceleration_covariance[4 * i] = args.accel_std ** 2
    builder.add("imu/data", imu, t_ns)
    mag = MagneticField()
    mag.header.stamp, mag.header.frame_id, mag.header.seq = builder.stamp(t_ns), args.imu_frame, builder.next_seq("imu/mag")
    mag.magnetic_field.x, mag.magnetic_field.y, mag.magnetic_field.z = (float(c) * 1e-6 for c in trial.imu_mag[k])
    builder.add("imu/mag", mag, t_ns)


def add_ground_truth(builder, trial, k, t_ns, args):
    from geometry_msgs.msg import PoseStamped
    msg = PoseStamped()
    msg.header.stamp, msg.header.frame_id, msg.header.seq = builder.stamp(t_ns), args.world_frame, builder.next_seq("ground_truth/pose")
    fill_pose(msg.pose, trial.opt_pos[k], trial.opt_quat[k] / np.linalg.norm(trial.opt_quat[k]))
    builder.add("ground_truth/pose", msg, t_ns)


def add_vision(builder, trial, k, t_ns, noise, args):
    """One vision frame: the reference at sample k with position noise noise[:3] [m] and the
    body-frame rotation noise noise[3:] [rad]."""
    from geometry_msgs.msg import PoseWithCovarianceStamped
    msg = PoseWithCovarianceStamped()
    msg.header.stamp, msg.header.frame_id, msg.header.seq = builder.stamp(t_ns), args.world_frame, builder.next_seq("vision/pose")
    q = broad_trial.quat_product(trial.opt_quat[k] / np.linalg.norm(trial.opt_quat[k]), rotation_vector_to_quat(noise[3:]))
    fill_pose(msg.pose.pose, trial.opt_pos[k] + noise[:3], q / np.linalg.norm(q))
    for i in range(6):
        msg.pose.covariance[7 * i] = (args.vision_position_std if i < 3 else args.vision_rotation_std) ** 2
    builder.add("vision/pose", msg, t_ns)


def convert(trial, args):
    """A BagBuilder with the trial's messages between args.begin and args.end seconds."""
    import simbag
    builder = simbag.BagBuilder(args.start_epoch)
    n = len(trial.imu_gyr)
    first, last = int(math.ceil(args.begin * trial.rate)), n if args.end is None else min(n, int(args.end * trial.rate) + 1)
    ns = lambda k: int(round(k * 1e9 / trial.rate))  # noqa: E731
    valid = np.all(np.isfinite(trial.opt_quat), axis=1) & np.all(np.isfinite(trial.opt_pos), axis=1)
    for k in range(first, last):
        add_imu(builder, trial, k, ns(k), args)
        if valid[k]:
            add_ground_truth(builder, trial, k, ns(k), args)
    rng = np.random.default_rng(args.seed)
    std = np.array([args.vision_position_std] * 3 + [args.vision_rotation_std] * 3)
    tick = 0
    while True:
        k = int(round(tick * trial.rate / args.vision_rate))
        if k >= n:
            break
        noise = rng.standard_normal(6) * std
        if first <= k < last and valid[k]:
            add_vision(builder, trial, k, ns(k), noise, args)
        tick += 1
    return builder


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    parser.add_argument("trial", help="a BROAD trial, .hdf5 or .mat")
    parser.add_argument("bag", help="output bag")
    parser.add_argument("--seed", type=int, default=1, help="seed of the vision noise (default %(default)s)")
    parser.add_argument("--vision-rate", type=float, default=12.5, help="Hz (default %(default)s: 80 ms)")
    parser.add_argument("--vision-position-std", type=float, default=0.005, help="m (default %(default)s)")
    parser.add_argument("--vision-rotation-std", type=float, default=0.01, help="rad (default %(default)s)")
    parser.add_argument("--gyro-std", type=float, default=0.005, help="rad/s, the Imu message's covariance")
    parser.add_argument("--accel-std", type=float, default=0.05, help="m/s^2, the Imu message's covariance")
    parser.add_argument("--begin", type=float, default=0.0, help="first second of the trial kept")
    parser.add_argument("--end", type=float, default=None, help="last second kept (default: the end)")
    parser.add_argument("--imu-frame", default="imu")
    parser.add_argument("--world-frame", default="world")
    parser.add_argument("--start-epoch", type=int, default=1700000000, help="bag time of the trial's first sample [s]")
    parser.add_argument("--compression", default="bz2", choices=("bz2", "lz4", "none"))
    args = parser.parse_args(argv)
    for name in ("vision_rate", "vision_position_std", "vision_rotation_std", "gyro_std", "accel_std"):
        if not getattr(args, name) > 0:
            parser.error("--%s must be positive" % name.replace("_", "-"))
    trial = broad_trial.load(args.trial)
    builder = convert(trial, args)
    builder.write(args.bag, args.compression)
    counts = builder.counts()
    print("%s: %s" % (args.bag, ", ".join("%s %d" % (t, counts[t]) for t in sorted(counts))))


if __name__ == "__main__":
    main()
