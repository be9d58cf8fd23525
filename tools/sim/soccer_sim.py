#!/usr/bin/python3
"""Deterministic simulator of Wang et al.'s dual-frequency soccer-robot localisation.

The robot (Tech United middle-size league) moves on a smooth figure-eight on the field.
Two independent position axes x and y are measured by

  topic              type                         rate     frame  model
  vision/pose        geometry_msgs/PointStamped   32 Hz    field  true position + white noise (std 0.0112 m)
  encoder/pose       geometry_msgs/PointStamped   1000 Hz  field  true position + bias drift (paper eqs. 1, 3-4)
  ground_truth/pose  geometry_msgs/PoseStamped    100 Hz   field  the simulator's true position

Only point.x and point.y carry data (z = 0). See doc/bags.md for the models.

  soccer_sim.py --seed 1 --duration 60 --out bags/soccer_seed1.bag
  soccer_sim.py --seed 1 --duration 70 --drop 30:80 --drop 63.5:45 --out bags/soccer_lost_vision.bag

Realistic vision transport (jitter, random losses, duplicates) and encoder ticks are off by
default; --realistic wang switches them on (sensor_errors.py, doc/bags.md).
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from geometry_msgs.msg import PointStamped, PoseStamped  # noqa: E402

import sensor_errors  # noqa: E402
import simbag  # noqa: E402

VISION_PERIOD_NS = simbag.NS_PER_S // 32      # 31.25 ms, exact
ENCODER_PERIOD_NS = simbag.NS_PER_S // 1000   # 1 ms
GT_PERIOD_NS = simbag.NS_PER_S // 100         # 10 ms
DT = 1e-3                                     # encoder period [s]

VISION_STD = 0.0112          # [m] paper section VI: white noise of the vision measurement
BIAS_T = 100.0               # [s] time constant T of the bias low-pass, eq. (3); paper: T = 100
# rate model, eq. (1): d(encoder)/dt = dx/dt + b + w
RATE_BIAS_STD = 0.006        # [m/s] stationary std of b; gives an RMS position drift of about
                             # 0.2 m over a 60 s run (paper section V: sigma_b around 0.2 m)
RATE_WHITE_STD = 0.04        # [m/s] std of the white rate noise w per 1 ms sample
# position model (--bias-model position): encoder = x + b
POS_BIAS_STD = 0.2           # [m] stationary std of b (paper section V: sigma_b around 0.2 m)


class Trajectory:
    """Smooth figure-eight: x = cx + Ax sin(wt + p) + Bx sin(3wt + q), y = cy + Ay sin(2wt + 2p)."""

    def __init__(self, seed):
        r = simbag.rng("soccer", seed, "trajectory")
        period = r.uniform(24.0, 32.0)
        self.w = 2.0 * math.pi / period
        self.ax, self.ay, self.bx = r.uniform(3.0, 4.0), r.uniform(1.5, 2.2), r.uniform(0.2, 0.5)
        self.cx, self.cy = r.uniform(-2.0, 2.0), r.uniform(-1.0, 1.0)
        self.p, self.q = r.uniform(0.0, 2.0 * math.pi), r.uniform(0.0, 2.0 * math.pi)

    def position(self, t):
        w = self.w
        return (self.cx + self.ax * math.sin(w * t + self.p) + self.bx * math.sin(3 * w * t + self.q),
                self.cy + self.ay * math.sin(2 * w * t + 2 * self.p))

    def velocity(self, t):
        w = self.w
        return (self.ax * w * math.cos(w * t + self.p) + 3 * w * self.bx * math.cos(3 * w * t + self.q),
                2 * w * self.ay * math.cos(2 * w * t + 2 * self.p))


class EncoderError:
    """Encoder position error of one axis, sampled every DT, from the paper's bias model.

    The bias b follows eq. (4), db/dt = -b/T + nu/T, discretised exactly for a driving
    noise nu held over each sample: b[j+1] = a b[j] + (1 - a) nu[j], a = exp(-DT/T), so
    that b is white noise through the low pass 1/(1 + Ts) of eq. (3).

    rate model (eq. 1, default): the encoder's rate is the true rate plus b plus white
    noise w, so the position error e integrates them: e[j+1] = e[j] + (b[j] + w[j]) DT,
    e[0] = 0 (encoder initialised at the true position); b[0] is drawn from b's
    stationary distribution (the bias was there before the recording).
    position model: the error is b itself, with b[0] = 0.
    """

    def __init__(self, seed, axis, model):
        self.r = simbag.rng("soccer", seed, "encoder", axis)
        self.model = model
        self.a = math.exp(-DT / BIAS_T)
        stationary = RATE_BIAS_STD if model == "rate" else POS_BIAS_STD
        # var(b) = var(nu) (1 - a)^2 / (1 - a^2) = var(nu) (1 - a) / (1 + a)
        self.nu_std = stationary / math.sqrt((1.0 - self.a) / (1.0 + self.a))
        self.b = self.r.gauss(0.0, stationary) if model == "rate" else 0.0
        self.e = 0.0

    def step(self):
        """Error at the current sample, then advance one sample."""
        e = self.e if self.model == "rate" else self.b
        if self.model == "rate":
            self.e += (self.b + self.r.gauss(0.0, RATE_WHITE_STD)) * DT
        self.b = self.a * self.b + (1.0 - self.a) * self.r.gauss(0.0, self.nu_std)
        return e


# Calibrated sets of the realistic options (doc/bags.md, "Realistic error options"):
# vision frames delayed and jittered, now and then lost or duplicated; encoder positions
# counted in ticks.
PRESETS = {
    "wang": dict(vision_delay_ms=31.25, vision_jitter_ms=3.0, vision_drop_prob=0.02, vision_dup_prob=0.002,
                 encoder_step=0.0001),
}
REALISTIC_DEFAULTS = dict(vision_delay_ms=0.0, vision_jitter_ms=0.0, vision_drop_prob=0.0, vision_dup_prob=0.0,
                          encoder_step=0.0)


def parse_drop(text):
    try:
        start, count = text.split(":")
        start, count = float(start), int(count)
    except ValueError:
        raise argparse.ArgumentTypeError("expected START_S:FRAMES, e.g. 63.5:45")
    if start < 0 or count < 1:
        raise argparse.ArgumentTypeError("START_S must be >= 0 and FRAMES >= 1")
    return start, count


def point(bag, topic, t_ns, x, y):
    msg = PointStamped()
    msg.header.seq = bag.next_seq(topic)
    msg.header.stamp = bag.stamp(t_ns)
    msg.header.frame_id = "field"
    msg.point.x, msg.point.y = x, y
    return msg


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seed", type=int, required=True, help="seed of trajectory and noise")
    parser.add_argument("--duration", type=float, default=60.0, help="run length in seconds (default 60)")
    parser.add_argument("--out", required=True, help="bag file to write")
    parser.add_argument("--drop", type=parse_drop, action="append", default=[], metavar="START_S:FRAMES",
                        help="lose FRAMES consecutive vision frames from the first at or after START_S "
                             "(repeatable)")
    parser.add_argument("--bias-model", choices=("rate", "position"), default="rate",
                        help="rate: eq. (1), the bias drives the encoder's rate (default); "
                             "position: encoder = true position + bias")
    parser.add_argument("--vision-delay-ms", type=float, default=None,
                        help="transport delay of vision frames: bag time = header stamp + delay (default 0)")
    parser.add_argument("--realistic", choices=sorted(PRESETS), default=None,
                        help="switch on a set of realistic errors (doc/bags.md); single options override it")
    parser.add_argument("--vision-jitter-ms", type=float, default=None,
                        help="mean of the exponential jitter added to the vision delay (default 0)")
    parser.add_argument("--vision-drop-prob", type=float, default=None,
                        help="probability that a vision frame is lost in transport (default 0)")
    parser.add_argument("--vision-dup-prob", type=float, default=None,
                        help="probability that a vision frame is recorded twice (default 0)")
    parser.add_argument("--encoder-step", type=float, default=None,
                        help="encoder position quantum per axis [m] (default 0: not quantised)")
    parser.add_argument("--start", type=int, default=simbag.DEFAULT_START_S,
                        help="simulated clock at the start, in seconds (default %(default)s)")
    parser.add_argument("--compression", choices=simbag.COMPRESSIONS, default="bz2")
    args = parser.parse_args(argv)
    if args.duration <= 0:
        parser.error("--duration must be positive")
    real = dict(REALISTIC_DEFAULTS)
    if args.realistic:
        real.update(PRESETS[args.realistic])
    for name in REALISTIC_DEFAULTS:
        if getattr(args, name) is not None:
            real[name] = getattr(args, name)
    if not (0.0 <= real["vision_drop_prob"] < 1.0 and 0.0 <= real["vision_dup_prob"] <= 1.0):
        parser.error("--vision-drop-prob and --vision-dup-prob must be probabilities")
    if min(real["vision_delay_ms"], real["vision_jitter_ms"], real["encoder_step"]) < 0:
        parser.error("delays, jitter and --encoder-step must be >= 0")

    end_ns = int(round(args.duration * simbag.NS_PER_S))
    traj = Trajectory(args.seed)
    bag = simbag.BagBuilder(args.start)

    # ground truth
    speeds = []
    for t_ns in range(0, end_ns + 1, GT_PERIOD_NS):
        t = t_ns * 1e-9
        x, y = traj.position(t)
        msg = PoseStamped()
        msg.header.seq = bag.next_seq("ground_truth/pose")
        msg.header.stamp = bag.stamp(t_ns)
        msg.header.frame_id = "field"
        msg.pose.position.x, msg.pose.position.y = x, y
        msg.pose.orientation.w = 1.0        # orientation is not modelled
        bag.add("ground_truth/pose", msg, t_ns)
        speeds.append(math.hypot(*traj.velocity(t)))

    # vision, 32 Hz; noise is drawn for every frame, lost ones included, so that runs with
    # and without losses have the same noise on the frames they share
    drops = set()
    for start, count in args.drop:
        first = int(math.ceil(start * simbag.NS_PER_S / VISION_PERIOD_NS - 1e-9))
        drops.update(range(first, first + count))
    rv = simbag.rng("soccer", args.seed, "vision")
    delay_ns = int(round(real["vision_delay_ms"] * 1e6))
    transport = None      # sensor_errors.Transport: jitter, random losses, duplicates
    if real["vision_jitter_ms"] or real["vision_drop_prob"] or real["vision_dup_prob"]:
        transport = sensor_errors.Transport(simbag.rng("soccer", args.seed, "err", "transport", "vision"),
                                            delay_ns, real["vision_jitter_ms"] * 1e6, real["vision_drop_prob"],
                                            real["vision_dup_prob"])
    sent = lost = 0
    for k in range(0, end_ns // VISION_PERIOD_NS + 1):
        t_ns = k * VISION_PERIOD_NS
        x, y = traj.position(t_ns * 1e-9)
        nx, ny = rv.gauss(0.0, VISION_STD), rv.gauss(0.0, VISION_STD)
        if k in drops:
            bag.skip_seq("vision/pose")
            lost += 1
            continue
        msg = point(bag, "vision/pose", t_ns, x + nx, y + ny)
        if transport is None:
            bag.add("vision/pose", msg, t_ns + delay_ns)
        else:
            arrivals = transport.deliver(t_ns)
            for arrival in arrivals:
                bag.add("vision/pose", msg, arrival)
            if not arrivals:
                lost += 1
                continue
        sent += 1

    # encoder, 1000 Hz
    ex = EncoderError(args.seed, "x", args.bias_model)
    ey = EncoderError(args.seed, "y", args.bias_model)
    sq = [0.0, 0.0]
    peak = [0.0, 0.0]
    n = 0
    ticks = None          # sensor_errors.TickCounter per axis, counting from the start position
    if real["encoder_step"] > 0:
        ticks = (sensor_errors.TickCounter(real["encoder_step"]), sensor_errors.TickCounter(real["encoder_step"]))
        x0, y0 = traj.position(0.0)
    for j in range(0, end_ns // ENCODER_PERIOD_NS + 1):
        t_ns = j * ENCODER_PERIOD_NS
        x, y = traj.position(t_ns * 1e-9)
        dx, dy = ex.step(), ey.step()
        if ticks is None:
            bag.add("encoder/pose", point(bag, "encoder/pose", t_ns, x + dx, y + dy), t_ns)
        else:
            for counter, pos, start in zip(ticks, (x + dx, y + dy), (x0, y0)):
                counter.advance(pos - start - counter.travel)
            bag.add("encoder/pose", point(bag, "encoder/pose", t_ns, x0 + ticks[0].reading(),
                                          y0 + ticks[1].reading()), t_ns)
        for i, d in enumerate((dx, dy)):
            sq[i] += d * d
            peak[i] = max(peak[i], abs(d))
        n += 1

    bag.write(args.out, args.compression)
    if real != REALISTIC_DEFAULTS:
        print("soccer errors: %s%s" % (" ".join("%s=%g" % kv for kv in sorted(real.items())),
                                       "" if transport is None else " vision_duplicated=%d" % transport.duplicated))
    print("soccer seed=%d duration=%.3fs bias_model=%s speed_mean=%.2fm/s speed_max=%.2fm/s "
          "vision_sent=%d vision_lost=%d encoder_error_rms=(%.3f, %.3f)m encoder_error_max=(%.3f, %.3f)m "
          "encoder_error_end=(%.3f, %.3f)m out=%s"
          % (args.seed, end_ns * 1e-9, args.bias_model, sum(speeds) / len(speeds), max(speeds), sent, lost,
             math.sqrt(sq[0] / n), math.sqrt(sq[1] / n), peak[0], peak[1], dx, dy, args.out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
