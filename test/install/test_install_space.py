"""The install space serves a downstream package: `cmake --install` of the workspace build,
then a throw-away catkin package that find_package()s only the installed sf_pkg builds a
fusion node from its own copy of a shipped header with sf_add_filter() and runs it, and one
that depends on the installed sf_msgs alone builds a program with its messages. The layout:
headers in the package's own include/sf_pkg/, the documented benchmarks installed when the
build has SF_BUILD_BENCHMARKS on, the test-only nodes not, `rosmsg show
sf_msgs/OutputEntityStamped` in the sourced install space.

Run by `catkin_make run_tests` (root CMakeLists.txt) with SF_BUILD_DIR (the workspace's
build directory) and SF_INSTALL_PREFIX (its install prefix) in the environment.
"""

import glob
import json
import os
import shutil
import subprocess
import tempfile
import unittest

BUILD_DIR = os.environ.get("SF_BUILD_DIR", "")
PREFIX = os.environ.get("SF_INSTALL_PREFIX", "")

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>my_robot_fusion</name>
  <version>0.0.1</version>
  <description>Downstream package of the install-space test.</description>
  <maintainer email="nobody@example.com">nobody</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
  <depend>sf_pkg</depend>
</package>
"""

CMAKELISTS = """cmake_minimum_required(VERSION 3.16)
project(my_robot_fusion CXX)
find_package(catkin REQUIRED COMPONENTS sf_pkg)
catkin_package()
sf_add_filter(my_train_kf config/my_train_kf.h)
"""


MESSAGES_PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>my_fusion_monitor</name>
  <version>0.0.1</version>
  <description>Reads a fusion node's output: the messages only.</description>
  <maintainer email="nobody@example.com">nobody</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
  <depend>sf_msgs</depend>
</package>
"""

MESSAGES_CMAKELISTS = """cmake_minimum_required(VERSION 3.16)
project(my_fusion_monitor CXX)
find_package(catkin REQUIRED COMPONENTS sf_msgs)
if(sf_pkg_FOUND OR DEFINED sf_pkg_DIR)
  message(FATAL_ERROR "sf_msgs pulled in sf_pkg")
endif()
catkin_package()
add_executable(monitor monitor.cpp)
target_include_directories(monitor PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(monitor ${catkin_LIBRARIES})
"""

MONITOR_CPP = """#include <iostream>
#include <sf_msgs/OutputEntityStamped.h>
#include <sf_msgs/StateEstimateStamped.h>
int main() {
  sf_msgs::OutputEntityStamped m;
  m.value = 1.5;
  std::cout << ros::message_traits::DataType<sf_msgs::StateEstimateStamped>::value() << ' '
            << m.value << std::endl;
}
"""


def cache_option(build_dir, name):
    """True if the CMake cache of build_dir has option `name` on."""
    with open(os.path.join(build_dir, "CMakeCache.txt")) as cache:
        for line in cache:
            if line.startswith(name + ":"):
                return line.split("=", 1)[1].strip().upper() in ("ON", "TRUE", "1", "YES")
    return False


def run(cmd, env, cwd=None):
    proc = subprocess.run(cmd, env=env, cwd=cwd, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True)
    if proc.returncode != 0:
        raise AssertionError("%s failed (exit %d):\n%s" % (" ".join(cmd), proc.returncode,
                                                          proc.stdout[-6000:]))
    return proc.stdout


@unittest.skipUnless(BUILD_DIR and PREFIX, "SF_BUILD_DIR and SF_INSTALL_PREFIX not set")
class InstallSpaceTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        # Only the installed prefix and the system, not the sourced devel space.
        cls.env = {"PATH": "/usr/bin:/bin", "HOME": os.environ.get("HOME", "/tmp"),
                   "CMAKE_PREFIX_PATH": PREFIX, "LANG": "C"}
        run(["cmake", "--install", BUILD_DIR], cls.env)

    def test_installed_files(self):
        share = os.path.join(PREFIX, "share", "sf_pkg")
        for rel in ["cmake/sf_add_filter.cmake", "sf_filter/src/fusion_node_main.cpp",
                    "sf_filter/src/fusion_node_smoothers.cpp", "sf_filter/src/fusion_node_step.cpp",
                    "sf_filter/src/fusion_node_jacobians.cpp",
                    "config/train_kf.h", "launch/filter.launch", "bags/pioneer_seed1.bag",
                    "tools/eval/evaluate.py"]:
            self.assertTrue(os.path.isfile(os.path.join(share, rel)), rel)
        include = os.path.join(PREFIX, "include")
        # the package's headers in its own include folder, the messages in sf_msgs'
        for rel in ["sf_pkg/sf_filter/config/configuration.hpp",
                    "sf_pkg/sf_filter/core/fusion_core.hpp", "sf_pkg/sf_estimation/estimator.hpp",
                    "sf_pkg/sf_filter/node_unit_prelude.hpp",
                    "sf_msgs/OutputEntityStamped.h", "sf_msgs/StateEstimateStamped.h"]:
            self.assertTrue(os.path.isfile(os.path.join(include, rel)), rel)
        for rel in ["sf_filter", "sf_estimation", "sf_pkg/OutputEntityStamped.h"]:
            self.assertFalse(os.path.exists(os.path.join(include, rel)), rel)
        self.assertTrue(os.path.isfile(os.path.join(PREFIX, "share", "sf_msgs", "msg",
                                                    "OutputEntityStamped.msg")))
        lib = os.path.join(PREFIX, "lib", "sf_pkg")
        for name in ["sf_train_kf", "sf_diff_drive_odom_imu", "sf_wang_table2", "sf_moving_train"]:
            self.assertTrue(os.access(os.path.join(lib, name), os.X_OK), name)
        # the benchmarks the docs run with rosrun (doc/node_benchmarks.md), with the option only
        benchmarks = ["sf_fusion_core_benchmark", "sf_estimation_benchmark", "sf_node_load_driver",
                      "sf_ros_floor_node", "sf_subscribe_floor_node", "measure_node_overhead.sh",
                      "ros_bench_lib.sh"]
        # (absent otherwise, unless an earlier install with the option left them in the prefix)
        if cache_option(BUILD_DIR, "SF_BUILD_BENCHMARKS"):
            for name in benchmarks:
                self.assertTrue(os.path.isfile(os.path.join(lib, name)), name)
        # nodes and drivers only for tests are not installed
        test_only = sorted(n for n in os.listdir(lib) if n.startswith("sf_test_"))
        self.assertEqual(test_only, [])

    def test_rosmsg_finds_the_messages(self):
        setup = os.path.join(PREFIX, "setup.bash")
        self.assertTrue(os.path.isfile(setup), setup)
        out = run(["bash", "-c", "set +u; source %s && rosmsg show sf_msgs/OutputEntityStamped"
                   % setup], self.env)
        self.assertIn("float64 value", out)
        self.assertIn("float64 variance", out)
        self.assertIn("std_msgs/Header header", out)

    def test_downstream_package_uses_the_messages_alone(self):
        with tempfile.TemporaryDirectory(prefix="sf_install_msgs_") as tmp:
            src = os.path.join(tmp, "my_fusion_monitor")
            os.makedirs(src)
            for name, text in [("package.xml", MESSAGES_PACKAGE_XML),
                               ("CMakeLists.txt", MESSAGES_CMAKELISTS),
                               ("monitor.cpp", MONITOR_CPP)]:
                with open(os.path.join(src, name), "w") as f:
                    f.write(text)
            build = os.path.join(tmp, "build")
            devel = os.path.join(tmp, "devel")
            run(["cmake", "-S", src, "-B", build, "-DCATKIN_DEVEL_PREFIX=" + devel], self.env)
            run(["cmake", "--build", build, "--", "-j1"], self.env)
            out = run([os.path.join(devel, "lib", "my_fusion_monitor", "monitor")], self.env)
            self.assertEqual(out.split(), ["sf_msgs/StateEstimateStamped", "1.5"])

    def test_downstream_package_builds_a_node(self):
        with tempfile.TemporaryDirectory(prefix="sf_install_test_") as tmp:
            src = os.path.join(tmp, "my_robot_fusion")
            os.makedirs(os.path.join(src, "config"))
            with open(os.path.join(src, "package.xml"), "w") as f:
                f.write(PACKAGE_XML)
            with open(os.path.join(src, "CMakeLists.txt"), "w") as f:
                f.write(CMAKELISTS)
            shutil.copy(os.path.join(PREFIX, "share", "sf_pkg", "config", "train_kf.h"),
                        os.path.join(src, "config", "my_train_kf.h"))
            build = os.path.join(tmp, "build")
            devel = os.path.join(tmp, "devel")
            # No CMAKE_BUILD_TYPE, as a plain catkin_make of the user's workspace: the node must
            # still be optimised (sf_add_filter's -O2 -DNDEBUG), never built with no -O at all.
            run(["cmake", "-S", src, "-B", build, "-DCMAKE_EXPORT_COMPILE_COMMANDS=ON",
                 "-DCATKIN_DEVEL_PREFIX=" + devel], self.env)
            with open(os.path.join(build, "compile_commands.json")) as f:
                commands = [e["command"] for e in json.load(f)
                            if e["file"].endswith("fusion_node_main.cpp")]
            self.assertEqual(len(commands), 1, commands)
            flags = commands[0].split()
            self.assertIn("-O2", flags)
            self.assertIn("-DNDEBUG", flags)
            # The unit force-includes the package's precompiled prelude, and GCC accepts it:
            # with other flags than the unit's it would fall back to parsing the headers and
            # say so (-Winvalid-pch).
            self.assertTrue(any(f.endswith("cmake_pch.hxx") for f in flags), commands[0])
            out = run(["cmake", "--build", build, "--target", "my_train_kf", "--", "-j1"],
                      self.env)
            self.assertNotIn("Winvalid-pch", out)
            self.assertTrue(glob.glob(os.path.join(build, "CMakeFiles", "*prelude*.dir",
                                                   "cmake_pch.hxx.gch")), out)
            node = os.path.join(devel, "lib", "my_robot_fusion", "my_train_kf")
            self.assertTrue(os.access(node, os.X_OK), node)
            usage = run([node, "--help"], self.env)
            self.assertIn("--replay", usage)


if __name__ == "__main__":
    unittest.main()
