#!/usr/bin/python3
"""Sensitivity of the Pioneer models to wheel slip and gyro bias (issue 16 item 4): nav2
(wheels only), nav3 (wheels, gyroscope, accelerometer) and nav3ctrl (nav3 with cmd_vel),
EKF each, on small simulated bags whose slip and gyro bias grow from zero past the
real-robot level.

Usage:
  pioneer_sensitivity.py [--levels 0,0.25,0.5,1,2,4] [--seeds 1,2] [--duration 60]
                         [--lib-dir DIR] [--work-dir DIR]

A level f scales the `--realistic husky` preset of tools/sim/pioneer_sim.py (doc/bags.md,
"Realistic error options") in the effect swept, with every other error option off:
  slip       --slip-chi 1 + 0.15 f  --slip-std 0.11 f  --slip-tau 0.12   (f = 1: the preset's slip)
  gyro bias  --gyro-bias-init 0.0005 f  --gyro-bias-rw 5e-5 f
(the values are read from the preset, sensor_errors.PRESETS["husky"]; the slip's correlation
time is not scaled)
  both       the two together
For every sweep, level and seed it writes a bag (--duration s, uncompressed) into the work
directory (default: a temporary one), replays sf_nav2_ekf, sf_nav3_ekf and sf_nav3ctrl_ekf
and evaluates them against the bag's ground truth (evaluate.py): final position error and
position RMSE, mean over the seeds. Prints one markdown table per sweep, and per sweep the
smallest level at which nav3 or nav3ctrl is at least 10 % better than nav2 in final error
and in RMSE (the crossover where fusing the gyroscope starts to pay; smaller differences are
within what two seeds resolve), "none" when it never is in the levels run.
"""

import argparse
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True
import evaluate as ev  # noqa: E402
import pioneer_nodes  # noqa: E402

SIM = os.path.join(REPO, "tools", "sim", "pioneer_sim.py")
sys.path.insert(0, os.path.join(REPO, "tools", "sim"))
import sensor_errors  # noqa: E402

PRESET = sensor_errors.PRESETS["husky"]
NODES = ["nav2_ekf", "nav3_ekf", "nav3ctrl_ekf"]


def sim_args(sweep, f):
    slip = ["--slip-chi", "%g" % (1 + (PRESET["slip_chi"] - 1) * f),
            "--slip-std", "%g" % (PRESET["slip_std"] * f), "--slip-tau", "%g" % PRESET["slip_tau"]]
    gyro = ["--gyro-bias-init", "%g" % (PRESET["gyro_bias_init"] * f),
            "--gyro-bias-rw", "%g" % (PRESET["gyro_bias_rw"] * f)]
    return {"slip": slip, "gyro bias": gyro, "both": slip + gyro}[sweep]


def run(cmd):
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=600)
    if proc.returncode != 0:
        raise RuntimeError("%s: exit %d\n%s" % (" ".join(cmd), proc.returncode, proc.stdout))
    return proc.stdout


def main(argv=None):
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    parser.add_argument("--levels", default="0,0.25,0.5,1,2,4")
    parser.add_argument("--seeds", default="1,2")
    parser.add_argument("--duration", type=float, default=60.0)
    parser.add_argument("--sweeps", default="slip,gyro bias,both")
    parser.add_argument("--lib-dir")
    parser.add_argument("--work-dir")
    args = parser.parse_args(argv)
    levels = [float(x) for x in args.levels.split(",")]
    seeds = [int(x) for x in args.seeds.split(",")]
    sweeps = [s.strip() for s in args.sweeps.split(",")]
    lib_dir = args.lib_dir or pioneer_nodes.find_lib_dir()
    if not lib_dir:
        print("error: no sf_nav* executables (source the devel space or give --lib-dir)",
              file=sys.stderr)
        return 2
    tmp = None
    work = args.work_dir
    if not work:
        tmp = tempfile.TemporaryDirectory()
        work = tmp.name
    os.makedirs(work, exist_ok=True)

    print("# Pioneer models against slip and gyro bias (%g s bags, seeds %s, EKF)"
          % (args.duration, ", ".join(map(str, seeds))))
    for sweep in sweeps:
        table = []  # (f, {node: (final, rmse)})
        for f in levels:
            sums = {n: [0.0, 0.0] for n in NODES}
            for seed in seeds:
                bag = os.path.join(work, "%s_%g_%d.bag" % (sweep.replace(" ", "_"), f, seed))
                if not os.path.exists(bag):
                    run([sys.executable, SIM, "--seed", str(seed), "--duration",
                         "%g" % args.duration, "--out", bag, "--compression", "none"]
                        + sim_args(sweep, f))
                truth = ev.load_truth(bag)
                for n in NODES:
                    csv_path = bag[:-4] + "_" + n + ".csv"
                    run([os.path.join(lib_dir, "sf_" + n), "--replay", bag, "--csv", csv_path])
                    e = ev.evaluate(ev.load_result_csv(csv_path), truth)
                    sums[n][0] += e.final_pos_err / len(seeds)
                    sums[n][1] += e.rmse_pos / len(seeds)
            table.append((f, sums))
        print()
        print("## %s" % sweep)
        print()
        print("| level f | simulator options | " + " | ".join(
            "%s final / RMSE [m]" % n.replace("_ekf", "") for n in NODES) + " |")
        print("| --- | --- |" + " --- |" * len(NODES))
        for f, sums in table:
            print("| %g | `%s` | " % (f, " ".join(sim_args(sweep, f))) + " | ".join(
                "%.3f / %.3f" % tuple(sums[n]) for n in NODES) + " |")
        for n in ("nav3_ekf", "nav3ctrl_ekf"):
            for k, name in ((0, "final error"), (1, "RMSE")):
                cross = next((f for f, s in table if s[n][k] < 0.9 * s["nav2_ekf"][k]), None)
                print("- %s at least 10 %% better than nav2 in %s from level: %s"
                      % (n.replace("_ekf", ""), name, "none" if cross is None else "%g" % cross))
    if tmp:
        tmp.cleanup()
    return 0


if __name__ == "__main__":
    sys.exit(main())
