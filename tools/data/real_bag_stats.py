#!/usr/bin/python3
"""Calibration figures of a real recording (default bags/husky_gps.bag), for the simulators:
wheel odometry yaw rate against gyro yaw rate, gyro noise and bias at standstill, the
latency between header.stamp and bag receive time, message rates, lost and repeated
stamps.

  real_bag_stats.py [BAG] [--odom-topic /encoder] [--imu-topic /imu/data]
                    [--standstill-tol 0.0]

Definitions (the functions below, unit-tested in test/eval/test_real_bag_stats.py):
- Yaw rates. The wheel yaw rate is the odometry's twist.twist.angular.z. Each gyro axis
  (angular_velocity.x, .y, .z) is interpolated linearly at the odometry stamps (header
  stamps; odometry messages outside the gyro's time range are left out); the axis with the
  largest |correlation| carries the base's yaw rate (sign included). On that axis: the
  Pearson correlation, the least-squares scale s of wheel = s * gyro (through the origin)
  and the residual standard deviation sqrt(sum r^2 / (n - 1)), r = wheel - s * gyro; also
  the affine fit wheel = s' * (gyro - b), whose b is the gyro's apparent offset while
  driving. The stamp shift (lag) at which the correlation is best, -0.3 to 0.3 s.
- Standstill: the gyro samples whose neighbouring odometry messages (the last at or before
  and the first after the sample) both report |linear.x| and |angular.z| <= the tolerance
  (default 0: the wheels report exactly zero). Their mean (bias) and sample standard
  deviation (noise per sample).
- Latency per topic: bag receive time - header.stamp (for /tf: of the first transform,
  grouped by its child frame, as each group comes from another publisher); median and
  95th percentile (linear interpolation between order statistics).
- Rates per topic: (n - 1) / (last - first stamp); the median, shortest and longest
  period; "gaps": periods
  longer than 1.5 median periods, with round(period / median) - 1 samples missing each;
  repeated stamps (period 0) and stamps going back; header.seq numbers skipped and repeated
  (not counted when every seq is 0, as in tf transforms).
  Topics without a header (geometry_msgs/Twist) use the bag time.
"""

import argparse
import bisect
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_BAG = os.path.join(HERE, "..", "..", "bags", "husky_gps.bag")


# -----------------------------------------------------------------------------
# Pure statistics (standard library)
# -----------------------------------------------------------------------------
def mean(values):
    values = list(values)
    return sum(values) / len(values)


def stdev(values):
    """Sample standard deviation (n - 1); None for fewer than 2 values."""
    values = list(values)
    if len(values) < 2:
        return None
    m = mean(values)
    return math.sqrt(sum((v - m) ** 2 for v in values) / (len(values) - 1))


def percentile(values, p):
    """p-th percentile (0..100), linear between the order statistics (numpy's default):
    rank p/100 * (n - 1) of the sorted values."""
    s = sorted(values)
    if not s:
        return None
    rank = p / 100.0 * (len(s) - 1)
    lo = int(math.floor(rank))
    hi = min(lo + 1, len(s) - 1)
    return s[lo] + (rank - lo) * (s[hi] - s[lo])


def interpolate_at(t, v, queries):
    """[(k, value)] of the series (t increasing, v) interpolated linearly at queries[k], for
    the queries inside [t[0], t[-1]] (others are left out)."""
    out = []
    for k, q in enumerate(queries):
        if not t or q < t[0] or q > t[-1]:
            continue
        j = bisect.bisect_left(t, q)  # t[j-1] < q <= t[j]
        if t[j] == q:
            out.append((k, v[j]))
        else:
            f = (q - t[j - 1]) / (t[j] - t[j - 1])
            out.append((k, v[j - 1] + f * (v[j] - v[j - 1])))
    return out


def correlation(a, b):
    """Pearson correlation of two equally long sequences (None when one is constant)."""
    ma, mb = mean(a), mean(b)
    sab = sum((x - ma) * (y - mb) for x, y in zip(a, b))
    saa = sum((x - ma) ** 2 for x in a)
    sbb = sum((y - mb) ** 2 for y in b)
    if saa == 0 or sbb == 0:
        return None
    return sab / math.sqrt(saa * sbb)


def scale_fit(x, y):
    """(s, residual std) of the least-squares fit y = s * x through the origin:
    s = sum x y / sum x^2, residual std = sqrt(sum (y - s x)^2 / (n - 1))."""
    sxx = sum(a * a for a in x)
    s = sum(a * b for a, b in zip(x, y)) / sxx
    r2 = sum((b - s * a) ** 2 for a, b in zip(x, y))
    return s, math.sqrt(r2 / (len(x) - 1))


def affine_fit(x, y):
    """(s, b) of the least-squares fit y = s * (x - b), i.e. y = s x + c with b = -c / s."""
    mx, my = mean(x), mean(y)
    s = sum((a - mx) * (c - my) for a, c in zip(x, y)) / sum((a - mx) ** 2 for a in x)
    c = my - s * mx
    return s, -c / s


def yaw_rate_comparison(odom_t, odom_wz, imu_t, imu_w):
    """Wheel against gyro yaw rate. imu_w: per gyro axis a list (x, y, z). Returns a dict:
    n, correlations per axis, axis (index), sign, correlation, scale, residual_std,
    affine_scale, gyro_offset."""
    per_axis, gyros = [], []
    for axis in range(3):
        pairs = interpolate_at(imu_t, [w[axis] for w in imu_w], odom_t)
        wheel = [odom_wz[k] for k, _ in pairs]
        gyros.append([g for _, g in pairs])
        per_axis.append(correlation(wheel, gyros[-1]))
    axis = max(range(3), key=lambda k: abs(per_axis[k] or 0.0))
    gyro = gyros[axis]
    scale, res = scale_fit(gyro, wheel)
    a_scale, offset = affine_fit(gyro, wheel)
    return {"n": len(wheel), "correlations": per_axis, "axis": axis,
            "sign": 1 if per_axis[axis] > 0 else -1, "correlation": per_axis[axis],
            "scale": scale, "residual_std": res, "affine_scale": a_scale, "gyro_offset": offset}


def best_lag(odom_t, odom_wz, imu_t, imu_w, axis, max_lag=0.3, step=0.01):
    """(lag [s], correlation): the shift d of the odometry stamps, on the grid k * step with
    |d| <= max_lag, at which the wheel yaw rate correlates best with the gyro axis `axis`
    interpolated at stamp + d. A positive lag means the gyro's stamps are late against the
    odometry's (the same motion is stamped d later on the gyro)."""
    best = None
    n = int(round(max_lag / step))
    for k in range(-n, n + 1):
        d = k * step
        pairs = interpolate_at(imu_t, [w[axis] for w in imu_w], [t + d for t in odom_t])
        c = correlation([odom_wz[j] for j, _ in pairs], [g for _, g in pairs])
        if c is not None and (best is None or abs(c) > abs(best[1])):
            best = (d, c)
    return best


def standstill_samples(odom_t, odom_v, odom_wz, imu_t, gyro, tol=0.0):
    """The gyro values at the samples where the odometry messages before (at or before) and
    after the sample both report |v| <= tol and |wz| <= tol."""
    still = [abs(v) <= tol and abs(w) <= tol for v, w in zip(odom_v, odom_wz)]
    out = []
    j = -1
    for t, g in zip(imu_t, gyro):
        while j + 1 < len(odom_t) and odom_t[j + 1] <= t:
            j += 1
        if j < 0 or j + 1 >= len(odom_t):
            continue
        if still[j] and still[j + 1]:
            out.append(g)
    return out


def rate_stats(stamps):
    """Rates and stamp irregularities of a topic's stamps in arrival order (a dict)."""
    n = len(stamps)
    periods = [b - a for a, b in zip(stamps, stamps[1:])]
    out = {"n": n, "rate": None, "median_period": None, "min_period": min(periods, default=None),
           "max_period": max(periods, default=None), "gaps": 0, "missing": 0,
           "repeated": sum(1 for p in periods if p == 0), "backwards": sum(1 for p in periods if p < 0)}
    if n < 2 or stamps[-1] == stamps[0]:
        return out
    out["rate"] = (n - 1) / (stamps[-1] - stamps[0])
    med = percentile([p for p in periods if p > 0], 50)
    out["median_period"] = med
    for p in periods:
        if p > 1.5 * med:
            out["gaps"] += 1
            out["missing"] += int(round(p / med)) - 1
    return out


def seq_stats(seqs):
    """(skipped, repeated, backwards) header.seq numbers of a topic, in arrival order."""
    d = [b - a for a, b in zip(seqs, seqs[1:])]
    return (sum(k - 1 for k in d if k > 1), sum(1 for k in d if k == 0),
            sum(1 for k in d if k < 0))


def latency_stats(stamps, receive):
    """(median, 95th percentile) of receive - stamp [s]."""
    lat = [r - s for s, r in zip(stamps, receive)]
    return percentile(lat, 50), percentile(lat, 95)


# -----------------------------------------------------------------------------
# Reading the bag
# -----------------------------------------------------------------------------
def read_bag(path):
    """{stream: {"stamp": [], "recv": [], "seq": [] or None}} per topic (and per /tf child
    frame), and the odometry and IMU series."""
    import rosbag  # Debian: python3-rosbag

    streams = {}
    series = {}
    with rosbag.Bag(path) as bag:
        for topic, msg, t in bag.read_messages():
            recv = t.to_sec()
            if hasattr(msg, "transforms"):
                if not msg.transforms:
                    continue
                head = msg.transforms[0].header
                name = "%s (%s%s)" % (topic, msg.transforms[0].child_frame_id,
                                      ", ..." if len(msg.transforms) > 1 else "")
            elif hasattr(msg, "header"):
                head = msg.header
                name = topic
            else:
                head = None
                name = topic
            s = streams.setdefault(name, {"stamp": [], "recv": [], "seq": [] if head else None,
                                          "type": msg._type})
            s["recv"].append(recv)
            s["stamp"].append(head.stamp.to_sec() if head else recv)
            if head:
                s["seq"].append(head.seq)
            series.setdefault(topic, []).append(msg)
    return streams, series


def odometry_series(msgs):
    return ([m.header.stamp.to_sec() for m in msgs], [m.twist.twist.linear.x for m in msgs],
            [m.twist.twist.angular.z for m in msgs])


def imu_series(msgs):
    return ([m.header.stamp.to_sec() for m in msgs],
            [(m.angular_velocity.x, m.angular_velocity.y, m.angular_velocity.z) for m in msgs])


def _f(v, fmt="%.4f"):
    return "-" if v is None else fmt % v


def report(path, odom_topic="/encoder", imu_topic="/imu/data", tol=0.0, out=sys.stdout):
    streams, series = read_bag(path)
    for topic in (odom_topic, imu_topic):
        if topic not in series:
            raise ValueError("%s: no topic %s" % (path, topic))
    ot, ov, ow = odometry_series(series[odom_topic])
    it, iw = imu_series(series[imu_topic])
    p = lambda *a: print(*a, file=out)

    yaw = yaw_rate_comparison(ot, ow, it, iw)
    axis = "xyz"[yaw["axis"]]
    p("# %s" % os.path.basename(path))
    p("## wheel yaw rate (%s twist.angular.z) against gyro (%s angular_velocity), at the "
      "odometry's stamps" % (odom_topic, imu_topic))
    p("odometry messages matched: %d" % yaw["n"])
    p("correlation per gyro axis: x %s, y %s, z %s" % tuple(_f(c, "%+.3f") for c in yaw["correlations"]))
    p("yaw axis: %s%s" % ("+" if yaw["sign"] > 0 else "-", axis))
    p("correlation: %.3f" % yaw["correlation"])
    p("scale s of wheel = s * gyro: %.3f; residual std %.4f rad/s" % (yaw["scale"], yaw["residual_std"]))
    p("affine fit wheel = s' * (gyro - b): s' %.3f, b %+.4f rad/s" % (yaw["affine_scale"], yaw["gyro_offset"]))
    lag, lag_c = best_lag(ot, ow, it, iw, yaw["axis"])
    p("best correlation over odometry stamp shifts of -0.3..0.3 s (0.01 s steps): %.3f at "
      "%+.2f s (positive: gyro stamped later)" % (lag_c, lag))
    gyro_yaw = [w[yaw["axis"]] for w in iw]
    still = standstill_samples(ot, ov, ow, it, gyro_yaw, tol)
    p("## gyro %s at standstill (|v|, |wz| <= %g on the odometry before and after)" % (axis, tol))
    if len(still) >= 2:
        p("samples: %d; bias (mean) %+.5f rad/s; noise (std per sample) %.5f rad/s"
          % (len(still), mean(still), stdev(still)))
    else:
        speeds = sorted(abs(v) for v in ov)
        p("samples: %d: not measurable (the odometry never reports standstill; smallest |v| "
          "%.4f m/s)" % (len(still), speeds[0] if speeds else float("nan")))
    p("## per topic: rate, stamps, latency = receive - header.stamp")
    p("| topic | type | messages | rate [Hz] | period median, min, max [s] | gaps (missing) | repeated stamps "
      "| stamps back | seq skipped / repeated | latency median [s] | latency p95 [s] |")
    p("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for name in sorted(streams):
        s = streams[name]
        r = rate_stats(s["stamp"])
        if s["seq"] is not None:
            sk, rep, _ = seq_stats(s["seq"])
            # tf publishers leave the transforms' header.seq at 0
            seq = "%d / %d" % (sk, rep) if any(s["seq"]) else "(all 0)"
            med, p95 = latency_stats(s["stamp"], s["recv"])
            lat = (_f(med), _f(p95))
        else:
            seq = "(no header)"
            lat = ("-", "-")
        p("| `%s` | %s | %d | %s | %s, %s, %s | %d (%d) | %d | %d | %s | %s | %s |" % (
            name, s["type"], r["n"], _f(r["rate"], "%.2f"), _f(r["median_period"], "%.4f"),
            _f(r["min_period"], "%.4f"), _f(r["max_period"], "%.4f"),
            r["gaps"], r["missing"], r["repeated"], r["backwards"], seq, lat[0], lat[1]))
    return 0


def main(argv=None):
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    parser.add_argument("bag", nargs="?", default=DEFAULT_BAG)
    parser.add_argument("--odom-topic", default="/encoder")
    parser.add_argument("--imu-topic", default="/imu/data")
    parser.add_argument("--standstill-tol", type=float, default=0.0,
                        help="|v| [m/s] and |wz| [rad/s] counted as standstill (default %(default)g)")
    args = parser.parse_args(argv)
    try:
        return report(args.bag, args.odom_topic, args.imu_topic, args.standstill_tol)
    except (ValueError, OSError) as exc:
        print("error: %s" % exc, file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
