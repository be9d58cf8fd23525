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
//     using Kind;                                   //   its extractor kind (extractors/kinds.hpp)
//     static constexpr int kind_quantity; };        //   the quantity's index in Kind
//
// Checked at compile time, each reported once and naming the macro: the entries' form, input
// index 0 <= index < m and listed once, the quantity and the mode names, the member's type
// (a quaternion, or a pose for X, Y, Z), angles only with the model-based methods.
// ROS-free (the config_errors tests compile it with stand-in messages); included by
// configuration.hpp after the inputs.
#pragma once

#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "sf_filter/config/detail/derived_inputs.hpp"
#include "sf_filter/config/extractors/pose_difference.hpp"

namespace sf_config {
namespace derived_detail {

/// Whether the input's member can be read for the entry's quantity (unknown types pass: their
/// mistake is reported elsewhere).
/// Quantity `quantity` has no DIFFERENTIAL form (its kind's kAbsoluteOnly).
template <std::size_t... K>
constexpr bool absoluteOnlyOf(int quantity, std::index_sequence<K...>) {
  const extractors::QuantityEntry e = extractors::quantityEntry(quantity);
  return ((static_cast<int>(K) == e.kind &&
           std::tuple_element_t<K, extractors::ExtractorKinds>::kAbsoluteOnly) ||
          ...);
}
constexpr bool absoluteOnly(int quantity) {
  return absoluteOnlyOf(quantity,
                        std::make_index_sequence<std::tuple_size_v<extractors::ExtractorKinds>>{});
}

/// Whether `quantity`'s kind can read member type Field (an unknown quantity passes: its
/// name is reported).
template <class Field, std::size_t... K>
constexpr bool kindFits(int quantity, std::index_sequence<K...>) {
  const extractors::QuantityEntry e = extractors::quantityEntry(quantity);
  return e.kind < 0 ||
         ((static_cast<int>(K) == e.kind &&
           std::tuple_element_t<K, extractors::ExtractorKinds>::template fits<Field>(e.local)) ||
          ...);
}

template <class Field>
constexpr bool memberFits(int quantity) {
  if constexpr (std::is_same_v<Field, detail::UnknownMessage>) {
    return true;
  } else {
    return kindFits<Field>(
        quantity, std::make_index_sequence<std::tuple_size_v<extractors::ExtractorKinds>>{});
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
                  "quaternion or a pose's orientation) or EAST, NORTH, UP (of a NavSatFix), nor "  \
                  "of the other extractor kinds of sf_filter/config/extractors/kinds.hpp");        \
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
                  "nav_msgs::Odometry; for another kind's quantity the member its fits() "         \
                  "accepts (sf_filter/config/extractors/)");                                       \
    static_assert(!SF_CFG_IS_AVERAGING || !derived_detail::isAngleQuantity(e.quantity),           \
                  SF_DI_PREFIX(k, entry) ": ROLL, PITCH and YAW are angle inputs, used by "        \
                  "KALMAN_FILTER, EXTENDED_KALMAN_FILTER, UNSCENTED_KALMAN_FILTER and "            \
                  "PARTICLE_FILTER_SIR only (MOVING_AVERAGE, MOVING_MEDIAN and "                   \
                  "CONFIDENCE_WEIGHTED_AVERAGING average linearly; so are the angles of the "      \
                  "other extractor kinds)");                                                       \
    static_assert(e.mode != derived_detail::Differential ||                                        \
                      !derived_detail::absoluteOnly(e.quantity),                                   \
                  SF_DI_PREFIX(k, entry) ": quantity '" SF_PP_STR(BOOST_PP_SEQ_ELEM(1, entry))     \
                  "' is ABSOLUTE only (it has no change since the previous message to fuse)");     \
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
      derived_detail::memberFits<typename derived_detail::InputFieldOf<I>::type>(quantity_index) &&
      !(derived_detail::kDerivedEntries[derived ? entry : 0].mode == derived_detail::Differential &&
        derived_detail::absoluteOnly(quantity_index));
  static constexpr extractors::PoseQuantity quantity =
      static_cast<extractors::PoseQuantity>(quantity_index < 0 ? 0 : quantity_index);
  static constexpr bool differential =
      derived &&
      derived_detail::kDerivedEntries[derived ? entry : 0].mode == derived_detail::Differential;
  /// The extractor kind that reads the input (extractors/kinds.hpp) and the quantity's index
  /// in it.
  using Kind = extractors::KindOf<quantity_index>;
  static constexpr int kind_quantity = extractors::quantityEntry(quantity_index).local;
};

}  // namespace sf_config
