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
#if defined(INPUT_TIMEOUT)
SF_PP_CHECK_LIST("INPUT_TIMEOUT", 2, 2, "((input index)(timeout in ms)), e.g. ((0)(500))", INPUT_TIMEOUT)
#endif
#define SF_TIMEOUT_OK SF_PP_IS_LIST(2, 2, INPUT_TIMEOUT)

// --- INPUT_RANGE ----------------------------------------------------------------------------------
#if defined(INPUT_RANGE)
SF_PP_CHECK_LIST("INPUT_RANGE", 3, 3, "((input index)(minimum)(maximum)), e.g. ((0)(-5.0)(5.0))",
                 INPUT_RANGE)
#endif
#define SF_RANGE_OK SF_PP_IS_LIST(3, 3, INPUT_RANGE)

#define SF_RANGE_ENTRY(r, data, k, entry)                                                          \
  struct BOOST_PP_CAT(RangeEntry, k) {                                                             \
    SF_AL_INDEX_MEMBERS("INPUT_RANGE", kRangeIndices, k, BOOST_PP_SEQ_ELEM(0, entry))              \
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
    static constexpr InputRange value{minimum, maximum};                                           \
  };

// clang-format on

namespace sf_config {

/// A plausible range of an input's values.
struct InputRange {
  double minimum = -std::numeric_limits<double>::infinity();
  double maximum = std::numeric_limits<double>::infinity();
};

// The index lists SF_AL_INDEX_MEMBERS checks "listed once" against.
namespace input_alignment_detail {
SF_OPTION_INDICES(SF_TIMEOUT_OK, kTimeoutIndices, SF_AL_INDEX, INPUT_TIMEOUT)
SF_OPTION_INDICES(SF_RANGE_OK, kRangeIndices, SF_AL_INDEX, INPUT_RANGE)
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

SF_OPTION_ENTRIES(SF_TIMEOUT_OK, SF_POSITIVE_ENTRY_OP,
                  (TimeoutEntry, "INPUT_TIMEOUT", kTimeoutIndices, "timeout",
                   " of milliseconds (leave the input out for no timeout)"),
                  INPUT_TIMEOUT)
SF_OPTION_ENTRIES(SF_RANGE_OK, SF_RANGE_ENTRY, ~, INPUT_RANGE)

}  // namespace input_faults_detail

constexpr bool kHasInputTimeout = SF_TIMEOUT_OK;
constexpr bool kHasInputRange = SF_RANGE_OK;

/// INPUT_TIMEOUT per input [ms]; infinity for inputs without a timeout.
inline constexpr std::array<double, kMeasurementSize> kInputTimeoutsMs =
    SF_OPTION_VALUES(double, kMeasurementSize, std::numeric_limits<double>::infinity(),
                     SF_TIMEOUT_OK, input_faults_detail::TimeoutEntry, INPUT_TIMEOUT);
/// INPUT_RANGE per input; (-inf, inf) for inputs without a range.
inline constexpr std::array<InputRange, kMeasurementSize> kInputRanges =
    SF_OPTION_VALUES(InputRange, kMeasurementSize, InputRange{}, SF_RANGE_OK,
                     input_faults_detail::RangeEntry, INPUT_RANGE);

}  // namespace sf_config
