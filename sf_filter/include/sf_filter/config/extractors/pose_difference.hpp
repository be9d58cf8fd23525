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
// The extractor kind PoseQuantities (extractor.hpp) reads them from a quaternion or pose member.
// ROS-free and header-only; unit-tested in test_extractors.cpp.
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <string_view>
#include <type_traits>
#include <utility>

#include "sf_filter/config/extractors/extractor.hpp"
#include "sf_filter/config/extractors/quaternion_angles.hpp"

namespace sf_config {
namespace extractors {

/// DERIVED_INPUTS quantities (the values of derived_detail::Quantity).
enum class PoseQuantity : int { X = 0, Y = 1, Z = 2, Roll = 3, Pitch = 4, Yaw = 5 };

struct Pose {
  double position[3] = {0.0, 0.0, 0.0};
  Quaternion orientation;
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

template <class T, class = void>
struct IsQuaternion : std::false_type {};
template <class T>
struct IsQuaternion<
    T, std::void_t<decltype(std::declval<const T&>().x), decltype(std::declval<const T&>().y),
                   decltype(std::declval<const T&>().z), decltype(std::declval<const T&>().w)>>
    : std::bool_constant<std::is_convertible_v<decltype(std::declval<const T&>().x), double> &&
                         std::is_convertible_v<decltype(std::declval<const T&>().y), double> &&
                         std::is_convertible_v<decltype(std::declval<const T&>().z), double> &&
                         std::is_convertible_v<decltype(std::declval<const T&>().w), double>> {};

template <class T, class = void>
struct IsPose : std::false_type {};
template <class T>
struct IsPose<T, std::void_t<decltype(std::declval<const T&>().position.x),
                             decltype(std::declval<const T&>().position.y),
                             decltype(std::declval<const T&>().position.z),
                             decltype(std::declval<const T&>().orientation)>>
    : std::bool_constant<
          IsQuaternion<std::decay_t<decltype(std::declval<const T&>().orientation)>>::value &&
          std::is_convertible_v<decltype(std::declval<const T&>().position.x), double> &&
          std::is_convertible_v<decltype(std::declval<const T&>().position.y), double> &&
          std::is_convertible_v<decltype(std::declval<const T&>().position.z), double>> {};

template <class Q>
Quaternion quaternionOf(const Q& q) {
  return {static_cast<double>(q.x), static_cast<double>(q.y), static_cast<double>(q.z),
          static_cast<double>(q.w)};
}

/// A pose member as a Pose; a quaternion member as a Pose at the origin.
template <class Member>
Pose poseOf(const Member& member) {
  Pose pose;
  if constexpr (IsPose<Member>::value) {
    pose.position[0] = static_cast<double>(member.position.x);
    pose.position[1] = static_cast<double>(member.position.y);
    pose.position[2] = static_cast<double>(member.position.z);
    pose.orientation = quaternionOf(member.orientation);
  } else if constexpr (IsQuaternion<Member>::value) {
    pose.orientation = quaternionOf(member);
  }
  return pose;
}

/// Extractor kind X, Y, Z, ROLL, PITCH, YAW of a pose or quaternion member, ABSOLUTE or
/// DIFFERENTIAL; its state is the previous pose of a differential input.
class PoseQuantities : public ExtractorState {
 public:
  static constexpr std::array<std::string_view, 6> kQuantities{"X",    "Y",     "Z",
                                                               "ROLL", "PITCH", "YAW"};
  static constexpr std::array<bool, 6> kAngle{false, false, false, true, true, true};
  static constexpr std::array<ExtractorParameter, 0> kParameters{};
  static constexpr bool kAbsoluteOnly = false;

  /// ROLL, PITCH, YAW of a quaternion or a pose; X, Y, Z of a pose only.
  template <class Member>
  static constexpr bool fits(int quantity) {
    return kAngle[static_cast<std::size_t>(quantity)]
               ? (IsQuaternion<Member>::value || IsPose<Member>::value)
               : IsPose<Member>::value;
  }

  template <int Quantity, bool Differential, class Message, class Member>
  std::optional<Sample> sample(const Message&, const Member& member, const SampleContext& c) {
    constexpr auto quantity = static_cast<PoseQuantity>(Quantity);
    if constexpr (Differential) {
      return differentialSample(quantity, poseOf(member), c.variance, c.stamp, memory_);
    } else {
      return Sample{absoluteValue(quantity, poseOf(member)), c.variance};
    }
  }

 private:
  PoseMemory memory_;
};

}  // namespace extractors
}  // namespace sf_config
