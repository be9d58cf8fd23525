"""The shipped launch files as roslaunch reads them (`roslaunch --nodes`, `--dump-params`,
`--args`; no master, no node started): filter slots left out with `none`, a repeated
configuration started once, /use_sim_time global inside a namespaced include, no
required player (whose normal end roslaunch reports as a red error), and the tuned noise of
config/tuned/ loaded into the configurations that have a file for the shipped bag."""

import glob
import os
import re
import subprocess
import tempfile
import unittest

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
LAUNCH = os.path.join(REPO, "launch")


def roslaunch(*args):
    # this source tree first on ROS_PACKAGE_PATH, so that $(find sf_pkg) is this tree
    env = dict(os.environ, ROS_PACKAGE_PATH=os.pathsep.join(
        [REPO] + [p for p in os.environ.get("ROS_PACKAGE_PATH", "/usr/share").split(os.pathsep) if p]))
    env["PATH"] = "/usr/bin:/bin:" + env.get("PATH", "")
    result = subprocess.run(["roslaunch"] + list(args), env=env, capture_output=True, text=True,
                            timeout=60)
    if result.returncode != 0:
        raise AssertionError("roslaunch %s failed:\n%s%s" % (" ".join(args), result.stdout,
                                                           result.stderr))
    return result.stdout


def nodes(launch_file, *args):
    return roslaunch("--nodes", os.path.join(LAUNCH, launch_file), *args).split()


class FilterSlotsTest(unittest.TestCase):
    def test_pioneer_slots(self):
        self.assertEqual(nodes("pioneer.launch"),
                         ["/nav3ctrl_ekf/fusion_node", "/nav3ctrl_ukf/fusion_node", "/recorder",
                          "/player"])
        self.assertEqual(nodes("pioneer.launch", "filter2:=none", "record:=false"),
                         ["/nav3ctrl_ekf/fusion_node", "/player"])
        self.assertEqual(nodes("pioneer.launch", "filter1:=none", "filter2:=none",
                               "filter3:=nav3red_kf"),
                         ["/nav3red_kf/fusion_node", "/recorder", "/player"])

    def test_a_repeated_configuration_runs_once(self):
        self.assertEqual(nodes("pioneer.launch", "filter3:=nav3ctrl_ekf", "filter4:=nav3ctrl_ukf"),
                         ["/nav3ctrl_ekf/fusion_node", "/nav3ctrl_ukf/fusion_node", "/recorder",
                          "/player"])
        # issue 17: `filter1:= filter2:=soccer_kf` (roslaunch drops the empty filter1:=) failed
        # with two nodes named /soccer_kf/fusion_node
        self.assertEqual(nodes("soccer.launch", "filter2:=soccer_kf"),
                         ["/soccer_kf/fusion_node", "/recorder", "/player"])
        self.assertEqual(nodes("soccer.launch", "filter1:=none", "filter2:=soccer_kf"),
                         ["/soccer_kf/fusion_node", "/recorder", "/player"])

    def test_tuned_files_are_loaded_into_the_configurations_that_have_one(self):
        for launch_file, config, bag in (("pioneer.launch", "nav3ctrl_ekf", "pioneer_seed1"),
                                         ("pioneer.launch", "nav3ctrl_ukf", "pioneer_seed1"),
                                         ("soccer.launch", "soccer_kf", "soccer_seed1")):
            with open(os.path.join(REPO, "config", "tuned",
                                   "%s_on_%s.yaml" % (config, bag))) as f:
                tuned = yaml.safe_load(f)
            params = yaml.safe_load(roslaunch("--dump-params",
                                              os.path.join(LAUNCH, launch_file)))
            key = "/%s/fusion_node/process_noise_covariance" % config
            self.assertEqual(params[key], tuned["process_noise_covariance"], launch_file)
            self.assertEqual(params["/%s/fusion_node/measurement_noise_covariance" % config],
                             tuned["measurement_noise_covariance"], launch_file)
            params = yaml.safe_load(roslaunch("--dump-params", os.path.join(LAUNCH, launch_file),
                                              "tuned:=false"))
            self.assertNotIn(key, params)
        # a configuration without a tuned file runs with its header's values
        params = yaml.safe_load(roslaunch("--dump-params", os.path.join(LAUNCH, "pioneer.launch"),
                                          "filter3:=nav3ctrl_pf"))
        self.assertIn("/nav3ctrl_ekf/fusion_node/process_noise_covariance", params)
        self.assertFalse([k for k in params if k.startswith("/nav3ctrl_pf/fusion_node/")
                          and "noise" in k], params)

    def test_recorder_follows_the_slots(self):
        args = roslaunch("--args", "/recorder", os.path.join(LAUNCH, "pioneer.launch"),
                         "filter2:=none", "filter3:=nav1_ekf")
        self.assertIn("/(nav3ctrl_ekf||nav1_ekf|)/.+|/ground_truth/pose", args)
        self.assertNotIn("none", args)


class SimTimeTest(unittest.TestCase):
    def test_use_sim_time_is_global_inside_a_namespace(self):
        with tempfile.NamedTemporaryFile("w", suffix=".launch") as f:
            f.write('<launch><group ns="robot1">'
                    '<include file="$(find sf_pkg)/launch/filter.launch">'
                    '<arg name="use_sim_time" value="true"/></include>'
                    '</group></launch>')
            f.flush()
            params = roslaunch("--dump-params", f.name)
        self.assertIn("/use_sim_time: true", params)
        self.assertNotIn("/robot1/use_sim_time", params)

    def test_robot_launch_files_run_on_sim_time(self):
        for name in ("pioneer.launch", "soccer.launch", "soccer_fusion_block.launch"):
            params = roslaunch("--dump-params", os.path.join(LAUNCH, name))
            self.assertIn("/use_sim_time: true", params, name)


class BagEndTest(unittest.TestCase):
    def test_no_required_player(self):
        for path in sorted(glob.glob(os.path.join(LAUNCH, "*.launch"))):
            with open(path) as f:
                text = re.sub(r"<!--.*?-->", "", f.read(), flags=re.S)
            for node in re.findall(r"<node\b[^>]*>", text):
                if 'name="player"' in node:
                    self.assertNotIn('required="true"', node, os.path.basename(path))
                    self.assertIn('type="play_bag.py"', node, os.path.basename(path))

    def test_player_ends_the_launch_unless_told_not_to(self):
        launch = os.path.join(LAUNCH, "soccer_fusion_block.launch")
        self.assertIn("play_bag.py --end-launch --clock", roslaunch("--args", "/player", launch))
        args = roslaunch("--args", "/player", launch, "end_with_bag:=false")
        self.assertNotIn("--end-launch", args)


if __name__ == "__main__":
    unittest.main()
