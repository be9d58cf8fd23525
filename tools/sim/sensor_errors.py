"""Error models of real mobile-robot sensors, shared by the bag simulators in tools/sim/
(pioneer_sim.py, diff_drive_sim.py, soccer_sim.py). See doc/bags.md, "Realistic error
options", for the models, their parameters and where the values come from.

Every model is off by default: an ErrorProfile built from the default command-line
options is inactive, the simulators then take exactly their old code paths and draw
nothing from any random stream, so the shipped bags stay byte-identical. The models draw
from their own streams (simbag.rng(robot, seed, "err", name)), never from the streams of
the original noise sources, so switching one model on leaves the other noise unchanged.

Models (each a small class or function, tested against closed forms in
test/eval/test_sensor_errors.py):

  skid_track_speeds   skid-steer slip: the ground speeds of the two tracks for a true body
                      motion (v, omega) when the effective track is chi times the track the
                      consumer assumes, plus a slip-rate disturbance s; the wheels' yaw rate
                      is then chi * omega + s
  GaussMarkov         first-order Gauss-Markov (Ornstein-Uhlenbeck) process, exact
                      discretisation, stationary start (the slip disturbance s)
  RandomWalk          bias random walk: variance grows as sigma^2 t
  radius_scales       wheel-radius error and its change with the lateral load transfer in
                      turns
  TickCounter         encoder quantisation: cumulative travel rounded to whole ticks
  GyroErrors          gyro bias (initial value plus random walk) and scale-factor error
  tilt_leakage        gravity leaking into the horizontal axes of a tilted accelerometer
  Transport           transport latency with jitter, dropped and duplicated messages
  driver_twist        odometry driver converting wheel speeds with a (possibly wrong)
                      wheel separation
"""

import argparse
import math

import simbag

G = 9.80665


# ------------------------------------------------------------------- stochastic processes
class RandomWalk:
    """x[k+1] = x[k] + N(0, sigma^2 dt): a Wiener process sampled every dt, so that
    var(x(t) - x(0)) = sigma^2 t. sigma in [unit / sqrt(s)]."""

    def __init__(self, r, sigma, dt, x0=0.0):
        self.r = r
        self.step_std = sigma * math.sqrt(dt)
        self.x = x0

    def step(self):
        if self.step_std > 0.0:
            self.x += self.r.gauss(0.0, self.step_std)
        return self.x


class GaussMarkov:
    """First-order Gauss-Markov process dx/dt = -x/tau + w with stationary std *std*,
    discretised exactly: x[k+1] = a x[k] + std sqrt(1 - a^2) n[k], a = exp(-dt/tau), and
    started from its stationary distribution, so var(x[k]) = std^2 for every k and
    corr(x[k], x[k+j]) = a^j."""

    def __init__(self, r, std, tau, dt):
        self.r = r
        self.a = math.exp(-dt / tau) if tau > 0.0 else 0.0
        self.q = std * math.sqrt(1.0 - self.a * self.a)
        self.x = r.gauss(0.0, std) if std > 0.0 else 0.0

    def step(self):
        if self.q > 0.0:
            self.x = self.a * self.x + self.r.gauss(0.0, self.q)
        return self.x


# ------------------------------------------------------------------- wheels and tracks
def skid_track_speeds(v, omega, track, chi=1.0, slip_rate=0.0):
    """Ground speeds (left, right) [m/s] of the two wheel tracks of a skid-steer robot whose
    body moves with forward speed v and yaw rate omega.

    The instantaneous centres of rotation of the tracks lie outside the tracks, so the
    tracks' speed difference is that of a differential drive with the track width
    chi * track (chi >= 1, the ICR expansion factor); slip_rate [rad/s] adds the
    floor's unmodelled, time-varying slip. A consumer that converts the wheel speeds with
    *track* sees the yaw rate (right - left) / track = chi * omega + slip_rate, so that
    with slip_rate = 0 the true yaw rate is exactly the wheels' one divided by chi.
    """
    half = 0.5 * track * (chi * omega + slip_rate)
    return v - half, v + half


def slip_gate(v, omega, track, full_speed=0.1):
    """Share of the slip disturbance present at body motion (v, omega): 0 at rest (a
    standing robot's wheels do not turn), rising linearly with the faster track's speed
    |v| + |omega| track / 2 to 1 at full_speed [m/s] and above."""
    return min(1.0, (abs(v) + 0.5 * track * abs(omega)) / full_speed)


def radius_scales(eps_left, eps_right, load_coef, lateral_accel):
    """Effective rolling radius of the left and right wheels relative to the nominal one.

    eps_*: static radius error (tyre wear, pressure, payload), as a fraction.
    load_coef: fractional radius change per g of lateral acceleration. In a turn with
    lateral (centripetal) acceleration a_lat = v omega > 0 (turning left) the load moves
    to the outer, right wheels: their tyres are compressed (radius smaller), the inner
    left ones relieved (radius larger). Returns (1 + eps_l + c a/g, 1 + eps_r - c a/g).
    """
    d = load_coef * lateral_accel / G
    return 1.0 + eps_left + d, 1.0 + eps_right - d


class TickCounter:
    """Encoder quantisation: counts the ticks of the cumulative travel of one wheel,
    count = round(travel / step), and reports the speed over a sample period from the
    change of the count. The reported cumulative travel count * step is never more than
    step / 2 away from the true one, and the speeds of consecutive periods sum to it."""

    def __init__(self, step):
        self.step = step
        self.travel = 0.0
        self.count = 0

    def advance(self, distance):
        self.travel += distance

    def reading(self):
        """Cumulative travel as the counter reports it: round(travel / step) * step."""
        return int(round(self.travel / self.step)) * self.step

    def speed(self, period_s):
        count = int(round(self.travel / self.step))
        ds = (count - self.count) * self.step
        self.count = count
        return ds / period_s


def wheel_speed_samples(r_slip, states, dt, track, sample_steps, profile):
    """Speeds (left, right) [m/s] the two wheels' encoders report at the integration steps
    in *sample_steps* (increasing), for the true motion *states* (one (x, y, theta, v,
    omega) per step of dt seconds), under the profile's skid-steer slip (chi, gated
    Gauss-Markov slip rate), wheel-radius errors with load transfer and encoder
    quantisation. A wheel reports its ground speed divided by its radius scale (the
    encoder counts turns and converts them with the nominal radius). Without tick
    quantisation the report is the instantaneous speed at the sample step; with it, the
    ticks counted since the previous sample over the time since then. Returns
    {step: (left, right, true_left, true_right)}, true_* being the tracks' ground speeds."""
    p = profile
    slip = GaussMarkov(r_slip, p.slip_std, p.slip_tau, dt)
    counters = (TickCounter(p.encoder_step), TickCounter(p.encoder_step)) if p.encoder_step > 0 else None
    wanted = set(sample_steps)
    last_sample = 0
    out = {}
    for j, state in enumerate(states):
        v, w = state[3], state[4]
        s = slip.step() * slip_gate(v, w, track)
        left, right = skid_track_speeds(v, w, track, p.slip_chi, s)
        sl, sr = radius_scales(p.radius_error_left, p.radius_error_right, p.radius_load_coef, v * w)
        ml, mr = left / sl, right / sr
        if j in wanted:
            if counters is None:
                out[j] = (ml, mr, left, right)
            else:
                period = max(j - last_sample, 1) * dt
                out[j] = (counters[0].speed(period), counters[1].speed(period), left, right)
            last_sample = j
        if counters is not None:
            counters[0].advance(ml * dt)
            counters[1].advance(mr * dt)
    return out


def driver_twist(left, right, track, separation_scale=1.0):
    """What an odometry driver reports from the wheel speeds when it believes the wheel
    separation is separation_scale * track: v = (l + r)/2, omega = (r - l)/(scale track).
    A separation that is too small (scale < 1) makes the odometry turn 1/scale times too
    far."""
    return 0.5 * (left + right), (right - left) / (separation_scale * track)


# ------------------------------------------------------------------- inertial sensors
class GyroErrors:
    """Gyro yaw-rate output (1 + scale) omega + b(t), b a random walk from b0 with sigma
    [rad/s/sqrt(s)], advanced once per sample (dt) before the sample is taken."""

    def __init__(self, r, b0, sigma, scale, dt):
        self.walk = RandomWalk(r, sigma, dt, b0)
        self.scale = scale

    def measure(self, omega):
        b = self.walk.step()
        return (1.0 + self.scale) * omega + b

    @property
    def bias(self):
        return self.walk.x


def tilt_leakage(roll, pitch):
    """Specific force of gravity in the frame of an accelerometer tilted by roll and
    pitch (about its x and y axes, tf2 convention, the body level), minus the (0, 0, g) an
    untilted sensor reads: R^T (0, 0, g) - (0, 0, g) with R = Ry(pitch) Rx(roll), i.e.
    (-g sin(pitch), g sin(roll) cos(pitch), g cos(roll) cos(pitch) - g)."""
    return (-G * math.sin(pitch), G * math.sin(roll) * math.cos(pitch),
            G * math.cos(roll) * math.cos(pitch) - G)


# ------------------------------------------------------------------- transport
class Transport:
    """Delivery of one topic's messages from the sensor to the recorder.

    Each message is lost with probability p_drop, otherwise delivered after
    latency = base + jitter, with the jitter exponential with mean *jitter* (>= 0, so
    latency >= base, mean base + jitter, std jitter); with probability p_dup it is
    delivered a second time dup_gap later (a re-sent message: same content, same stamp,
    same seq). Messages of one topic travel one connection in order: an arrival is never
    earlier than the previous one. Times in integer ns."""

    def __init__(self, r, base_ns, jitter_ns, p_drop=0.0, p_dup=0.0, dup_gap_ns=1000000):
        self.r = r
        self.base_ns = int(base_ns)
        self.jitter_ns = float(jitter_ns)
        self.p_drop, self.p_dup = p_drop, p_dup
        self.dup_gap_ns = int(dup_gap_ns)
        self.last_ns = None
        self.sent = self.dropped = self.duplicated = 0

    def deliver(self, t_ns):
        """Arrival times (bag times) of the message stamped t_ns: [], [a] or [a, a + gap]."""
        self.sent += 1
        # one draw of each kind per message, whatever the outcome, so that the streams do
        # not depend on earlier outcomes
        u_drop, u_dup = self.r.random(), self.r.random()
        jitter = self.r.expovariate(1.0 / self.jitter_ns) if self.jitter_ns > 0.0 else 0.0
        if u_drop < self.p_drop:
            self.dropped += 1
            return []
        arrival = t_ns + self.base_ns + int(round(jitter))
        if self.last_ns is not None and arrival < self.last_ns:
            arrival = self.last_ns
        out = [arrival]
        if u_dup < self.p_dup:
            self.duplicated += 1
            out.append(arrival + self.dup_gap_ns)
        self.last_ns = out[-1]
        return out

    def add(self, bag, topic, msg, t_ns):
        """Add *msg* (sampled at t_ns) to the BagBuilder at its arrival time(s)."""
        for arrival in self.deliver(t_ns):
            bag.add(topic, msg, arrival)


def emit(bag, transport, topic, msg, t_ns):
    """bag.add at the sample time, or through *transport* when it is not None."""
    if transport is None:
        bag.add(topic, msg, t_ns)
    else:
        transport.add(bag, topic, msg, t_ns)


# ------------------------------------------------------------------- profile and options
class ErrorProfile:
    """Parameters of all models; the defaults switch every model off."""

    FIELDS = {
        # name: (default, unit/help)
        "slip_chi": (1.0, "skid-steer ICR expansion factor chi: the tracks' effective width over the "
                          "track the consumer converts wheel speeds with (1 = no slip)"),
        "slip_std": (0.0, "std of the floor's time-varying slip rate added to the wheels' yaw rate [rad/s]"),
        "slip_tau": (1.0, "correlation time of that slip rate [s]"),
        "lateral_slip": (0.0, "lateral slip in turns: true side velocity = -K v omega, K in [s]"),
        "radius_error_left": (0.0, "static radius error of the left wheels (fraction)"),
        "radius_error_right": (0.0, "static radius error of the right wheels (fraction)"),
        "radius_load_coef": (0.0, "radius change per g of lateral acceleration (load transfer, fraction/g)"),
        "encoder_step": (0.0, "encoder travel quantum [m] (0 = no tick quantisation)"),
        "gyro_bias_init": (0.0, "initial gyro yaw-rate bias [rad/s] (diff_drive_sim: added to --gyro-bias on the yaw axis)"),
        "gyro_bias_rw": (0.0, "gyro bias random walk [rad/s/sqrt(s)]"),
        "gyro_scale": (0.0, "gyro scale-factor error (fraction)"),
        "accel_bias": (0.0, "constant accelerometer bias added to each axis [m/s^2]"),
        "accel_bias_rw": (0.0, "accelerometer bias random walk [m/s^2/sqrt(s)] on each axis"),
        "tilt_roll": (0.0, "accelerometer/IMU mounting or floor tilt, roll [rad]"),
        "tilt_pitch": (0.0, "accelerometer/IMU mounting or floor tilt, pitch [rad]"),
        "imu_latency_ms": (0.0, "IMU transport latency, fixed part [ms]"),
        "imu_jitter_ms": (0.0, "IMU transport latency, mean of the exponential jitter [ms]"),
        "wheel_latency_ms": (0.0, "wheel/odometry transport latency, fixed part [ms]"),
        "wheel_jitter_ms": (0.0, "wheel/odometry latency, mean of the exponential jitter [ms]"),
        "drop_prob": (0.0, "probability that a sensor message is lost"),
        "dup_prob": (0.0, "probability that a sensor message is recorded twice"),
        "odom_separation_scale": (1.0, "odometry driver's wheel separation over the true one "
                                       "(diff_drive_sim only; < 1 makes odometry over-turn)"),
    }

    def __init__(self, **values):
        for name, (default, _) in self.FIELDS.items():
            setattr(self, name, float(values.pop(name, default)))
        if values:
            raise TypeError("unknown error parameters: %s" % sorted(values))

    def defaults(self):
        return {name: d for name, (d, _) in self.FIELDS.items()}

    def changed(self, *names):
        d = self.defaults()
        names = names or tuple(d)
        return any(getattr(self, n) != d[n] for n in names)

    @property
    def active(self):
        return self.changed()

    @property
    def wheels_active(self):
        return self.changed("slip_chi", "slip_std", "lateral_slip", "radius_error_left", "radius_error_right",
                            "radius_load_coef", "encoder_step", "odom_separation_scale")

    @property
    def gyro_active(self):
        return self.changed("gyro_bias_init", "gyro_bias_rw", "gyro_scale")

    @property
    def accel_active(self):
        return self.changed("accel_bias", "accel_bias_rw", "tilt_roll", "tilt_pitch")

    @property
    def transport_active(self):
        return self.changed("imu_latency_ms", "imu_jitter_ms", "wheel_latency_ms", "wheel_jitter_ms",
                            "drop_prob", "dup_prob")

    def transport(self, robot, seed, topic, kind):
        """Transport of *topic* (kind "imu" or "wheel"), or None when all transport errors are off."""
        if not self.transport_active:
            return None
        base = getattr(self, kind + "_latency_ms")
        jitter = getattr(self, kind + "_jitter_ms")
        return Transport(simbag.rng(robot, seed, "err", "transport", topic), base * 1e6, jitter * 1e6,
                         self.drop_prob, self.dup_prob)

    def summary(self):
        d = self.defaults()
        return " ".join("%s=%g" % (n, getattr(self, n)) for n in d if getattr(self, n) != d[n]) or "none"


# Calibrated sets (doc/bags.md explains each value and its source).
PRESETS = {
    # Clearpath Husky-like skid steer on a floor that differs from the one its track was
    # calibrated on; the slip rate's correlation time (0.12 s) and, through it, its std, the
    # encoder step, the latencies and the tilt read from the real Husky recording
    # (yaw_agreement.py --layout husky; doc/bags.md, "Calibration against a real recording").
    "husky": dict(slip_chi=1.15, slip_std=0.11, slip_tau=0.12, lateral_slip=0.02,
                  radius_error_left=0.005, radius_error_right=-0.003, radius_load_coef=0.02,
                  encoder_step=0.001,
                  gyro_bias_init=0.0005, gyro_bias_rw=5e-5, gyro_scale=0.01,
                  accel_bias=0.05, accel_bias_rw=0.002, tilt_roll=0.01, tilt_pitch=-0.01,
                  imu_latency_ms=2.0, imu_jitter_ms=2.0, wheel_latency_ms=0.4, wheel_jitter_ms=0.75,
                  drop_prob=0.002, dup_prob=0.001),
}


def add_arguments(parser, presets=PRESETS, skip=()):
    """Add --realistic PRESET and one option per error parameter (default: off)."""
    group = parser.add_argument_group("realistic sensor errors (all off by default; see doc/bags.md)")
    group.add_argument("--realistic", choices=sorted(presets), default=None,
                       help="switch on a calibrated set of errors; single options below override it")
    for name, (default, text) in ErrorProfile.FIELDS.items():
        if name in skip:
            continue
        group.add_argument("--" + name.replace("_", "-"), type=float, default=None, metavar="X",
                           help="%s (default %g)" % (text, default))
    return group


def profile_from_args(args, presets=PRESETS):
    values = dict(presets[args.realistic]) if getattr(args, "realistic", None) else {}
    for name in ErrorProfile.FIELDS:
        value = getattr(args, name, None)
        if value is not None:
            values[name] = value
    profile = ErrorProfile(**values)
    if profile.slip_chi <= 0 or profile.odom_separation_scale <= 0:
        raise argparse.ArgumentTypeError("--slip-chi and --odom-separation-scale must be positive")
    if not 0.0 <= profile.drop_prob < 1.0 or not 0.0 <= profile.dup_prob <= 1.0:
        raise argparse.ArgumentTypeError("--drop-prob and --dup-prob must be probabilities")
    if profile.encoder_step < 0 or profile.slip_std < 0 or profile.slip_tau <= 0:
        raise argparse.ArgumentTypeError("--encoder-step, --slip-std must be >= 0, --slip-tau > 0")
    return profile
