// Derived inputs (doc/configuration.md, "Derived inputs"): TOPICS_IN entries whose value is
// derived from a quaternion or pose member of the message instead of read from a numeric field.
//
//   DERIVED_INPUTS  ((input index)(quantity)(mode)) per derived TOPICS_IN entry; the entry's
//                   field names the member, e.g.
//                     TOPICS_IN ((imu/data)(sensor_msgs::Imu)(orientation))
//                               ((odom)(nav_msgs::Odometry)(pose.pose))
//                     DERIVED_INPUTS ((0)(YAW)(ABSOLUTE))((1)(X)(DIFFERENTIAL))
//                   quantity ROLL, PITCH, YAW of a quaternion (x, y, z, w) or of a pose's
//                            orientation; angle inputs (ANGLE_INPUTS) automatically
//                            X, Y, Z of a pose's position (members position and orientation)
//                   quantity EAST, NORTH, UP of a sensor_msgs/NavSatFix (GPS inputs: the
//                            message is checked and read in gps_inputs.hpp)
//                   mode     ABSOLUTE, or DIFFERENTIAL: the change since the previous message
//                            of the topic in the previous pose's frame, its variance the sum
//                            of the two messages' (extractors/pose_difference.hpp)
//
// Generates, in namespace sf_config:
//   template <int I> struct Derivation {            // how TOPICS_IN entry I is read
//     static constexpr bool derived;                //   false: its field, as configured
//     static constexpr extractors::PoseQuantity quantity; static constexpr bool differential;
//     template <class Member> static extractors::Pose pose(const Member&); };
//
// Checked at compile time, each reported once and naming the macro: the entries' form, input
// index 0 <= index < m and listed once, the quantity and the mode names, the member's type
// (a quaternion, or a pose for X, Y, Z), angles only with the model-based methods.
// ROS-free (the config_errors tests compile it with stand-in messages); included by
// configuration.hpp after the inputs.
#pragma once

#include <type_traits>
#include <utility>

#include "sf_filter/config/detail/derived_inputs.hpp"
#include "sf_filter/config/extractors/pose_difference.hpp"

namespace sf_config {
namespace derived_detail {

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
extractors::Quaternion quaternionOf(const Q& q) {
  return {static_cast<double>(q.x), static_cast<double>(q.y), static_cast<double>(q.z),
          static_cast<double>(q.w)};
}

/// A pose member as a Pose; a quaternion member as a Pose at the origin.
template <class Member>
extractors::Pose poseOf(const Member& member) {
  extractors::Pose pose;
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

/// Whether the input's member can be read for the entry's quantity (unknown types pass: their
/// mistake is reported elsewhere).
template <class Field>
constexpr bool memberFits(int quantity) {
  if constexpr (std::is_same_v<Field, detail::UnknownMessage>) {
    return true;
  } else if (isGpsQuantity(quantity)) {
    return true;  // any member of the fix: gps_inputs.hpp checks the message
  } else {
    return isAngleQuantity(quantity) ? (IsQuaternion<Field>::value || IsPose<Field>::value)
                                     : IsPose<Field>::value;
  }
}

template <int I, bool InRange = (I >= 0 && I < kMeasurementSize)>
struct InputFieldOf {
  using type = detail::UnknownMessage;
};
template <int I>
struct InputFieldOf<I, true> {
  using type = typename std::tuple_element_t<I, Inputs>::Field;
};

}  // namespace derived_detail

// clang-format off
#define SF_DI_PREFIX(k, entry) "DERIVED_INPUTS entry " SF_PP_STR(k) " (" SF_PP_STR(entry) ")"
#define SF_DI_ENTRY(r, data, k, entry)                                                             \
  struct BOOST_PP_CAT(DerivedInputEntry, k) {                                                      \
    static constexpr derived_detail::DerivedEntry e = derived_detail::kDerivedEntries[k];          \
    using Field = typename derived_detail::InputFieldOf<e.input>::type;                            \
    static_assert(std::is_integral<decltype(BOOST_PP_SEQ_ELEM(0, entry))>::value &&               \
                      e.input >= 0 && e.input < kMeasurementSize,                                  \
                  SF_DI_PREFIX(k, entry) ": input index '" SF_PP_STR(BOOST_PP_SEQ_ELEM(0, entry))  \
                  "' is out of range, expected an integer from 0 to "                              \
                  SF_PP_STR(BOOST_PP_DEC(SF_CFG_M)) " (the TOPICS_IN entry whose field is the "    \
                  "member to derive from; " SF_CFG_M_WHY ")");                                     \
    static_assert(derived_detail::entryOf(e.input) == k,                                           \
                  SF_DI_PREFIX(k, entry) ": the input is already listed in an earlier entry; "     \
                  "an input derives one quantity (list the topic again in TOPICS_IN for another)"); \
    static_assert(e.quantity != derived_detail::UnknownQuantity,                                   \
                  SF_DI_PREFIX(k, entry) ": quantity '" SF_PP_STR(BOOST_PP_SEQ_ELEM(1, entry))     \
                  "' is not one of X, Y, Z (of a pose's position), ROLL, PITCH, YAW (of a "        \
                  "quaternion or a pose's orientation) or EAST, NORTH, UP (of a NavSatFix)");       \
    static_assert(e.mode != derived_detail::UnknownMode,                                           \
                  SF_DI_PREFIX(k, entry) ": mode '" SF_PP_STR(BOOST_PP_SEQ_ELEM(2, entry))         \
                  "' is not ABSOLUTE or DIFFERENTIAL (the change since the topic's previous "      \
                  "message)");                                                                     \
    static_assert(e.quantity == derived_detail::UnknownQuantity ||                                 \
                      derived_detail::memberFits<Field>(e.quantity),                               \
                  SF_DI_PREFIX(k, entry) ": the field of TOPICS_IN entry "                         \
                  SF_PP_STR(BOOST_PP_SEQ_ELEM(0, entry)) " is not a "                              \
                  "pose (members position and orientation) or, for ROLL, PITCH and YAW, a "        \
                  "quaternion (x, y, z, w); e.g. orientation of sensor_msgs::Imu, pose.pose of "   \
                  "nav_msgs::Odometry");                                                           \
    static_assert(!SF_CFG_IS_AVERAGING || !derived_detail::isAngleQuantity(e.quantity),           \
                  SF_DI_PREFIX(k, entry) ": ROLL, PITCH and YAW are angle inputs, used by "        \
                  "KALMAN_FILTER, EXTENDED_KALMAN_FILTER, UNSCENTED_KALMAN_FILTER and "            \
                  "PARTICLE_FILTER_SIR only (MOVING_AVERAGE, MOVING_MEDIAN and "                   \
                  "CONFIDENCE_WEIGHTED_AVERAGING average linearly)");                              \
  };
// clang-format on

#if SF_DI_OK
BOOST_PP_SEQ_FOR_EACH_I(SF_DI_ENTRY, ~, DERIVED_INPUTS)
#endif

/// How TOPICS_IN entry I is read (see above).
template <int I>
struct Derivation {
  static constexpr int entry = derived_detail::entryOf(I);
  static constexpr bool derived = entry >= 0;
  static constexpr int quantity_index =
      derived ? derived_detail::kDerivedEntries[derived ? entry : 0].quantity : -1;
  /// false when a check above failed: the node then skips the input's code.
  static constexpr bool valid =
      derived && I >= 0 && I < kMeasurementSize && quantity_index >= 0 &&
      derived_detail::kDerivedEntries[derived ? entry : 0].mode >= 0 &&
      derived_detail::memberFits<typename derived_detail::InputFieldOf<I>::type>(quantity_index);
  static constexpr extractors::PoseQuantity quantity =
      static_cast<extractors::PoseQuantity>(quantity_index < 0 ? 0 : quantity_index);
  static constexpr bool differential =
      derived &&
      derived_detail::kDerivedEntries[derived ? entry : 0].mode == derived_detail::Differential;
  template <class Member>
  static extractors::Pose pose(const Member& member) {
    return derived_detail::poseOf(member);
  }
};

}  // namespace sf_config
