// Input extractor: a quantity of a pose (X, Y, Z of its position; ROLL, PITCH, YAW of its
// orientation), absolute or differential (DERIVED_INPUTS ABSOLUTE, DIFFERENTIAL).
//
// DIFFERENTIAL is robot_localization's differential mode: of two consecutive poses P(k-1) and
// P(k) of one topic, the relative pose D = P(k-1)^-1 P(k), i.e. the motion expressed in the
// frame of the previous pose (the robot's frame, which a state's velocities and turn rates are
// in; robot_localization divides D by the stamp difference to make a twist of it):
//   X, Y, Z           R(q(k-1))^T (p(k) - p(k-1)), one component
//   ROLL, PITCH, YAW  the Euler angles of q(k-1)^-1 q(k) (planar motion: yaw(k) - yaw(k-1),
//                     wrapped to (-pi, pi])
// The variance of the difference is the sum of the two variances (independent errors); with no
// variance from either message there is none (the header's R is used). The first message gives
// no value, and so does a message whose stamp is not after the previous one's (a restarted
// recording or a clock jump): it starts the differences anew. A pose that is not finite gives
// a NaN value (dropped and counted by the fusion core) and keeps the previous pose.
// ROS-free and header-only; unit-tested in test_extractors.cpp.
#pragma once

#include <cmath>
#include <optional>

#include "sf_filter/config/extractors/quaternion_angles.hpp"

namespace sf_config {
namespace extractors {

/// DERIVED_INPUTS quantities (the values of derived_detail::Quantity).
enum class PoseQuantity : int { X = 0, Y = 1, Z = 2, Roll = 3, Pitch = 4, Yaw = 5 };

struct Pose {
  double position[3] = {0.0, 0.0, 0.0};
  Quaternion orientation;
};

/// A value and its variance (nullopt: the header's R).
struct Sample {
  double value;
  std::optional<double> variance;
};

/// The previous pose of a differential input.
struct PoseMemory {
  bool valid = false;
  Pose pose;
  std::optional<double> variance;
  double stamp = 0.0;  ///< NaN for messages without a header
};

inline bool isFinite(const Pose& p) {
  const Quaternion& q = p.orientation;
  return std::isfinite(p.position[0]) && std::isfinite(p.position[1]) &&
         std::isfinite(p.position[2]) && std::isfinite(q.x) && std::isfinite(q.y) &&
         std::isfinite(q.z) && std::isfinite(q.w) && (q.x != 0 || q.y != 0 || q.z != 0 || q.w != 0);
}

/// The quantity of pose p itself.
inline double absoluteValue(PoseQuantity quantity, const Pose& p) {
  switch (quantity) {
    case PoseQuantity::X:
      return p.position[0];
    case PoseQuantity::Y:
      return p.position[1];
    case PoseQuantity::Z:
      return p.position[2];
    case PoseQuantity::Roll:
      return eulerAngles(p.orientation).roll;
    case PoseQuantity::Pitch:
      return eulerAngles(p.orientation).pitch;
    case PoseQuantity::Yaw:
      return eulerAngles(p.orientation).yaw;
  }
  return std::nan("");
}

/// The quantity of the relative pose previous^-1 current (see above).
inline double relativeValue(PoseQuantity quantity, const Pose& previous, const Pose& current) {
  const Quaternion q0 = normalized(previous.orientation);
  const int axis = static_cast<int>(quantity);
  if (axis < 3) {
    const double d[3] = {current.position[0] - previous.position[0],
                         current.position[1] - previous.position[1],
                         current.position[2] - previous.position[2]};
    double local[3];
    rotate(conjugate(q0), d, local);
    return local[axis];
  }
  Pose delta;
  delta.orientation = multiply(conjugate(q0), normalized(current.orientation));
  return absoluteValue(quantity, delta);
}

/// The differential sample of `current` (with its variance and stamp), updating `memory`;
/// nullopt for the first message and after a stamp that did not advance.
inline std::optional<Sample> differentialSample(PoseQuantity quantity, const Pose& current,
                                                std::optional<double> variance, double stamp,
                                                PoseMemory& memory) {
  if (!isFinite(current)) return Sample{std::nan(""), variance};
  const bool restart = !memory.valid || (std::isfinite(stamp) && std::isfinite(memory.stamp) &&
                                         !(stamp > memory.stamp));
  std::optional<Sample> sample;
  if (!restart) {
    sample = Sample{relativeValue(quantity, memory.pose, current), std::nullopt};
    if (variance && memory.variance) sample->variance = *variance + *memory.variance;
  }
  memory.valid = true;
  memory.pose = current;
  memory.variance = variance;
  memory.stamp = stamp;
  return sample;
}

}  // namespace extractors
}  // namespace sf_config
