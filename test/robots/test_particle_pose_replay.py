"""The particle filter's own pose (issue 34; doc/estimation.md, "Shared dead reckoning"): the
nav3ctrl particle filter on bags/pioneer_seed1.bag, its pose columns against the ground truth
next to the track its own speed and turn rate (x5, x3) integrate to offline
(tools/eval/evaluate.py --dead-reckoning). With the pose carried as one shared Gaussian (the
default of a header with ANGLE_STATES) the two are within 20 % of each other; carried per
particle (`pf_shared_dead_reckoning: false` through --params) the pose is the path of a few
resampled ancestors, several times worse than its own velocities."""

import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from replay_helpers import REPO, replay_exe  # noqa: E402

sys.path.insert(0, os.path.join(REPO, "tools", "eval"))
import evaluate  # noqa: E402

BAG = os.path.join(REPO, "bags", "pioneer_seed1.bag")


class ParticlePoseTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.truth = evaluate.load_truth(BAG)

    def rmse_pair(self, *extra):
        """(RMSE of the pose columns, RMSE of the integrated velocities) [m]."""
        with tempfile.TemporaryDirectory(prefix="sf_pf_pose_") as tmp:
            csv_path = os.path.join(tmp, "pf.csv")
            params = []
            if extra:
                params_path = os.path.join(tmp, "params.yaml")
                with open(params_path, "w") as f:
                    f.write("\n".join(extra) + "\n")
                params = ["--params", params_path]
            replay_exe("sf_nav3ctrl_pf", BAG, csv_path, *params)
            own = evaluate.evaluate(evaluate.load_result_csv(csv_path, ["x0", "x1", "x2"]),
                                    self.truth)
            integrated = evaluate.evaluate(
                evaluate.load_result_dead_reckoned(csv_path, "v=x5,omega=x3"), self.truth)
        return own.rmse_pos, integrated.rmse_pos

    def test_shared_pose_follows_its_velocities(self):
        own, integrated = self.rmse_pair()
        print("nav3ctrl PF, shared dead reckoning: pose %.3f m, velocities integrated %.3f m"
              % (own, integrated))
        self.assertLess(abs(own - integrated), 0.2 * integrated)

    def test_per_particle_pose_is_the_path_of_a_few_ancestors(self):
        own, integrated = self.rmse_pair("pf_shared_dead_reckoning: false")
        print("nav3ctrl PF, per-particle pose: pose %.3f m, velocities integrated %.3f m"
              % (own, integrated))
        self.assertGreater(own, 3.0 * integrated)


if __name__ == "__main__":
    unittest.main()
