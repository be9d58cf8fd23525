#!/usr/bin/python3
"""Deterministic simulator of a generic differential-drive robot with wheel odometry and an
IMU on their usual ROS topics, for config/diff_drive_odom_imu.h (doc/generic_robot.md).

The robot is driven through the seeded teleoperation script of pioneer_sim.py (its own
path per seed, stops, curves, back to the start) and records what a typical robot's
`rosbag record /odom /imu/data /tf /tf_static` would hold, plus its true pose:

  topic              type                       rate    frame                  content
  odom               nav_msgs/Odometry          50 Hz   odom -> base_link      wheel odometry: twist
                                                                              from the wheel speeds,
                                                                              pose integrated from it
  imu/data           sensor_msgs/Imu            100 Hz  imu_link               gyro with a constant
                                                                              bias, accelerometer;
                                                                              no orientation
  tf                 tf2_msgs/TFMessage         50 Hz   odom -> base_link      the wheel odometry's
  tf_static          tf2_msgs/TFMessage         once    base_link -> imu_link  the IMU's mount (latched)
  ground_truth/pose  geometry_msgs/PoseStamped  50 Hz   odom                   the true pose
  fix (--gps only)   sensor_msgs/NavSatFix      2.5 Hz  base_link              the true position
                                                                              in ENU with a slow
                                                                              and a white error

The IMU is mounted on its side (roll 90 deg, yaw 90 deg: its y axis is the robot's z axis),
so the yaw rate appears on angular_velocity.y: only the rotation by tf2 gives the filter a
yaw rate. The gyro's bias is constant and given in the IMU's frame (--gyro-bias); the bias
of the base-frame yaw rate is its component along the robot's z axis, printed at the end.

  diff_drive_sim.py --seed 1 --duration 60 --out bags/diff_drive_seed1.bag

--imu-mount level mounts the IMU with base_link's axes (the yaw rate on angular_velocity.z, as
on the real Husky recording that config/husky_skid_steer_odom_imu.h reads); --no-stops drives
a path that is never at rest (it starts and ends in motion and does not return to the start).

--gps adds a GPS receiver (gps_sim.py: the odom frame's x axis at --gps-heading in ENU, a
Gauss-Markov error of --gps-sigma and --gps-tau plus --gps-white per axis, the declared
--gps-declared; defaults as measured on the real Husky recording's fixes), from its own
random stream: without --gps the bag is byte for byte what it was.

Realistic errors (sensor_errors.py; also --odom-separation-scale, a driver with a wrong wheel
separation) are off by default; --realistic husky switches on a calibrated set.
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from geometry_msgs.msg import PoseStamped, TransformStamped  # noqa: E402
from nav_msgs.msg import Odometry  # noqa: E402
from sensor_msgs.msg import Imu  # noqa: E402
from tf2_msgs.msg import TFMessage  # noqa: E402

import gps_sim  # noqa: E402  (--gps)
import pioneer_sim  # noqa: E402  (teleoperation script and true motion)
import sensor_errors  # noqa: E402
import simbag  # noqa: E402

G = 9.80665
TRACK = 0.5                                 # wheel separation [m]
WHEEL_STD = math.sqrt(5e-5)                 # wheel speed noise per odometry message [m/s]:
#                                             v std 0.005 m/s, yaw rate std 0.02 rad/s
ODOM_PERIOD_MS, ODOM_PHASE_MS = 20, 10      # diff_drive_controller's default 50 Hz
IMU_PERIOD_MS, IMU_PHASE_MS = 10, 3         # 100 Hz
GYRO_STD = 0.005                            # [rad/s] per sample, each axis
GYRO_RES = math.radians(1.0 / 131.0)        # 16-bit, +-250 deg/s
ACCEL_STD = 0.05                            # [m/s^2]
ACCEL_RES = G / 16384.0                     # 16-bit, +-2 g
GT_PERIOD_MS = 20                           # ground truth at 50 Hz (phase 0)
GPS_PHASE_MS = 5                            # --gps: the first fix 5 ms after the start
MOUNT_XYZ = (0.12, 0.0, 0.18)               # IMU position on base_link [m]
MOUNT_RPY = (math.pi / 2, 0.0, math.pi / 2)  # IMU orientation on base_link (tf2 RPY)
MOUNTS = {"side": MOUNT_RPY,                # --imu-mount: the default, yaw rate on y
          "level": (0.0, 0.0, 0.0)}         # z up, as the real Husky's (doc/real_robot.md)
DEFAULT_GYRO_BIAS = (0.004, 0.012, -0.006)  # [rad/s] in the IMU's frame


def rotation_rpy(roll, pitch, yaw):
    """Rotation matrix Rz(yaw) Ry(pitch) Rx(roll) (tf2's setRPY), rows of a 3x3 list."""
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch),
                              math.cos(yaw), math.sin(yaw))
    return [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr]]


def quaternion_rpy(roll, pitch, yaw):
    """(x, y, z, w) of the same rotation."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy, cr * cp * cy + sr * sp * sy)


def transpose_times(m, v):
    """m^T v: a base_link vector in the IMU's frame when m rotates IMU vectors into base_link."""
    return [sum(m[r][c] * v[r] for r in range(3)) for c in range(3)]


def base_z_bias(gyro_bias, mount_rpy=MOUNT_RPY):
    """Bias of the base-frame yaw rate: the z row of the mount rotation times the IMU-frame
    bias."""
    m = rotation_rpy(*mount_rpy)
    return sum(m[2][c] * gyro_bias[c] for c in range(3))


def transform(bag, t_ns, parent, child, xyz, quat):
    t = TransformStamped()
    t.header.stamp = bag.stamp(t_ns)
    t.header.frame_id = parent
    t.child_frame_id = child
    t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = xyz
    (t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z,
     t.transform.rotation.w) = quat
    return t


def build_bag(seed, truth, tele, gyro_bias, start_s, profile=None, mount_rpy=MOUNT_RPY, gps=None):
    bag = simbag.BagBuilder(start_s)
    states = truth.log
    n_ms = len(tele.cmds) * pioneer_sim.TICK_MS
    ms = simbag.NS_PER_S // 1000

    # the IMU's mount, once at the start, latched
    bag.latch("tf_static")
    bag.add("tf_static", TFMessage(transforms=[
        transform(bag, 0, "base_link", "imu_link", MOUNT_XYZ, quaternion_rpy(*mount_rpy))]), 0)

    # wheel odometry (diff_drive_controller): twist from the wheel speeds of this message,
    # pose integrated from the twist (midpoint heading); its tf odom -> base_link
    rw = simbag.rng("diff_drive", seed, "wheels")
    p = profile or sensor_errors.ErrorProfile()
    odom_steps = range(ODOM_PHASE_MS, n_ms + 1, ODOM_PERIOD_MS)
    measured = None
    if p.wheels_active:   # slip, radius errors, ticks (sensor_errors); else the ideal wheels
        measured = sensor_errors.wheel_speed_samples(simbag.rng("diff_drive", seed, "err", "slip"), states,
                                                     pioneer_sim.DT, TRACK, odom_steps, p)
    tr_odom = p.transport("diff_drive", seed, "odom", "wheel")
    ox = oy = oth = 0.0
    last_ms = None
    odom_heading_end = 0.0
    for k in odom_steps:
        _, _, _, v, w = states[k]
        wheels = []
        if measured is None:
            pairs = ((v - 0.5 * TRACK * w, v - 0.5 * TRACK * w), (v + 0.5 * TRACK * w, v + 0.5 * TRACK * w))
        else:
            ml, mr, gl, gr = measured[k]
            pairs = ((ml, gl), (mr, gr))
        for speed, ground in pairs:
            noise = rw.gauss(0.0, WHEEL_STD)
            wheels.append(speed + noise if abs(ground) > 1e-6 else 0.0)
        if p.odom_separation_scale != 1.0:   # miscalibrated driver (sensor_errors.driver_twist)
            vm, wm = sensor_errors.driver_twist(wheels[0], wheels[1], TRACK, p.odom_separation_scale)
        else:
            vm, wm = 0.5 * (wheels[0] + wheels[1]), (wheels[1] - wheels[0]) / TRACK
        dt = (k - last_ms) * 1e-3 if last_ms is not None else 0.0
        last_ms = k
        mid = oth + 0.5 * wm * dt
        ox += vm * dt * math.cos(mid)
        oy += vm * dt * math.sin(mid)
        oth += wm * dt
        odom_heading_end = oth
        msg = Odometry()
        msg.header.seq = bag.next_seq("odom")
        msg.header.stamp = bag.stamp(k * ms)
        msg.header.frame_id = "odom"
        msg.child_frame_id = "base_link"
        msg.pose.pose.position.x, msg.pose.pose.position.y = ox, oy
        q = pioneer_sim.quaternion_z(oth)
        msg.pose.pose.orientation.z, msg.pose.pose.orientation.w = q
        msg.pose.covariance = [0.0] * 36
        for i, var in enumerate((1e-3, 1e-3, 1e6, 1e6, 1e6, 1e-2)):
            msg.pose.covariance[7 * i] = var
        msg.twist.twist.linear.x, msg.twist.twist.angular.z = vm, wm
        msg.twist.covariance = [0.0] * 36
        for i, var in enumerate((WHEEL_STD ** 2 / 2, 1e6, 1e6, 1e6, 1e6,
                                 2 * WHEEL_STD ** 2 / TRACK ** 2)):
            msg.twist.covariance[7 * i] = var
        tf = TFMessage(transforms=[transform(bag, k * ms, "odom", "base_link", (ox, oy, 0.0), (0.0, 0.0) + q)])
        # the driver publishes odom and its tf together: both arrive (or are lost) together
        for arrival in ([k * ms] if tr_odom is None else tr_odom.deliver(k * ms)):
            bag.add("odom", msg, arrival)
            bag.add("tf", tf, arrival)

    # IMU in imu_link: base-frame rates and accelerations rotated into the sensor's frame
    mount = rotation_rpy(*mount_rpy)
    rg = simbag.rng("diff_drive", seed, "gyro")
    ra = simbag.rng("diff_drive", seed, "accel")
    gyro = None           # sensor_errors: bias walk and scale factor of the yaw axis
    if p.gyro_active:
        gyro = sensor_errors.GyroErrors(simbag.rng("diff_drive", seed, "err", "gyro"), p.gyro_bias_init,
                                        p.gyro_bias_rw, p.gyro_scale, IMU_PERIOD_MS * 1e-3)
    if p.accel_active:    # tilt leakage, constant bias, bias random walk (base frame)
        leak = sensor_errors.tilt_leakage(p.tilt_roll, p.tilt_pitch)
        rwa = simbag.rng("diff_drive", seed, "err", "accel_bias")
        walks = [sensor_errors.RandomWalk(rwa, p.accel_bias_rw, IMU_PERIOD_MS * 1e-3) for _ in range(3)]
    tr_imu = p.transport("diff_drive", seed, "imu/data", "imu")
    for k in range(IMU_PHASE_MS, n_ms, IMU_PERIOD_MS):
        _, _, _, v, w = states[k]
        a_long = (states[k + 1][3] - v) / pioneer_sim.DT
        base_accel = (a_long, v * w, G)
        if gyro is not None:
            w = gyro.measure(w)
        if p.accel_active:
            base_accel = tuple(base_accel[i] + leak[i] + p.accel_bias + walks[i].step() for i in range(3))
        rate = transpose_times(mount, (0.0, 0.0, w))
        accel = transpose_times(mount, base_accel)
        msg = Imu()
        msg.header.seq = bag.next_seq("imu/data")
        msg.header.stamp = bag.stamp(k * ms)
        msg.header.frame_id = "imu_link"
        msg.orientation.w = 1.0
        msg.orientation_covariance[0] = -1.0      # no orientation (REP 145)
        g = [simbag.quantise(rate[i] + gyro_bias[i] + rg.gauss(0.0, GYRO_STD), GYRO_RES)
             for i in range(3)]
        a = [simbag.quantise(accel[i] + ra.gauss(0.0, ACCEL_STD), ACCEL_RES) for i in range(3)]
        msg.angular_velocity.x, msg.angular_velocity.y, msg.angular_velocity.z = g
        msg.linear_acceleration.x, msg.linear_acceleration.y, msg.linear_acceleration.z = a
        for i in range(3):
            msg.angular_velocity_covariance[4 * i] = GYRO_STD ** 2
            msg.linear_acceleration_covariance[4 * i] = ACCEL_STD ** 2
        sensor_errors.emit(bag, tr_imu, "imu/data", msg, k * ms)

    for k in range(0, n_ms + 1, GT_PERIOD_MS):
        x, y, th, _, _ = states[k]
        pose = PoseStamped()
        pose.header.seq = bag.next_seq("ground_truth/pose")
        pose.header.stamp = bag.stamp(k * ms)
        pose.header.frame_id = "odom"
        pose.pose.position.x, pose.pose.position.y = x, y
        pose.pose.orientation.z, pose.pose.orientation.w = pioneer_sim.quaternion_z(th)
        bag.add("ground_truth/pose", pose, k * ms)
    if gps is not None:   # gps_sim.py: the fixes from their own stream
        for k, _, _, _, lat, lon, alt in gps_sim.fixes(gps, simbag.rng("diff_drive", seed, "gps"),
                                                       states, n_ms, GPS_PHASE_MS):
            msg = gps_sim.fix_message(gps, bag.next_seq("fix"), bag.stamp(k * ms), lat, lon, alt)
            bag.add("fix", msg, k * ms)
    return bag, (ox, oy, odom_heading_end)


def parse_vector(text):
    try:
        values = [float(v) for v in text.split(",")]
    except ValueError:
        values = []
    if len(values) != 3:
        raise argparse.ArgumentTypeError("expected X,Y,Z, e.g. 0.004,0.012,-0.006")
    return values


def add_gps_arguments(parser):
    g = parser.add_argument_group("GPS (tools/sim/gps_sim.py; off by default)")
    g.add_argument("--gps", action="store_true",
                   help="record sensor_msgs/NavSatFix on fix (APPROXIMATED covariance)")
    g.add_argument("--gps-rate", type=float, default=gps_sim.DEFAULT_RATE_HZ, help="[Hz]")
    g.add_argument("--gps-heading", type=float, default=gps_sim.DEFAULT_HEADING_DEG,
                   help="heading of the odom x axis in ENU [deg, counter-clockwise from east]")
    g.add_argument("--gps-sigma", type=float, default=gps_sim.DEFAULT_SIGMA,
                   help="standard deviation of the slow (Gauss-Markov) error per axis [m]")
    g.add_argument("--gps-tau", type=float, default=gps_sim.DEFAULT_TAU,
                   help="time constant of the slow error [s]")
    g.add_argument("--gps-white", type=float, default=gps_sim.DEFAULT_WHITE,
                   help="standard deviation of the white error per axis [m]")
    g.add_argument("--gps-declared", type=float, default=gps_sim.DEFAULT_DECLARED,
                   help="the standard deviation the fix declares per horizontal axis [m]")


def gps_model(args):
    """The gps_sim.GpsModel of the options, None without --gps."""
    if not args.gps:
        return None
    return gps_sim.GpsModel(heading_deg=args.gps_heading, rate_hz=args.gps_rate,
                            sigma=args.gps_sigma, tau=args.gps_tau, white=args.gps_white,
                            declared=args.gps_declared)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seed", type=int, required=True, help="seed of path and noise")
    parser.add_argument("--duration", type=float, default=60.0,
                        help="run length in seconds, a multiple of 0.1 (default 60; at least about 40)")
    parser.add_argument("--gyro-bias", type=parse_vector, default=list(DEFAULT_GYRO_BIAS),
                        metavar="X,Y,Z", help="constant gyro bias in the IMU's frame [rad/s] "
                        "(default %s)" % ",".join(str(v) for v in DEFAULT_GYRO_BIAS))
    parser.add_argument("--out", required=True, help="bag file to write")
    parser.add_argument("--start", type=int, default=simbag.DEFAULT_START_S,
                        help="simulated clock at the start, in seconds (default %(default)s)")
    parser.add_argument("--compression", choices=simbag.COMPRESSIONS, default="bz2")
    parser.add_argument("--no-stops", action="store_true",
                        help="a path that is never at rest: starts and ends driving, forward only, "
                        "no stops, no return to the start (pioneer_sim.plan_moving_run)")
    parser.add_argument("--imu-mount", choices=sorted(MOUNTS), default="side",
                        help="side: roll and yaw 90 deg, the yaw rate on angular_velocity.y "
                        "(default); level: the IMU's axes are base_link's, the yaw rate on z")
    add_gps_arguments(parser)
    sensor_errors.add_arguments(parser)
    args = parser.parse_args(argv)
    if args.duration <= 0 or abs(args.duration * 10 - round(args.duration * 10)) > 1e-9:
        parser.error("--duration must be positive and a multiple of 0.1 s")
    try:
        profile = sensor_errors.profile_from_args(args)
        gps = gps_model(args)
    except Exception as exc:  # noqa: BLE001 - report bad option values as usage errors
        parser.error(str(exc))

    plan = pioneer_sim.plan_moving_run if args.no_stops else pioneer_sim.plan_run
    truth, tele = plan(args.seed, args.duration, robot="diff_drive", lateral_slip=profile.lateral_slip)
    x, y, th = truth.state[:3]
    if not args.no_stops and math.hypot(x, y) > pioneer_sim.LOOP_TOLERANCE:
        raise SystemExit("loop not closed: final true pose (%.4f, %.4f) m" % (x, y))
    mount_rpy = MOUNTS[args.imu_mount]
    bag, odom_end = build_bag(args.seed, truth, tele, args.gyro_bias, args.start, profile, mount_rpy, gps)
    bag.write(args.out, args.compression)
    if profile.active:
        print("diff_drive errors: %s" % profile.summary())
    path_len = sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(truth.log, truth.log[1:]))
    print("diff_drive seed=%d duration=%.1fs path=%.2fm gyro_bias_imu=(%g, %g, %g)rad/s "
          "gyro_bias_base_z=%.6frad/s wheel_odometry_final_error=%.3fm,%.2fdeg out=%s"
          % (args.seed, len(tele.cmds) * pioneer_sim.TICK_S, path_len, *args.gyro_bias,
             base_z_bias(args.gyro_bias, mount_rpy), math.hypot(odom_end[0] - x, odom_end[1] - y),
             math.degrees(pioneer_sim.wrap(odom_end[2] - th)), args.out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
