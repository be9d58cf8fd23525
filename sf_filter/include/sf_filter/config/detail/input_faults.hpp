// Generated per-input fault handling (doc/reliability.md) from the optional macros
//
//   INPUT_TIMEOUT  ((index)(ms)) per input with a sensor timeout: with no value accepted for
//                  longer, the input is timed out (missing every period, HOLD and FILL stop
//                  substituting) and its diagnostic status goes to WARN
//   INPUT_RANGE    ((index)(minimum)(maximum)) per input with a plausible range: values
//                  outside it are dropped on arrival and counted
//
// into namespace sf_config:
//
//   constexpr bool kHasInputTimeout, kHasInputRange;
//   inline constexpr std::array<double, m> kInputTimeoutsMs;    // infinity: no timeout
//   inline constexpr std::array<InputRange, m> kInputRanges;    // (-inf, inf): no range
//
// Checked at compile time, each reported once and naming the macro: the entries' form, input
// indices in range and listed once per macro, timeouts positive numbers of ms, ranges of
// numbers with minimum < maximum. Both macros apply to every METHOD.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "sf_filter/config/detail/input_alignment.hpp"

// clang-format off

// --- INPUT_TIMEOUT --------------------------------------------------------------------------------
#define SF_TIMEOUT_FORMAT "((input index)(timeout in ms)), e.g. ((0)(500))"
#if defined(INPUT_TIMEOUT)
SF_PP_CHECK_LIST("INPUT_TIMEOUT", 2, 2, SF_TIMEOUT_FORMAT, INPUT_TIMEOUT)
#define SF_TIMEOUT_OK SF_PP_IS_LIST(2, 2, INPUT_TIMEOUT)
#else
#define SF_TIMEOUT_OK 0
#endif

#define SF_TIMEOUT_ENTRY(r, data, k, entry)                                                        \
  struct BOOST_PP_CAT(TimeoutEntry, k) {                                                           \
    SF_AL_INDEX_MEMBERS("INPUT_TIMEOUT", firstTimeoutEntry, k, BOOST_PP_SEQ_ELEM(0, entry))        \
    static constexpr auto configured_timeout = BOOST_PP_SEQ_ELEM(1, entry);                        \
    static_assert(std::is_arithmetic<decltype(configured_timeout)>::value &&                       \
                      configured_timeout > 0 &&                                                    \
                      configured_timeout < std::numeric_limits<double>::infinity(),                \
                  SF_AL_PREFIX("INPUT_TIMEOUT", k, entry) ": timeout '"                            \
                  SF_PP_STR(BOOST_PP_SEQ_ELEM(1, entry)) "' must be a positive finite number of "  \
                  "milliseconds (leave the input out for no timeout)");                            \
    static constexpr double timeout_ms = static_cast<double>(configured_timeout);                  \
  };

// --- INPUT_RANGE ----------------------------------------------------------------------------------
#define SF_RANGE_FORMAT "((input index)(minimum)(maximum)), e.g. ((0)(-5.0)(5.0))"
#if defined(INPUT_RANGE)
SF_PP_CHECK_LIST("INPUT_RANGE", 3, 3, SF_RANGE_FORMAT, INPUT_RANGE)
#define SF_RANGE_OK SF_PP_IS_LIST(3, 3, INPUT_RANGE)
#else
#define SF_RANGE_OK 0
#endif

#define SF_RANGE_ENTRY(r, data, k, entry)                                                          \
  struct BOOST_PP_CAT(RangeEntry, k) {                                                             \
    SF_AL_INDEX_MEMBERS("INPUT_RANGE", firstRangeEntry, k, BOOST_PP_SEQ_ELEM(0, entry))            \
    static constexpr auto configured_minimum = BOOST_PP_SEQ_ELEM(1, entry);                        \
    static constexpr auto configured_maximum = BOOST_PP_SEQ_ELEM(2, entry);                        \
    static_assert(std::is_arithmetic<decltype(configured_minimum)>::value &&                       \
                      std::is_arithmetic<decltype(configured_maximum)>::value,                     \
                  SF_AL_PREFIX("INPUT_RANGE", k, entry) ": minimum '"                              \
                  SF_PP_STR(BOOST_PP_SEQ_ELEM(1, entry)) "' and maximum '"                         \
                  SF_PP_STR(BOOST_PP_SEQ_ELEM(2, entry)) "' must be numbers");                     \
    static constexpr double minimum = numberOrZero(configured_minimum);                            \
    static constexpr double maximum = numberOrZero(configured_maximum);                            \
    static_assert(!std::is_arithmetic<decltype(configured_minimum)>::value ||                      \
                      !std::is_arithmetic<decltype(configured_maximum)>::value ||                  \
                      minimum < maximum,                                                           \
                  SF_AL_PREFIX("INPUT_RANGE", k, entry) ": minimum '"                              \
                  SF_PP_STR(BOOST_PP_SEQ_ELEM(1, entry)) "' must be less than maximum '"           \
                  SF_PP_STR(BOOST_PP_SEQ_ELEM(2, entry)) "'");                                     \
  };

#define SF_TIMEOUT_APPLY(r, ARRAY, k, entry)                                                       \
  if (BOOST_PP_CAT(TimeoutEntry, k)::input_index >= 0 && BOOST_PP_CAT(TimeoutEntry, k)::input_index < kMeasurementSize) {     \
    ARRAY[static_cast<std::size_t>(BOOST_PP_CAT(TimeoutEntry, k)::input_index)] = BOOST_PP_CAT(TimeoutEntry, k)::timeout_ms;   \
  }
#define SF_RANGE_APPLY(r, ARRAY, k, entry)                                                         \
  if (BOOST_PP_CAT(RangeEntry, k)::input_index >= 0 && BOOST_PP_CAT(RangeEntry, k)::input_index < kMeasurementSize) {         \
    ARRAY[static_cast<std::size_t>(BOOST_PP_CAT(RangeEntry, k)::input_index)] =                    \
        InputRange{BOOST_PP_CAT(RangeEntry, k)::minimum, BOOST_PP_CAT(RangeEntry, k)::maximum};    \
  }

// clang-format on

namespace sf_config {

/// A plausible range of an input's values.
struct InputRange {
  double minimum = -std::numeric_limits<double>::infinity();
  double maximum = std::numeric_limits<double>::infinity();
};

// The index checks of SF_AL_INDEX_MEMBERS look their "first entry of this input" functions up
// in input_alignment_detail.
namespace input_alignment_detail {
#if SF_TIMEOUT_OK
inline constexpr int kTimeoutIndices[] = {BOOST_PP_SEQ_FOR_EACH_I(SF_AL_INDEX_OP, ~, INPUT_TIMEOUT)};
constexpr int firstTimeoutEntry(int input) { return detail::entryNaming(kTimeoutIndices, input); }
#endif
#if SF_RANGE_OK
inline constexpr int kRangeIndices[] = {BOOST_PP_SEQ_FOR_EACH_I(SF_AL_INDEX_OP, ~, INPUT_RANGE)};
constexpr int firstRangeEntry(int input) { return detail::entryNaming(kRangeIndices, input); }
#endif
}  // namespace input_alignment_detail

namespace input_faults_detail {

/// The entry as a double; 0 for one that is not a number (reported by a static_assert), so
/// that no follow-up error is printed.
template <class T>
constexpr double numberOrZero(const T& value) {
  if constexpr (std::is_arithmetic<T>::value) {
    return static_cast<double>(value);
  } else {
    return 0.0;
  }
}

#if SF_TIMEOUT_OK
BOOST_PP_SEQ_FOR_EACH_I(SF_TIMEOUT_ENTRY, ~, INPUT_TIMEOUT)
#endif
#if SF_RANGE_OK
BOOST_PP_SEQ_FOR_EACH_I(SF_RANGE_ENTRY, ~, INPUT_RANGE)
#endif

constexpr std::array<double, kMeasurementSize> makeTimeouts() {
  std::array<double, kMeasurementSize> timeouts{};
  for (double& t : timeouts) t = std::numeric_limits<double>::infinity();
#if SF_TIMEOUT_OK
  BOOST_PP_SEQ_FOR_EACH_I(SF_TIMEOUT_APPLY, timeouts, INPUT_TIMEOUT)
#endif
  return timeouts;
}

constexpr std::array<InputRange, kMeasurementSize> makeRanges() {
  std::array<InputRange, kMeasurementSize> ranges{};
#if SF_RANGE_OK
  BOOST_PP_SEQ_FOR_EACH_I(SF_RANGE_APPLY, ranges, INPUT_RANGE)
#endif
  return ranges;
}

}  // namespace input_faults_detail

constexpr bool kHasInputTimeout =
#if defined(INPUT_TIMEOUT)
    true;
#else
    false;
#endif
constexpr bool kHasInputRange =
#if defined(INPUT_RANGE)
    true;
#else
    false;
#endif

/// INPUT_TIMEOUT per input [ms]; infinity for inputs without a timeout.
inline constexpr std::array<double, kMeasurementSize> kInputTimeoutsMs =
    input_faults_detail::makeTimeouts();
/// INPUT_RANGE per input; (-inf, inf) for inputs without a range.
inline constexpr std::array<InputRange, kMeasurementSize> kInputRanges =
    input_faults_detail::makeRanges();

}  // namespace sf_config
