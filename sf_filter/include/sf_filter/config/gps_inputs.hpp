// GPS inputs (doc/configuration.md, "GPS"): DERIVED_INPUTS entries of quantity EAST, NORTH or UP
// on a TOPICS_IN entry of type sensor_msgs/NavSatFix, e.g.
//
//   TOPICS_IN ((fix)(sensor_msgs::NavSatFix)(longitude))((fix)(sensor_msgs::NavSatFix)(latitude))
//   DERIVED_INPUTS ((0)(EAST)(ABSOLUTE))((1)(NORTH)(ABSOLUTE))
//
// The field only has to be a member of the fix (longitude for EAST, latitude for NORTH and
// altitude for UP read best): the value is derived from the whole fix, its position about the
// datum in the odom frame, with the covariance from its position_covariance (the node's
// gps::GpsInputs, compiled once: sf_filter/gps/gps_inputs.hpp), correlations between the
// fix's GPS inputs included.
//
// Generates, in namespace sf_config:
//   template <int I> struct GpsDerivation {   // how TOPICS_IN entry I is read
//     static constexpr bool gps;              //   a GPS input
//     static constexpr bool valid;            //   false when a check below failed
//     static constexpr int axis; };           //   0 EAST (odom x), 1 NORTH (odom y), 2 UP (z)
// The fix is read by the GPS input extractor (generated/input_extractors.hpp).
//
// GPS_COVARIANCE_SCALE (optional, default 1) multiplies the covariance of every fix before it
// reaches the filter: a header that models the receiver's slowly changing error as a state
// (config/husky_skid_steer_gps.h) gives the filter only the white part of the error the fix
// declares. Generates sf_config::kGpsCovarianceScale; checked: a number > 0.
//
// Checked at compile time, each reported once and naming the macro and the entry: the message
// is a NavSatFix (latitude, longitude, altitude, status.status, position_covariance,
// position_covariance_type), the mode is ABSOLUTE, and the input has no other variance source
// (INPUT_COVARIANCE entry or variance field: the fix's covariance is the GPS input's), and each
// quantity is taken once per topic (a fix's GPS inputs are handed over together with their
// covariances). input_covariance_blocks.hpp refuses a GPS input in an INPUT_COVARIANCE_BLOCK.
// ROS-free; included by configuration.hpp after derived_inputs.hpp and input_covariance.hpp.
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>

namespace sf_config {
namespace gps_detail {

template <class T, class = void>
struct IsNavSatFix : std::false_type {};
template <class T>
struct IsNavSatFix<T, std::void_t<decltype(std::declval<const T&>().latitude),
                                  decltype(std::declval<const T&>().longitude),
                                  decltype(std::declval<const T&>().altitude),
                                  decltype(std::declval<const T&>().status.status),
                                  decltype(std::declval<const T&>().position_covariance[8]),
                                  decltype(std::declval<const T&>().position_covariance_type)>>
    : std::true_type {};

/// The message may be read as a fix (an unknown message type is reported elsewhere).
template <class Message>
constexpr bool messageFits() {
  return detail::isUnknownMessage<Message>() || IsNavSatFix<Message>::value;
}

template <int I>
constexpr bool isGpsInput() {
  return I >= 0 && I < kMeasurementSize && derived_detail::isDerivedGps(I);
}

/// The input of an earlier DERIVED_INPUTS entry that takes the same GPS quantity from the same
/// topic as entry k, -1 if none: one fix gives each of EAST, NORTH, UP once (its inputs are
/// handed over together, with their covariances; two equal rows would not be a covariance).
constexpr int sameAxisBefore(int k) {
  const derived_detail::DerivedEntry& e = derived_detail::kDerivedEntries[k];
  if (e.input < 0 || e.input >= kMeasurementSize) return -1;
  for (int j = 0; j < k; ++j) {
    const derived_detail::DerivedEntry& f = derived_detail::kDerivedEntries[j];
    if (f.quantity == e.quantity && f.input >= 0 && f.input < kMeasurementSize &&
        detail::firstIndexOf(kInputTopics, f.input) == detail::firstIndexOf(kInputTopics, e.input))
      return f.input;
  }
  return -1;
}

}  // namespace gps_detail

// clang-format off
#define SF_GPS_PREFIX(k, entry) "DERIVED_INPUTS entry " SF_PP_STR(k) " (" SF_PP_STR(entry) ")"
#define SF_GPS_ENTRY(r, data, k, entry)                                                            \
  struct BOOST_PP_CAT(GpsInputEntry, k) {                                                          \
    static constexpr derived_detail::DerivedEntry e = derived_detail::kDerivedEntries[k];          \
    static constexpr bool gps = derived_detail::isGpsQuantity(e.quantity) && e.input >= 0 &&       \
                                e.input < kMeasurementSize;                                        \
    using Message = typename detail::InputMessageOf<gps ? e.input : -1>::type;                     \
    static_assert(!gps || gps_detail::messageFits<Message>(),                                      \
                  SF_GPS_PREFIX(k, entry) ": EAST, NORTH and UP are the position of a GPS fix, "   \
                  "but the message type of TOPICS_IN entry " SF_PP_STR(BOOST_PP_SEQ_ELEM(0, entry)) \
                  " is not a sensor_msgs::NavSatFix (members latitude, longitude, altitude, "      \
                  "status.status, position_covariance, position_covariance_type)");               \
    static_assert(!gps || e.mode == derived_detail::Absolute,                                      \
                  SF_GPS_PREFIX(k, entry) ": EAST, NORTH and UP are ABSOLUTE only (a position "    \
                  "about the datum); for a velocity fuse another input");                          \
    static_assert(!gps || !CovarianceSource<gps ? e.input : 0>::given,                             \
                  SF_GPS_PREFIX(k, entry) ": the input also has an INPUT_COVARIANCE entry; a GPS " \
                  "input takes its variance from the fix's position_covariance (by its type), "    \
                  "remove the INPUT_COVARIANCE entry");                                            \
    static_assert(!gps || !covariance_detail::hasVarianceField(e.input),                           \
                  SF_GPS_PREFIX(k, entry) ": TOPICS_IN entry " SF_PP_STR(BOOST_PP_SEQ_ELEM(0, entry)) \
                  " has a variance field; a GPS input takes its variance from the fix's "          \
                  "position_covariance (by its type), remove the variance field");                 \
    static_assert(!gps || gps_detail::sameAxisBefore(k) < 0,                                       \
                  SF_GPS_PREFIX(k, entry) ": an earlier entry already takes this quantity from "   \
                  "the same topic's fix; each of EAST, NORTH and UP once per GPS topic");          \
  };
// clang-format on

#if SF_DI_OK
BOOST_PP_SEQ_FOR_EACH_I(SF_GPS_ENTRY, ~, DERIVED_INPUTS)
#endif

#if defined(GPS_COVARIANCE_SCALE)
namespace gps_detail {
inline constexpr auto kConfiguredCovarianceScale = GPS_COVARIANCE_SCALE;
static_assert(
    std::is_arithmetic<std::remove_const_t<decltype(kConfiguredCovarianceScale)>>::value &&
        kConfiguredCovarianceScale > 0 && kConfiguredCovarianceScale < 1e100,
    "GPS_COVARIANCE_SCALE: expected a finite factor > 0 on each fix's covariance, found "
    "'" SF_PP_STR(GPS_COVARIANCE_SCALE) "'");
}  // namespace gps_detail
/// GPS_COVARIANCE_SCALE: the factor on each fix's covariance (see above).
constexpr double kGpsCovarianceScale = static_cast<double>(gps_detail::kConfiguredCovarianceScale);
#else
constexpr double kGpsCovarianceScale = 1.0;
#endif

/// How TOPICS_IN entry I is read when it is a GPS input (see above).
template <int I>
struct GpsDerivation {
  static constexpr bool gps = gps_detail::isGpsInput<I>();
  static constexpr int axis =
      gps ? derived_detail::kDerivedEntries[derived_detail::entryOf(I)].quantity -
                derived_detail::East
          : 0;
  static constexpr bool valid =
      gps && gps_detail::IsNavSatFix<typename detail::InputMessageOf<I>::type>::value &&
      derived_detail::kDerivedEntries[gps ? derived_detail::entryOf(I) : 0].mode ==
          derived_detail::Absolute;
};

}  // namespace sf_config
