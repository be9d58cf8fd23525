// The table of extractor kinds (extractor.hpp): the one place a new kind is registered. Its
// quantity names become DERIVED_INPUTS quantities (and INPUTS (derived, quantity, mode)), its
// angles ANGLE_INPUTS, its parameters private node parameters, and the node and the replay read
// its inputs through it. Quantities are numbered across the kinds in this order (X = 0 ...
// YAW = 5, EAST = 6 ... UP = 8, MAGNETIC_YAW = 9): append new kinds at the end.
// ROS-free and header-only; read before the inputs are generated (detail/derived_inputs.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <tuple>
#include <utility>

#include "sf_filter/config/extractors/extractor.hpp"
#include "sf_filter/config/extractors/magnetic_heading.hpp"
#include "sf_filter/config/extractors/pose_difference.hpp"

namespace sf_config {
namespace extractors {

/// Extractor kind EAST, NORTH, UP of a sensor_msgs/NavSatFix: the fix about the datum in the
/// odom frame. Its inputs are read by generated/input_extractors.hpp's GpsInput and handed
/// over together with their covariance block (GpsGroup): the datum (gps/gps_inputs.hpp) is
/// shared by the topic's inputs, and the checks are config/gps_inputs.hpp's.
struct GpsPosition : ExtractorState {
  static constexpr std::array<std::string_view, 3> kQuantities{"EAST", "NORTH", "UP"};
  static constexpr std::array<bool, 3> kAngle{false, false, false};
  static constexpr std::array<ExtractorParameter, 0> kParameters{};
  /// false: gps_inputs.hpp refuses DIFFERENTIAL with its own message.
  static constexpr bool kAbsoluteOnly = false;
  template <class Member>
  static constexpr bool fits(int) {
    return true;  // any member of the fix: gps_inputs.hpp checks the message
  }
};

// clang-format off
using ExtractorKinds = std::tuple<
    PoseQuantities,
    GpsPosition,
    MagneticHeading>;
// clang-format on

/// One DERIVED_INPUTS quantity: its name, its kind (index into ExtractorKinds) and its index
/// in the kind's kQuantities.
struct QuantityEntry {
  std::string_view name;
  bool angle = false;
  int kind = -1;
  int local = -1;
};

template <std::size_t... K>
constexpr std::size_t quantityCount(std::index_sequence<K...>) {
  return (std::tuple_element_t<K, ExtractorKinds>::kQuantities.size() + ...);
}
inline constexpr std::size_t kQuantityCount =
    quantityCount(std::make_index_sequence<std::tuple_size_v<ExtractorKinds>>{});

template <class Kind>
constexpr void addQuantities(std::array<QuantityEntry, kQuantityCount>& table, std::size_t& n,
                             int kind) {
  for (std::size_t q = 0; q < Kind::kQuantities.size(); ++q) {
    table[n++] = {Kind::kQuantities[q], Kind::kAngle[q], kind, static_cast<int>(q)};
  }
}
template <std::size_t... K>
constexpr std::array<QuantityEntry, kQuantityCount> quantityTable(std::index_sequence<K...>) {
  std::array<QuantityEntry, kQuantityCount> table{};
  std::size_t n = 0;
  (addQuantities<std::tuple_element_t<K, ExtractorKinds>>(table, n, static_cast<int>(K)), ...);
  return table;
}
/// Every DERIVED_INPUTS quantity, numbered across the kinds.
inline constexpr std::array<QuantityEntry, kQuantityCount> kQuantityTable =
    quantityTable(std::make_index_sequence<std::tuple_size_v<ExtractorKinds>>{});

/// The number of quantity `name`, -1 if no kind has it.
constexpr int quantityNumber(std::string_view name) {
  for (std::size_t q = 0; q < kQuantityCount; ++q) {
    if (kQuantityTable[q].name == name) return static_cast<int>(q);
  }
  return -1;
}
/// The entry of quantity number q (a default entry, kind -1, for an unknown one).
constexpr QuantityEntry quantityEntry(int q) {
  return q >= 0 && q < static_cast<int>(kQuantityCount)
             ? kQuantityTable[static_cast<std::size_t>(q)]
             : QuantityEntry{};
}

/// The kind of quantity number Q (PoseQuantities for an unknown one: its checks failed).
template <int Q>
using KindOf =
    std::tuple_element_t<(quantityEntry(Q).kind < 0 ? 0 : quantityEntry(Q).kind), ExtractorKinds>;

}  // namespace extractors
}  // namespace sf_config
