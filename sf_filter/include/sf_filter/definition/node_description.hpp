// What a configuration header says about a fusion node's interface, in run-time form.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sf_filter {

/// POSE_OUT_3D: where the 3D pose is in the state.
struct Pose3dIndices {
  std::array<int, 3> position;  ///< x, y, z; {-1, -1, -1} for an orientation-only output
  int quaternion;               ///< the quaternion's w, a QUATERNION_STATES entry
};

/// What the configuration header says about the node's interface.
struct NodeDescription {
  std::string method;
  std::vector<std::string> inputs;                   ///< "topic field" per measurement input
  std::vector<std::string> controls;                 ///< "topic field" per control input
  std::vector<std::pair<std::string, int>> outputs;  ///< topic and state index (TOPICS_OUT)
  std::optional<std::array<int, 3>> pose;            ///< state indices of x, y, heading (POSE_OUT)
  std::optional<std::array<int, 2>> twist;           ///< state indices of v, omega (TWIST_OUT)
  std::optional<int> accel;                          ///< state index of a (ACCEL_OUT)
  std::optional<Pose3dIndices> pose3d;               ///< POSE_OUT_3D
  std::optional<std::array<int, 6>> twist3d;         ///< v x, y, z, omega x, y, z (TWIST_OUT_3D)

  /// Whether the node publishes a nav_msgs/Odometry (POSE_OUT or POSE_OUT_3D).
  bool hasOdometry() const { return pose.has_value() || pose3d.has_value(); }
};

}  // namespace sf_filter
