#!/usr/bin/python3
"""The slowly changing error of a recording's GPS fixes: a first-order Gauss-Markov model.

Usage:
  gps_error_model.py BAG TRACK.csv [--fix-topic /fix] [--max-lag 12]

TRACK.csv is a dead-reckoned track of the same run without GPS (a replay CSV, or
wheel_gyro_reference.py's output). It is fitted onto the valid fixes (in ENU about the first)
by the rotation, shift and scale that fit it best (the wheels' scale error is one of the
things the GPS header estimates); what is left, r(t) = fix - fitted track, is taken as the
fixes' error (plus what the dead reckoning gets wrong beyond a scale, so the figures are an
upper bound of the receiver's). Printed: the residual's standard deviation per axis, its
structure function D(lag) = mean |r(t + lag) - r(t)|^2 over the fix pairs lag apart (both
axes), and the model fitted to it,
    D(lag) = 2 (2 w^2 + 2 sigma^2 (1 - exp(-lag / tau)))   (two axes),
w the white part, sigma the slow part's standard deviation per axis and tau its time
constant (least squares on a grid of tau). The core functions are pure and unit-tested in
test/eval/test_gps_error_model.py.
"""

import argparse
import bisect
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import evaluate as ev  # noqa: E402
import gps_reference as gr  # noqa: E402


def fit_similarity_2d(src, dst):
    """(angle, scale, tx, ty) minimising sum |s R src + t - dst|^2 (closed form, Umeyama)."""
    n = float(len(src))
    mx = sum(p[0] for p in src) / n
    my = sum(p[1] for p in src) / n
    nx = sum(p[0] for p in dst) / n
    ny = sum(p[1] for p in dst) / n
    sxx = sxy = var = 0.0
    for (ax, ay), (bx, by) in zip(src, dst):
        ax, ay, bx, by = ax - mx, ay - my, bx - nx, by - ny
        sxx += ax * bx + ay * by
        sxy += ax * by - ay * bx
        var += ax * ax + ay * ay
    angle = math.atan2(sxy, sxx)
    scale = math.hypot(sxx, sxy) / var
    c, s = scale * math.cos(angle), scale * math.sin(angle)
    return angle, scale, nx - (c * mx - s * my), ny - (s * mx + c * my)


def residuals(track, points):
    """[(t, re, rn)]: the points [(t, e, n)] minus `track` fitted onto them (fit_similarity_2d),
    at the points inside the track's time range."""
    pairs = [(ev.interpolate(track, t), (t, e, n)) for t, e, n in points]
    pairs = [(p[:2], q) for p, q in pairs if p is not None]
    angle, scale, tx, ty = fit_similarity_2d([p for p, _ in pairs], [q[1:] for _, q in pairs])
    c, s = scale * math.cos(angle), scale * math.sin(angle)
    return [(t, e - (c * x - s * y + tx), n - (s * x + c * y + ty)) for (x, y), (t, e, n) in pairs]


def structure_function(res, lags):
    """{lag: mean |r(t + lag) - r(t)|^2} over the residual pairs (in time order) whose stamps
    differ by lag within a fifth of the smallest lag."""
    times = [r[0] for r in res]
    tol = 0.2 * min(lags)
    out = {}
    for lag in lags:
        values = []
        for a in res:
            j = bisect.bisect_left(times, a[0] + lag - tol)
            if j < len(res) and abs(res[j][0] - a[0] - lag) < tol:
                b = res[j]
                values.append((b[1] - a[1]) ** 2 + (b[2] - a[2]) ** 2)
        if values:
            out[lag] = sum(values) / len(values)
    return out


def fit_gauss_markov(d):
    """(w, sigma, tau) of the model above fitted to the structure function d {lag: value}:
    for each tau of a grid, w^2 and sigma^2 by linear least squares (clipped at 0)."""
    best = None
    for k in range(1, 400):
        tau = 0.25 * k
        rows = [(4.0, 4.0 * (1.0 - math.exp(-lag / tau)), v) for lag, v in d.items()]
        a11 = sum(r[0] * r[0] for r in rows)
        a12 = sum(r[0] * r[1] for r in rows)
        a22 = sum(r[1] * r[1] for r in rows)
        b1 = sum(r[0] * r[2] for r in rows)
        b2 = sum(r[1] * r[2] for r in rows)
        det = a11 * a22 - a12 * a12
        w2, s2 = (a22 * b1 - a12 * b2) / det, (a11 * b2 - a12 * b1) / det
        w2, s2 = max(w2, 0.0), max(s2, 0.0)
        cost = sum((r[0] * w2 + r[1] * s2 - r[2]) ** 2 for r in rows)
        if best is None or cost < best[0]:
            best = (cost, math.sqrt(w2), math.sqrt(s2), tau)
    return best[1:]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("bag")
    parser.add_argument("track")
    parser.add_argument("--fix-topic", default="/fix")
    parser.add_argument("--max-lag", type=float, default=12.0, help="[s] (default 12)")
    args = parser.parse_args(argv)
    frame, fixes = gr.gps_track(gr.read_fixes(args.bag, args.fix_topic))
    points = list(zip(fixes.t, fixes.x, fixes.y))
    res = residuals(ev.load_result_csv(args.track), points)
    period = (res[-1][0] - res[0][0]) / (len(res) - 1)
    lags = [period * k for k in range(1, int(args.max_lag / period) + 1)]
    d = structure_function(res, lags)
    w, sigma, tau = fit_gauss_markov(d)
    for axis, k in (("east", 1), ("north", 2)):
        print("residual %s: std %.3f m" % (axis, math.sqrt(sum(r[k] ** 2 for r in res) / len(res))))
    for lag, v in sorted(d.items()):
        print("D(%.1f s) = %.4f m^2" % (lag, v))
    print("fit: white %.3f m, slow sigma %.3f m, tau %.1f s (per axis)" % (w, sigma, tau))
    return 0


if __name__ == "__main__":
    sys.exit(main())
