"""A simulated GPS receiver for diff_drive_sim.py --gps: sensor_msgs/NavSatFix of the true
position with a receiver's error.

The robot's odom frame (the simulator's true x, y) lies in a local east-north-up frame about
the datum (the start, --gps-datum) with its x axis at heading HEADING in ENU (counter-clockwise
from east; --gps-heading): east = cos a x - sin a y, north = sin a x + cos a y. The fix is
that point plus an error per axis (east, north) of two parts:

  slow   a first-order Gauss-Markov process, standard deviation SIGMA, time constant TAU:
         e(k+1) = phi e(k) + sqrt(1 - phi^2) SIGMA n,  phi = exp(-dt / TAU), starting from
         its stationary distribution; what a real receiver's error mostly is (multipath,
         atmosphere, the satellites' geometry change over tens of seconds to minutes)
  white  independent per fix, standard deviation WHITE

and the altitude the datum's plus the up error (both parts, doubled). The fix declares
position_covariance_type APPROXIMATED with DECLARED^2 on east and north (4 DECLARED^2 up), as
a consumer receiver reports its horizontal accuracy estimate. The defaults are those measured
on the real Husky recording's fixes (doc/real_robot.md, "GPS fused at a reduced rate").
Converted to latitude and longitude exactly (WGS84; enu_to_geodetic inverts gps_reference's
geodesy to below 1e-9 m). Pure Python but for the message class; the error comes from its own
seeded stream (simbag.rng), so the simulator's other topics do not change with --gps.
"""

import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "eval"))
import gps_reference as gr  # noqa: E402  (WGS84 geodesy)

DEFAULT_DATUM = (43.4725, -80.5448, 330.0)  # latitude, longitude [deg], altitude [m]
DEFAULT_HEADING_DEG = 60.0
DEFAULT_RATE_HZ = 2.5
DEFAULT_SIGMA = 1.1     # [m] slow error per axis
DEFAULT_TAU = 60.0      # [s]
DEFAULT_WHITE = 0.05    # [m] per axis
DEFAULT_DECLARED = 1.1  # [m] per horizontal axis


class GpsModel:
    """The receiver's settings (see above)."""

    def __init__(self, datum=DEFAULT_DATUM, heading_deg=DEFAULT_HEADING_DEG,
                 rate_hz=DEFAULT_RATE_HZ, sigma=DEFAULT_SIGMA, tau=DEFAULT_TAU,
                 white=DEFAULT_WHITE, declared=DEFAULT_DECLARED):
        if not (rate_hz > 0 and tau > 0 and sigma >= 0 and white >= 0 and declared > 0):
            raise ValueError("GPS: rate, tau and declared must be > 0, sigma and white >= 0")
        self.datum, self.heading = tuple(datum), math.radians(heading_deg)
        self.rate_hz, self.sigma, self.tau = rate_hz, sigma, tau
        self.white, self.declared = white, declared


class GaussMarkov:
    """One axis of the slow error: a first-order Gauss-Markov process sampled every dt."""

    def __init__(self, rng, sigma, tau, dt):
        self.rng, self.sigma = rng, sigma
        self.phi = math.exp(-dt / tau)
        self.value = rng.gauss(0.0, sigma)

    def step(self):
        """The current value, then one step on."""
        value = self.value
        self.value = self.phi * value + math.sqrt(1.0 - self.phi ** 2) * self.rng.gauss(0.0, self.sigma)
        return value


def ecef_to_geodetic(x, y, z):
    """WGS84 latitude, longitude [deg] and height [m] of an ECEF point (iterated to convergence:
    the latitude to 1e-15 rad, about 6e-9 m)."""
    lon = math.atan2(y, x)
    p = math.hypot(x, y)
    lat = math.atan2(z, p * (1.0 - gr.WGS84_E2))
    for _ in range(20):
        n = gr.WGS84_A / math.sqrt(1.0 - gr.WGS84_E2 * math.sin(lat) ** 2)
        h = p / math.cos(lat) - n
        new = math.atan2(z, p * (1.0 - gr.WGS84_E2 * n / (n + h)))
        if abs(new - lat) < 1e-15:
            lat = new
            break
        lat = new
    n = gr.WGS84_A / math.sqrt(1.0 - gr.WGS84_E2 * math.sin(lat) ** 2)
    return math.degrees(lat), math.degrees(lon), p / math.cos(lat) - n


def enu_to_geodetic(datum, east, north, up):
    """Latitude, longitude [deg] and height [m] of the point (east, north, up) [m] about the
    datum (lat, lon, h): the transpose of gps_reference.ecef_to_enu's rotation."""
    lat, lon = math.radians(datum[0]), math.radians(datum[1])
    sl, cl, so, co = math.sin(lat), math.cos(lat), math.sin(lon), math.cos(lon)
    x0, y0, z0 = gr.geodetic_to_ecef(*datum)
    return ecef_to_geodetic(x0 - so * east - sl * co * north + cl * co * up,
                            y0 + co * east - sl * so * north + cl * so * up,
                            z0 + cl * north + sl * up)


def fixes(model, rng, states, n_ms, phase_ms=0):
    """[(t_ms, east, north, up, lat, lon, alt)] of the fixes every 1 / rate s from phase_ms;
    states[k] is the true (x, y, ...) at k ms; the error drawn from rng."""
    period_ms = int(round(1000.0 / model.rate_hz))
    dt = period_ms * 1e-3
    slow = [GaussMarkov(rng, model.sigma, model.tau, dt) for _ in range(3)]
    c, s = math.cos(model.heading), math.sin(model.heading)
    out = []
    for k in range(phase_ms, n_ms + 1, period_ms):
        x, y = states[k][0], states[k][1]
        errors = [g.step() + rng.gauss(0.0, model.white) for g in slow]
        east = c * x - s * y + errors[0]
        north = s * x + c * y + errors[1]
        up = 2.0 * errors[2]
        out.append((k, east, north, up) + enu_to_geodetic(model.datum, east, north, up))
    return out


def fix_message(model, seq, stamp, lat, lon, alt):
    """The sensor_msgs/NavSatFix of one fix (status FIX, GPS service, APPROXIMATED)."""
    from sensor_msgs.msg import NavSatFix, NavSatStatus

    msg = NavSatFix()
    msg.header.seq = seq
    msg.header.stamp = stamp
    msg.header.frame_id = "base_link"
    msg.status.status = NavSatStatus.STATUS_FIX
    msg.status.service = NavSatStatus.SERVICE_GPS
    msg.latitude, msg.longitude, msg.altitude = lat, lon, alt
    var = model.declared ** 2
    msg.position_covariance = [var, 0.0, 0.0, 0.0, var, 0.0, 0.0, 0.0, 4.0 * var]
    msg.position_covariance_type = NavSatFix.COVARIANCE_TYPE_APPROXIMATED
    return msg
