// What a configuration header says about a fusion node's interface, in run-time form.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sf_filter {

/// What the configuration header says about the node's interface.
struct NodeDescription {
  std::string method;
  std::vector<std::string> inputs;                   ///< "topic field" per measurement input
  std::vector<std::string> controls;                 ///< "topic field" per control input
  std::vector<std::pair<std::string, int>> outputs;  ///< topic and state index (TOPICS_OUT)
  std::optional<std::array<int, 3>> pose;            ///< state indices of x, y, heading (POSE_OUT)
  std::optional<std::array<int, 2>> twist;           ///< state indices of v, omega (TWIST_OUT)
  std::optional<int> accel;                          ///< state index of a (ACCEL_OUT)
};

}  // namespace sf_filter
