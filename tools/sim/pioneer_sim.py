#!/usr/bin/python3
"""Deterministic simulator of the Pioneer 3-AT dead-reckoning experiment (thesis ch. 5).

The robot is driven by a scripted teleoperator through cmd_vel and finally returns to
its marked starting position, as in thesis section 5.1. The simulator writes a bag with
the topics, message types, units and rates of thesis Table 5.2 plus the simulator's
true pose:

  topic                  type                            unit    rate    frame
  cmd_vel                geometry_msgs/Twist             m/s,rad/s 10 Hz  -
  velocity_wheel_left    std_msgs/Float32                mm/s    10 Hz   -
  velocity_wheel_right   std_msgs/Float32                mm/s    10 Hz   -
  acceleration           geometry_msgs/Vector3Stamped    m/s^2   100 Hz  kxtf9
  angular_velocity       geometry_msgs/Vector3Stamped    rad/s   100 Hz  imu3000
  ground_truth/pose      geometry_msgs/PoseStamped       m       100 Hz  odom
  ground_truth/twist     geometry_msgs/TwistStamped      m/s     100 Hz  base_link

See doc/bags.md for the models and their parameters.

  pioneer_sim.py --seed 1 --duration 90 --out bags/pioneer_seed1.bag

Realistic errors (wheel slip, radius and load, encoder ticks, gyro bias walk and scale,
accelerometer tilt and bias, latency, losses, duplicates; sensor_errors.py) are off by
default; --realistic husky switches on a calibrated set:

  pioneer_sim.py --seed 1 --duration 90 --realistic husky --out bags/pioneer_seed1.bag
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from geometry_msgs.msg import PoseStamped, Twist, TwistStamped, Vector3Stamped  # noqa: E402
from std_msgs.msg import Float32  # noqa: E402

import sensor_errors  # noqa: E402
import simbag  # noqa: E402

# ---------------------------------------------------------------- robot (thesis 5.1.2)
R_EFF = 0.3          # effective skid-steer radius [m]: omega = (vr - vl) / (2 R)
A_LIN = 0.3          # linear acceleration limit of the microcontroller [m/s^2]
A_ANG = 0.5          # angular acceleration limit [rad/s^2] (assumption, see doc/bags.md)
V_MAX = 0.7          # teleoperation bound on |cmd_vel.linear.x| [m/s]
W_MAX = 0.7          # teleoperation bound on |cmd_vel.angular.z| [rad/s]

STEP_MS = 1          # integration step of the true motion
TICK_MS = 100        # teleoperation period (cmd_vel at 10 Hz)
DT = STEP_MS * 1e-3
TICK_S = TICK_MS * 1e-3

# ---------------------------------------------------------------- sensors
G = 9.80665
ENC_PERIOD_MS, ENC_PHASE_MS = 100, 40    # rosaria publishes wheel speeds at 10 Hz
ENC_RES = 1.0                            # [mm/s]: ARIA reports wheel velocities as integer mm/s
ENC_VAR = 2.0                            # total variance [(mm/s)^2], thesis R = diag(..., 2, 2)
ENC_STD = math.sqrt(ENC_VAR - ENC_RES ** 2 / 12.0)   # white part; quantisation adds res^2/12
ACC_PERIOD_MS, ACC_PHASE_MS = 10, 3      # kxtf9 driver: 100 Hz (10 ms, thesis 5.2.2)
ACC_STD = 0.5                            # [m/s^2], thesis R: variance 0.25
ACC_RES = G / 1024.0                     # KXTF9 12-bit, +-2 g: 1024 counts/g
ACC_DRIFT_PER_MIN = (0.06, 0.12)         # |steady bias drift| of the y axis [m/s^2 per minute]
ACC_RW_PER_SQRT_MIN = 0.03               # bias random walk [m/s^2 per sqrt(minute)], all axes
GYR_PERIOD_MS, GYR_PHASE_MS = 10, 6      # imu3000 driver: 100 Hz
GYR_STD = math.sqrt(0.00017)             # [rad/s], thesis R: variance 0.00017
GYR_RES = math.radians(1.0 / 131.0)      # IMU-3000 16-bit, +-250 deg/s: 131 LSB/(deg/s)
GT_PERIOD_MS, GT_PHASE_MS = 10, 0        # ground truth at 100 Hz

LOOP_TOLERANCE = 0.03                    # [m] the final true pose must be this close to the start


def wrap(angle):
    return math.atan2(math.sin(angle), math.cos(angle))


def ceil_ticks(seconds):
    return max(1, int(math.ceil(seconds / TICK_S - 1e-9)))


def rate_limit(value, target, max_step):
    delta = target - value
    if delta > max_step:
        return value + max_step
    if delta < -max_step:
        return value - max_step
    return target


class Truth:
    """True planar motion at 1 kHz: (x, y, theta) driven by v, omega that follow the
    commanded velocities under acceleration limits (rate limiter)."""

    def __init__(self, lateral_slip=0.0, speed=0.0):
        self.state = (0.0, 0.0, 0.0, speed, 0.0)  # x, y, theta (unwrapped), v, omega
        self.log = [self.state]                 # state at t = k ms
        self.lateral_slip = lateral_slip        # K [s]: side velocity -K v omega (sensor_errors)

    @staticmethod
    def advance(state, v_cmd, w_cmd, steps, log=None, lateral_slip=0.0):
        x, y, th, v, w = state
        dv, dw = A_LIN * DT, A_ANG * DT
        for _ in range(steps):
            v1 = rate_limit(v, v_cmd, dv)
            w1 = rate_limit(w, w_cmd, dw)
            dth = 0.5 * (w + w1) * DT
            ds = 0.5 * (v + v1) * DT
            mid = th + 0.5 * dth
            x += ds * math.cos(mid)
            y += ds * math.sin(mid)
            if lateral_slip:
                # skid steer sliding outwards in a turn: side velocity -K v omega (body +y left)
                dl = -lateral_slip * 0.5 * (v * w + v1 * w1) * DT
                x -= dl * math.sin(mid)
                y += dl * math.cos(mid)
            th += dth
            v, w = v1, w1
            if log is not None:
                log.append((x, y, th, v, w))
        return (x, y, th, v, w)

    def run(self, v_cmd, w_cmd, steps):
        self.state = self.advance(self.state, v_cmd, w_cmd, steps, self.log, self.lateral_slip)


class Teleop:
    """Scripted operator: one cmd_vel per 100 ms tick, applied to the true robot."""

    def __init__(self, truth):
        self.truth = truth
        self.cmds = []

    def hold(self, v, w, ticks):
        v = max(-V_MAX, min(V_MAX, v))
        w = max(-W_MAX, min(W_MAX, w))
        for _ in range(ticks):
            self.cmds.append((v, w))
            self.truth.run(v, w, TICK_MS // STEP_MS)

    # -- rest-to-rest manoeuvres whose displacement is known exactly: a command held
    #    for D seconds under a symmetric rate limit moves by command * D.
    @staticmethod
    def stop_ticks(state, pause_s):
        v, w = abs(state[3]), abs(state[4])
        return ceil_ticks(max(v / A_LIN, w / A_ANG) + pause_s)

    @staticmethod
    def turn_plan(angle, w_nom=0.5):
        a = abs(angle)
        ticks = ceil_ticks(max(a / w_nom, math.sqrt(a / A_ANG)))
        return angle / (ticks * TICK_S), ticks

    @staticmethod
    def drive_plan(dist, v_nom=0.6):
        ticks = ceil_ticks(max(abs(dist) / v_nom, math.sqrt(abs(dist) / A_LIN)))
        return dist / (ticks * TICK_S), ticks

    def stop(self, pause_s=1.0):
        self.hold(0.0, 0.0, self.stop_ticks(self.truth.state, pause_s))

    def turn_by(self, angle):
        if abs(angle) > 1e-6:
            w, ticks = self.turn_plan(angle)
            self.hold(0.0, w, ticks)
        self.stop()

    def drive(self, dist):
        if abs(dist) > 1e-4:
            v, ticks = self.drive_plan(dist)
            self.hold(v, 0.0, ticks)
        self.stop()


def closing_ticks(state):
    """Ticks the return to the start takes from *state* (see Teleop.close_loop)."""
    ticks = Teleop.stop_ticks(state, 1.0)
    x, y, th = Truth.advance(state, 0.0, 0.0, ticks * TICK_MS // STEP_MS)[:3]
    d = math.hypot(x, y)
    heading_home = math.atan2(-y, -x) if d > 1e-4 else th
    turn1 = wrap(heading_home - th)
    turn2 = wrap(-heading_home)
    for angle in (turn1, turn2):
        w, n = Teleop.turn_plan(angle) if abs(angle) > 1e-6 else (0.0, 0)
        ticks += n + ceil_ticks(abs(w) / A_ANG + 1.0)
    v, n = Teleop.drive_plan(d) if d > 1e-4 else (0.0, 0)
    ticks += n + ceil_ticks(abs(v) / A_LIN + 1.0)
    return ticks + 2   # margin: the planned angles can differ by a hair from the flown ones


def close_loop(tele):
    """Return to the start pose: stop, turn towards the start, drive there, turn back to
    the initial heading. Each manoeuvre is planned from the true pose reached by the
    previous one (the operator looks at the robot and the floor marking)."""
    tele.stop()
    x, y, th = tele.truth.state[:3]
    if math.hypot(x, y) > 1e-4:
        tele.turn_by(wrap(math.atan2(-y, -x) - th))
        x, y, th = tele.truth.state[:3]
        tele.drive(math.hypot(x, y))
    tele.turn_by(wrap(-tele.truth.state[2]))


def random_segment(rng, state):
    """One teleoperation segment: list of (v, omega, ticks)."""
    x, y, th = state[:3]
    d_home = math.hypot(x, y)
    kind = rng.choices(("straight", "arc", "turn", "stop", "home"),
                       weights=(0.32, 0.30, 0.18, 0.10, 0.10 + 0.08 * max(0.0, d_home - 3.0)))[0]
    if kind == "straight":
        if rng.random() < 0.12:
            v = -rng.uniform(0.2, 0.35)           # short reverse
            return [(v, 0.0, ceil_ticks(rng.uniform(1.5, 3.0)))]
        return [(rng.uniform(0.3, V_MAX), 0.0, ceil_ticks(rng.uniform(2.0, 6.0)))]
    if kind == "arc":
        w = rng.choice((-1, 1)) * rng.uniform(0.2, W_MAX)
        return [(rng.uniform(0.2, 0.5), w, ceil_ticks(rng.uniform(2.0, 5.0)))]
    if kind == "turn":
        w = rng.choice((-1, 1)) * rng.uniform(0.3, W_MAX)
        return [(0.0, w, ceil_ticks(rng.uniform(1.5, 4.0)))]
    if kind == "stop":
        return [(0.0, 0.0, ceil_ticks(rng.uniform(1.0, 3.0)))]
    # "home": the operator steers roughly back towards the start, then drives on.
    err = wrap(math.atan2(-y, -x) - th) + rng.gauss(0.0, 0.3) if d_home > 0.5 else rng.uniform(-2, 2)
    w = math.copysign(rng.uniform(0.4, 0.6), err)
    return [(rng.uniform(0.0, 0.15), w, ceil_ticks(abs(err) / abs(w))),
            (rng.uniform(0.4, V_MAX), 0.0, ceil_ticks(rng.uniform(2.0, min(8.0, 1.0 + d_home))))]


def plan_run(seed, duration, robot="pioneer", lateral_slip=0.0):
    """Drive the true robot through a seeded teleoperation script of *duration* seconds.
    *robot* names the random stream, so other simulators reusing the script get their own
    paths. lateral_slip: see Truth (the planner's predictions ignore it; the loop closure
    is planned from the true pose and its manoeuvres, straights and turns in place, do
    not slip sideways)."""
    total_ticks = int(round(duration / TICK_S))
    rng = simbag.rng(robot, seed, "path")
    truth = Truth(lateral_slip)
    tele = Teleop(truth)
    tele.hold(0.0, 0.0, ceil_ticks(rng.uniform(2.0, 3.0)))   # standing at the start
    final_stop = 20                                          # >= 2 s at rest at the end
    failures = 0
    while failures < 8:
        segs = random_segment(rng, truth.state)
        if rng.random() < 0.35:
            segs.append((0.0, 0.0, ceil_ticks(rng.uniform(0.5, 2.5))))
        predicted = truth.state
        for v, w, n in segs:
            predicted = Truth.advance(predicted, v, w, n * TICK_MS // STEP_MS)
        needed = len(tele.cmds) + sum(n for _, _, n in segs) + closing_ticks(predicted) + final_stop
        if needed > total_ticks:
            failures += 1
            continue
        for v, w, n in segs:
            tele.hold(v, w, n)
    if len(tele.cmds) + closing_ticks(truth.state) + final_stop > total_ticks:
        raise SystemExit("duration %.1f s is too short for a run that returns to the start" % duration)
    close_loop(tele)
    if len(tele.cmds) > total_ticks:
        raise SystemExit("internal error: closing took longer than planned")
    tele.hold(0.0, 0.0, total_ticks - len(tele.cmds))
    return truth, tele


V_MOVING_MIN = 0.15   # [m/s] slowest forward speed of a run that never stops


def moving_segment(rng, state):
    """One segment of a run that never stops (plan_moving_run): random_segment's kinds
    without its stops and reversals (a reversal passes through rest), turns on the spot
    replaced by tight arcs at the slowest speed: list of (v, omega, ticks)."""
    x, y, th = state[:3]
    d_home = math.hypot(x, y)
    kind = rng.choices(("straight", "arc", "turn", "home"),
                       weights=(0.32, 0.30, 0.18, 0.10 + 0.08 * max(0.0, d_home - 3.0)))[0]
    if kind == "straight":
        return [(rng.uniform(0.3, V_MAX), 0.0, ceil_ticks(rng.uniform(2.0, 6.0)))]
    if kind == "arc":
        w = rng.choice((-1, 1)) * rng.uniform(0.2, W_MAX)
        return [(rng.uniform(0.2, 0.5), w, ceil_ticks(rng.uniform(2.0, 5.0)))]
    if kind == "turn":
        w = rng.choice((-1, 1)) * rng.uniform(0.3, W_MAX)
        return [(V_MOVING_MIN, w, ceil_ticks(rng.uniform(1.5, 4.0)))]
    err = wrap(math.atan2(-y, -x) - th) + rng.gauss(0.0, 0.3) if d_home > 0.5 else rng.uniform(-2, 2)
    w = math.copysign(rng.uniform(0.4, 0.6), err)
    return [(rng.uniform(V_MOVING_MIN, 0.3), w, ceil_ticks(abs(err) / abs(w))),
            (rng.uniform(0.4, V_MAX), 0.0, ceil_ticks(rng.uniform(2.0, min(8.0, 1.0 + d_home))))]


def plan_moving_run(seed, duration, robot="pioneer", lateral_slip=0.0):
    """Like plan_run, but the robot is never at rest: the recording starts while it drives
    (a cut from a longer drive) and ends while it drives, every command has v >= V_MOVING_MIN
    and the rate limiter moves v between such commands monotonically, so v never falls below
    it. The operator still steers back towards the start now and then; the loop is not
    closed (that would need stops). Its own random stream: not a prefix of plan_run's path."""
    total_ticks = int(round(duration / TICK_S))
    rng = simbag.rng(robot, seed, "moving-path")
    truth = Truth(lateral_slip, speed=rng.uniform(0.3, 0.5))
    tele = Teleop(truth)
    while len(tele.cmds) < total_ticks:
        for v, w, n in moving_segment(rng, truth.state):
            tele.hold(v, w, min(n, total_ticks - len(tele.cmds)))
    return truth, tele


def quaternion_z(yaw):
    return math.sin(0.5 * yaw), math.cos(0.5 * yaw)


def build_bag(seed, truth, tele, start_s, profile=None):
    bag = simbag.BagBuilder(start_s)
    states = truth.log
    n_ms = len(tele.cmds) * TICK_MS       # run length in ms; states has n_ms + 1 entries
    ms = simbag.NS_PER_S // 1000

    # cmd_vel: the operator's command at each tick (Twist has no header)
    for i, (v, w) in enumerate(tele.cmds):
        msg = Twist()
        msg.linear.x = v
        msg.angular.z = w
        bag.add("cmd_vel", msg, i * TICK_MS * ms)

    # wheel encoders, rosaria (thesis eqs. 5.17-5.18): integer mm/s, no counts at standstill
    rl, rr = simbag.rng("pioneer", seed, "wheel_left"), simbag.rng("pioneer", seed, "wheel_right")
    p = profile or sensor_errors.ErrorProfile()
    enc_steps = range(ENC_PHASE_MS, n_ms + 1, ENC_PERIOD_MS)
    wheels = None
    if p.wheels_active:   # slip, radius errors, ticks (sensor_errors); else the ideal wheels
        wheels = sensor_errors.wheel_speed_samples(simbag.rng("pioneer", seed, "err", "slip"), states,
                                                   DT, 2.0 * R_EFF, enc_steps, p)
    tr_l = p.transport("pioneer", seed, "velocity_wheel_left", "wheel")
    tr_r = p.transport("pioneer", seed, "velocity_wheel_right", "wheel")
    for k in enc_steps:
        _, _, _, v, w = states[k]
        if wheels is None:
            pairs = (((v - w * R_EFF) * 1000.0, None), ((v + w * R_EFF) * 1000.0, None))
        else:
            ml, mr, gl, gr = wheels[k]
            pairs = ((ml * 1000.0, gl), (mr * 1000.0, gr))
        for topic, (mm_s, ground), r, tr in zip(("velocity_wheel_left", "velocity_wheel_right"), pairs,
                                                (rl, rr), (tr_l, tr_r)):
            noise = r.gauss(0.0, ENC_STD)
            moving = abs(mm_s) > 1e-6 if ground is None else abs(ground) > 1e-9
            value = simbag.quantise(mm_s + noise, ENC_RES) if moving else 0.0
            sensor_errors.emit(bag, tr, topic, Float32(data=value), k * ms)

    # accelerometer KXTF9: sensor y = robot x, sensor x = -robot y, sensor z = up
    ra = simbag.rng("pioneer", seed, "accel")
    rb = simbag.rng("pioneer", seed, "accel_bias")
    drift = -rb.uniform(*ACC_DRIFT_PER_MIN) / 60.0           # [m/s^2 per s], decreasing (Fig. 5.15)
    rw_step = ACC_RW_PER_SQRT_MIN * math.sqrt(ACC_PERIOD_MS * 1e-3 / 60.0)
    bias = [0.0, 0.0, 0.0]                                   # zero after the start-up calibration
    bias_log = []
    extra = None          # sensor_errors: tilt leakage, constant bias and bias random walk
    if p.accel_active:    # in the robot frame (x forward, y left, z up)
        leak = sensor_errors.tilt_leakage(p.tilt_roll, p.tilt_pitch)
        rwa = simbag.rng("pioneer", seed, "err", "accel_bias")
        walks = [sensor_errors.RandomWalk(rwa, p.accel_bias_rw, ACC_PERIOD_MS * 1e-3) for _ in range(3)]
    tr_acc = p.transport("pioneer", seed, "acceleration", "imu")
    for k in range(ACC_PHASE_MS, n_ms, ACC_PERIOD_MS):
        _, _, _, v, w = states[k]
        v_next = states[k + 1][3]
        a_long = (v_next - v) / DT                           # true dv/dt during this ms
        a_lat = v * w                                        # centripetal, towards robot +y
        t = k * 1e-3
        bias[0] += rb.gauss(0.0, rw_step)
        bias[1] += rb.gauss(0.0, rw_step)
        bias[2] += rb.gauss(0.0, rw_step)
        by = drift * t + bias[1]
        bias_log.append(by)
        msg = Vector3Stamped()
        msg.header.seq = bag.next_seq("acceleration")
        msg.header.stamp = bag.stamp(k * ms)
        msg.header.frame_id = "kxtf9"
        if p.accel_active:
            extra = [leak[i] + p.accel_bias + walks[i].step() for i in range(3)]
            a_long += extra[0]
            a_lat += extra[1]
        msg.vector.x = simbag.quantise(-a_lat + bias[0] + ra.gauss(0.0, ACC_STD), ACC_RES)
        msg.vector.y = simbag.quantise(a_long + by + ra.gauss(0.0, ACC_STD), ACC_RES)
        if extra is None:
            msg.vector.z = simbag.quantise(G + bias[2] + ra.gauss(0.0, ACC_STD), ACC_RES)
        else:
            msg.vector.z = simbag.quantise(G + extra[2] + bias[2] + ra.gauss(0.0, ACC_STD), ACC_RES)
        sensor_errors.emit(bag, tr_acc, "acceleration", msg, k * ms)

    # gyroscope IMU-3000: z = yaw rate; no roll/pitch motion on a flat floor
    rg = simbag.rng("pioneer", seed, "gyro")
    gyro = None           # sensor_errors: bias (initial + random walk) and scale factor
    if p.gyro_active:
        gyro = sensor_errors.GyroErrors(simbag.rng("pioneer", seed, "err", "gyro"), p.gyro_bias_init,
                                        p.gyro_bias_rw, p.gyro_scale, GYR_PERIOD_MS * 1e-3)
    tr_gyr = p.transport("pioneer", seed, "angular_velocity", "imu")
    for k in range(GYR_PHASE_MS, n_ms + 1, GYR_PERIOD_MS):
        w = states[k][4]
        if gyro is not None:
            w = gyro.measure(w)
        msg = Vector3Stamped()
        msg.header.seq = bag.next_seq("angular_velocity")
        msg.header.stamp = bag.stamp(k * ms)
        msg.header.frame_id = "imu3000"
        msg.vector.x = simbag.quantise(rg.gauss(0.0, GYR_STD), GYR_RES)
        msg.vector.y = simbag.quantise(rg.gauss(0.0, GYR_STD), GYR_RES)
        msg.vector.z = simbag.quantise(w + rg.gauss(0.0, GYR_STD), GYR_RES)
        sensor_errors.emit(bag, tr_gyr, "angular_velocity", msg, k * ms)

    # ground truth: the simulator's true pose and velocity
    for k in range(GT_PHASE_MS, n_ms + 1, GT_PERIOD_MS):
        x, y, th, v, w = states[k]
        pose = PoseStamped()
        pose.header.seq = bag.next_seq("ground_truth/pose")
        pose.header.stamp = bag.stamp(k * ms)
        pose.header.frame_id = "odom"
        pose.pose.position.x = x
        pose.pose.position.y = y
        pose.pose.orientation.z, pose.pose.orientation.w = quaternion_z(th)
        bag.add("ground_truth/pose", pose, k * ms)
        twist = TwistStamped()
        twist.header.seq = bag.next_seq("ground_truth/twist")
        twist.header.stamp = pose.header.stamp
        twist.header.frame_id = "base_link"
        twist.twist.linear.x = v
        if truth.lateral_slip:
            twist.twist.linear.y = -truth.lateral_slip * v * w
        twist.twist.angular.z = w
        bag.add("ground_truth/twist", twist, k * ms)
    return bag, drift, bias_log


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seed", type=int, required=True, help="seed of path and noise")
    parser.add_argument("--duration", type=float, default=120.0,
                        help="run length in seconds (default 120; at least about 40)")
    parser.add_argument("--out", required=True, help="bag file to write")
    parser.add_argument("--start", type=int, default=simbag.DEFAULT_START_S,
                        help="simulated clock at the start, in seconds (default %(default)s)")
    parser.add_argument("--compression", choices=simbag.COMPRESSIONS, default="bz2")
    sensor_errors.add_arguments(parser, skip=("odom_separation_scale",))
    args = parser.parse_args(argv)
    if args.duration <= 0 or abs(args.duration * 10 - round(args.duration * 10)) > 1e-9:
        parser.error("--duration must be positive and a multiple of 0.1 s")
    try:
        profile = sensor_errors.profile_from_args(args)
    except Exception as exc:  # noqa: BLE001 - report bad option values as usage errors
        parser.error(str(exc))

    truth, tele = plan_run(args.seed, args.duration, lateral_slip=profile.lateral_slip)
    x, y, th = truth.state[:3]
    err = math.hypot(x, y)
    if err > LOOP_TOLERANCE or abs(truth.state[3]) > 1e-9 or abs(truth.state[4]) > 1e-9:
        raise SystemExit("loop not closed: final true pose (%.4f, %.4f) m" % (x, y))
    bag, drift, bias_log = build_bag(args.seed, truth, tele, args.start, profile)
    bag.write(args.out, args.compression)
    if profile.active:
        print("pioneer errors: %s" % profile.summary())

    path_len = sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(truth.log, truth.log[1:]))
    turned = sum(abs(b[2] - a[2]) for a, b in zip(truth.log, truth.log[1:]))
    far = max(math.hypot(s[0], s[1]) for s in truth.log)
    print("pioneer seed=%d duration=%.1fs path=%.2fm turned=%.1frad max_dist_from_start=%.2fm "
          "final_pose_error=%.1em final_heading_error=%.1erad accel_y_bias_end=%.3fm/s^2 out=%s"
          % (args.seed, len(tele.cmds) * TICK_S, path_len, turned, far, err,
             wrap(th), bias_log[-1], args.out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
