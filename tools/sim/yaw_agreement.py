#!/usr/bin/python3
"""Agreement of the wheels' yaw rate with the gyro's yaw rate in a bag.

For every wheel/odometry sample the gyro's yaw rate is interpolated linearly at the
sample's time, and the script prints the number of pairs, the correlation of the two
series, the standard deviation of their difference (wheels minus gyro), the
least-squares slope of wheels on gyro through the origin, the standard deviation
left after that slope, and that residual's autocorrelation at one and two samples with the
correlation time it implies (residual_correlation; the samples are 10 Hz in every layout).
Layouts:

  pioneer    velocity_wheel_left/right (mm/s, Float32, bag time), R = 0.3 m,
             angular_velocity.vector.z (header stamp)
  diff_drive odom twist.twist.angular.z (header stamp), imu/data angular_velocity.y
             (the simulated IMU lies on its side; header stamp)
  husky      /encoder twist.twist.angular.z, /imu/data angular_velocity.z (header stamps):
             the real Clearpath Husky recording described in doc/bags.md; also prints
             its track widths, latencies, losses, encoder resolution and mean
             accelerometer reading (husky_extras)

  yaw_agreement.py --layout pioneer bags/pioneer_seed1.bag
"""

import argparse
import bisect
import math
import sys


def interpolate(times, values, t):
    """Linear interpolation of (times, values) at t; None outside the covered interval."""
    i = bisect.bisect_left(times, t)
    if i < len(times) and times[i] == t:
        return values[i]
    if i == 0 or i >= len(times):
        return None
    t0, t1 = times[i - 1], times[i]
    f = (t - t0) / (t1 - t0)
    return values[i - 1] * (1.0 - f) + values[i] * f


def statistics(wheel, gyro):
    """(n, correlation, std of wheel - gyro, LS slope through 0, std of wheel - slope gyro)."""
    n = len(wheel)
    mw, mg = sum(wheel) / n, sum(gyro) / n
    sww = sum((a - mw) ** 2 for a in wheel)
    sgg = sum((b - mg) ** 2 for b in gyro)
    swg = sum((a - mw) * (b - mg) for a, b in zip(wheel, gyro))
    diff = [a - b for a, b in zip(wheel, gyro)]
    md = sum(diff) / n
    resid = math.sqrt(sum((d - md) ** 2 for d in diff) / n)
    slope = sum(a * b for a, b in zip(wheel, gyro)) / sum(b * b for b in gyro)
    rest = [a - slope * b for a, b in zip(wheel, gyro)]
    mr = sum(rest) / n
    resid_slope = math.sqrt(sum((d - mr) ** 2 for d in rest) / n)
    return n, swg / math.sqrt(sww * sgg), resid, slope, resid_slope


def residual_correlation(wheel, gyro, slope, period=0.1):
    """Autocorrelation of the residual wheels - slope * gyro at lags of 1 and 2 samples, and
    the correlation time it implies. A first-order Gauss-Markov disturbance with correlation
    time tau plus white noise has acf(k) = c exp(-k period / tau) for k >= 1 (c < 1 the
    disturbance's share of the variance), so tau = -period / ln(acf(2) / acf(1)), whatever
    the white part. Returns (acf1, acf2, tau or None)."""
    rest = [a - slope * b for a, b in zip(wheel, gyro)]
    n = len(rest)
    m = sum(rest) / n
    d = [x - m for x in rest]
    var = sum(x * x for x in d)
    acf = [sum(d[i] * d[i + k] for i in range(n - k)) / var for k in (1, 2)]
    tau = None
    if 0.0 < acf[1] < acf[0]:
        tau = -period / math.log(acf[1] / acf[0])
    return acf[0], acf[1], tau


def pair(wheel_samples, gyro_samples):
    """Pairs (wheel yaw rate, gyro yaw rate interpolated at the wheel sample's time)."""
    gyro_samples = sorted(gyro_samples)
    gt = [t for t, _ in gyro_samples]
    gv = [v for _, v in gyro_samples]
    wheel, gyro = [], []
    for t, w in sorted(wheel_samples):
        g = interpolate(gt, gv, t)
        if g is not None:
            wheel.append(w)
            gyro.append(g)
    return wheel, gyro


def read_bag(path, layout):
    import rosbag  # only here: the statistics above need no ROS
    wheel, gyro, left, right = [], [], {}, {}
    with rosbag.Bag(path) as bag:
        for topic, msg, t in bag.read_messages():
            if layout == "pioneer":
                if topic == "velocity_wheel_left":
                    left[t.to_nsec()] = msg.data
                elif topic == "velocity_wheel_right":
                    right[t.to_nsec()] = msg.data
                elif topic == "angular_velocity":
                    gyro.append((msg.header.stamp.to_sec(), msg.vector.z))
            elif layout == "diff_drive":
                if topic == "odom":
                    wheel.append((msg.header.stamp.to_sec(), msg.twist.twist.angular.z))
                elif topic == "imu/data":
                    gyro.append((msg.header.stamp.to_sec(), msg.angular_velocity.y))
            else:
                if topic == "/encoder":
                    wheel.append((msg.header.stamp.to_sec(), msg.twist.twist.angular.z))
                elif topic == "/imu/data":
                    gyro.append((msg.header.stamp.to_sec(), msg.angular_velocity.z))
    if layout == "pioneer":
        # the wheel speeds carry no stamp: pair left and right by nearest bag time
        # (each side's transport delays it by a millisecond or so)
        rt = sorted(right)
        for t_ns, vl in sorted(left.items()):
            i = bisect.bisect_left(rt, t_ns)
            near = [j for j in (i - 1, i) if 0 <= j < len(rt)]
            if not near:
                continue
            j = min(near, key=lambda j: abs(rt[j] - t_ns))
            if abs(rt[j] - t_ns) < 20000000:
                wheel.append((t_ns * 1e-9, (right[rt[j]] - vl) * 1e-3 / 0.6))
    return wheel, gyro


def husky_extras(path):
    """Further figures of the real Husky recording (doc/bags.md, calibration):
    track widths from the raw wheel speeds of /husky/data/encoders (right minus left,
    encoders[1] - encoders[0]): over /encoder's yaw rate (the driver's track) and over the
    gyro's (the effective track; least squares through 0 on samples with |gyro| > 0.2
    rad/s); arrival latency (bag time - header stamp) of /encoder and /imu/data; seq steps;
    whether the encoder travel is in whole millimetres; the mean accelerometer reading."""
    import rosbag
    raw, odom, gyro, lat, seqs, acc = [], [], [], {}, {}, [0.0, 0.0, 0.0, 0]
    whole_mm = total = 0
    with rosbag.Bag(path) as bag:
        for topic, msg, t in bag.read_messages(topics=["/husky/data/encoders", "/encoder", "/imu/data"]):
            if topic == "/husky/data/encoders":
                raw.append((t.to_sec(), msg.encoders[1].speed - msg.encoders[0].speed))
                for e in msg.encoders:
                    total += 1
                    whole_mm += abs(e.travel * 1000.0 - round(e.travel * 1000.0)) < 1e-6
                continue
            lat.setdefault(topic, []).append((t - msg.header.stamp).to_sec())
            seqs.setdefault(topic, []).append(msg.header.seq)
            if topic == "/encoder":
                odom.append((t.to_sec(), msg.twist.twist.angular.z))
            else:
                gyro.append((msg.header.stamp.to_sec(), msg.angular_velocity.z))
                a = msg.linear_acceleration
                acc[0] += a.x
                acc[1] += a.y
                acc[2] += a.z
                acc[3] += 1
    gt, gv = [t for t, _ in sorted(gyro)], [v for _, v in sorted(gyro)]
    pairs = [(d, interpolate(gt, gv, t)) for t, d in raw]
    pairs = [(d, g) for d, g in pairs if g is not None and abs(g) > 0.2]
    eff = sum(d * g for d, g in pairs) / sum(g * g for _, g in pairs)
    ot, ov = [t for t, _ in odom], [v for _, v in odom]
    pairs = [(d, interpolate(ot, ov, t)) for t, d in raw]
    pairs = [(d, w) for d, w in pairs if w is not None and abs(w) > 0.1]
    drv = sum(d * w for d, w in pairs) / sum(w * w for _, w in pairs)
    print("husky effective_track=%.3fm driver_track=%.3fm travel_whole_mm=%d/%d accel_mean=(%.3f, %.3f, %.3f)"
          % (eff, drv, whole_mm, total, acc[0] / acc[3], acc[1] / acc[3], acc[2] / acc[3]))
    for topic in sorted(lat):
        ms = [x * 1e3 for x in lat[topic]]
        m = sum(ms) / len(ms)
        sd = math.sqrt(sum((x - m) ** 2 for x in ms) / len(ms))
        steps = [b - a for a, b in zip(seqs[topic], seqs[topic][1:])]
        print("husky %s latency mean=%.2fms std=%.2fms max=%.2fms messages=%d seq_steps_not_1=%d"
              % (topic, m, sd, max(ms), len(ms), sum(1 for x in steps if x != 1)))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--layout", choices=("pioneer", "diff_drive", "husky"), required=True)
    parser.add_argument("bags", nargs="+")
    args = parser.parse_args(argv)
    for path in args.bags:
        w, g = pair(*read_bag(path, args.layout))
        n, corr, resid, slope, resid_slope = statistics(w, g)
        mg = sum(g) / n
        gyro_std = math.sqrt(sum((x - mg) ** 2 for x in g) / n)
        print("%s pairs=%d corr=%.3f resid_std=%.4frad/s slope=%.3f resid_after_slope=%.4frad/s gyro_std=%.3frad/s"
              % (path, n, corr, resid, slope, resid_slope, gyro_std))
        acf1, acf2, tau = residual_correlation(w, g, slope)
        print("%s residual after the slope: acf(1 sample)=%.3f acf(2 samples)=%.3f correlation_time=%s"
              % (path, acf1, acf2, "%.2fs" % tau if tau is not None else "-"))
        if args.layout == "husky":
            husky_extras(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
