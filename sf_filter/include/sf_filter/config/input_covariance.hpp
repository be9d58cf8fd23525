// Variances from the message's covariance array (doc/configuration.md, "Covariance from the
// message"):
//
//   INPUT_COVARIANCE  ((input index)(covariance array member)(entry)) per TOPICS_IN entry whose
//                     variance is taken from a covariance array of its message, e.g.
//                     ((0)(orientation_covariance)(8)) for the yaw of sensor_msgs::Imu,
//                     ((1)(pose.covariance)(35)) for the yaw of nav_msgs::Odometry
//
// A message whose array is all zero or has -1 first (ROS's "unknown") gives no variance: the
// header's MEASUREMENT_NOISE_COVARIANCE entry is used and the fallback counted
// (extractors/message_covariance.hpp). The entry replaces a variance field of the TOPICS_IN
// entry (both are refused). Generates, in namespace sf_config:
//
//   template <int I> struct CovarianceSource {      // the variance source of TOPICS_IN entry I
//     static constexpr bool given;                  //   false: the variance field, if any
//     template <class Message> static std::optional<double> variance(const Message&);
//     static constexpr bool valid; };               //   false if a check below failed
//
// Checked at compile time, each reported once and naming the macro: the entries' form, input
// index 0 <= index < m and listed once, no variance field as well, the member is an array of
// numbers and the entry a non-negative integer below its size when the size is known.
#pragma once

#include <iterator>
#include <optional>
#include <type_traits>
#include <utility>

#include "sf_filter/config/detail/option_entries.hpp"
#include "sf_filter/config/extractors/message_covariance.hpp"

// clang-format off
#define SF_IC_FORMAT "((input index)(covariance array member)(entry)), e.g. " \
  "((0)(orientation_covariance)(8))"

#if defined(INPUT_COVARIANCE)
SF_PP_CHECK_LIST("INPUT_COVARIANCE", 3, 3, SF_IC_FORMAT, INPUT_COVARIANCE)
#endif
#define SF_IC_OK SF_PP_IS_LIST(3, 3, INPUT_COVARIANCE)

#define SF_IC_PREFIX(k, entry) "INPUT_COVARIANCE entry " SF_PP_STR(k) " (" SF_PP_STR(entry) ")"
#define SF_IC_INDEX(entry) static_cast<int>(BOOST_PP_SEQ_ELEM(0, entry))

// NAME<MessageT>: whether MessageT has the array-of-numbers member MEMBER (ok), the array's
// static size (size; -1 when not fixed) and the member itself (array(m); nullptr when not ok).
// The detector of INPUT_COVARIANCE and INPUT_COVARIANCE_BLOCK entries.
#define SF_IC_ARRAY_MEMBER(NAME, MEMBER)                                                           \
  template <class MessageT, class = void>                                                          \
  struct NAME {                                                                                    \
    static constexpr bool ok = false;                                                              \
    static constexpr long size = -1;                                                               \
    template <class M> static const double* array(const M&) { return nullptr; }                    \
  };                                                                                               \
  template <class MessageT>                                                                        \
  struct NAME<MessageT, std::void_t<decltype(std::size(std::declval<const MessageT&>().MEMBER)),   \
                                    decltype(std::declval<const MessageT&>().MEMBER[0])>> {        \
    static constexpr bool ok =                                                                     \
        std::is_convertible_v<decltype(std::declval<const MessageT&>().MEMBER[0]), double>;        \
    static constexpr long size = ::sf_config::covariance_detail::staticSize<                       \
        std::remove_cv_t<std::remove_reference_t<decltype(std::declval<const MessageT&>().MEMBER)>>>(); \
    template <class M> static const auto& array(const M& m) { return m.MEMBER; }                   \
  };

#define SF_IC_ENTRY(r, data, k, entry)                                                             \
  namespace covariance_detail {                                                                    \
  SF_IC_ARRAY_MEMBER(BOOST_PP_CAT(ArrayMember, k), BOOST_PP_SEQ_ELEM(1, entry))                    \
  }                                                                                                \
  struct BOOST_PP_CAT(CovarianceEntry, k) {                                                        \
    static constexpr bool given = true;                                                            \
    static constexpr int input_index = SF_IC_INDEX(entry);                                         \
    static constexpr auto configured_entry = BOOST_PP_SEQ_ELEM(2, entry);                          \
    static constexpr long entry_index = static_cast<long>(configured_entry);                       \
    using Message = typename ::sf_config::detail::InputMessageOf<input_index>::type;               \
    using Member = covariance_detail::BOOST_PP_CAT(ArrayMember, k)<Message>;                       \
    template <class M>                                                                             \
    static std::optional<double> variance(const M& message) {                                      \
      using Of = covariance_detail::BOOST_PP_CAT(ArrayMember, k)<M>;                               \
      if constexpr (Of::ok) {                                                                      \
        return ::sf_config::extractors::covarianceEntry(Of::array(message),                        \
                                                        static_cast<std::size_t>(entry_index));    \
      } else {                                                                                     \
        return std::nullopt;                                                                       \
      }                                                                                            \
    }                                                                                              \
    static constexpr bool unknown = ::sf_config::detail::isUnknownMessage<Message>();              \
    static constexpr bool valid = input_index >= 0 && input_index < kMeasurementSize &&           \
        !unknown && Member::ok && entry_index >= 0 &&                                              \
        (Member::size < 0 || entry_index < Member::size);                                          \
    static_assert(std::is_integral<decltype(BOOST_PP_SEQ_ELEM(0, entry))>::value &&               \
                      input_index >= 0 && input_index < kMeasurementSize,                          \
                  SF_IC_PREFIX(k, entry) ": input index '" SF_PP_STR(BOOST_PP_SEQ_ELEM(0, entry))  \
                  "' is out of range, expected an integer from 0 to "                              \
                  SF_PP_STR(BOOST_PP_DEC(SF_CFG_M)) " (" SF_CFG_M_WHY ")");                        \
    static_assert(covariance_detail::firstEntryOf(input_index) == k,                               \
                  SF_IC_PREFIX(k, entry) ": the input is already listed in an earlier entry");     \
    static_assert(!(input_index >= 0 && input_index < kMeasurementSize) ||                         \
                      !covariance_detail::hasVarianceField(input_index),                          \
                  SF_IC_PREFIX(k, entry) ": TOPICS_IN entry " SF_PP_STR(BOOST_PP_SEQ_ELEM(0, entry)) \
                  " has a variance field too; remove one of the two variance sources");            \
    static_assert(unknown || Member::ok,                                                           \
                  SF_IC_PREFIX(k, entry) ": member '" SF_PP_STR(BOOST_PP_SEQ_ELEM(1, entry))       \
                  "' of the message type of TOPICS_IN entry " SF_PP_STR(BOOST_PP_SEQ_ELEM(0, entry)) \
                  " is not an array of numbers (e.g. orientation_covariance of sensor_msgs::Imu, " \
                  "pose.covariance of nav_msgs::Odometry)");                                       \
    static_assert(std::is_integral<decltype(configured_entry)>::value && entry_index >= 0 &&      \
                      (unknown || !Member::ok || Member::size < 0 ||                               \
                       entry_index < Member::size),                                                \
                  SF_IC_PREFIX(k, entry) ": entry '" SF_PP_STR(BOOST_PP_SEQ_ELEM(2, entry))        \
                  "' is not an integer index into the array (row-major: row r, column c of a "     \
                  "6x6 covariance is 6 r + c, e.g. 35 for yaw; of a 3x3 one 3 r + c, 8 for yaw)"); \
  };
// clang-format on

namespace sf_config {
namespace covariance_detail {

/// The size of a fixed-size array type (C array, std::array, boost::array), -1 otherwise.
template <class T, class = void>
struct StaticSize {
  static constexpr long value = -1;
};
template <class T, std::size_t N>
struct StaticSize<T[N]> {
  static constexpr long value = static_cast<long>(N);
};
template <class T>
struct StaticSize<T, std::void_t<decltype(T::static_size)>> {
  static constexpr long value = static_cast<long>(T::static_size);  // boost::array
};
template <class T>
constexpr long staticSize() {
  return StaticSize<T>::value;
}

SF_OPTION_INDICES(SF_IC_OK, kCovarianceIndices, SF_IC_INDEX, INPUT_COVARIANCE)

/// The first INPUT_COVARIANCE entry of `input`, -1 if none.
constexpr int firstEntryOf(int input) { return detail::entryNaming(kCovarianceIndices, input); }

template <std::size_t... I>
constexpr bool hasVarianceFieldOf(int input, std::index_sequence<I...>) {
  return ((static_cast<int>(I) == input && std::tuple_element_t<I, Inputs>::has_variance) || ...);
}
constexpr bool hasVarianceField(int input) {
  return hasVarianceFieldOf(input, std::make_index_sequence<kMeasurementSize>{});
}

}  // namespace covariance_detail

/// No INPUT_COVARIANCE entry: the variance field, if any.
struct NoCovarianceSource {
  static constexpr bool given = false;
  static constexpr bool valid = false;
};

SF_OPTION_ENTRIES(SF_IC_OK, SF_IC_ENTRY, ~, INPUT_COVARIANCE)

/// The INPUT_COVARIANCE source of TOPICS_IN entry I (CovarianceEntry<k>), or NoCovarianceSource.
template <int I>
using CovarianceSource = SF_OPTION_DESCRIPTOR(SF_IC_OK, CovarianceEntry, INPUT_COVARIANCE,
                                              covariance_detail::firstEntryOf(I),
                                              NoCovarianceSource);

}  // namespace sf_config
