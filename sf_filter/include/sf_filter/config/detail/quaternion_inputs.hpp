// Generated declarations of measured rotations (doc/configuration.md, "Rotations in 3D") from
// the optional
//
//   QUATERNION_INPUTS (i)(j)...  each index starts a measured unit quaternion: TOPICS_IN
//                                entries i..i+3 are its w, x, y, z (e.g. a sensor_msgs/Imu's
//                                orientation.w .. orientation.z), OBSERVATION_MODEL rows i..i+3
//                                the predicted quaternion, R's rows i..i+3 zero on w and the
//                                3 x 3 rotation-vector covariance (rad^2, world axes) on x, y, z
//
// into namespace sf_config:
//
//   constexpr bool kHasQuaternionInputs;  constexpr bool isQuaternionInput(int input);
//   using MeasurementLayout = ...  (with QUATERNION_STATES: an So3WorldBlock per entry,
//     VectorBlock<1> otherwise; the EKF and UKF compare those rows as z [-] h(x) on SO(3),
//     sf_estimation/manifold/measurement_rows.hpp)
//
// The four inputs are aligned LAST by default (input_alignment.hpp): a period's readings are
// not averaged component by component, which would mix q and -q. Checked at compile time, each
// reported once and naming the macro: the sequence form, QUATERNION_STATES present, the four
// entries inside TOPICS_IN and read from one topic (so one message type), overlapping no other
// entry and no ANGLE_INPUTS entry.
#pragma once

#include <type_traits>

#include "sf_filter/config/detail/angles.hpp"
#include "sf_filter/config/detail/constants.hpp"
#include "sf_filter/config/detail/option_entries.hpp"
#include "sf_filter/config/detail/preprocessor.hpp"
#include "sf_filter/config/detail/quaternion_spans.hpp"
#include "sf_filter/config/detail/quaternions.hpp"
#include "sf_filter/config/detail/topics.hpp"

// clang-format off

// --- preprocessing-time errors ------------------------------------------------------------------
#if defined(QUATERNION_INPUTS) && !defined(QUATERNION_STATES)
#error QUATERNION_INPUTS needs QUATERNION_STATES: a measured quaternion is compared on SO(3) by the EXTENDED_KALMAN_FILTER and UNSCENTED_KALMAN_FILTER of a state with rotations; declare the quaternion of the state with QUATERNION_STATES
#include "SF_CONFIGURATION_ERROR__compilation_stopped__fix_the_first_error_above"
#endif

// --- form -----------------------------------------------------------------------------------------
#if defined(QUATERNION_INPUTS) && !SF_PP_IS_VECTOR(QUATERNION_INPUTS)
static_assert(false, "QUATERNION_INPUTS: expected a sequence of TOPICS_IN indices, each in "
              "parentheses, e.g. (3) for a quaternion measured as TOPICS_IN entries 3..6 (w, x, "
              "y, z); found '" SF_PP_STR(QUATERNION_INPUTS) "'");
#endif
#define SF_QUATERNION_INPUTS_OK SF_PP_IS_VECTOR(QUATERNION_INPUTS)

// --- entries: one struct per index, checked -------------------------------------------------------
#define SF_QUATERNION_INPUT_PREFIX(k, index) \
  "QUATERNION_INPUTS entry " SF_PP_STR(k) ": the quaternion of TOPICS_IN entries " \
  SF_PP_STR(index) "..+3 "
#define SF_QUATERNION_INPUT_ENTRY(r, data, k, index)                                               \
  struct BOOST_PP_CAT(QuaternionInputEntry, k) {                                                   \
    SF_QUATERNION_START_MEMBERS(QUATERNION_INPUTS, k, index, SF_CFG_M, "among the inputs",      \
                                "its w, x, y, z are TOPICS_IN entries i..i+3", SF_CFG_M_WHY)       \
    static_assert(value < 0 || value + 3 >= (SF_CFG_M) ||                                          \
                      quaternion_inputs_detail::oneTopic(value),                                   \
                  SF_QUATERNION_INPUT_PREFIX(k, index) "is not read from one topic; its w, x, y, " \
                  "z come from one message (e.g. orientation.w .. orientation.z of a "             \
                  "sensor_msgs/Imu or pose.pose.orientation.w .. of a nav_msgs/Odometry)");        \
    static_assert(value < 0 || quaternion_inputs_detail::overlappedEntry(value, k) < 0,            \
                  SF_QUATERNION_INPUT_PREFIX(k, index) "overlaps the quaternion of an earlier "    \
                  "entry; each input belongs to one quaternion");                                  \
    static_assert(value < 0 || !quaternion_inputs_detail::overlapsAngleInput(value),               \
                  SF_QUATERNION_INPUT_PREFIX(k, index) "overlaps an ANGLE_INPUTS entry (or a "     \
                  "ROLL, PITCH or YAW derived input); an input is an angle or part of a "          \
                  "quaternion, not both");                                                         \
  };

// clang-format on

namespace sf_config {
namespace quaternion_inputs_detail {

/// Where each entry's quaternion starts, in order (then detail::kNoIndex).
SF_OPTION_INDICES(SF_QUATERNION_INPUTS_OK, kStarts, SF_ANGLE_INDEX, QUATERNION_INPUTS)

constexpr bool oneTopic(int start) {
  for (int i = start + 1; i < start + 4; ++i) {
    if (detail::firstIndexOf(kInputTopics, i) != detail::firstIndexOf(kInputTopics, start))
      return false;
  }
  return true;
}

/// The first of the entries before `entry` whose quaternion shares an input with the one at
/// `start`, or -1.
constexpr int overlappedEntry(int start, int entry) {
  return detail::overlappedQuaternion(kStarts, start, entry);
}

constexpr bool overlapsAngleInput(int start) {
  return detail::quaternionHitsFlag(kAngleInputs, start);
}

SF_OPTION_ENTRIES(SF_QUATERNION_INPUTS_OK, SF_QUATERNION_INPUT_ENTRY, ~, QUATERNION_INPUTS)

}  // namespace quaternion_inputs_detail

constexpr bool kHasQuaternionInputs = SF_QUATERNION_INPUTS_OK;

/// Whether TOPICS_IN entry `input` is one of a measured quaternion's four components.
constexpr bool isQuaternionInput(int input) {
  for (const int start : quaternion_inputs_detail::kStarts) {
    if (start != detail::kNoIndex && start <= input && input <= start + 3) return true;
  }
  return false;
}

#if SF_CFG_HAS_QUATERNION_STATES
namespace quaternion_inputs_detail {
struct InputKinds {
  static constexpr bool quaternionAt(int i) {
    for (const int start : kStarts) {
      if (start == i) return true;
    }
    return false;
  }
  // Angle inputs stay flat rows: the filters wrap their innovations (AngleMask).
  static constexpr bool angleAt(int) { return false; }
};
}  // namespace quaternion_inputs_detail

/// The measurement's blocks (the filters' MeasurementLayout); flat without QUATERNION_INPUTS.
using MeasurementLayout = quaternions_detail::LayoutFrom<quaternion_inputs_detail::InputKinds,
                                                         kMeasurementSize, false, 0>::type;
#endif

}  // namespace sf_config
