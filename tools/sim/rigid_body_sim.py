#!/usr/bin/python3
"""Deterministic simulator of a body moving in three dimensions (a drone, a legged or wheeled
robot on slopes) with an IMU, 3D odometry and a pose sensor ("vision"), for the 3D headers
(issue 35) and their tests.

The motion is analytic, so that every sensor reads the exact truth before its errors: the
position is a Lissajous figure about a height, the orientation three Euler angles (ZYX: yaw,
pitch, roll) that oscillate while the yaw also turns steadily; velocity, acceleration and the
body's angular velocity are their exact derivatives (functions `pose`, `body_rates`, unit-tested
in test/eval/test_rigid_body_sim.py against finite differences). --motion slow|fast scales the
frequencies (fast: twice the angular rates and 4 times the
accelerations of slow).

  topic              type                                     rate      frame
  imu/data           sensor_msgs/Imu                          100 Hz    imu_link: gyro and
                                                                        accelerometer (specific
                                                                        force, gravity 9.80665
                                                                        m/s^2 along the world's
                                                                        -z), no orientation
  odom               nav_msgs/Odometry                        50 Hz     odom -> base_link: the
                                                                        body-frame twist (linear
                                                                        and angular, 6x6
                                                                        covariance), pose
                                                                        integrated from it
  vision/pose        geometry_msgs/PoseWithCovarianceStamped  12.5 Hz   odom: the true pose with
                                                                        noise (position, rotation
                                                                        vector), its covariance
  ground_truth/pose  geometry_msgs/PoseStamped                100 Hz    odom
  tf_static          tf2_msgs/TFMessage                       once      base_link -> imu_link

The IMU's mount (--imu-mount-rpy, default level) is in tf_static. Noise: gyro 0.005 rad/s,
accelerometer 0.05 m/s^2 per sample and axis; odometry twist 0.02 m/s and 0.01 rad/s; vision
0.01 m and 0.01 rad (--vision-std). Realistic errors (sensor_errors.py, off by default): gyro
and accelerometer bias (initial value --gyro-bias-init on every axis, random walks
--gyro-bias-rw and --accel-bias-rw, constant --accel-bias) per axis, gyro scale factor,
latency with jitter (--imu-latency-ms for the IMU, --wheel-latency-ms for the odometry and
the vision), dropped and duplicated messages; --realistic drone switches on a calibrated set.

  rigid_body_sim.py --seed 1 --duration 60 --out /tmp/rigid_body_seed1.bag
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from geometry_msgs.msg import PoseStamped, PoseWithCovarianceStamped  # noqa: E402
from nav_msgs.msg import Odometry  # noqa: E402
from sensor_msgs.msg import Imu  # noqa: E402
from tf2_msgs.msg import TFMessage  # noqa: E402

import sensor_errors  # noqa: E402
import simbag  # noqa: E402
from diff_drive_sim import quaternion_rpy, rotation_rpy, transform, transpose_times  # noqa: E402

G = 9.80665
IMU_PERIOD_MS, ODOM_PERIOD_MS, VISION_PERIOD_MS, GT_PERIOD_MS = 10, 20, 80, 10
GYRO_STD, ACCEL_STD = 0.005, 0.05
ODOM_LINEAR_STD, ODOM_ANGULAR_STD = 0.02, 0.01
# A consumer-grade IMU on a small drone: MEMS gyro and accelerometer bias instability and
# turn-on bias of the order of a few mrad/s and 0.05 m/s^2, USB/serial latency of a few ms.
PRESETS = {"drone": dict(gyro_bias_init=0.003, gyro_bias_rw=1e-4, gyro_scale=0.005, accel_bias=0.05,
                         accel_bias_rw=0.002, imu_latency_ms=2.0, imu_jitter_ms=1.0,
                         wheel_latency_ms=20.0, wheel_jitter_ms=5.0, drop_prob=0.002)}
# Options of sensor_errors that have no meaning for this body (wheel slip and encoders).
PLANAR_ONLY = ("slip_chi", "slip_std", "slip_tau", "lateral_slip", "radius_error_left",
               "radius_error_right", "radius_load_coef", "encoder_step", "tilt_roll", "tilt_pitch",
               "odom_separation_scale")


class Motion:
    """Amplitudes [m, rad] and angular frequencies [rad/s] of the analytic motion."""

    def __init__(self, kind):
        scale = {"slow": 1.0, "fast": 2.0}[kind]
        self.position = ((2.0, 0.3 * scale), (1.5, 0.4 * scale), (0.5, 0.5 * scale))
        self.height = 1.5
        self.angles = ((0.25, 0.9 * scale), (0.2, 0.7 * scale), (0.6, 0.5 * scale))  # roll, pitch, yaw
        self.yaw_rate = 0.15 * scale


def _trig(amplitude, omega, t, phase=0.0):
    """(value, first, second derivative) of amplitude * sin(omega t + phase)."""
    s, c = math.sin(omega * t + phase), math.cos(omega * t + phase)
    return amplitude * s, amplitude * omega * c, -amplitude * omega * omega * s


def pose(motion, t):
    """(position, velocity, acceleration) in the world frame and (roll, pitch, yaw) with their
    first derivatives, at time t [s]."""
    axes = [_trig(a, w, t, 0.7 * k) for k, (a, w) in enumerate(motion.position)]
    position = [axes[0][0], axes[1][0], axes[2][0] + motion.height]
    velocity = [a[1] for a in axes]
    acceleration = [a[2] for a in axes]
    angles = [_trig(a, w, t, 1.1 * k) for k, (a, w) in enumerate(motion.angles)]
    rpy = [angles[0][0], angles[1][0], angles[2][0] + motion.yaw_rate * t]
    rpy_rate = [angles[0][1], angles[1][1], angles[2][1] + motion.yaw_rate]
    return position, velocity, acceleration, rpy, rpy_rate


def body_rates(rpy, rpy_rate):
    """Angular velocity in the body frame from ZYX Euler angles and their rates."""
    roll, pitch, _ = rpy
    droll, dpitch, dyaw = rpy_rate
    return [droll - dyaw * math.sin(pitch),
            dpitch * math.cos(roll) + dyaw * math.cos(pitch) * math.sin(roll),
            -dpitch * math.sin(roll) + dyaw * math.cos(pitch) * math.cos(roll)]


def specific_force(rpy, acceleration):
    """What an accelerometer on the body reads: R^T (a + g e_z), the world's acceleration minus
    gravity (-g e_z), in the body frame."""
    return transpose_times(rotation_rpy(*rpy), [acceleration[0], acceleration[1], acceleration[2] + G])


def _set_pose(msg_pose, position, quaternion):
    msg_pose.position.x, msg_pose.position.y, msg_pose.position.z = position
    (msg_pose.orientation.x, msg_pose.orientation.y, msg_pose.orientation.z,
     msg_pose.orientation.w) = quaternion


def _diagonal(variances):
    cov = [0.0] * 36
    for i, v in enumerate(variances):
        cov[7 * i] = v
    return cov


class Sensors:
    """The sensors' errors and the bag they write into."""

    def __init__(self, seed, profile, mount_rpy, vision_std, start_s):
        self.seed, self.p, self.vision_std = seed, profile, vision_std
        self.bag = simbag.BagBuilder(start_s)
        self.mount = rotation_rpy(*mount_rpy)
        dt = IMU_PERIOD_MS * 1e-3
        walks = simbag.rng("rigid_body", seed, "err", "bias")
        self.gyro_bias = [sensor_errors.RandomWalk(walks, profile.gyro_bias_rw, dt, profile.gyro_bias_init)
                          for _ in range(3)]
        self.accel_bias = [sensor_errors.RandomWalk(walks, profile.accel_bias_rw, dt, profile.accel_bias)
                           for _ in range(3)]
        self.bag.latch("tf_static")
        self.bag.add("tf_static", TFMessage(transforms=[transform(
            self.bag, 0, "base_link", "imu_link", (0.0, 0.0, 0.0), quaternion_rpy(*mount_rpy))]), 0)

    def rng(self, name):
        return simbag.rng("rigid_body", self.seed, name)

    def transport(self, topic, kind):
        return self.p.transport("rigid_body", self.seed, topic, kind)


def write_imu(s, motion, n_ms):
    rg, ra, tr = s.rng("gyro"), s.rng("accel"), s.transport("imu/data", "imu")
    ms = simbag.NS_PER_S // 1000
    for k in range(0, n_ms + 1, IMU_PERIOD_MS):
        _, _, acceleration, rpy, rpy_rate = pose(motion, k * 1e-3)
        rate = transpose_times(s.mount, body_rates(rpy, rpy_rate))
        force = transpose_times(s.mount, specific_force(rpy, acceleration))
        gb = [b.step() for b in s.gyro_bias]
        ab = [b.step() for b in s.accel_bias]
        msg = Imu()
        msg.header.seq = s.bag.next_seq("imu/data")
        msg.header.stamp = s.bag.stamp(k * ms)
        msg.header.frame_id = "imu_link"
        msg.orientation.w = 1.0
        msg.orientation_covariance[0] = -1.0  # no orientation (REP 145)
        g = [(1.0 + s.p.gyro_scale) * rate[i] + gb[i] + rg.gauss(0.0, GYRO_STD) for i in range(3)]
        a = [force[i] + ab[i] + ra.gauss(0.0, ACCEL_STD) for i in range(3)]
        msg.angular_velocity.x, msg.angular_velocity.y, msg.angular_velocity.z = g
        msg.linear_acceleration.x, msg.linear_acceleration.y, msg.linear_acceleration.z = a
        for i in range(3):
            msg.angular_velocity_covariance[4 * i] = GYRO_STD ** 2
            msg.linear_acceleration_covariance[4 * i] = ACCEL_STD ** 2
        sensor_errors.emit(s.bag, tr, "imu/data", msg, k * ms)


def write_odometry(s, motion, n_ms):
    """Body-frame twist with noise, and the pose integrated from it (first order in the world
    frame, the orientation by the exact rotation of each step's rate)."""
    ro, tr = s.rng("odom"), s.transport("odom", "wheel")
    ms = simbag.NS_PER_S // 1000
    dt = ODOM_PERIOD_MS * 1e-3
    position, _, _, rpy, _ = pose(motion, 0.0)
    rotation = rotation_rpy(*rpy)
    for k in range(0, n_ms + 1, ODOM_PERIOD_MS):
        _, velocity, _, rpy, rpy_rate = pose(motion, k * 1e-3)
        linear = [v + ro.gauss(0.0, ODOM_LINEAR_STD)
                  for v in transpose_times(rotation_rpy(*rpy), velocity)]
        angular = [w + ro.gauss(0.0, ODOM_ANGULAR_STD) for w in body_rates(rpy, rpy_rate)]
        msg = Odometry()
        msg.header.seq = s.bag.next_seq("odom")
        msg.header.stamp = s.bag.stamp(k * ms)
        msg.header.frame_id, msg.child_frame_id = "odom", "base_link"
        _set_pose(msg.pose.pose, position, _quaternion_of(rotation))
        msg.pose.covariance = _diagonal([1e-2] * 6)
        t = msg.twist.twist
        t.linear.x, t.linear.y, t.linear.z = linear
        t.angular.x, t.angular.y, t.angular.z = angular
        msg.twist.covariance = _diagonal([ODOM_LINEAR_STD ** 2] * 3 + [ODOM_ANGULAR_STD ** 2] * 3)
        for arrival in ([k * ms] if tr is None else tr.deliver(k * ms)):
            s.bag.add("odom", msg, arrival)
        world = [sum(rotation[r][c] * linear[c] for c in range(3)) for r in range(3)]
        position = [position[i] + world[i] * dt for i in range(3)]
        rotation = _times(rotation, _exp(angular, dt))


def write_vision(s, motion, n_ms):
    """The true pose with Gaussian noise: position, and rotation by a random rotation vector."""
    rv, tr = s.rng("vision"), s.transport("vision/pose", "wheel")
    ms = simbag.NS_PER_S // 1000
    std = s.vision_std
    for k in range(0, n_ms + 1, VISION_PERIOD_MS):
        position, _, _, rpy, _ = pose(motion, k * 1e-3)
        noisy = _times(rotation_rpy(*rpy), _exp([rv.gauss(0.0, std) for _ in range(3)], 1.0))
        msg = PoseWithCovarianceStamped()
        msg.header.seq = s.bag.next_seq("vision/pose")
        msg.header.stamp = s.bag.stamp(k * ms)
        msg.header.frame_id = "odom"
        _set_pose(msg.pose.pose, [p + rv.gauss(0.0, std) for p in position], _quaternion_of(noisy))
        msg.pose.covariance = _diagonal([std ** 2] * 6)
        sensor_errors.emit(s.bag, tr, "vision/pose", msg, k * ms)


def write_truth(s, motion, n_ms):
    ms = simbag.NS_PER_S // 1000
    for k in range(0, n_ms + 1, GT_PERIOD_MS):
        position, _, _, rpy, _ = pose(motion, k * 1e-3)
        msg = PoseStamped()
        msg.header.seq = s.bag.next_seq("ground_truth/pose")
        msg.header.stamp = s.bag.stamp(k * ms)
        msg.header.frame_id = "odom"
        _set_pose(msg.pose, position, quaternion_rpy(*rpy))
        s.bag.add("ground_truth/pose", msg, k * ms)


def _exp(omega, dt):
    """Rotation matrix of the rotation vector omega * dt (Rodrigues)."""
    v = [w * dt for w in omega]
    angle = math.sqrt(sum(x * x for x in v))
    k = [x / angle for x in v] if angle > 0 else [0.0, 0.0, 1.0]
    c, s_, t = math.cos(angle), math.sin(angle), 1 - math.cos(angle)
    return [[c + k[0] * k[0] * t, k[0] * k[1] * t - k[2] * s_, k[0] * k[2] * t + k[1] * s_],
            [k[1] * k[0] * t + k[2] * s_, c + k[1] * k[1] * t, k[1] * k[2] * t - k[0] * s_],
            [k[2] * k[0] * t - k[1] * s_, k[2] * k[1] * t + k[0] * s_, c + k[2] * k[2] * t]]


def _times(a, b):
    return [[sum(a[r][i] * b[i][c] for i in range(3)) for c in range(3)] for r in range(3)]


def _quaternion_of(m):
    """(x, y, z, w) of a rotation matrix (Shepperd's method, w >= 0 branch first)."""
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0:
        s = 2.0 * math.sqrt(1.0 + trace)
        return ((m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, 0.25 * s)
    i = max(range(3), key=lambda j: m[j][j])
    j, k = (i + 1) % 3, (i + 2) % 3
    s = 2.0 * math.sqrt(1.0 + m[i][i] - m[j][j] - m[k][k])
    q = [0.0] * 3
    q[i] = 0.25 * s
    q[j] = (m[j][i] + m[i][j]) / s
    q[k] = (m[k][i] + m[i][k]) / s
    return (q[0], q[1], q[2], (m[k][j] - m[j][k]) / s)


def build_bag(seed, duration, motion_kind, profile, mount_rpy, vision_std, start_s):
    s = Sensors(seed, profile, mount_rpy, vision_std, start_s)
    motion = Motion(motion_kind)
    n_ms = int(round(duration * 1000))
    write_imu(s, motion, n_ms)
    write_odometry(s, motion, n_ms)
    write_vision(s, motion, n_ms)
    write_truth(s, motion, n_ms)
    return s.bag


def parse_rpy(text):
    try:
        values = [float(v) for v in text.split(",")]
    except ValueError:
        values = []
    if len(values) != 3 or not all(math.isfinite(v) for v in values):
        raise argparse.ArgumentTypeError("expected ROLL,PITCH,YAW in radians, e.g. 0,0,1.5708")
    return values


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    parser.add_argument("--seed", type=int, required=True, help="seed of the noise")
    parser.add_argument("--duration", type=float, default=60.0, help="seconds (default 60)")
    parser.add_argument("--motion", choices=("slow", "fast"), default="slow")
    parser.add_argument("--imu-mount-rpy", type=parse_rpy, default=[0.0, 0.0, 0.0], metavar="R,P,Y",
                        help="the IMU's orientation on base_link [rad] (default level)")
    parser.add_argument("--vision-std", type=float, default=0.01,
                        help="vision noise: position [m] and rotation [rad] per axis (default 0.01)")
    parser.add_argument("--out", required=True, help="bag file to write")
    parser.add_argument("--start", type=int, default=simbag.DEFAULT_START_S,
                        help="simulated clock at the start, in seconds (default %(default)s)")
    parser.add_argument("--compression", choices=simbag.COMPRESSIONS, default="bz2")
    sensor_errors.add_arguments(parser, presets=PRESETS, skip=PLANAR_ONLY)
    args = parser.parse_args(argv)
    if not args.duration > 0 or not args.vision_std >= 0:
        parser.error("--duration must be positive and --vision-std >= 0")
    try:
        profile = sensor_errors.profile_from_args(args, presets=PRESETS)
    except Exception as exc:  # noqa: BLE001 - report bad option values as usage errors
        parser.error(str(exc))
    bag = build_bag(args.seed, args.duration, args.motion, profile, args.imu_mount_rpy,
                    args.vision_std, args.start)
    bag.write(args.out, args.compression)
    print("rigid_body seed=%d duration=%gs motion=%s errors: %s messages %s out=%s" % (
        args.seed, args.duration, args.motion, profile.summary(),
        " ".join("%s=%d" % kv for kv in sorted(bag.counts().items())), args.out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
