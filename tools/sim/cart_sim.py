#!/usr/bin/python3
"""Simulator with exactly known noise for the noise identification (doc/tuning.md): a cart on
a line, x = (position p, speed v), that moves as the discrete nearly-constant-velocity model
of test/configs/tune_cart_kf.h,

    p_k = p_{k-1} + T v_{k-1} + w_p,   v_k = v_{k-1} + w_v,   w ~ N(0, diag(q_p, q_v)),

with one position and one speed reading per period T,

    cart/position  geometry_msgs/PointStamped    point.x  = p_k + r_p,  r_p ~ N(0, r_p var)
    cart/speed     geometry_msgs/Vector3Stamped  vector.x = v_k + r_v,  r_v ~ N(0, r_v var)

the position at k T, the speed at k T + 0.4 T, so each estimation period of the offline
replay (its schedule starts at the first message) holds exactly one of each. The online node
starts its schedule at the first /clock it sees instead, a few milliseconds off, so readings
on the period ends would fall on either side; --mid-period places them at k T + 0.3 T and
k T + 0.7 T and repeats the first speed reading at 0, which starts both schedules there and
keeps every reading 30 ms or more from a period end (test/tuned_params_online.test). Q and R of the model are
then the simulator's own numbers (--q-position, --q-speed, --r-position, --r-speed; variances
per period), the reference the identified values are checked against
(test/robots/test_noise_tuning.py). Seeded (simbag.py): the same command gives the same bag.

  cart_sim.py --seed 1 --periods 3000 --out /tmp/cart.bag
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from geometry_msgs.msg import PointStamped, Vector3Stamped  # noqa: E402

import simbag  # noqa: E402

PERIOD_NS = 100000000  # T = 0.1 s, ESTIMATION_PERIOD of test/configs/tune_cart_kf.h
Q_POSITION = 4e-4      # m^2 per period
Q_SPEED = 1e-3         # (m/s)^2 per period
R_POSITION = 2.5e-3    # m^2
R_SPEED = 2.5e-3       # (m/s)^2


def simulate(seed, periods, q=(Q_POSITION, Q_SPEED), r=(R_POSITION, R_SPEED)):
    """[(k, p_k, v_k, z_position, z_speed)] for k = 0 .. periods - 1, from p = v = 0."""
    process = simbag.rng("cart", seed, "process")
    sensors = simbag.rng("cart", seed, "sensors")
    t = PERIOD_NS / 1e9
    p = v = 0.0
    out = []
    for k in range(periods):
        if k > 0:
            p, v = p + t * v + process.gauss(0.0, math.sqrt(q[0])), v + process.gauss(
                0.0, math.sqrt(q[1]))
        out.append((k, p, v, p + sensors.gauss(0.0, math.sqrt(r[0])),
                    v + sensors.gauss(0.0, math.sqrt(r[1]))))
    return out


def add_reading(bag, topic, t_ns, value):
    """One reading of `topic` (cart/position or cart/speed) at t_ns into `bag`."""
    if topic == "cart/position":
        msg = PointStamped()
        msg.header.frame_id = "odom"
        msg.point.x = value
    else:
        msg = Vector3Stamped()
        msg.header.frame_id = "base_link"
        msg.vector.x = value
    msg.header.seq = bag.next_seq(topic)
    msg.header.stamp = bag.stamp(t_ns)
    bag.add(topic, msg, t_ns)


def write_bag(path, samples, mid_period=False):
    bag = simbag.BagBuilder()
    phase_p, phase_v = (3, 7) if mid_period else (0, 4)  # tenths of a period
    for k, _, _, z_p, z_v in samples:
        if mid_period and k == 0:
            add_reading(bag, "cart/speed", 0, z_v)
        add_reading(bag, "cart/position", k * PERIOD_NS + phase_p * PERIOD_NS // 10, z_p)
        add_reading(bag, "cart/speed", k * PERIOD_NS + phase_v * PERIOD_NS // 10, z_v)
    bag.write(path, compression="none")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--periods", type=int, default=3000)
    parser.add_argument("--q-position", type=float, default=Q_POSITION)
    parser.add_argument("--q-speed", type=float, default=Q_SPEED)
    parser.add_argument("--r-position", type=float, default=R_POSITION)
    parser.add_argument("--r-speed", type=float, default=R_SPEED)
    parser.add_argument("--mid-period", action="store_true",
                        help="readings 0.3 and 0.7 periods after the period starts (online runs)")
    parser.add_argument("--out", required=True)
    args = parser.parse_args(argv)
    if args.periods < 1 or min(args.q_position, args.q_speed, args.r_position, args.r_speed) < 0:
        parser.error("--periods must be >= 1 and the variances >= 0")
    samples = simulate(args.seed, args.periods, (args.q_position, args.q_speed),
                       (args.r_position, args.r_speed))
    write_bag(args.out, samples, args.mid_period)
    simbag.log("wrote %s: %d periods of %.1f s, Q = diag(%g, %g), R = diag(%g, %g)" % (
        args.out, args.periods, PERIOD_NS / 1e9, args.q_position, args.q_speed,
        args.r_position, args.r_speed))


if __name__ == "__main__":
    main()
