// Generated per-input alignment options (doc/alignment_policies.md) from the optional macros
//
//   INPUT_ALIGNMENT      one entry per input that is not AVERAGE:
//                          ((index)(AVERAGE)) ((index)(LAST)) ((index)(SAMPLED))
//                          ((index)(HOLD)(LAGRANGE|BEZIER|TAYLOR)(order)) or (...)(variance))
//                          ((index)(FILL)(omega)(N)) or ((index)(FILL)(omega)(N)(variance))
//   INPUT_GATE           ((index)(threshold)) per gated input
//   ALIGN_BY_STAMP       (index)(index)... the inputs aligned by header stamp
//   MAX_MEASUREMENT_LAG  ms a period waits for stamped values (default: one estimation period
//                        with ALIGN_BY_STAMP, else 0)
//
// into namespace sf_config:
//
//   constexpr bool kHasInputAlignment, kHasInputGate, kHasAlignByStamp;
//   inline constexpr std::array<sf_filter::AlignmentPolicy, m> kInputAlignment;
//   inline constexpr std::array<double, m> kGateThresholds;    // infinity: no gate
//   inline constexpr std::array<bool, m> kAlignByStamp;
//   inline constexpr std::array<bool, m> kInputHasStamp;       // the message has header.stamp
//   constexpr double kMaxMeasurementLagMs;
// (sf_config::defaultInputOptions() in input_options.hpp combines them per input.)
//
// Checked at compile time, each reported once and naming the macro: the entries' form, the
// policy and primitive names, the entry size of each policy, input indices in range and
// listed once per macro, HOLD order 0..15, FILL omega > 0 and N 1..16, variances and gate
// thresholds > 0, MAX_MEASUREMENT_LAG >= 0, stamped message types for ALIGN_BY_STAMP, and no
// gate and no FILL for the averaging methods (they predict no measurement).
#pragma once

#include <array>
#include <cstddef>
#include <iterator>
#include <limits>
#include <optional>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include <boost/preprocessor/facilities/is_empty.hpp>
#include <boost/preprocessor/tuple/elem.hpp>
#include <boost/preprocessor/tuple/enum.hpp>

#include "sf_filter/config/detail/constants.hpp"
#include "sf_filter/config/detail/option_entries.hpp"
#include "sf_filter/config/detail/preprocessor.hpp"
#include "sf_filter/config/detail/quaternion_inputs.hpp"
#include "sf_filter/config/detail/support.hpp"
#include "sf_filter/config/detail/topics.hpp"
#include "sf_filter/core/input_options.hpp"

// clang-format off

// --- preprocessing-time errors ------------------------------------------------------------------
#if defined(INPUT_GATE) && SF_CFG_IS_AVERAGING
#error INPUT_GATE needs the predicted measurement and innovation covariance of the filter, which MOVING_AVERAGE, MOVING_MEDIAN and CONFIDENCE_WEIGHTED_AVERAGING do not give: remove INPUT_GATE or choose a model-based METHOD
#include "SF_CONFIGURATION_ERROR__compilation_stopped__fix_the_first_error_above"
#endif
#if defined(MAX_MEASUREMENT_LAG) && BOOST_PP_IS_EMPTY(MAX_MEASUREMENT_LAG)
#error MAX_MEASUREMENT_LAG is defined but empty: expected a number of milliseconds >= 0, e.g. #define MAX_MEASUREMENT_LAG 50
#include "SF_CONFIGURATION_ERROR__compilation_stopped__fix_the_first_error_above"
#endif
#if defined(MAX_MEASUREMENT_LAG) && !defined(ALIGN_BY_STAMP)
#pragma GCC warning "MAX_MEASUREMENT_LAG is not used without ALIGN_BY_STAMP and is ignored (the ~max_measurement_lag parameter may still use it with ~align_by_stamp)"
#endif

// --- INPUT_ALIGNMENT ------------------------------------------------------------------------------
#if defined(INPUT_ALIGNMENT)
SF_PP_CHECK_LIST("INPUT_ALIGNMENT", 2, 5,
                 "((index)(AVERAGE)), ((index)(LAST)), ((index)(SAMPLED)), "
                 "((index)(HOLD)(LAGRANGE|BEZIER|TAYLOR)(order)[(variance)]) or "
                 "((index)(FILL)(omega)(N)[(variance)])",
                 INPUT_ALIGNMENT)
#endif
#define SF_AL_OK SF_PP_IS_LIST(2, 5, INPUT_ALIGNMENT)

// Policy names: (id, fewest elements, most elements, form of the entry). A name is recognized
// by pasting it to SF_AL_KIND_: an unknown name gives an identifier, not a tuple.
#define SF_AL_KIND_AVERAGE (0, 2, 2, "((index)(AVERAGE))")
#define SF_AL_KIND_LAST (1, 2, 2, "((index)(LAST))")
#define SF_AL_KIND_SAMPLED (2, 2, 2, "((index)(SAMPLED))")
#define SF_AL_KIND_HOLD (3, 4, 5, "((index)(HOLD)(LAGRANGE|BEZIER|TAYLOR)(order)[(variance)])")
#define SF_AL_KIND_FILL (4, 4, 5, "((index)(FILL)(omega)(N)[(variance)])")
#define SF_AL_PRIMITIVE_LAGRANGE (Lagrange)
#define SF_AL_PRIMITIVE_BEZIER (Bezier)
#define SF_AL_PRIMITIVE_TAYLOR (Taylor)

#define SF_AL_INFO(entry) BOOST_PP_CAT(SF_AL_KIND_, BOOST_PP_SEQ_ELEM(1, entry))
#define SF_AL_KNOWN(entry) BOOST_PP_IS_BEGIN_PARENS(SF_AL_INFO(entry))
#define SF_AL_ID(entry) BOOST_PP_TUPLE_ELEM(4, 0, SF_AL_INFO(entry))
#define SF_AL_SIZE_OK(entry)                                                                       \
  BOOST_PP_BITAND(                                                                                 \
      BOOST_PP_GREATER_EQUAL(BOOST_PP_SEQ_SIZE(entry), BOOST_PP_TUPLE_ELEM(4, 1, SF_AL_INFO(entry))), \
      BOOST_PP_LESS_EQUAL(BOOST_PP_SEQ_SIZE(entry), BOOST_PP_TUPLE_ELEM(4, 2, SF_AL_INFO(entry))))
#define SF_AL_PRIMITIVE_INFO(entry) BOOST_PP_CAT(SF_AL_PRIMITIVE_, BOOST_PP_SEQ_ELEM(2, entry))

// Message prefix naming an entry, e.g. "INPUT_ALIGNMENT entry 1 ((2)(HOLD)(SPLINE)(1))".
#define SF_AL_PREFIX(MACRO, k, entry) MACRO " entry " SF_PP_STR(k) " (" SF_PP_STR(entry) ")"

// The input index of an entry of a per-input option, checked (range, listed once: INDICES is
// the option's index list in input_alignment_detail, see SF_OPTION_INDICES).
#define SF_AL_INDEX_MEMBERS(MACRO, INDICES, k, index)                                                \
  static constexpr auto configured_index = index;                                                  \
  static constexpr int input_index = static_cast<int>(configured_index);                           \
  static_assert(std::is_integral<decltype(configured_index)>::value && configured_index >= 0 &&   \
                    configured_index < kMeasurementSize,                                           \
                MACRO " entry " SF_PP_STR(k) ": input index '" SF_PP_STR(index)                    \
                "' is out of range, expected an integer from 0 to " SF_PP_STR(BOOST_PP_DEC(SF_CFG_M)) \
                " (the TOPICS_IN entry; " SF_CFG_M_WHY ")");                                       \
  static_assert(input_index < 0 || input_index >= kMeasurementSize ||                             \
                    detail::entryNaming(input_alignment_detail::INDICES, input_index) == k,                               \
                MACRO " entry " SF_PP_STR(k) ": input " SF_PP_STR(index)                           \
                " is already listed in an earlier entry; list each input once");

// The optional variance (5th element) of a HOLD or FILL entry.
#define SF_AL_VARIANCE_MEMBERS(k, entry)                                                           \
  static constexpr std::optional<double> variance = BOOST_PP_IIF(                                  \
      BOOST_PP_EQUAL(BOOST_PP_SEQ_SIZE(entry), 5), SF_AL_VARIANCE_GIVEN, SF_AL_VARIANCE_NONE)(entry); \
  static_assert(!variance || *variance > 0.0,                                                      \
                SF_AL_PREFIX("INPUT_ALIGNMENT", k, entry) ": variance must be positive (the "      \
                "measurement variance of the substitutes; leave it out to use R)");
#define SF_AL_VARIANCE_GIVEN(entry) std::optional<double>(static_cast<double>(BOOST_PP_SEQ_ELEM(4, entry)))
#define SF_AL_VARIANCE_NONE(entry) std::optional<double>()

// An entry ((index)(value)) of a per-input option whose value is a positive finite number
// (INPUT_GATE, INPUT_TIMEOUT): struct STRUCT<k> with its checked input_index and `value`. As
// SF_OPTION_ENTRIES' ENTRY: data = (STRUCT, MACRO, INDICES, WHAT, HINT).
#define SF_POSITIVE_ENTRY_OP(r, data, k, entry) SF_POSITIVE_ENTRY(BOOST_PP_TUPLE_ENUM(data), k, entry)
#define SF_POSITIVE_ENTRY(...) SF_POSITIVE_ENTRY_I(__VA_ARGS__)
#define SF_POSITIVE_ENTRY_I(STRUCT, MACRO, INDICES, WHAT, HINT, k, entry)                          \
  struct BOOST_PP_CAT(STRUCT, k) {                                                                 \
    SF_AL_INDEX_MEMBERS(MACRO, INDICES, k, BOOST_PP_SEQ_ELEM(0, entry))                            \
    static constexpr auto configured_value = BOOST_PP_SEQ_ELEM(1, entry);                          \
    static_assert(std::is_arithmetic<decltype(configured_value)>::value && configured_value > 0 && \
                      configured_value < std::numeric_limits<double>::infinity(),                  \
                  SF_AL_PREFIX(MACRO, k, entry) ": " WHAT " '" SF_PP_STR(BOOST_PP_SEQ_ELEM(1, entry)) \
                  "' must be a positive finite number" HINT);                                      \
    static constexpr double value = static_cast<double>(configured_value);                         \
  };

#define SF_AL_ENTRY(r, data, k, entry)                                                             \
  BOOST_PP_IIF(SF_AL_KNOWN(entry), SF_AL_ENTRY_KNOWN, SF_AL_ENTRY_UNKNOWN)(k, entry)
#define SF_AL_ENTRY_UNKNOWN(k, entry)                                                              \
  struct BOOST_PP_CAT(AlignmentEntry, k) : input_alignment_detail::EntryBase {                     \
    static_assert(false, SF_AL_PREFIX("INPUT_ALIGNMENT", k, entry) ": unknown policy '"            \
                  SF_PP_STR(BOOST_PP_SEQ_ELEM(1, entry))                                           \
                  "', expected AVERAGE, LAST, SAMPLED, HOLD or FILL (in capitals)");               \
  };
#define SF_AL_ENTRY_KNOWN(k, entry)                                                                \
  BOOST_PP_IIF(SF_AL_SIZE_OK(entry), SF_AL_ENTRY_SIZED, SF_AL_ENTRY_BAD_SIZE)(k, entry)
#define SF_AL_ENTRY_BAD_SIZE(k, entry)                                                             \
  struct BOOST_PP_CAT(AlignmentEntry, k) : input_alignment_detail::EntryBase {                     \
    static_assert(false, SF_AL_PREFIX("INPUT_ALIGNMENT", k, entry) ": "                            \
                  SF_PP_STR(BOOST_PP_SEQ_ELEM(1, entry)) " takes the form "                        \
                  BOOST_PP_TUPLE_ELEM(4, 3, SF_AL_INFO(entry)) ", found "                          \
                  SF_PP_STR(BOOST_PP_SEQ_SIZE(entry)) " elements");                                \
  };
#define SF_AL_ENTRY_SIZED(k, entry) BOOST_PP_CAT(SF_AL_ENTRY_KIND_, SF_AL_ID(entry))(k, entry)

#define SF_AL_ENTRY_SIMPLE(k, entry, FACTORY)                                                      \
  struct BOOST_PP_CAT(AlignmentEntry, k) : input_alignment_detail::EntryBase {                     \
    SF_AL_INDEX_MEMBERS("INPUT_ALIGNMENT", kAlignmentIndices, k, BOOST_PP_SEQ_ELEM(0, entry))      \
    static constexpr ::sf_filter::AlignmentPolicy value = ::sf_filter::AlignmentPolicy::FACTORY(); \
  };
#define SF_AL_ENTRY_KIND_0(k, entry) SF_AL_ENTRY_SIMPLE(k, entry, average)
#define SF_AL_ENTRY_KIND_1(k, entry) SF_AL_ENTRY_SIMPLE(k, entry, last)
#define SF_AL_ENTRY_KIND_2(k, entry) SF_AL_ENTRY_SIMPLE(k, entry, sampled)

#define SF_AL_ENTRY_KIND_3(k, entry)                                                               \
  BOOST_PP_IIF(BOOST_PP_IS_BEGIN_PARENS(SF_AL_PRIMITIVE_INFO(entry)), SF_AL_ENTRY_HOLD,           \
               SF_AL_ENTRY_BAD_PRIMITIVE)(k, entry)
#define SF_AL_ENTRY_BAD_PRIMITIVE(k, entry)                                                        \
  struct BOOST_PP_CAT(AlignmentEntry, k) : input_alignment_detail::EntryBase {                     \
    static_assert(false, SF_AL_PREFIX("INPUT_ALIGNMENT", k, entry) ": unknown hold primitive '"    \
                  SF_PP_STR(BOOST_PP_SEQ_ELEM(2, entry)) "', expected LAGRANGE, BEZIER or TAYLOR " \
                  "(Armesto et al., Table 1), e.g. ((0)(HOLD)(LAGRANGE)(1)) for a first-order hold"); \
  };
#define SF_AL_ENTRY_HOLD(k, entry)                                                                 \
  struct BOOST_PP_CAT(AlignmentEntry, k) : input_alignment_detail::EntryBase {                     \
    SF_AL_INDEX_MEMBERS("INPUT_ALIGNMENT", kAlignmentIndices, k, BOOST_PP_SEQ_ELEM(0, entry))      \
    SF_AL_VARIANCE_MEMBERS(k, entry)                                                               \
    static constexpr auto configured_order = BOOST_PP_SEQ_ELEM(3, entry);                          \
    static_assert(std::is_integral<decltype(configured_order)>::value && configured_order >= 0 &&  \
                      configured_order <= ::sf_filter::kMaxHoldOrder,                              \
                  SF_AL_PREFIX("INPUT_ALIGNMENT", k, entry) ": HOLD order '"                       \
                  SF_PP_STR(BOOST_PP_SEQ_ELEM(3, entry)) "' is not an integer from 0 to 15 (0 "    \
                  "zero-order hold, 1 first-order hold, ...)");                                    \
    static constexpr ::sf_filter::AlignmentPolicy value = ::sf_filter::AlignmentPolicy::hold(     \
        ::sf_filter::HoldPrimitive::BOOST_PP_TUPLE_ELEM(1, 0, SF_AL_PRIMITIVE_INFO(entry)),        \
        static_cast<int>(configured_order), variance);                                             \
  };

#define SF_AL_ENTRY_KIND_4(k, entry)                                                               \
  struct BOOST_PP_CAT(AlignmentEntry, k) : input_alignment_detail::EntryBase {                     \
    SF_AL_INDEX_MEMBERS("INPUT_ALIGNMENT", kAlignmentIndices, k, BOOST_PP_SEQ_ELEM(0, entry))      \
    SF_AL_VARIANCE_MEMBERS(k, entry)                                                               \
    static constexpr auto configured_omega = BOOST_PP_SEQ_ELEM(2, entry);                          \
    static constexpr auto configured_samples = BOOST_PP_SEQ_ELEM(3, entry);                        \
    static_assert(std::is_arithmetic<decltype(configured_omega)>::value && configured_omega > 0,  \
                  SF_AL_PREFIX("INPUT_ALIGNMENT", k, entry) ": FILL omega '"                       \
                  SF_PP_STR(BOOST_PP_SEQ_ELEM(2, entry)) "' must be a positive number of "         \
                  "seconds (Wang et al. use 0.001)");                                              \
    static_assert(std::is_integral<decltype(configured_samples)>::value &&                         \
                      configured_samples >= 1 &&                                                   \
                      configured_samples <= ::sf_filter::SampleHistory::kCapacity,                 \
                  SF_AL_PREFIX("INPUT_ALIGNMENT", k, entry) ": FILL N '"                           \
                  SF_PP_STR(BOOST_PP_SEQ_ELEM(3, entry)) "' is not an integer from 1 to 16 (the "  \
                  "number of stored samples; Wang et al. use 5)");                                 \
    static_assert(!SF_CFG_IS_AVERAGING,                                                            \
                  SF_AL_PREFIX("INPUT_ALIGNMENT", k, entry) ": FILL needs the filter's predicted " \
                  "measurement h(x(k|k-1)), which " SF_CFG_METHOD_NAME " does not give; choose a " \
                  "model-based METHOD or another policy");                                         \
    static constexpr ::sf_filter::AlignmentPolicy value = ::sf_filter::AlignmentPolicy::fill(     \
        static_cast<double>(configured_omega), static_cast<int>(configured_samples), variance);    \
  };

// --- INPUT_GATE -----------------------------------------------------------------------------------
#if defined(INPUT_GATE)
SF_PP_CHECK_LIST("INPUT_GATE", 2, 2, "((input index)(chi-square threshold)), e.g. ((1)(9.0))", INPUT_GATE)
#endif
#define SF_GATE_OK SF_PP_IS_LIST(2, 2, INPUT_GATE)

// --- ALIGN_BY_STAMP -------------------------------------------------------------------------------
#if defined(ALIGN_BY_STAMP)
#if SF_PP_IS_VECTOR(ALIGN_BY_STAMP)
#define SF_STAMP_OK 1
#else
static_assert(false, "ALIGN_BY_STAMP: expected a sequence of input indices, each in parentheses, "
              "e.g. (0)(2); found '" SF_PP_STR(ALIGN_BY_STAMP) "'");
#define SF_STAMP_OK 0
#endif
#else
#define SF_STAMP_OK 0
#endif

#define SF_STAMP_ENTRY(r, data, k, index)                                                          \
  struct BOOST_PP_CAT(StampEntry, k) {                                                             \
    SF_AL_INDEX_MEMBERS("ALIGN_BY_STAMP", kStampIndices, k, index)                               \
    using Message = typename ::sf_config::detail::InputMessageOf<input_index>::type;               \
    static_assert(::sf_config::detail::isUnknownMessage<Message>() ||                              \
                      ::sf_config::detail::HasHeaderStamp<Message>::value,                         \
                  "ALIGN_BY_STAMP entry " SF_PP_STR(k) ": the message type of TOPICS_IN entry "    \
                  SF_PP_STR(index) " has no header.stamp; only stamped messages can be aligned "   \
                  "by stamp");                                                                     \
    static constexpr bool value = true;                                                            \
  };

#define SF_AL_INDEX(entry) static_cast<int>(BOOST_PP_SEQ_ELEM(0, entry))
#define SF_STAMP_INDEX(index) static_cast<int>(index)
// clang-format on

namespace sf_config {
namespace input_alignment_detail {

SF_OPTION_INDICES(SF_AL_OK, kAlignmentIndices, SF_AL_INDEX, INPUT_ALIGNMENT)
SF_OPTION_INDICES(SF_GATE_OK, kGateIndices, SF_AL_INDEX, INPUT_GATE)
SF_OPTION_INDICES(SF_STAMP_OK, kStampIndices, SF_STAMP_INDEX, ALIGN_BY_STAMP)

/// What a malformed entry contributes: nothing (its mistake was reported).
struct EntryBase {
  static constexpr int input_index = -1;
  static constexpr ::sf_filter::AlignmentPolicy value{};
};

SF_OPTION_ENTRIES(SF_AL_OK, SF_AL_ENTRY, ~, INPUT_ALIGNMENT)
SF_OPTION_ENTRIES(SF_GATE_OK, SF_POSITIVE_ENTRY_OP,
                  (GateEntry, "INPUT_GATE", kGateIndices, "threshold",
                   " (the chi-square quantile with 1 degree of freedom, e.g. 3.84 for 95 %, 6.63 "
                   "for 99 %, 9 for 3 sigma)"),
                  INPUT_GATE)
SF_OPTION_ENTRIES(SF_STAMP_OK, SF_STAMP_ENTRY, ~, ALIGN_BY_STAMP)

template <std::size_t... I>
constexpr std::array<bool, kMeasurementSize> makeInputHasStamp(std::index_sequence<I...>) {
  return {{detail::HasHeaderStamp<typename std::tuple_element_t<I, Inputs>::Message>::value...}};
}

}  // namespace input_alignment_detail

constexpr bool kHasInputAlignment = SF_AL_OK;
constexpr bool kHasInputGate = SF_GATE_OK;
constexpr bool kHasAlignByStamp = SF_STAMP_OK;

namespace input_alignment_detail {
/// INPUT_ALIGNMENT's entries, LAST for the QUATERNION_INPUTS it does not list (a period's
/// readings of a quaternion are not averaged component by component: q and -q would cancel),
/// AVERAGE for the other inputs it does not list.
constexpr std::array<::sf_filter::AlignmentPolicy, kMeasurementSize> makeInputAlignment() {
  std::array<::sf_filter::AlignmentPolicy, kMeasurementSize> policies =
      SF_OPTION_VALUES(::sf_filter::AlignmentPolicy, kMeasurementSize,
                       ::sf_filter::AlignmentPolicy{}, SF_AL_OK, AlignmentEntry, INPUT_ALIGNMENT);
  for (int i = 0; i < kMeasurementSize; ++i) {
    if (isQuaternionInput(i) && detail::entryNaming(kAlignmentIndices, i) < 0) {
      policies[static_cast<std::size_t>(i)] = ::sf_filter::AlignmentPolicy::last();
    }
  }
  return policies;
}
}  // namespace input_alignment_detail

/// INPUT_ALIGNMENT per input (TOPICS_IN order); for inputs it does not list AVERAGE, or LAST
/// for a QUATERNION_INPUTS component.
inline constexpr std::array<::sf_filter::AlignmentPolicy, kMeasurementSize> kInputAlignment =
    input_alignment_detail::makeInputAlignment();

namespace input_alignment_detail {
/// The first QUATERNION_INPUTS component aligned otherwise than LAST or SAMPLED, or -1.
constexpr int averagedQuaternionInput() {
  for (int i = 0; i < kMeasurementSize; ++i) {
    const ::sf_filter::AlignmentKind kind = kInputAlignment[static_cast<std::size_t>(i)].kind;
    if (isQuaternionInput(i) && kind != ::sf_filter::AlignmentKind::Last &&
        kind != ::sf_filter::AlignmentKind::Sampled)
      return i;
  }
  return -1;
}
static_assert(averagedQuaternionInput() < 0,
              "QUATERNION_INPUTS: an INPUT_ALIGNMENT entry averages or extrapolates a measured "
              "quaternion's component (AVERAGE, HOLD or FILL); a quaternion's components are "
              "taken together as read, LAST (its default) or SAMPLED: averaging them one by one "
              "leaves the rotation group and mixes q and -q");
}  // namespace input_alignment_detail
/// INPUT_GATE per input; infinity for inputs without gate.
inline constexpr std::array<double, kMeasurementSize> kGateThresholds =
    SF_OPTION_VALUES(double, kMeasurementSize, std::numeric_limits<double>::infinity(), SF_GATE_OK,
                     input_alignment_detail::GateEntry, INPUT_GATE);
/// ALIGN_BY_STAMP per input.
inline constexpr std::array<bool, kMeasurementSize> kAlignByStamp = SF_OPTION_VALUES(
    bool, kMeasurementSize, false, SF_STAMP_OK, input_alignment_detail::StampEntry, ALIGN_BY_STAMP);
/// Whether each input's message type has header.stamp.
inline constexpr std::array<bool, kMeasurementSize> kInputHasStamp =
    input_alignment_detail::makeInputHasStamp(std::make_index_sequence<kMeasurementSize>{});

#if defined(MAX_MEASUREMENT_LAG)
namespace input_alignment_detail {
inline constexpr auto kConfiguredLag = MAX_MEASUREMENT_LAG;
static_assert(std::is_arithmetic<std::remove_const_t<decltype(kConfiguredLag)>>::value &&
                  kConfiguredLag >= 0,
              "MAX_MEASUREMENT_LAG: expected a number of milliseconds >= 0, found '" SF_PP_STR(
                  MAX_MEASUREMENT_LAG) "'");
}  // namespace input_alignment_detail
/// MAX_MEASUREMENT_LAG [ms] (as given: 0 is allowed and means "estimate at the period's end").
constexpr double kMaxMeasurementLagMs = static_cast<double>(input_alignment_detail::kConfiguredLag);
#else
/// MAX_MEASUREMENT_LAG [ms] not given: one estimation period when inputs are aligned by stamp
/// (a lag of 0 would make every value arriving after its period's end late and dropped, so a
/// stamped input with any transport delay would lose most of its values), else 0.
constexpr double kMaxMeasurementLagMs = kHasAlignByStamp ? kEstimationPeriodMs : 0.0;
#endif

}  // namespace sf_config
