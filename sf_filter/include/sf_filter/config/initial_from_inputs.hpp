// State variables that start at an input's first reading instead of INITIAL_STATE
// (doc/configuration.md, "Initial state"):
//
//   INITIAL_STATE_FROM_INPUTS  ((state index)(input index)) per such state variable: x[state]
//              takes the first measured value of input `input` (the aligned value of the first
//              period in which the input has one), before that period's step
//
// For a velocity the header cannot know: a recording that starts in motion must not read
// x0 = 0 as standstill (config/skid_steer_odom_imu.h). The input should observe the state
// directly (its observation model is x[state] at the initial state). Generates, in namespace
// sf_config:
//   inline constexpr FirstReading kInitialFromInputs[];  // {state, input} (nullptr without)
//   constexpr std::size_t kInitialFromInputsCount;
// Checked at compile time, naming the macro: the entries' form, state indices 0 <= i < n and
// input indices 0 <= j < m.
#pragma once

#include <cstddef>
#include <iterator>

#include <boost/preprocessor/seq/elem.hpp>
#include <boost/preprocessor/seq/for_each.hpp>

#include "sf_filter/config/detail/constants.hpp"
#include "sf_filter/config/detail/preprocessor.hpp"

// clang-format off
#define SF_FIRST_READING_FORMAT "((state index)(input index)), e.g. ((3)(0))"
#if defined(INITIAL_STATE_FROM_INPUTS)
SF_PP_CHECK_LIST("INITIAL_STATE_FROM_INPUTS", 2, 2, SF_FIRST_READING_FORMAT,
                 INITIAL_STATE_FROM_INPUTS)
#define SF_FIRST_READING_OK SF_PP_IS_LIST(2, 2, INITIAL_STATE_FROM_INPUTS)
#else
#define SF_FIRST_READING_OK 0
#endif
#define SF_FIRST_READING_ENTRY(r, data, entry) \
  {static_cast<int>(BOOST_PP_SEQ_ELEM(0, entry)), static_cast<int>(BOOST_PP_SEQ_ELEM(1, entry))},
// clang-format on

namespace sf_config {

struct FirstReading {
  int state;
  int input;
};

#if SF_FIRST_READING_OK
inline constexpr FirstReading kInitialFromInputs[] = {
    BOOST_PP_SEQ_FOR_EACH(SF_FIRST_READING_ENTRY, ~, INITIAL_STATE_FROM_INPUTS)};
constexpr bool firstReadingsInRange() {
  for (const FirstReading& f : kInitialFromInputs) {
    if (f.state < 0 || f.state >= kStateSize || f.input < 0 || f.input >= kMeasurementSize) {
      return false;
    }
  }
  return true;
}
static_assert(firstReadingsInRange(),
              "INITIAL_STATE_FROM_INPUTS: every state index must be from 0 to n - 1 and every "
              "input index from 0 to m - 1; found '" SF_PP_STR(INITIAL_STATE_FROM_INPUTS) "'");
constexpr std::size_t kInitialFromInputsCount = std::size(kInitialFromInputs);
#else
inline constexpr const FirstReading* kInitialFromInputs = nullptr;
constexpr std::size_t kInitialFromInputsCount = 0;
#endif

}  // namespace sf_config
