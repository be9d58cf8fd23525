#!/usr/bin/python3
"""Regenerates the tables and figures of doc/armesto.md: Armesto, Tornero and Vincze's
inertial+vision filter ("Fast ego-motion estimation with multi-rate fusion of inertial and
vision") on the BROAD trials, its claims checked with numbers.

Every trial found: the paper's costs J_p and J_q (eq. 24) of the fused MR-EKF and MR-UKF with
the paper's Q and R (eqs. 25-26), of vision alone (the last frame held) and of the IMU alone
(the same filter without vision), and the filters' CPU time per step. Then the sweeps of the
paper's Figs. 6-9 on a slow and a fast trial: J_q over (R_q, R_omega) on rotation trials, J_p
over (R_p, R_a) on translation trials, for both filters; the figures go to doc/img/. The
stream, the vision noise and the costs are tools/eval/armesto_run.py's.

Example (the page's own run):

    tools/eval/armesto_report.py /path/to/broad --binary build/sf_estimation_armesto_fusion"""

import os
import pickle
import sys
import time
from multiprocessing import Pool

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "data"))
import armesto_run  # noqa: E402
import broad_report  # noqa: E402
import broad_trial  # noqa: E402
import doc_section  # noqa: E402

METHODS = ("ekf", "ukf", "ukf1", "held", "imu", "gyro")
TITLES = {"ekf": "MR-EKF", "ukf": "MR-UKF", "ukf1": "MR-UKF alpha 1", "held": "vision held", "imu": "IMU alone",
          "gyro": "gyro integrated"}
# UKF-M's sigma-point spread: the library's default (1e-3, UKF-M's benchmarks) and whole
# standard deviations (alpha 1), nearer the paper's kappa-weighted points.
UKF_WIDE = ["--ukf-alpha", "1"]


def decades(first, last):
    """1e<first> .. 1e<last>, written as the decimal literals (10.0 ** -4 is not 1e-4)."""
    return np.array([float("1e%d" % k) for k in range(first, last + 1)])


# The sweeps (the paper's Figs. 6-9): the trials at slow and fast motion, the two R entries
# swept (in decades about the paper's value, far enough that the optimum is inside) and the cost they are judged by.
SWEEPS = {
    "rotation": dict(trials={"slow": "02", "fast": "07"}, axes=("quat", "gyro"), cost=1,
                     values=(decades(-12, -4), decades(-7, -1))),
    "translation": dict(trials={"slow": "10", "fast": "15"}, axes=("pos", "acc"), cost=0,
                        values=(decades(-13, -5), decades(-6, 0))),
}
SYMBOL = {"quat": "R_q", "gyro": "R_omega", "pos": "R_p", "acc": "R_a"}
IMAGE_DIR = os.path.join("doc", "img", "armesto")


def stream_of(path, seed):
    return armesto_run.from_trial(broad_trial.load(path), seed=seed)


def evaluate(job):
    """{method: (J_p, J_q)} and {filter: CPU us per step} of one trial."""
    path, binary, seed = job
    stream = stream_of(path, seed)
    costs, cpu = {"held": armesto_run.costs(stream, *armesto_run.vision_held(stream))}, {}
    for kind in ("ekf", "ukf"):
        p, q, cpu[kind] = armesto_run.run(stream, kind, binary)
        costs[kind] = armesto_run.costs(stream, p, q)
    p, q, _ = armesto_run.run(stream, "ukf", binary, UKF_WIDE)
    costs["ukf1"] = armesto_run.costs(stream, p, q)
    p, q, _ = armesto_run.run(stream, "ekf", binary, ["--no-vision"])
    costs["imu"] = armesto_run.costs(stream, p, q)
    print("  %s done" % os.path.basename(path), file=sys.stderr, flush=True)
    return os.path.splitext(os.path.basename(path))[0], costs, cpu


def gyro_integrated(stream):
    """The orientation of the gyro alone, integrated from the first frame, q_k = q_k-1 exp(w T):
    what the IMU alone gives for J_q without the filter's accelerometer update."""
    turns = armesto_run.rotation_vector_to_quat(stream.imu[:, 3:] * armesto_run.PERIOD)
    q = np.empty_like(turns)
    q[0] = stream.vision[0, 3:]
    for k in range(1, len(q)):
        q[k] = armesto_run.quat_product(q[k - 1], turns[k])
        q[k] /= np.linalg.norm(q[k])
    return q


def add_gyro_integrated(job):
    """(J_p undefined, J_q) of the gyro integrated over one trial."""
    path, seed = job
    stream = stream_of(path, seed)
    return os.path.splitext(os.path.basename(path))[0], (float("nan"), armesto_run.costs(stream, stream.ref_p, gyro_integrated(stream))[1])


def sweep(job):
    """The grid of costs (rows: first axis' values, columns: second's) of one filter on one
    trial; inf where the filter diverged."""
    path, binary, seed, kind, name = job
    spec = SWEEPS[name]
    stream = stream_of(path, seed)
    grid = np.zeros((len(spec["values"][0]), len(spec["values"][1])))
    for i, first in enumerate(spec["values"][0]):
        for j, second in enumerate(spec["values"][1]):
            r = dict(armesto_run.PAPER_R, **{spec["axes"][0]: first, spec["axes"][1]: second})
            p, q, _ = armesto_run.run(stream, kind, binary, armesto_run.noise_options(r))
            grid[i, j] = armesto_run.costs(stream, p, q)[spec["cost"]]
    print("  sweep %s %s %s done" % (name, kind, os.path.basename(path)), file=sys.stderr, flush=True)
    return (name, kind, path), grid


def fmt(value):
    if np.isnan(value):
        return "-"
    return "diverged" if not np.isfinite(value) else "%.3g" % value


def trial_table(results, names, index):
    lines = ["| trial | " + " | ".join(TITLES[m] for m in METHODS) + " |",
             "| --- |" + " ---: |" * len(METHODS)]
    for name in names:
        lines.append("| %s | %s |" % (name, " | ".join(fmt(results[name][0][m][index]) for m in METHODS)))
    return lines


def group_rows(results, groups, index):
    """Per group: the geometric mean of each method's cost (costs span decades) and how many
    trials the fused EKF beats both sensors on."""
    lines = ["| group | " + " | ".join(TITLES[m] for m in METHODS) + " | EKF below both |",
             "| --- |" + " ---: |" * (len(METHODS) + 1)]
    for label, names in groups:
        means = [np.exp(np.mean([np.log(results[n][0][m][index]) for n in names])) for m in METHODS]
        wins = sum(results[n][0]["ekf"][index] < min(results[n][0]["held"][index], results[n][0]["imu"][index])
                   for n in names)
        lines.append("| %s | %s | %d of %d |" % (label, " | ".join(fmt(v) for v in means), wins, len(names)))
    return lines


def optimum(grid, values):
    i, j = np.unravel_index(np.argmin(grid), grid.shape)
    return values[0][i], values[1][j], grid[i, j]


def plot_sweeps(grids, paths_by_number, out_dir):
    """One PNG per sweep: log10 of the cost over the grid, EKF and UKF at slow and fast motion;
    the paper's R (+) and the optimum (*) marked."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(out_dir, exist_ok=True)
    files = []
    for name, spec in SWEEPS.items():
        fig, axes = plt.subplots(2, 2, figsize=(7.5, 6.2), sharex=True, sharey=True)
        lx, ly = np.log10(spec["values"][1]), np.log10(spec["values"][0])
        for row, kind in enumerate(("ekf", "ukf")):
            for col, speed in enumerate(("slow", "fast")):
                grid = grids[(name, kind, paths_by_number[spec["trials"][speed]])]
                ax = axes[row, col]
                image = ax.imshow(np.log10(np.where(np.isfinite(grid), grid, np.nan)), origin="lower", aspect="auto",
                                  extent=(lx[0] - 0.5, lx[-1] + 0.5, ly[0] - 0.5, ly[-1] + 0.5), cmap="viridis")
                fig.colorbar(image, ax=ax, label="log10 J_%s" % ("q" if spec["cost"] else "p"))
                a, b, _ = optimum(grid, spec["values"])
                ax.plot(np.log10(armesto_run.PAPER_R[spec["axes"][1]]), np.log10(armesto_run.PAPER_R[spec["axes"][0]]), "w+", ms=12)
                ax.plot(np.log10(b), np.log10(a), "r*", ms=12)
                ax.set_title("%s, %s (trial %s)" % (TITLES[kind], speed, spec["trials"][speed]), fontsize=9)
                ax.set_xlabel("log10 %s" % SYMBOL[spec["axes"][1]])
                ax.set_ylabel("log10 %s" % SYMBOL[spec["axes"][0]])
        fig.tight_layout()
        path = os.path.join(out_dir, "%s_sweep.png" % name)
        fig.savefig(path, dpi=70)
        plt.close(fig)
        files.append(path)
    return files


def trust(grid, values):
    """log10 of R_vision / R_inertial at the optimum: the lower, the more vision is trusted
    relative to the inertial sensor."""
    a, b, _ = optimum(grid, values)
    return float(np.log10(a / b))


def sweep_table(grids, paths_by_number):
    lines = ["| sweep | filter | motion (trial) | optimum | J there | J at the paper's R | log10 R_vision/R_inertial at the optimum "
             "| J at (largest R_vision, smallest R_inertial) / optimum |", "| --- | --- | --- | --- | ---: | ---: | ---: | ---: |"]
    for name, spec in SWEEPS.items():
        values = spec["values"]
        middle = tuple(list(values[k]).index(armesto_run.PAPER_R[spec["axes"][k]]) for k in (0, 1))
        for kind in ("ekf", "ukf"):
            for speed in ("slow", "fast"):
                grid = grids[(name, kind, paths_by_number[spec["trials"][speed]])]
                a, b, best = optimum(grid, values)
                lines.append("| %s | %s | %s (%s) | %s = %.0e, %s = %.0e%s | %s | %s | %+.0f | %s |" % (
                    name, TITLES[kind], speed, spec["trials"][speed], SYMBOL[spec["axes"][0]], a, SYMBOL[spec["axes"][1]], b,
                    " (edge)" if edge(grid) else "",
                    fmt(best), fmt(grid[middle]), trust(grid, values), fmt(corner_penalty(grid))))
    return lines


def peaks(grids):
    """(cells where the UKF's cost exceeds the EKF's by more than 2x or only the UKF diverged,
    the reverse, cells compared, largest UKF / EKF ratio)."""
    ukf_worse = ekf_worse = cells = 0
    largest = 0.0
    for (name, kind, path), ekf in grids.items():
        if kind != "ekf":
            continue
        ukf = grids[(name, "ukf", path)]
        ratio = ukf / ekf
        ukf_worse += int(np.sum((ratio > 2.0) | (~np.isfinite(ukf) & np.isfinite(ekf))))
        ekf_worse += int(np.sum((ratio < 0.5) | (~np.isfinite(ekf) & np.isfinite(ukf))))
        cells += ekf.size
        finite = np.isfinite(ratio)
        largest = max(largest, float(np.max(ratio[finite])) if finite.any() else 0.0)
    return ukf_worse, ekf_worse, cells, largest


def verdict_fusion(results, names):
    lines = []
    for index, symbol in ((1, "J_q"), (0, "J_p")):
        wins = sum(results[n][0]["ekf"][index] < min(results[n][0]["held"][index], results[n][0]["imu"][index]) for n in names)
        ratio = {m: np.exp(np.mean([np.log(results[n][0][m][index] / results[n][0]["ekf"][index]) for n in names]))
                 for m in ("held", "imu", "ukf")}
        lines.append("- **Fusion beats either sensor (%s)**: %s %d of %d trials; on (geometric) average vision held "
                     "has %.3g times the MR-EKF's cost, the IMU alone %.3g times; the MR-UKF %.5f times."
                     % (symbol, "holds on all" if wins == len(names) else "holds on", wins, len(names),
                        ratio["held"], ratio["imu"], ratio["ukf"]))
    return lines


def corner_penalty(grid):
    """The cost with vision trusted least and the inertial sensor most (largest R_vision,
    smallest R_inertial of the grid) over the optimum."""
    return float(grid[-1, 0] / np.min(grid))


def edge(grid):
    i, j = np.unravel_index(np.argmin(grid), grid.shape)
    return i in (0, grid.shape[0] - 1) or j in (0, grid.shape[1] - 1)


def verdict_sweeps(grids, paths_by_number):
    lines = []
    for name, spec in SWEEPS.items():
        for kind in ("ekf", "ukf"):
            slow, fast = (grids[(name, kind, paths_by_number[spec["trials"][s]])] for s in ("slow", "fast"))
            t_slow, t_fast = trust(slow, spec["values"]), trust(fast, spec["values"])
            c_slow, c_fast = corner_penalty(slow), corner_penalty(fast)
            lines.append("- **Vision at low speed, inertial at high speed (%s, %s)**: log10 %s/%s at the optimum is "
                         "%+.0f slow and %+.0f fast%s (%s); distrusting vision and trusting the inertial sensor "
                         "(largest %s, smallest %s) costs %s times the optimum slow and %s times fast (%s)." % (
                             name, TITLES[kind], SYMBOL[spec["axes"][0]], SYMBOL[spec["axes"][1]], t_slow, t_fast,
                             ", an optimum at the grid's edge" if edge(slow) or edge(fast) else "",
                             "vision trusted relatively more at low speed: holds" if t_slow < t_fast else
                             ("the same trust: not shown" if t_slow == t_fast else "vision trusted relatively more at high speed: does not hold"),
                             SYMBOL[spec["axes"][0]], SYMBOL[spec["axes"][1]], fmt(c_slow), fmt(c_fast),
                             "worse at low speed: holds" if c_slow > c_fast else "worse at high speed: does not hold"))
    spec = SWEEPS["translation"]
    for kind in ("ekf", "ukf"):
        slow, fast = (grids[("translation", kind, paths_by_number[spec["trials"][s]])] for s in ("slow", "fast"))
        c_slow, c_fast = corner_penalty(slow), corner_penalty(fast)
        lines.append("- **Slow translations lose the bias when vision is trusted little (%s)**: J_p at R_p = %.0e, "
                     "R_a = %.0e is %s times its optimum slow and %s times fast: %s." % (
                         TITLES[kind], spec["values"][0][-1], spec["values"][1][0], fmt(c_slow), fmt(c_fast),
                         "holds" if c_slow > c_fast else "does not hold"))
    return lines


def verdict_cost(results, names, grids):
    cpu = {k: float(np.mean([results[n][1][k] for n in names])) for k in ("ekf", "ukf")}
    imu, gyro = (np.exp(np.mean([np.log(results[n][0][m][1]) for n in names])) for m in ("imu", "gyro"))
    ukf_worse, ekf_worse, cells, largest = peaks(grids)
    wide = max(abs(results[n][0]["ukf1"][k] / results[n][0]["ekf"][k] - 1.0) for n in names for k in (0, 1))
    return ["- **The UKF's numerical peaks**: over the %d sweep cells the MR-UKF's cost exceeds the MR-EKF's by more "
            "than 2x (or only it diverged) in %d, the reverse in %d; the largest UKF/EKF ratio is %.5f. With sigma "
            "points at whole standard deviations (alpha 1) the MR-UKF's J_p and J_q differ from the MR-EKF's by at "
            "most %.2g (relative) over the %d trials." % (cells, ukf_worse, ekf_worse, largest, wide, len(names)),
            "- **The UKF's cost**: %.1f us per step for the MR-EKF, %.1f us for the MR-UKF (mean over %d trials): "
            "%.2f times (the paper: about 7 times)." % (cpu["ekf"], cpu["ukf"], len(names), cpu["ukf"] / cpu["ekf"]),
            "- **The IMU alone**: the filter without vision has J_q %.3g (geometric mean), the gyro integrated alone "
            "%.3g: %s." % (imu, gyro, "the filter's accelerometer update costs orientation" if imu > gyro else
                             "the filter's accelerometer update helps")]


def body(results, grids, paths_by_number, figures, args, seconds):
    names = sorted(results)
    undisturbed = [n for n in names if int(n[:2]) <= broad_trial.UNDISTURBED_LAST]
    groups = [("all %d trials found" % len(names), names), ("%d undisturbed" % len(undisturbed), undisturbed),
              ("%d disturbed" % (len(names) - len(undisturbed)), [n for n in names if n not in undisturbed])]
    lines = ["Trials found: %d (%s). Vision noise seed %d; the paper's Q and R throughout the first tables."
             % (len(names), ", ".join(n[:2] for n in names), args.seed), "", "**Verdicts** (numbers below):", ""]
    lines += verdict_fusion(results, names) + verdict_sweeps(grids, paths_by_number) + verdict_cost(results, names, grids)
    lines += ["", "J_q (eq. 24, quaternion components squared, per sample) per group, geometric means over the trials:", ""]
    lines += group_rows(results, groups, 1)
    lines += ["", "J_p [m^2] per group, geometric means over the trials:", ""] + group_rows(results, groups, 0)
    lines += ["", "Sweeps (%s): the optimum over the grid, the cost at the paper's R, and where the optimum puts the "
              "trust; every other R as eqs. 25-26." % ", ".join("%s over %s x %s" % (
                  n, SYMBOL[s["axes"][0]], SYMBOL[s["axes"][1]]) for n, s in SWEEPS.items()), ""]
    lines += sweep_table(grids, paths_by_number)
    page_dir = os.path.dirname(os.path.abspath(args.page if args.page != "-" else "doc/armesto.md"))
    lines += [""] + ["![%s](%s)" % (os.path.basename(f), os.path.relpath(os.path.abspath(f), page_dir)) for f in figures]
    lines += ["", "J_q per trial:", ""] + trial_table(results, names, 1)
    lines += ["", "J_p [m^2] per trial:", ""] + trial_table(results, names, 0)
    lines += ["", "Command: `tools/eval/armesto_report.py BROAD --binary BUILD/sf_estimation_armesto_fusion%s` "
              "(the runs took %.0f s with %d jobs)." % ("" if args.seed == 1 else " --seed %d" % args.seed, seconds, args.jobs), "",
              "Machine: %s." % broad_report.machine()]
    return lines


def main():
    parser = doc_section.command_parser(__doc__, "doc/armesto.md")
    parser.add_argument("data", help="directory with the BROAD trials (its checkout, or data_hdf5/, data_mat/)")
    parser.add_argument("--binary", default=armesto_run.DEFAULT_BINARY, help="sf_estimation_armesto_fusion")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--seed", type=int, default=1, help="seed of the vision noise (default %(default)s)")
    parser.add_argument("--images", default=IMAGE_DIR, help="directory of the figures (default %(default)s)")
    parser.add_argument("--cache", help="pickle of the runs' results, read if present and written (to redo the page "
                        "without the runs; delete it after changing the filter)")
    args = parser.parse_args()
    started = time.time()
    paths = broad_trial.find_trials(args.data)
    if not paths:
        parser.error("no BROAD trial in %s" % args.data)
    by_number = {os.path.basename(p)[:2]: p for p in paths}
    needed = {n for spec in SWEEPS.values() for n in spec["trials"].values()}
    if not needed <= set(by_number):
        parser.error("the sweeps need trials %s" % ", ".join(sorted(needed - set(by_number))))
    sweeps = [(by_number[n], args.binary, args.seed, kind, name) for name, spec in SWEEPS.items()
              for n in spec["trials"].values() for kind in ("ekf", "ukf")]
    if args.cache and os.path.exists(args.cache):
        with open(args.cache, "rb") as f:
            results, grids, seconds = pickle.load(f)
    else:
        with Pool(args.jobs) as pool:
            results = {name: (costs, cpu) for name, costs, cpu in pool.map(evaluate, [(p, args.binary, args.seed) for p in paths])}
            grids = dict(pool.map(sweep, sweeps))
        seconds = time.time() - started
        if args.cache:
            with open(args.cache, "wb") as f:
                pickle.dump((results, grids, seconds), f)
    with Pool(args.jobs) as pool:
        for name, costs in pool.map(add_gyro_integrated, [(p, args.seed) for p in paths]):
            results[name][0]["gyro"] = costs
    figures = plot_sweeps(grids, by_number, args.images)
    doc_section.publish(args.page, "armesto-results", body(results, grids, by_number, figures, args, seconds))


if __name__ == "__main__":
    main()
