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
#if defined(ANGLE_STATES)
#if SF_PP_IS_VECTOR(ANGLE_STATES)
#define SF_ANGLE_STATES_OK 1
#else
static_assert(false, "ANGLE_STATES: expected a sequence of state indices, each in parentheses, "
              "e.g. (2) for a heading x[2]; found '" SF_PP_STR(ANGLE_STATES) "'");
#define SF_ANGLE_STATES_OK 0
#endif
#else
#define SF_ANGLE_STATES_OK 0
#endif

#if defined(ANGLE_INPUTS)
#if SF_PP_IS_VECTOR(ANGLE_INPUTS)
#define SF_ANGLE_INPUTS_OK 1
#else
static_assert(false, "ANGLE_INPUTS: expected a sequence of TOPICS_IN indices, each in "
              "parentheses, e.g. (1) for a compass as TOPICS_IN entry 1; found '"
              SF_PP_STR(ANGLE_INPUTS) "'");
#define SF_ANGLE_INPUTS_OK 0
#endif
#else
#define SF_ANGLE_INPUTS_OK 0
#endif

// --- entries: one struct per index, checked -------------------------------------------------------
// NAME "ANGLE_STATES", BOUND n or m, WHAT the text after "expected an integer from 0 to ...".
#define SF_ANGLE_ENTRY_MEMBERS(NAME, BOUND, WHAT, FIRST, k, index)                                 \
  static constexpr auto configured_index = index;                                                  \
  static constexpr int value = static_cast<int>(configured_index);                                 \
  static_assert(std::is_integral<decltype(configured_index)>::value && configured_index >= 0 &&   \
                    configured_index < (BOUND),                                                    \
                NAME " entry " SF_PP_STR(k) ": index '" SF_PP_STR(index) "' is out of range, "     \
                "expected an integer from 0 to " SF_PP_STR(BOOST_PP_DEC(BOUND)) " " WHAT);         \
  static_assert(value < 0 || value >= (BOUND) || angles_detail::FIRST(value) == k,                 \
                NAME " entry " SF_PP_STR(k) ": index " SF_PP_STR(index) " is already listed in "   \
                "an earlier entry; list each index once");

#define SF_ANGLE_STATE_ENTRY(r, data, k, index)                                                    \
  struct BOOST_PP_CAT(AngleStateEntry, k) {                                                        \
    SF_ANGLE_ENTRY_MEMBERS("ANGLE_STATES", SF_CFG_N, "(a state variable x[i]; " SF_CFG_N_WHY ")", \
                           firstAngleState, k, index)                                              \
  };
#define SF_ANGLE_INPUT_ENTRY(r, data, k, index)                                                    \
  struct BOOST_PP_CAT(AngleInputEntry, k) {                                                        \
    SF_ANGLE_ENTRY_MEMBERS("ANGLE_INPUTS", SF_CFG_M, "(the TOPICS_IN entry; " SF_CFG_M_WHY ")",    \
                           firstAngleInput, k, index)                                              \
  };

#define SF_ANGLE_INDEX_OP(r, data, k, index) BOOST_PP_COMMA_IF(k) static_cast<int>(index)
#define SF_ANGLE_APPLY(r, data, k, index)                                                          \
  if (BOOST_PP_CAT(BOOST_PP_TUPLE_ELEM(2, 1, data), k)::value >= 0 &&                              \
      BOOST_PP_CAT(BOOST_PP_TUPLE_ELEM(2, 1, data), k)::value < static_cast<int>(flags.size())) {  \
    flags[static_cast<std::size_t>(BOOST_PP_CAT(BOOST_PP_TUPLE_ELEM(2, 1, data), k)::value)] = true; \
  }

// clang-format on

namespace sf_config {
namespace angles_detail {

#if SF_ANGLE_STATES_OK
inline constexpr int kAngleStateIndices[] = {
    BOOST_PP_SEQ_FOR_EACH_I(SF_ANGLE_INDEX_OP, ~, ANGLE_STATES)};
constexpr int firstAngleState(int value) { return detail::entryNaming(kAngleStateIndices, value); }
BOOST_PP_SEQ_FOR_EACH_I(SF_ANGLE_STATE_ENTRY, ~, ANGLE_STATES)
#endif
#if SF_ANGLE_INPUTS_OK
inline constexpr int kAngleInputIndices[] = {
    BOOST_PP_SEQ_FOR_EACH_I(SF_ANGLE_INDEX_OP, ~, ANGLE_INPUTS)};
constexpr int firstAngleInput(int value) { return detail::entryNaming(kAngleInputIndices, value); }
BOOST_PP_SEQ_FOR_EACH_I(SF_ANGLE_INPUT_ENTRY, ~, ANGLE_INPUTS)
#endif

constexpr std::array<bool, kStateSize> makeAngleStates() {
  std::array<bool, kStateSize> flags{};
#if SF_ANGLE_STATES_OK
  BOOST_PP_SEQ_FOR_EACH_I(SF_ANGLE_APPLY, (~, AngleStateEntry), ANGLE_STATES)
#endif
  return flags;
}

constexpr std::array<bool, kMeasurementSize> makeAngleInputs() {
  std::array<bool, kMeasurementSize> flags{};
  // DERIVED_INPUTS ROLL, PITCH and YAW are angles without being listed.
  for (int i = 0; i < kMeasurementSize; ++i) {
    if (derived_detail::isDerivedAngle(i)) flags[static_cast<std::size_t>(i)] = true;
  }
#if SF_ANGLE_INPUTS_OK
  BOOST_PP_SEQ_FOR_EACH_I(SF_ANGLE_APPLY, (~, AngleInputEntry), ANGLE_INPUTS)
#endif
  return flags;
}

}  // namespace angles_detail

constexpr bool kHasAngleStates =
#if defined(ANGLE_STATES)
    true;
#else
    false;
#endif
constexpr bool kHasAngleInputs =
#if defined(ANGLE_INPUTS)
    true;
#else
    false;
#endif

/// ANGLE_STATES per state variable: true for an angle.
inline constexpr std::array<bool, kStateSize> kAngleStates = angles_detail::makeAngleStates();
/// ANGLE_INPUTS per input (TOPICS_IN order): true for a measured angle.
inline constexpr std::array<bool, kMeasurementSize> kAngleInputs = angles_detail::makeAngleInputs();

}  // namespace sf_config
