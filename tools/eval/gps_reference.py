#!/usr/bin/python3
"""A GPS track as the reference of an estimated 2-D track: RMSE, maximum and final error.

Usage:
  gps_reference.py BAG ESTIMATE [options]

BAG holds sensor_msgs/NavSatFix on /fix (--fix-topic). The fixes are converted to a local
east-north-up frame (WGS84) about a datum, the first valid fix (a fix with status < 0, "no
fix", or a latitude/longitude that is not finite is skipped). ESTIMATE is read by
tools/eval/evaluate.py's reader: a replay CSV (columns time, pose_x, pose_y; --pose-columns
picks others), or a bag with nav_msgs/Odometry or PoseStamped on --odom-topic (e.g.
--odom-topic /encoder: the recording's own wheel odometry).

The estimate is interpolated linearly at each fix's header stamp (fixes outside the
estimate's time range are left out). An estimate lives in its own odometry frame, whose
origin and heading are arbitrary with respect to east/north, so the 2-D rotation and shift
that fit the estimate best onto the GPS track (least squares, closed form, no scale) are
applied before the errors are taken (--no-align compares the raw coordinates). Printed: the
number of fixes used, the fitted rotation [deg] and shift [m], the RMSE, the maximum and the
final (last fix used) horizontal error [m].

--against BASELINE compares a second estimate on the same fixes (each aligned on its own) and
says whether ESTIMATE is closer to them than BASELINE by more than chance (paired_gain: the
mean of the squared errors' difference per fix, with a one-sided 95 % bound that counts
neighbouring fixes' correlation): the check of a tuned file against the header's.

--write-track OUT.csv writes the GPS track as time,x,y (x east, y north, metres), a truth
CSV that evaluate.py --truth reads.

The core functions (geodetic_to_ecef, ecef_to_enu, fit_rigid_2d, ...) are pure and use only
the standard library.
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import evaluate as ev  # noqa: E402  (the replay CSV and bag readers, interpolation)

# WGS84 defining constants (NIMA TR8350.2): semi-major axis [m] and flattening.
WGS84_A = 6378137.0
WGS84_F = 1.0 / 298.257223563
WGS84_E2 = WGS84_F * (2.0 - WGS84_F)  # first eccentricity squared


def geodetic_to_ecef(lat_deg, lon_deg, h):
    """Earth-centred, earth-fixed (X, Y, Z) [m] of a WGS84 latitude, longitude [deg] and
    ellipsoidal height [m] (exact):
        N = a / sqrt(1 - e^2 sin^2 lat)
        X = (N + h) cos lat cos lon,  Y = (N + h) cos lat sin lon,  Z = (N (1 - e^2) + h) sin lat
    """
    lat = math.radians(lat_deg)
    lon = math.radians(lon_deg)
    s = math.sin(lat)
    n = WGS84_A / math.sqrt(1.0 - WGS84_E2 * s * s)
    return ((n + h) * math.cos(lat) * math.cos(lon),
            (n + h) * math.cos(lat) * math.sin(lon),
            (n * (1.0 - WGS84_E2) + h) * s)


def ecef_to_enu(ecef, datum_lat_deg, datum_lon_deg, datum_ecef):
    """(east, north, up) [m] of the ECEF point `ecef` in the local tangent frame at the datum
    (its geodetic latitude/longitude and its ECEF position): the difference vector rotated
    by the exact ECEF->ENU rotation
        e = -sin lon dX + cos lon dY
        n = -sin lat cos lon dX - sin lat sin lon dY + cos lat dZ
        u =  cos lat cos lon dX + cos lat sin lon dY + sin lat dZ
    """
    lat = math.radians(datum_lat_deg)
    lon = math.radians(datum_lon_deg)
    dx, dy, dz = (ecef[0] - datum_ecef[0], ecef[1] - datum_ecef[1], ecef[2] - datum_ecef[2])
    sl, cl = math.sin(lat), math.cos(lat)
    so, co = math.sin(lon), math.cos(lon)
    return (-so * dx + co * dy,
            -sl * co * dx - sl * so * dy + cl * dz,
            cl * co * dx + cl * so * dy + sl * dz)


class LocalFrame:
    """East-north-up frame about a geodetic datum (lat [deg], lon [deg], h [m])."""

    def __init__(self, lat_deg, lon_deg, h=0.0):
        self.lat = float(lat_deg)
        self.lon = float(lon_deg)
        self.h = float(h) if math.isfinite(h) else 0.0
        self.ecef = geodetic_to_ecef(self.lat, self.lon, self.h)

    def enu(self, lat_deg, lon_deg, h=None):
        """(east, north, up) [m] of a geodetic point; a missing or NaN height is taken as the
        datum's (NavSatFix: "quiet NaN if no altitude is available")."""
        if h is None or not math.isfinite(h):
            h = self.h
        return ecef_to_enu(geodetic_to_ecef(lat_deg, lon_deg, h), self.lat, self.lon, self.ecef)


def valid_fix(status, lat, lon):
    """A usable fix: status >= 0 (STATUS_FIX or augmented) and a finite position."""
    return status >= 0 and math.isfinite(lat) and math.isfinite(lon)


def gps_track(fixes):
    """(frame, Trajectory of east/north) from fixes (t, status, lat, lon, alt) in time order;
    the datum is the first valid fix, invalid fixes are skipped. Raises ValueError when no fix
    is valid."""
    frame = None
    t, x, y = [], [], []
    for stamp, status, lat, lon, alt in fixes:
        if not valid_fix(status, lat, lon):
            continue
        if frame is None:
            frame = LocalFrame(lat, lon, alt)
        e, n, _ = frame.enu(lat, lon, alt)
        t.append(stamp)
        x.append(e)
        y.append(n)
    if frame is None:
        raise ValueError("no valid fix (every fix has status < 0 or no position)")
    return frame, ev.make_trajectory(t, x, y)


def read_fixes(path, topic="/fix"):
    """[(header stamp [s], status, lat, lon, alt)] of the NavSatFix messages on `topic`."""
    import rosbag  # Debian: python3-rosbag

    out = []
    with rosbag.Bag(path) as bag:
        for _, msg, t in bag.read_messages(topics=ev._topic_variants(topic)):
            stamp = msg.header.stamp if (msg.header.stamp.secs or msg.header.stamp.nsecs) else t
            out.append((stamp.to_sec(), msg.status.status, msg.latitude, msg.longitude,
                        msg.altitude))
    if not out:
        raise ValueError("%s: no messages on %s" % (path, topic))
    return out


COVARIANCE_TYPES = ("UNKNOWN", "APPROXIMATED", "DIAGONAL_KNOWN", "KNOWN")


def covariance_summary(covariances):
    """What the fixes' position_covariance holds, from [(position_covariance_type, the 9
    entries of position_covariance)]: {"types": {type name: count}, "off_diagonal": fixes
    with an entry off the diagonal, "unequal_en": fixes whose east and north variances
    differ}. Either gives a turned covariance a correlation of x and y (configuration.md,
    "GPS"); without both it has none at any yaw offset."""
    types = {}
    off_diagonal = unequal = 0
    for kind, c in covariances:
        name = COVARIANCE_TYPES[kind] if 0 <= kind < len(COVARIANCE_TYPES) else str(kind)
        types[name] = types.get(name, 0) + 1
        off_diagonal += any(c[k] != 0.0 for k in (1, 2, 3, 5, 6, 7))
        unequal += c[0] != c[4]
    return {"types": types, "off_diagonal": off_diagonal, "unequal_en": unequal}


def read_covariances(path, topic="/fix"):
    """[(position_covariance_type, position_covariance)] of the NavSatFix messages on
    `topic`."""
    import rosbag  # Debian: python3-rosbag

    with rosbag.Bag(path) as bag:
        return [(msg.position_covariance_type, tuple(msg.position_covariance))
                for _, msg, _ in bag.read_messages(topics=ev._topic_variants(topic))]


def fit_rigid_2d(src, dst):
    """(theta, tx, ty): the rotation and shift that minimise sum |R(theta) p + t - q|^2 over
    the pairs p in src, q in dst (lists of (x, y)); closed form (2-D Kabsch without scale):
    with centroids p0, q0 and centred pairs p', q',
        theta = atan2(sum p'x q'y - p'y q'x, sum p'x q'x + p'y q'y),  t = q0 - R p0."""
    n = len(src)
    if n != len(dst) or n == 0:
        raise ValueError("fit_rigid_2d: need equally many (>= 1) points")
    px = sum(p[0] for p in src) / n
    py = sum(p[1] for p in src) / n
    qx = sum(q[0] for q in dst) / n
    qy = sum(q[1] for q in dst) / n
    s_cross = s_dot = 0.0
    for (ax, ay), (bx, by) in zip(src, dst):
        ax -= px
        ay -= py
        bx -= qx
        by -= qy
        s_cross += ax * by - ay * bx
        s_dot += ax * bx + ay * by
    theta = math.atan2(s_cross, s_dot) if (s_cross or s_dot) else 0.0
    c, s = math.cos(theta), math.sin(theta)
    return theta, qx - (c * px - s * py), qy - (s * px + c * py)


def apply_rigid_2d(transform, points):
    theta, tx, ty = transform
    c, s = math.cos(theta), math.sin(theta)
    return [(c * x - s * y + tx, s * x + c * y + ty) for x, y in points]


def error_stats(errors):
    """(RMSE, maximum, final) of a sequence of error distances."""
    errors = list(errors)
    if not errors:
        raise ValueError("no errors")
    return ev.rmse(errors), max(errors), errors[-1]


def compare(estimate, reference, align=True, tolerance=ev.DEFAULT_TIME_TOLERANCE):
    """Compares the Trajectory `estimate` with the GPS Trajectory `reference` at the
    reference's stamps. Returns a dict: n (fixes used), times, transform (theta, tx, ty) or
    None, errors [m] per fix used, rmse, max, final."""
    times, est, ref = [], [], []
    for k, stamp in enumerate(reference.t):
        p = ev.interpolate(estimate, stamp, tolerance)
        if p is None:
            continue
        times.append(stamp)
        est.append((p[0], p[1]))
        ref.append((reference.x[k], reference.y[k]))
    if not times:
        raise ValueError("no fix inside the estimate's time range")
    transform = fit_rigid_2d(est, ref) if align else None
    moved = apply_rigid_2d(transform, est) if align else est
    errors = [math.hypot(a[0] - b[0], a[1] - b[1]) for a, b in zip(moved, ref)]
    rmse, emax, final = error_stats(errors)
    return {"n": len(times), "times": times, "transform": transform, "errors": errors,
            "rmse": rmse, "max": emax, "final": final}


# One-sided 95 % quantile of the standard normal: the paired comparison's bound.
Z_95 = 1.6448536269514722


def paired_gain(errors_a, errors_b):
    """Whether track B is closer to the fixes than track A by more than chance: the mean of
    d_k = e_b(k)^2 - e_a(k)^2 over the fixes both use (same stamps), and its one-sided 95 %
    upper bound d + Z_95 s / sqrt(n_eff), n_eff = n (1 - r) / (1 + r) with r the lag-1
    autocorrelation of d (kept >= 0: a fix's slow error makes neighbouring d alike). Returns
    (mean, bound, gain): gain when the bound is below 0, i.e. B's mean squared error is lower
    with 95 % confidence. Fewer than 3 pairs: no gain."""
    d = [b * b - a * a for a, b in zip(errors_a, errors_b)]
    n = len(d)
    if n < 3:
        return (sum(d) / n if n else 0.0), math.inf, False
    mean = sum(d) / n
    var = sum((x - mean) ** 2 for x in d) / (n - 1)
    lag = sum((d[k] - mean) * (d[k + 1] - mean) for k in range(n - 1)) / ((n - 1) * var) \
        if var > 0 else 0.0
    r = min(max(lag, 0.0), 0.99)
    bound = mean + Z_95 * math.sqrt(var / (n * (1 - r) / (1 + r)))
    return mean, bound, bound < 0


def compare_two(estimate_a, estimate_b, reference, tolerance=ev.DEFAULT_TIME_TOLERANCE):
    """compare() of both estimates (each aligned on its own), and paired_gain() of B over A
    on the fixes both use."""
    a, b = (compare(e, reference, tolerance=tolerance) for e in (estimate_a, estimate_b))
    errors_a, errors_b = dict(zip(a["times"], a["errors"])), dict(zip(b["times"], b["errors"]))
    common = [t for t in a["times"] if t in errors_b]
    mean, bound, gain = paired_gain([errors_a[t] for t in common], [errors_b[t] for t in common])
    return a, b, {"n": len(common), "mean": mean, "bound": bound, "gain": gain}


def write_track(path, track):
    with open(path, "w") as f:
        f.write("time,x,y\n")
        for t, x, y in zip(track.t, track.x, track.y):
            f.write("%.9f,%.4f,%.4f\n" % (t, x, y))


def main(argv=None):
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    parser.add_argument("bag", help="bag with sensor_msgs/NavSatFix")
    parser.add_argument("estimate", help="replay CSV, or a bag (--odom-topic)")
    parser.add_argument("--fix-topic", default="/fix")
    parser.add_argument("--odom-topic", default="/odometry/filtered",
                        help="topic of the estimate when it is a bag (default %(default)s)")
    parser.add_argument("--pose-columns", default="pose_x,pose_y",
                        help="CSV columns X,Y of the estimate (default %(default)s)")
    parser.add_argument("--no-align", action="store_true",
                        help="no rotation/shift fit: the estimate is already east/north")
    parser.add_argument("--write-track", metavar="CSV", help="write the GPS track (time,x,y)")
    parser.add_argument("--against", metavar="BASELINE",
                        help="also compare BASELINE (read as ESTIMATE) and say whether ESTIMATE "
                             "is significantly closer to the fixes (paired_gain)")
    args = parser.parse_args(argv)

    cols = [c.strip() for c in args.pose_columns.split(",")]
    if len(cols) != 2:
        parser.error("--pose-columns needs 2 names")
    try:
        fixes = read_fixes(args.bag, args.fix_topic)
        frame, track = gps_track((f for f in fixes))
        estimate = ev.load_result(args.estimate, cols, args.odom_topic)
        result = compare(estimate, track, align=not args.no_align)
        if args.against:
            baseline = ev.load_result(args.against, cols, args.odom_topic)
            base, result, paired = compare_two(baseline, estimate, track)
    except (ValueError, OSError) as exc:
        print("error: %s" % exc, file=sys.stderr)
        return 2
    if args.write_track:
        write_track(args.write_track, track)
    print("datum: lat %.8f deg, lon %.8f deg, h %.2f m (first valid fix of %d, %d valid)"
          % (frame.lat, frame.lon, frame.h, len(fixes), len(track.t)))
    print("fixes used: %d (%.1f s)" % (result["n"], result["times"][-1] - result["times"][0]))
    if result["transform"] is not None:
        theta, tx, ty = result["transform"]
        print("fit: rotation %.2f deg, shift (%.3f, %.3f) m" % (math.degrees(theta), tx, ty))
    print("RMSE %.3f m, max %.3f m, final %.3f m" % (result["rmse"], result["max"],
                                                     result["final"]))
    if args.against:
        print("against %s (RMSE %.4f m; this estimate %.4f m), over %d fixes: mean of the "
              "squared errors' difference %.4g m^2, 95 %% upper bound %.4g m^2: %s" % (
                  args.against, base["rmse"], result["rmse"], paired["n"], paired["mean"],
                  paired["bound"], "a gain" if paired["gain"] else "no gain (not significantly "
                  "closer to the fixes)"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
