// Generated angle declarations (doc/configuration.md, "Angles") from the optional macros
//
//   ANGLE_STATES   (i)(j)...  state variables x[i] that are angles in radians (a heading)
//   ANGLE_INPUTS   (i)(j)...  TOPICS_IN entries that measure an angle in radians (a compass);
//                             DERIVED_INPUTS ROLL, PITCH and YAW are angle inputs without it
//
// into namespace sf_config:
//
//   constexpr bool kHasAngleStates, kHasAngleInputs;
//   inline constexpr std::array<bool, n> kAngleStates;
//   inline constexpr std::array<bool, m> kAngleInputs;
//
// The filter then wraps these states and the innovations of these inputs to (-pi, pi] and
// averages the angle states on the circle (sf_estimation/angles.hpp). Checked at compile
// time, each reported once and naming the macro: the sequence form, integer indices in
// range, each listed once; both are refused (#error) for MOVING_AVERAGE, MOVING_MEDIAN and
// CONFIDENCE_WEIGHTED_AVERAGING, which average linearly.
#pragma once

#include <array>
#include <type_traits>

#include "sf_filter/config/detail/constants.hpp"
#include "sf_filter/config/detail/derived_inputs.hpp"
#include "sf_filter/config/detail/option_entries.hpp"
#include "sf_filter/config/detail/preprocessor.hpp"

// clang-format off

// --- preprocessing-time errors ------------------------------------------------------------------
#if defined(ANGLE_STATES) && SF_CFG_IS_AVERAGING
#error ANGLE_STATES is used by KALMAN_FILTER, EXTENDED_KALMAN_FILTER, UNSCENTED_KALMAN_FILTER and PARTICLE_FILTER_SIR only: MOVING_AVERAGE, MOVING_MEDIAN and CONFIDENCE_WEIGHTED_AVERAGING average linearly; remove ANGLE_STATES or choose a model-based METHOD
#include "SF_CONFIGURATION_ERROR__compilation_stopped__fix_the_first_error_above"
#endif
#if defined(ANGLE_INPUTS) && SF_CFG_IS_AVERAGING
#error ANGLE_INPUTS is used by KALMAN_FILTER, EXTENDED_KALMAN_FILTER, UNSCENTED_KALMAN_FILTER and PARTICLE_FILTER_SIR only: MOVING_AVERAGE, MOVING_MEDIAN and CONFIDENCE_WEIGHTED_AVERAGING average linearly; remove ANGLE_INPUTS or choose a model-based METHOD
#include "SF_CONFIGURATION_ERROR__compilation_stopped__fix_the_first_error_above"
#endif

// --- form -----------------------------------------------------------------------------------------
#if defined(ANGLE_STATES) && !SF_PP_IS_VECTOR(ANGLE_STATES)
static_assert(false, "ANGLE_STATES: expected a sequence of state indices, each in parentheses, "
              "e.g. (2) for a heading x[2]; found '" SF_PP_STR(ANGLE_STATES) "'");
#endif
#define SF_ANGLE_STATES_OK SF_PP_IS_VECTOR(ANGLE_STATES)
#if defined(ANGLE_INPUTS) && !SF_PP_IS_VECTOR(ANGLE_INPUTS)
static_assert(false, "ANGLE_INPUTS: expected a sequence of TOPICS_IN indices, each in "
              "parentheses, e.g. (1) for a compass as TOPICS_IN entry 1; found '"
              SF_PP_STR(ANGLE_INPUTS) "'");
#endif
#define SF_ANGLE_INPUTS_OK SF_PP_IS_VECTOR(ANGLE_INPUTS)

// --- entries: one struct per index, checked -------------------------------------------------------
// NAME "ANGLE_STATES", BOUND n or m, WHAT the text after "expected an integer from 0 to ...".
#define SF_ANGLE_ENTRY_MEMBERS(NAME, BOUND, WHAT, INDICES, k, index)                               \
  static constexpr auto configured_index = index;                                                  \
  static constexpr int input_index = static_cast<int>(configured_index);                           \
  static constexpr bool value = true;                                                              \
  static_assert(std::is_integral<decltype(configured_index)>::value && configured_index >= 0 &&   \
                    configured_index < (BOUND),                                                    \
                NAME " entry " SF_PP_STR(k) ": index '" SF_PP_STR(index) "' is out of range, "     \
                "expected an integer from 0 to " SF_PP_STR(BOOST_PP_DEC(BOUND)) " " WHAT);         \
  static_assert(input_index < 0 || input_index >= (BOUND) ||                                       \
                    detail::entryNaming(angles_detail::INDICES, input_index) == k,                 \
                NAME " entry " SF_PP_STR(k) ": index " SF_PP_STR(index) " is already listed in "   \
                "an earlier entry; list each index once");

#define SF_ANGLE_STATE_ENTRY(r, data, k, index)                                                    \
  struct BOOST_PP_CAT(AngleStateEntry, k) {                                                        \
    SF_ANGLE_ENTRY_MEMBERS("ANGLE_STATES", SF_CFG_N, "(a state variable x[i]; " SF_CFG_N_WHY ")", \
                           kAngleStateIndices, k, index)                                              \
  };
#define SF_ANGLE_INPUT_ENTRY(r, data, k, index)                                                    \
  struct BOOST_PP_CAT(AngleInputEntry, k) {                                                        \
    SF_ANGLE_ENTRY_MEMBERS("ANGLE_INPUTS", SF_CFG_M, "(the TOPICS_IN entry; " SF_CFG_M_WHY ")",    \
                           kAngleInputIndices, k, index)                                              \
  };

#define SF_ANGLE_INDEX(index) static_cast<int>(index)

// clang-format on

namespace sf_config {
namespace angles_detail {

SF_OPTION_INDICES(SF_ANGLE_STATES_OK, kAngleStateIndices, SF_ANGLE_INDEX, ANGLE_STATES)
SF_OPTION_INDICES(SF_ANGLE_INPUTS_OK, kAngleInputIndices, SF_ANGLE_INDEX, ANGLE_INPUTS)
SF_OPTION_ENTRIES(SF_ANGLE_STATES_OK, SF_ANGLE_STATE_ENTRY, ~, ANGLE_STATES)
SF_OPTION_ENTRIES(SF_ANGLE_INPUTS_OK, SF_ANGLE_INPUT_ENTRY, ~, ANGLE_INPUTS)

/// ANGLE_INPUTS, and the DERIVED_INPUTS ROLL, PITCH and YAW (angles without being listed).
constexpr std::array<bool, kMeasurementSize> makeAngleInputs() {
  std::array<bool, kMeasurementSize> flags = SF_OPTION_VALUES(
      bool, kMeasurementSize, false, SF_ANGLE_INPUTS_OK, AngleInputEntry, ANGLE_INPUTS);
  for (int i = 0; i < kMeasurementSize; ++i) {
    if (derived_detail::isDerivedAngle(i)) flags[static_cast<std::size_t>(i)] = true;
  }
  return flags;
}

}  // namespace angles_detail

constexpr bool kHasAngleStates = SF_ANGLE_STATES_OK;
constexpr bool kHasAngleInputs = SF_ANGLE_INPUTS_OK;

/// ANGLE_STATES per state variable: true for an angle.
inline constexpr std::array<bool, kStateSize> kAngleStates = SF_OPTION_VALUES(
    bool, kStateSize, false, SF_ANGLE_STATES_OK, angles_detail::AngleStateEntry, ANGLE_STATES);
/// ANGLE_INPUTS per input (TOPICS_IN order): true for a measured angle.
inline constexpr std::array<bool, kMeasurementSize> kAngleInputs = angles_detail::makeAngleInputs();

}  // namespace sf_config
