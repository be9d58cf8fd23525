#!/usr/bin/python3
"""The page and the plots of tools/eval/chapter5_report.py, from its measurements."""

import math
import os

import evaluate

METRICS = {
    "final": lambda ev: ev.final_pos_err,
    "rmse": lambda ev: ev.rmse_pos,
    "heading": lambda ev: abs(ev.final_heading_err_deg)
    if ev.final_heading_err_deg is not None else None,
}


class Measurements:
    """Replays and evaluations per bag; statistics over the bags."""

    def __init__(self, bags, paths, runs, replays, truths, twists, trajectories, evaluations):
        self.bags = bags
        self.paths = paths
        self.runs = runs
        self.replays = replays  # bag -> run label -> (csv, us per step)
        self.truths = truths  # bag -> Trajectory
        self.twists = twists  # bag -> (t, v, omega) of ground_truth/twist
        self.trajectories = trajectories  # bag -> path label -> Trajectory
        self.evaluations = evaluations  # bag -> path label -> Evaluation

    def has(self, label):
        return all(label in self.evaluations[b] for b in self.bags)

    def values(self, label, metric):
        return [METRICS[metric](self.evaluations[b][label]) for b in self.bags]

    def stat(self, label, metric):
        return evaluate.mean_spread(self.values(label, metric))

    def times(self, run):
        return [self.replays[b][run][1] for b in self.bags]

    def time_stat(self, run):
        return evaluate.mean_spread(self.times(run))

    def wins(self, a, b, metric="final"):
        """In how many bags path a has the smaller metric than path b."""
        return sum(1 for x, y in zip(self.values(a, metric), self.values(b, metric)) if x < y)

    def distance(self, a, b, bag):
        """RMS distance between the paths a and b of one bag (b interpolated at a's stamps)."""
        return evaluate.evaluate(self.trajectories[bag][a], self.trajectories[bag][b]).rmse_pos

    def distance_stat(self, a, b):
        return evaluate.mean_spread([self.distance(a, b, bag) for bag in self.bags])

    def final_distance_stat(self, a, b):
        """Distance between the final positions of paths a and b."""
        return evaluate.mean_spread([
            evaluate.evaluate(self.trajectories[bag][a], self.trajectories[bag][b]).final_pos_err
            for bag in self.bags])

    def delayed_rmse_stat(self, label, periods, period_s):
        """RMSE of a path taken `periods` estimation periods earlier (its delay removed)."""
        return evaluate.mean_spread([
            evaluate.evaluate(evaluate.shift_trajectory(self.trajectories[bag][label],
                                                        -periods * period_s),
                              self.truths[bag]).rmse_pos for bag in self.bags])

    def bag_name(self, bag):
        return os.path.splitext(os.path.basename(bag))[0]


def numbers(m):
    """Every measured number, for --json."""
    out = {"bags": [m.bag_name(b) for b in m.bags], "paths": {}, "us_per_step": {}}
    for p in m.paths:
        out["paths"][p.label] = {metric: m.values(p.label, metric) for metric in METRICS}
    for r in m.runs:
        out["us_per_step"][r.label] = m.times(r.label)
    return out


# -----------------------------------------------------------------------------
# Formatting
# -----------------------------------------------------------------------------
def pm(stat, digits=3, unit=""):
    """'mean ± spread' of a (mean, spread) pair."""
    mean, spread = stat
    if mean is None:
        return "-"
    return "%.*f ± %.*f%s" % (digits, mean, digits, spread, unit)


def pm_auto(stat):
    """mean ± spread with 3 significant digits of the mean (times span 0.1 to 1000 us)."""
    mean, spread = stat
    if mean is None:
        return "-"
    digits = max(0, 2 - int(math.floor(math.log10(abs(mean))))) if mean else 2
    return pm(stat, digits)


def table(header, rows, numeric=True):
    """Markdown table; numeric: the columns after the first right-aligned."""
    lines = ["| " + " | ".join(header) + " |",
             "| --- |" + (" ---: |" if numeric else " --- |") * (len(header) - 1)]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(lines)


def accuracy_table(m, rows, with_time=False):
    """rows: (display label, path label, run label or None)."""
    header = ["filter", "final position error [m]", "position RMSE [m]",
              "final heading error [deg]"]
    if with_time:
        header.append("time per step [us]")
    body = []
    for shown, label, run in rows:
        if not m.has(label):
            continue
        r = [shown, pm(m.stat(label, "final")), pm(m.stat(label, "rmse")),
             pm(m.stat(label, "heading"), 2)]
        if with_time:
            r.append(pm_auto(m.time_stat(run)) if run else "-")
        body.append(r)
    return table(header, body)


# -----------------------------------------------------------------------------
# Plots (first bag)
# -----------------------------------------------------------------------------
DPI = 72


def plot_paths(m, name, img_dir, labels, title, limit=None):
    bag = m.bags[0]
    results = [(shown, m.trajectories[bag][label], m.evaluations[bag][label])
               for shown, label in labels if label in m.evaluations[bag]]
    path = os.path.join(img_dir, name)
    evaluate.plot_paths(path, m.truths[bag], results, "%s, %s" % (title, m.bag_name(bag)),
                        limit=limit, dpi=DPI)
    return path


def _window(t, t0, t1):
    return [i for i, s in enumerate(t) if t0 <= s <= t1]


def plot_signals(m, name, img_dir, title, ylabel, truth_series, series, window):
    """Signals over time (Fig. 5.5, 5.12): truth_series = (label, t, values) or None;
    series: (label, run label, CSV column, step style)."""
    plt = evaluate._pyplot()
    bag = m.bags[0]
    t0 = m.truths[bag].t[0]
    fig, ax = plt.subplots(figsize=(10, 4.2))
    if truth_series:  # underneath, wide and grey, so that the estimates stay visible
        label, t, values = truth_series
        idx = _window([s - t0 for s in t], *window)
        ax.plot([t[i] - t0 for i in idx], [values[i] for i in idx], "-", color="black", lw=3.0,
                alpha=0.3, label=label)
    for label, run, column, style in series:
        t, cols = evaluate.read_csv_columns(m.replays[bag][run][0], [column])
        idx = _window([s - t0 for s in t], *window)
        kw = dict(lw=1.0, label=label)
        if style == "steps":
            ax.step([t[i] - t0 for i in idx], [cols[column][i] for i in idx], where="post", **kw)
        else:
            ax.plot([t[i] - t0 for i in idx], [cols[column][i] for i in idx], **kw)
    ax.set_xlabel("time since start (s)")
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="best")
    ax.set_title("%s, %s" % (title, m.bag_name(bag)))
    fig.tight_layout()
    path = os.path.join(img_dir, name)
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return path


def true_acceleration(m):
    """(t, a) of the first bag: the ground truth's linear velocity differentiated."""
    t, v, _ = m.twists[m.bags[0]]
    ta = [(t[k] + t[k + 1]) / 2 for k in range(len(t) - 1)]
    a = [(v[k + 1] - v[k]) / (t[k + 1] - t[k]) for k in range(len(t) - 1)]
    return ta, a



# -----------------------------------------------------------------------------
# The page
# -----------------------------------------------------------------------------
# Thesis Table 5.3: execution time per estimation step [ms] on the robot's CPU (Mamba
# EBX-37, dual core 2.26 GHz), with the particle counts N.
THESIS_TABLE_5_3 = {"nav3ctrl_ekf": 1.6, "nav3ctrl_ukf": 5.8, "nav3ctrl_pf": 180.0,
                    "nav3red_kf": 0.8, "nav3red_ekf": 1.1, "nav3red_ukf": 4.0,
                    "nav3red_pf": 79.0}
THESIS_NAV3CTRL_KF_MS = 0.9
MODEL_INFO = {
    "nav1": "gyroscope, accelerometer",
    "nav1ctrl": "gyroscope, accelerometer, cmd_vel",
    "nav2": "wheels",
    "nav2ctrl": "wheels, cmd_vel",
    "nav3": "gyroscope, accelerometer, wheels",
    "nav3ctrl": "gyroscope, accelerometer, wheels, cmd_vel",
    "nav3red": "as nav3ctrl, state (ω, v, a) only",
}


def yes_no(flag):
    return "**yes**" if flag else "**no**"


def mean_of(m, label, metric="final"):
    return m.stat(label, metric)[0]


def wins_text(m, a, b, metric="final"):
    return "%d of %d bags" % (m.wins(a, b, metric), len(m.bags))


# A difference counts when it has the same sign in every bag and changes the mean by more
# than this fraction; otherwise the page calls it "no clear difference".
CLEAR_CHANGE = 0.10


def compare(m, a, b, metric="final"):
    """How path a compares with path b: ('smaller' | 'larger' | 'no clear difference',
    relative change of the mean, bags where a is smaller)."""
    ma, mb = mean_of(m, a, metric), mean_of(m, b, metric)
    rel = (ma - mb) / mb
    k = m.wins(a, b, metric)
    if k == len(m.bags) and rel < -CLEAR_CHANGE:
        return "smaller", rel, k
    if k == 0 and rel > CLEAR_CHANGE:
        return "larger", rel, k
    return "no clear difference", rel, k


def change_text(m, a, b, metric="final"):
    word, rel, k = compare(m, a, b, metric)
    return "%s (%+.0f %%, smaller in %d of %d bags)" % (word, 100 * rel, k, len(m.bags))


def dist(stat):
    """A (mean, spread) distance in mm below 1 cm, else in m."""
    mean, spread = stat
    if mean < 0.01:
        return "%.1f ± %.1f mm" % (1000 * mean, 1000 * spread)
    return "%.3f ± %.3f m" % (mean, spread)


def add_images(sec, *images):
    """Appends the plots (file name, alt text) to a section, one paragraph each."""
    for name, alt in images:
        sec.append("![%s](img/chapter5/%s)" % (alt, name))
        sec.append("")


def write(m, ctx, out_path, img_dir):
    """Writes the page and its plots; returns (page path, plot paths)."""
    figures = []
    n = len(m.bags)
    bag_list = ", ".join("`%s`" % m.bag_name(b) for b in m.bags)
    lengths = ", ".join("%.0f s" % (m.truths[b].t[-1] - m.truths[b].t[0]) for b in m.bags)
    out = []
    w = out.append

    w("# Chapter 5 experiments on the shipped Pioneer bags")
    w("")
    w("This page repeats the comparisons of the thesis's chapter 5 (Pioneer 3-AT dead "
      "reckoning) with the nodes of `config/` ([pioneer.md](pioneer.md)) on the bags %s "
      "(%s). It is generated: the numbers, verdicts and plots below come from one run of "
      "the command at the end; only the explanations are written by hand." % (bag_list, lengths))
    w("")
    w("**The bags are simulated, with the errors of a real skid-steer base** "
      "([bags.md](bags.md#realistic-error-options)). The true motion follows the skid-steer "
      "model of eqs. 5.17–5.18, but the sensors see it through the simulator's realistic "
      "error set (`--realistic husky`, calibrated on a real Husky recording): the wheels' "
      "effective track is 15 % wider than the one the filters convert with, so the wheels "
      "report 1.15 times the true yaw rate, plus a drifting slip rate (std 0.11 rad/s, 0.12 s "
      "correlation time), radius errors and their change with load in turns, 1 mm encoder "
      "ticks on top of the 1.4 mm/s noise and 1 mm/s rounding; the gyroscope has a drifting "
      "bias (0.5 mrad/s at the start, random walk 0.05 mrad/s/√s) and a 1 % scale error on "
      "top of its white noise; the accelerometer its heavy noise (0.5 m/s²), the drifting "
      "bias of Fig. 5.15, a further bias and the leakage of a 0.01 rad tilt; the messages "
      "arrive 0.4 to 4 ms late with jitter, and 0.2 % are lost, 0.1 % duplicated. Wheel "
      "slip and the wheels' heading drift are the effects the thesis names to explain its "
      "ranking of the models. The same runs without these errors are compared at the end "
      "([On the ideal bags](#on-the-ideal-bags)).")
    w("")
    w("Every number is the mean ± the sample standard deviation over the %d bags. *Final "
      "error*: distance between the last estimate and the true final position (the thesis's "
      "measure: the robot returns to its start); *RMSE*: root mean square position error "
      "along the path; *heading*: |final heading error|. Nodes without a pose in their state "
      "(nav3red, the averaging) and the particle filters get their path offline from their "
      "logged velocities, as in the thesis ([pioneer.md](pioneer.md#nodes-without-a-pose)). "
      "Plots show `%s`." % (n, m.bag_name(m.bags[0])))
    w("")
    w("The alignment policies of issue 5 (AVERAGE, LAST, SAMPLED, HOLD, FILL) on these bags "
      "at a 10 ms period, and the soccer robot's centralised filter against its fusion block, "
      "are on their own page: [multirate_experiments.md](multirate_experiments.md).")
    w("")

    # ---------------------------------------------------------------- summary
    best_ukf = min((mo for mo in MODELS_WITH_POSE if m.has(mo + "_ukf")),
                   key=lambda mo: mean_of(m, mo + "_ukf"))
    summary = []

    # ---------------------------------------------------------------- 5.2.2
    sec = []
    sec.append("## 5.2.2 From averaging to estimation")
    sec.append("")
    sec.append("The thesis: integrating the averaged accelerometer and gyroscope (\"raw\") gives "
               "an unusable path because of the accelerometer's bias; nav1, an estimator whose "
               "model holds a and ω constant, is no better than that averaging; fusing cmd_vel "
               "(nav1ctrl) makes the same bad sensor useful (Figs. 5.5, 5.6, with EKFs). The "
               "robot's own wheel odometry (\"rosaria\") is the reference.")
    sec.append("")
    sec.append(accuracy_table(m, [
        ("averaging of gyroscope and accelerometer (\"raw\", `nav1_moving_average`)",
         "nav1_moving_average", None),
        ("nav1 EKF", "nav1_ekf", None),
        ("nav1ctrl EKF", "nav1ctrl_ekf", None),
        ("averaging of the wheel speeds (wheel odometry, `nav2_moving_average`)",
         "nav2_moving_average", None),
        ("nav2 EKF (wheels)", "nav2_ekf", None),
    ]))
    sec.append("")
    d_raw = m.distance_stat("nav1_ekf", "nav1_moving_average")
    raw_final = mean_of(m, "nav1_moving_average")
    nav1_same = d_raw[0] < 0.05 * raw_final
    ctrl_better = m.wins("nav1ctrl_ekf", "nav1_ekf") == n
    d_odo = m.distance_stat("nav2_ekf", "nav2_moving_average")
    sec.append("- nav1 is an averaging: the nav1 EKF's path lies %s (RMS distance) from the "
               "averaged path, against %.0f m final error of both: %s." % (
                   dist(d_raw), raw_final, yes_no(nav1_same)))
    sec.append("- Fusing cmd_vel makes the accelerometer useful: nav1ctrl's final error is "
               "%s m against nav1's %s m, smaller in %s: %s." % (
                   pm(m.stat("nav1ctrl_ekf", "final")), pm(m.stat("nav1_ekf", "final"), 1),
                   wins_text(m, "nav1ctrl_ekf", "nav1_ekf"), yes_no(ctrl_better)))
    sec.append("- Estimation on the wheels alone (nav2) follows plain wheel odometry: their "
               "paths are %s apart. With no second source of ω an estimator has nothing to "
               "correct the wheels' slip with, and both end %s° off in heading." % (
                   dist(d_odo), pm(m.stat("nav2_ekf", "heading"), 0)))
    sec.append("")
    sec.append("Why raw and nav1 agree: with a and ω modelled as constant and no second source "
               "for them, the Kalman gain only weighs each new period mean against the old "
               "estimate, a low-pass filter of the same inputs, and integrating the smoothed "
               "values gives nearly the same path (the thesis's explanation holds). The bias of "
               "the accelerometer (the drift of Fig. 5.15 reaches −0.11 to −0.27 m/s² by the "
               "end of the runs; the realistic set adds 0.05 m/s² and the tilt's leakage) is "
               "integrated twice into the position by both.")
    sec.append("")
    figures.append(plot_paths(m, "averaging_paths.png", img_dir, [
        ("raw (averaging)", "nav1_moving_average"), ("nav1 EKF", "nav1_ekf"),
        ("nav1ctrl EKF", "nav1ctrl_ekf"), ("wheel odometry", "nav2_moving_average")],
        "Fig. 5.6: averaging and nav1/nav1ctrl EKFs"))
    figures.append(plot_paths(m, "averaging_zoom.png", img_dir, [
        ("nav1ctrl EKF", "nav1ctrl_ekf"), ("wheel odometry", "nav2_moving_average")],
        "Fig. 5.6 right: nav1ctrl against wheel odometry", limit=1.0))
    ta, a_true = true_acceleration(m)
    figures.append(plot_signals(
        m, "acceleration.png", img_dir, "Fig. 5.5: acceleration", "a (m/s²)",
        ("true a", ta, a_true),
        [("raw (period mean of the accelerometer)", "nav1_moving_average", "x1", "steps"),
         ("nav1 EKF", "nav1_ekf", "x6", "line"), ("nav1ctrl EKF", "nav1ctrl_ekf", "x6", "line")],
        (0.0, 30.0)))
    add_images(sec,
               ("averaging_paths.png", "paths of the averaging, nav1 and nav1ctrl"),
               ("averaging_zoom.png", "nav1ctrl and wheel odometry"),
               ("acceleration.png", "acceleration: raw, nav1, nav1ctrl"))
    sec.append("As in Fig. 5.5, nav1 smooths the raw accelerometer means and nav1ctrl follows "
               "the acceleration that cmd_vel asks for; the true acceleration (black) is "
               "limited to 0.3 m/s² by the simulated robot.")
    sec.append("")
    summary.append(("5.2.2: nav1 (estimation, constant model) ≈ averaging", yes_no(nav1_same),
                    "paths %s apart, final errors ~%.0f m" % (dist(d_raw), raw_final)))
    summary.append(("5.2.2: fusing cmd_vel makes the bad accelerometer usable (nav1ctrl ≪ nav1)",
                    yes_no(ctrl_better), "%s m against %s m" % (
                        pm(m.stat("nav1ctrl_ekf", "final")),
                        pm(m.stat("nav1_ekf", "final"), 1))))
    sections = [sec]

    # ---------------------------------------------------------------- 5.2.3
    sec = []
    sec.append("## 5.2.3 Model versus reality: the models compared")
    sec.append("")
    sec.append("The thesis (Fig. 5.7, five UKFs on one run): the more information a model "
               "fuses, the smaller the error; nav3ctrl is the best; nav1ctrl came closer than "
               "nav2 and nav2ctrl, whose headings deviated (wheel drift).")
    sec.append("")
    header = ["model", "inputs", "UKF final [m]", "UKF RMSE [m]", "UKF heading [deg]",
              "EKF final [m]", "PF final [m]"]
    body = []
    for mo in MODELS_WITH_POSE + ["nav3red"]:
        ukf = mo + "_ukf"
        if not m.has(ukf):
            continue
        body.append([mo, MODEL_INFO[mo], pm(m.stat(ukf, "final")), pm(m.stat(ukf, "rmse")),
                     pm(m.stat(ukf, "heading"), 2), pm(m.stat(mo + "_ekf", "final")),
                     pm(m.stat(mo + "_pf", "final"))])
    sec.append(table(header, body))
    sec.append("")
    sec.append("(nav3red and the PF column: path computed offline from v and ω.) nav1 runs "
               "away with every method: nothing but the biased accelerometer tells v; the "
               "particle filter runs further, its v also random-walking with the particle "
               "filter's process noise.")
    sec.append("")
    pairs = [("nav1", "nav1ctrl"), ("nav2", "nav2ctrl"), ("nav3", "nav3ctrl"),
             ("nav2", "nav3"), ("nav2ctrl", "nav3ctrl"), ("nav1ctrl", "nav3ctrl")]
    lines = []
    more_info_holds = []
    more_info_larger = []
    for less, more in pairs:
        a, b = more + "_ukf", less + "_ukf"
        word, rel, k = compare(m, a, b)
        if word == "smaller":
            more_info_holds.append("%s → %s" % (less, more))
        elif word == "larger":
            more_info_larger.append("%s → %s (%+.0f %%)" % (less, more, 100 * rel))
        lines.append("| %s → %s | %s → %s | %+.0f %% | %d of %d | %s |" % (
            less, more, pm(m.stat(b, "final")), pm(m.stat(a, "final")), 100 * rel, k, n, word))
    sec.append("| more information | UKF final error [m] | change | smaller in | verdict |")
    sec.append("| --- | --- | ---: | ---: | --- |")
    sec.extend(lines)
    sec.append("")
    sec.append("(*smaller* or *larger*: in every bag, and the mean by more than %.0f %%; "
               "otherwise *no clear difference*. The same rule decides every comparison "
               "below.)" % (100 * CLEAR_CHANGE))
    sec.append("")
    nav1ctrl_beats_nav2 = (compare(m, "nav1ctrl_ukf", "nav2_ukf")[0] == "smaller" and
                           compare(m, "nav1ctrl_ukf", "nav2ctrl_ukf")[0] == "smaller")
    rivals = [mo for mo in MODELS_WITH_POSE if mo != "nav3ctrl" and
              compare(m, "nav3ctrl_ukf", mo + "_ukf")[0] != "smaller"]
    nav3ctrl_best = not rivals
    sec.append("- nav3ctrl best: %s. The smallest mean final error (UKF) is %s's, %s m; "
               "nav3ctrl %s: %s." % (
                   yes_no(nav3ctrl_best), best_ukf, pm(m.stat(best_ukf + "_ukf", "final")),
                   "has %s m" % pm(m.stat("nav3ctrl_ukf", "final")),
                   "no clear difference to " + ", ".join(rivals) if rivals else
                   "clearly smaller than every other model"))
    sec.append("- nav1ctrl closer than nav2 and nav2ctrl: %s (%s m against %s and %s m)." % (
        yes_no(nav1ctrl_beats_nav2), pm(m.stat("nav1ctrl_ukf", "final")),
        pm(m.stat("nav2_ukf", "final")), pm(m.stat("nav2ctrl_ukf", "final"))))
    ekf_steps = ["%s → %s: %s" % (less, more, change_text(m, more + "_ekf", less + "_ekf"))
                 for less, more in pairs[1:5]]
    sec.append("- The steps with the wheels, with the EKF instead of the UKF: %s." %
               "; ".join(ekf_steps))
    sec.append("- RMSE along the path: nav2 %s m, nav2ctrl %s m (%s), nav3 %s m, nav3ctrl "
               "%s m." % (pm(m.stat("nav2_ukf", "rmse")), pm(m.stat("nav2ctrl_ukf", "rmse")),
                          change_text(m, "nav2ctrl_ukf", "nav2_ukf", "rmse"),
                          pm(m.stat("nav3_ukf", "rmse")), pm(m.stat("nav3ctrl_ukf", "rmse"))))
    sec.append("")
    head = {mo: m.stat(mo + "_ukf", "heading") for mo in MODELS_WITH_POSE}
    sec.append("Where this agrees with the thesis, where not, and why. Without the wheels "
               "(nav1, nav1ctrl) cmd_vel decides between a useless and a usable path, as in the "
               "thesis. With the wheels, their slip decides: the wheels report 1.15 times the "
               "robot's yaw rate plus the floor's slip rate, and every model that takes its "
               "heading from them ends far off (final heading error, UKF: nav2 %s°, nav2ctrl "
               "%s°, nav3 %s°, nav3ctrl %s°). nav1ctrl turns by the gyroscope alone and ends "
               "%s° off, so it comes closer than nav2 and nav2ctrl, whose headings drift: the "
               "thesis's observation and its explanation hold. What does not hold is that the "
               "gyroscope of nav3 and nav3ctrl corrects that drift. With the thesis's variances "
               "(section 5.1.2) one period's pair of wheel speeds gives ω with the variance "
               "2 · 2 (mm/s)² / (0.6 m)² = 1.1e-5 (rad/s)², the gyroscope's period mean "
               "1.7e-4 (rad/s)², fifteen times more; the filter therefore weighs the wheels' ω "
               "about fifteen times more than the gyroscope's and follows the wheels' slip. "
               "Adding the gyroscope to the wheels (nav2 → nav3, nav2ctrl → nav3ctrl) then "
               "changes little, and nothing makes nav3ctrl the best model. The thesis's ranking "
               "needs a gyroscope weighted against slipping wheels: a shorter period does that "
               "(section 5.2.5 below), or a wheel variance that allows for slip, as "
               "`config/skid_steer_odom_imu.h` does for the generic robot "
               "([real_robot.md](real_robot.md)). The thesis's real runs may have had such a "
               "weighting; with the variances it lists and a 100 ms period these headers do "
               "not. Where the UKF and the EKF of one model disagree on a step (the two lists "
               "above), the final error is a single point of a path that is tens of degrees "
               "off in heading, and which of two nearly equal paths ends nearer the start is "
               "chance; the RMSE along the path ranks the models with the wheels within a few "
               "per cent of each other." % (pm(head["nav2"], 0), pm(head["nav2ctrl"], 0), pm(head["nav3"], 0),
                         pm(head["nav3ctrl"], 0), pm(head["nav1ctrl"], 1)))
    sec.append("")
    figures.append(plot_paths(m, "models.png", img_dir, [
        (mo + " UKF", mo + "_ukf") for mo in ["nav1ctrl", "nav2", "nav2ctrl", "nav3", "nav3ctrl"]],
        "Fig. 5.7: UKFs with different models", limit=1.0))
    add_images(sec,
               ("models.png", "paths of five UKFs"))
    summary.append(("5.2.3: more information gives a smaller error",
                    "in %d of %d steps" % (len(more_info_holds), len(pairs)),
                    "smaller: %s; larger: %s; no clear difference in the other steps" % (
                        ", ".join(more_info_holds) or "none",
                        ", ".join(more_info_larger) or "none")))
    summary.append(("5.2.3: nav3ctrl is the best model", yes_no(nav3ctrl_best),
                    "nav3ctrl %s m; not clearly smaller than %s; the smallest: %s %s m" % (
                        pm(m.stat("nav3ctrl_ukf", "final")), ", ".join(rivals), best_ukf,
                        pm(m.stat(best_ukf + "_ukf", "final")))
                    if rivals else "nav3ctrl %s m" % pm(m.stat("nav3ctrl_ukf", "final"))))
    summary.append(("5.2.3: nav1ctrl closer than nav2 and nav2ctrl (their headings drift)",
                    yes_no(nav1ctrl_beats_nav2), "%s m against %s and %s m; final heading "
                    "errors %s°, %s°, %s°" % (
                        pm(m.stat("nav1ctrl_ukf", "final")), pm(m.stat("nav2_ukf", "final")),
                        pm(m.stat("nav2ctrl_ukf", "final")), pm(head["nav1ctrl"], 1),
                        pm(head["nav2"], 0), pm(head["nav2ctrl"], 0))))
    sections.append(sec)

    # ---------------------------------------------------------------- 5.2.4
    sec = []
    sec.append("## 5.2.4 Execution time and the estimation methods")
    sec.append("")
    sec.append("The thesis (Table 5.3, Figs. 5.8, 5.9): Kalman filters are many times faster "
               "than the particle filter and the UKF slower than the KF and EKF; a smaller "
               "state (nav3red) is faster; all Kalman filters reach nearly the same accuracy "
               "(EKF and UKF indistinguishable), the position in the state makes no difference; "
               "the particle filter is less accurate, and its own x, y, θ are useless.")
    sec.append("")
    rows = [("nav3ctrl EKF", "nav3ctrl_ekf", "nav3ctrl_ekf"),
            ("nav3ctrl UKF", "nav3ctrl_ukf", "nav3ctrl_ukf"),
            ("nav3ctrl PF, its own pose", "nav3ctrl_pf own pose", "nav3ctrl_pf"),
            ("nav3ctrl PF, path from v, ω", "nav3ctrl_pf", "nav3ctrl_pf"),
            ("nav3ctrl PF with the thesis's R, path from v, ω", "nav3ctrl_pf thesis R", None),
            ("nav3red KF (path from v, ω)", "nav3red_kf", "nav3red_kf"),
            ("nav3red EKF (path from v, ω)", "nav3red_ekf", "nav3red_ekf"),
            ("nav3red UKF (path from v, ω)", "nav3red_ukf", "nav3red_ukf"),
            ("nav3red PF (path from v, ω)", "nav3red_pf", "nav3red_pf"),
            ("nav3red PF with the thesis's R", "nav3red_pf thesis R", None),
            ("nav3 PF (path from v, ω)", "nav3_pf", None),
            ("nav3 PF with the thesis's R", "nav3_pf thesis R", None)]
    sec.append(accuracy_table(m, rows))
    sec.append("")
    sec.append("Execution time of one estimation step (the estimator's `estimate` call, timed "
               "by the replay; the fastest of %d replays per bag, then mean ± spread over the "
               "bags), against thesis Table 5.3:" % ctx["timing_repeats"])
    sec.append("")
    header = ["model", "method", "N", "here [µs]", "thesis [ms]", "thesis / here"]
    body = []
    for run, thesis_ms in THESIS_TABLE_5_3.items():
        if run not in m.replays[m.bags[0]]:
            continue
        model, method = run.split("_")
        st = m.time_stat(run)
        body.append([model, method.upper(), "700" if run == "nav3ctrl_pf" else
                     ("500" if run == "nav3red_pf" else ""), pm_auto(st), "%g" % thesis_ms,
                     "%.0f" % (thesis_ms * 1000.0 / st[0])])
    for run, n_particles in (("nav3ctrl_pf thesis R", 700), ("nav3red_pf thesis R", 500)):
        st = m.time_stat(run)
        thesis_ms = THESIS_TABLE_5_3[run.split()[0]]
        body.append([run.split("_")[0], "PF, thesis's R", str(n_particles), pm_auto(st),
                     "%g" % thesis_ms, "%.0f" % (thesis_ms * 1000.0 / st[0])])
    body.append(["nav3ctrl", "KF", "", "– (nonlinear model)", "%g" % THESIS_NAV3CTRL_KF_MS, ""])
    sec.append(table(header, body))
    sec.append("")
    t = {r: m.time_stat(r)[0] for r in THESIS_TABLE_5_3}
    order_ok = t["nav3ctrl_ekf"] < t["nav3ctrl_ukf"] < t["nav3ctrl_pf"] and \
        t["nav3red_kf"] <= t["nav3red_ukf"] < t["nav3red_pf"]
    red_faster = all(t["nav3red_" + k] < t["nav3ctrl_" + k] for k in ("ekf", "ukf", "pf"))
    pf_factor = t["nav3ctrl_pf"] / t["nav3ctrl_ekf"]
    d_ekf_ukf = m.distance_stat("nav3ctrl_ekf", "nav3ctrl_ukf")
    f_ekf_ukf = m.final_distance_stat("nav3ctrl_ekf", "nav3ctrl_ukf")
    d_red = m.distance_stat("nav3red_kf", "nav3ctrl_ekf")
    kfs = ["nav3ctrl_ekf", "nav3ctrl_ukf", "nav3red_kf", "nav3red_ekf", "nav3red_ukf"]
    kfs_equal = all(compare(m, a, b)[0] == "no clear difference" for a in kfs for b in kfs
                    if a != b)
    pf_worse = all(compare(m, pf, kf)[0] == "larger" for pf in ("nav3ctrl_pf", "nav3red_pf")
                   for kf in kfs)
    own_useless = mean_of(m, "nav3ctrl_pf own pose") > 10 * mean_of(m, "nav3ctrl_pf")
    sec.append("- Order KF/EKF < UKF < PF: %s. The PF takes %.0f times the EKF's time "
               "(thesis: %.0f times)." % (yes_no(order_ok), pf_factor,
                                            THESIS_TABLE_5_3["nav3ctrl_pf"] /
                                            THESIS_TABLE_5_3["nav3ctrl_ekf"]))
    sec.append("- The reduced state is faster with every method: %s (EKF %.2f → %.2f µs, UKF "
               "%.2f → %.2f µs, PF %.0f → %.0f µs, the PF also with 500 instead of 700 "
               "particles)." % (yes_no(red_faster), t["nav3ctrl_ekf"], t["nav3red_ekf"],
                                t["nav3ctrl_ukf"], t["nav3red_ukf"], t["nav3ctrl_pf"],
                                t["nav3red_pf"]))
    sec.append("- All Kalman filters reach the same accuracy (no clear difference between any "
               "two of the five): %s. The EKF's and UKF's final positions lie %s apart, their "
               "paths %s (RMS), against %s m final error." % (
                   yes_no(kfs_equal), dist(f_ekf_ukf), dist(d_ekf_ukf),
                   pm(m.stat("nav3ctrl_ekf", "final"))))
    sec.append("- The position in the state makes no difference: the nav3red KF's offline "
               "path lies %s from the nav3ctrl EKF's." % dist(d_red))
    sec.append("- The PF is less accurate than every Kalman filter: %s; its own pose is "
               "useless (%s m final error, against %s m for the path from its v and ω): %s." % (
                   yes_no(pf_worse), pm(m.stat("nav3ctrl_pf own pose", "final"), 1),
                   pm(m.stat("nav3ctrl_pf", "final")), yes_no(own_useless)))
    if not own_useless:
        sec.append("- The own pose (useless: more than ten times the final error of the path "
                   "from v and ω) ends %.1f times as far off as that path here, because that "
                   "path itself carries the wheels' heading error; the own pose still ends %s "
                   "m off." % (mean_of(m, "nav3ctrl_pf own pose") / mean_of(m, "nav3ctrl_pf"),
                               pm(m.stat("nav3ctrl_pf own pose", "final"), 1)))
    if not pf_worse:
        sec.append("- Why the PF is not less accurate here: every filter carries the heading "
                   "error of the slipping wheels (the Kalman filters' final errors are %s m), "
                   "and the particle filter's own spread, which made it less accurate on the "
                   "ideal bags, is small against it (see [On the ideal bags](#on-the-ideal-bags))."
                   % pm(m.stat("nav3ctrl_ekf", "final")))
    sec.append("")
    ratios = [THESIS_TABLE_5_3[r] * 1000.0 / t[r] for r in THESIS_TABLE_5_3]
    sec.append("The times here are %.0f to %.0f times shorter than the thesis's. Part of it is "
               "the machine (a server core here, the robot's 2.26 GHz Mamba EBX-37 there), most "
               "of it the code: the thesis's original sf-pkg, built with -O2 on this machine, "
               "is quoted at 4.4 µs (KF) to 275 µs (PF) per step "
               "([benchmarks.md](benchmarks.md), not re-measured), already 180 to 650 times "
               "below its Table 5.3 (the original package builds without -O by default, see "
               "CMakeLists.txt); the estimators here are fixed-size "
               "and allocate nothing in a step, another 5 to 25 times. The ratios between the "
               "methods are algorithmic and agree in their order with the thesis: the PF's "
               "cost grows with N times the state, the UKF propagates 2n + 1 sigma points. "
               "The KF and EKF of nav3red cost about the same here, both being a few 3 × 3 "
               "products." % (min(ratios), max(ratios)))
    sec.append("")
    lost = sum(1 for v in m.values("nav3_pf thesis R", "final") if v > 1.0)
    gain = [compare(m, pf, pf + " thesis R")[0] for pf in ("nav3ctrl_pf", "nav3red_pf")]
    sec.append("The particle filters. With the thesis's variances (R of section 5.1.2) the "
               "likelihood of the wheels (1.4 mm/s) and the gyroscope (0.013 rad/s) is far "
               "narrower than the spread the particle filter's Q gives the particles in one "
               "period (0.32 m/s, 0.7 rad/s). Every period then keeps a single particle (the "
               "published variances are about 1e-30), and what the sensors see only one period "
               "later, the acceleration through v, is never estimated. With cmd_vel in the "
               "model (nav3ctrl, nav3red) a is recomputed from the command every period, so "
               "the filter still tracks; without it (nav3) a random-walks unseen, and with the "
               "thesis's R nav3's particle filter lost the track (final error over 1 m) in %d "
               "of %d bags. The shipped particle filter headers therefore weigh with all "
               "variances times 1000, which keeps several particles alive (likelihood "
               "tempering; 300 to 3000 all kept the track). Final error against the thesis's R: "
               "nav3ctrl PF %s, nav3red PF %s; a step costs somewhat more (table above), the "
               "moments being taken over many distinct particles instead of one. The own pose "
               "stays useless for the reason the thesis gives: its process "
               "noise of 0.1 on x, y, θ and Δs is never corrected by a measurement, so the "
               "particles' poses random-walk and resampling picks among them at random "
               "(Fig. 5.8)." % (lost, n, change_text(m, "nav3ctrl_pf", "nav3ctrl_pf thesis R"),
                                change_text(m, "nav3red_pf", "nav3red_pf thesis R")))
    sec.append("")
    figures.append(plot_paths(m, "methods.png", img_dir, [
        ("nav3red KF (v, ω offline)", "nav3red_kf"), ("nav3ctrl EKF", "nav3ctrl_ekf"),
        ("nav3ctrl UKF", "nav3ctrl_ukf"), ("nav3ctrl PF (v, ω offline)", "nav3ctrl_pf")],
        "Fig. 5.9: KF, EKF, UKF and PF", limit=1.0))
    figures.append(plot_paths(m, "particle_filter.png", img_dir, [
        ("nav3ctrl PF, own pose", "nav3ctrl_pf own pose"),
        ("nav3ctrl PF, path from v, ω", "nav3ctrl_pf")],
        "Fig. 5.8: the particle filter's own pose"))
    add_images(sec,
               ("methods.png", "paths of KF, EKF, UKF and PF"),
               ("particle_filter.png", "the particle filter's own pose"))
    summary.append(("5.2.4: time order KF/EKF < UKF < PF, PF many times slower",
                    yes_no(order_ok), "PF %.0f × EKF (thesis %.0f ×)" % (
                        pf_factor, THESIS_TABLE_5_3["nav3ctrl_pf"] /
                        THESIS_TABLE_5_3["nav3ctrl_ekf"])))
    summary.append(("5.2.4: the reduced state (nav3red) is faster", yes_no(red_faster),
                    "EKF %.2f → %.2f µs, UKF %.2f → %.2f µs, PF %.0f → %.0f µs" % (
                        t["nav3ctrl_ekf"], t["nav3red_ekf"], t["nav3ctrl_ukf"],
                        t["nav3red_ukf"], t["nav3ctrl_pf"], t["nav3red_pf"])))
    summary.append(("5.2.4: all Kalman filters equally accurate; EKF = UKF; pose in the "
                    "state makes no difference", yes_no(kfs_equal),
                    "final positions of EKF and UKF %s apart; nav3red KF and nav3ctrl EKF "
                    "paths %s apart" % (dist(f_ekf_ukf), dist(d_red))))
    summary.append(("5.2.4: the PF is less accurate; its own pose is useless",
                    yes_no(pf_worse and own_useless),
                    "PF %s m (v, ω offline), own pose %s m" % (
                        pm(m.stat("nav3ctrl_pf", "final")),
                        pm(m.stat("nav3ctrl_pf own pose", "final"), 1))))
    sections.append(sec)

    # ---------------------------------------------------------------- 5.2.5
    sec = []
    sec.append("## 5.2.5 Tuning")
    sec.append("")
    sec.append("The thesis (Figs. 5.10–5.12, 5.14), UKFs with nav3ctrl: a shorter period "
               "gives a better accuracy (\"the best improvement\"); R × 10 improves the result; "
               "R × 10 with a 10 ms period is better still; Q × 0.1 and Q × 0.01 (at 10 ms) "
               "give much poorer results, the velocity oscillating after every command change.")
    sec.append("")
    rows = [("(1) nav3ctrl UKF, 100 ms (section 5.1.2)", "nav3ctrl_ukf", 0.1),
            ("(2) R × 10", "nav3ctrl_ukf R*10", 0.1),
            ("(3) R × 10, 10 ms", "nav3ctrl_ukf R*10 10ms", 0.01),
            ("period 200 ms", "nav3ctrl_ukf 200ms", 0.2),
            ("period 50 ms", "nav3ctrl_ukf 50ms", 0.05),
            ("period 20 ms", "nav3ctrl_ukf 20ms", 0.02),
            ("period 10 ms", "nav3ctrl_ukf 10ms", 0.01),
            ("Q × 0.1, 10 ms", "nav3ctrl_ukf Q*0.1 10ms", 0.01),
            ("Q × 0.01, 10 ms", "nav3ctrl_ukf Q*0.01 10ms", 0.01),
            ("nav3 UKF, 100 ms", "nav3_ukf", 0.1),
            ("nav3 UKF, 20 ms", "nav3_ukf 20ms", 0.02),
            ("nav3 UKF, 10 ms", "nav3_ukf 10ms", 0.01)]
    body = []
    for shown, label, period in rows:
        body.append([shown, pm(m.stat(label, "final")), pm(m.stat(label, "rmse")),
                     pm(m.delayed_rmse_stat(label, 2, period)), pm(m.stat(label, "heading"), 2)])
    sec.append(table(["filter", "final position error [m]", "position RMSE [m]",
                      "RMSE, 2 periods earlier [m]", "final heading error [deg]"], body))
    sec.append("")
    base = "nav3ctrl_ukf"
    period_word = compare(m, base + " 10ms", base)[0]
    rmse_50 = compare(m, base + " 50ms", base, "rmse")
    r10_word = compare(m, base + " R*10", base)[0]
    q_words = [compare(m, base + q, base + " 10ms")[0] for q in (" Q*0.1 10ms", " Q*0.01 10ms")]
    d_rq = m.distance_stat(base + " R*10 10ms", base + " Q*0.1 10ms")
    sec.append("- A shorter period is better (final error): nav3ctrl 10 ms against 100 ms: %s; "
               "(3) against (1): %s." % (change_text(m, base + " 10ms", base),
                                         change_text(m, base + " R*10 10ms", base)))
    sec.append("- Along the path (RMSE): nav3ctrl 50 ms against 100 ms: %s; nav3 10 ms "
               "against 100 ms: %s." % (change_text(m, base + " 50ms", base, "rmse"),
                                        change_text(m, "nav3_ukf 10ms", "nav3_ukf", "rmse")))
    sec.append("- R × 10 against (1): %s." % change_text(m, base + " R*10", base))
    sec.append("- Q × 0.1 and Q × 0.01 against Q, all at 10 ms: %s; %s. With Q × 0.01 the "
               "velocity oscillates after every command change, as in Fig. 5.12 (figure "
               "below)." % (
        change_text(m, base + " Q*0.1 10ms", base + " 10ms"),
        change_text(m, base + " Q*0.01 10ms", base + " 10ms")))
    sec.append("- R × 10 and Q × 0.1 give the same filter: their paths at 10 ms lie %s apart. "
               "Multiplying Q and R by one factor leaves a Kalman filter's gain unchanged "
               "(P scales with them; only P0 differs, and it is forgotten within a few "
               "periods; for the UKF the width of the sigma points changes too, which matters "
               "little here). So (3) of Fig. 5.10 and 0.1 Q at 10 ms of Fig. 5.11 are one "
               "configuration: the thesis found it better than (1) and much poorer than Q at "
               "10 ms, which together would make Q at 10 ms the best of all runs." % dist(d_rq))
    sec.append("")
    sec.append("Why the period matters here. At 100 ms the filter weighs the wheels' ω about "
               "fifteen times more than the gyroscope's (section 5.2.3), so the gyroscope "
               "carries about 6 %% of the heading. At 10 ms the gyroscope (100 Hz) reports in "
               "every period and the wheels (10 Hz) in every tenth: per 100 ms ten gyroscope "
               "observations (information 10 / 1.7e-4 = 5.9e4 (rad/s)⁻²) stand against one "
               "wheel pair (1 / 1.1e-5 = 9.1e4), and the gyroscope's share rises to about 40 %%. "
               "The final heading error of nav3ctrl drops from %s° at 100 ms to %s° at 10 ms "
               "(nav3: %s° to %s°). On these bags that is what makes a shorter period better. "
               "The period also shortens the estimate's delay: the thesis's models move the "
               "pose with the previous period's velocities (x and y by Δs = v·T of the period "
               "before, eqs. 5.1, 5.5; θ by the previous ω, eq. 5.3), so the path trails the "
               "robot by about two periods; taken two periods earlier, the 100 ms path's RMSE "
               "is %s m instead of %s m (%s). Against both works eq. 5.14, which sets the "
               "acceleration to (cmd_vel.linear.x − v)/T, i.e. the robot reaches the commanded "
               "speed within one period: at 10 ms it demands ten times as much as at 100 ms, "
               "and between two wheel readings (every 100 ms) nine periods pull v to the "
               "command (figure below: the 10 ms estimate jumps to cmd_vel and back at each "
               "wheel reading). On the ideal bags, where the wheels need no correction, this "
               "made nav3ctrl's final error at 10 ms larger than at 100 ms ([On the ideal "
               "bags](#on-the-ideal-bags)); nav3, whose model does not use cmd_vel, has no such "
               "limit. The thesis's model used a hard-coded period (FILTER_T, section 5.3.1); "
               "if that stayed at 0.1 s in its 10 ms filters, its eq. 5.14 asked for the same "
               "acceleration as at 100 ms." % (
                   pm(m.stat(base, "heading"), 1), pm(m.stat(base + " 10ms", "heading"), 1),
                   pm(m.stat("nav3_ukf", "heading"), 1),
                   pm(m.stat("nav3_ukf 10ms", "heading"), 1),
                   pm(m.delayed_rmse_stat(base, 2, 0.1)), pm(m.stat(base, "rmse")),
                   "the delay is most of the error"
                   if m.delayed_rmse_stat(base, 2, 0.1)[0] < 0.7 * m.stat(base, "rmse")[0]
                   else "here the delay is a small part of the error, the heading most of it"))
    sec.append("")
    figures.append(plot_paths(m, "tuning_r.png", img_dir, [
        ("(1) 100 ms", base), ("(2) R × 10", base + " R*10"),
        ("(3) R × 10, 10 ms", base + " R*10 10ms"), ("10 ms", base + " 10ms")],
        "Fig. 5.10: nav3ctrl UKF tuned", limit=1.0))
    figures.append(plot_paths(m, "tuning_q.png", img_dir, [
        ("Q, 10 ms", base + " 10ms"), ("Q × 0.1, 10 ms", base + " Q*0.1 10ms"),
        ("Q × 0.01, 10 ms", base + " Q*0.01 10ms")],
        "Fig. 5.11: nav3ctrl UKF, 10 ms, Q scaled", limit=1.0))
    tt, tv, _ = m.twists[m.bags[0]]
    figures.append(plot_signals(
        m, "velocity.png", img_dir, "Fig. 5.12: v at 10 ms", "v (m/s)", ("true v", tt, tv),
        [("Q", base + " 10ms", "x5", "line"), ("Q × 0.01", base + " Q*0.01 10ms", "x5", "line"),
         ("Q, 100 ms", base, "x5", "steps")], (0.0, 20.0)))
    add_images(sec,
               ("velocity.png", "velocity estimates at 10 ms"),
               ("tuning_r.png", "tuned UKFs"),
               ("tuning_q.png", "UKFs with scaled Q"))
    summary.append(("5.2.5: a shorter period is better",
                    "final error: %s; RMSE: %s" % (
                        "yes" if period_word == "smaller" else "**no**",
                        "yes, down to 50 ms" if rmse_50[0] == "smaller" else "no"),
                    "nav3ctrl 10 ms: final error %s; nav3 10 ms RMSE %s" % (
                        change_text(m, base + " 10ms", base),
                        change_text(m, "nav3_ukf 10ms", "nav3_ukf", "rmse"))))
    summary.append(("5.2.5: R × 10 is better", yes_no(r10_word == "smaller"),
                    change_text(m, base + " R*10", base)))
    summary.append(("5.2.5: Q × 0.1 and × 0.01 are much poorer",
                    yes_no(all(w == "larger" for w in q_words)),
                    "%s; %s; Q × 0.1 is R × 10 (paths %s apart)" % (
                        change_text(m, base + " Q*0.1 10ms", base + " 10ms"),
                        change_text(m, base + " Q*0.01 10ms", base + " 10ms"), dist(d_rq))))
    sections.append(sec)

    # ---------------------------------------------------------------- assemble
    w("## Summary")
    w("")
    w(table(["thesis claim", "holds here", "measured"], [list(r) for r in summary],
            numeric=False))
    w("")
    for sec in sections:
        out.extend(sec)
    w("## How this page was made")
    w("")
    w("```")
    w(ctx["command"])
    w("```")
    w("")
    w("after building the nodes (`catkin_make -DCMAKE_BUILD_TYPE=Release --make-args "
      "<sf_ + each name of SF_PIONEER_CONFIGS in CMakeLists.txt>`, with the devel space "
      "sourced). Machine: %s. Other jobs shared the machine (load average %.2f before and "
      "%.2f after the replays), so the Table 5.3 times are the fastest of several replays; "
      "the other times in the replay summaries vary by up to a few times between runs. "
      "Revision %s, %s. %d replays." % (
          ctx["machine"], ctx["load"][0][0], ctx["load"][1][0], ctx["revision"], ctx["date"],
          sum(len(m.replays[b]) for b in m.bags)))
    w("")
    # The hand-written sections after KEEP_MARKER (the comparison with the ideal bags and the
    # sensitivity table, made by other commands) are carried over from the existing page.
    kept = ""
    if os.path.isfile(out_path):
        with open(out_path) as f:
            old = f.read()
        if KEEP_MARKER in old:
            kept = old[old.index(KEEP_MARKER):]
    with open(out_path, "w") as f:
        f.write("\n".join(out) + "\n")
        if kept:
            f.write("\n" + kept)
    return out_path, figures


MODELS_WITH_POSE = ["nav1", "nav1ctrl", "nav2", "nav2ctrl", "nav3", "nav3ctrl"]
# Everything from this line on is kept when the page is rewritten (written by hand or by
# other commands, each named in its section).
KEEP_MARKER = "<!-- kept by chapter5_report.py: the sections below are not regenerated -->"
