// The table of DERIVED_INPUTS (doc/configuration.md, "Derived inputs"), read before the inputs
// are generated: which TOPICS_IN entries derive their value from a quaternion or pose member
// instead of reading a numeric field, and which of them are angles (made ANGLE_INPUTS
// automatically). The per-entry checks and the extraction are in config/derived_inputs.hpp.
//
//   DERIVED_INPUTS  ((input index)(quantity)(mode)) per derived TOPICS_IN entry, where the
//                   entry's field is the member the value is derived from:
//                   quantity ROLL, PITCH, YAW   of a quaternion member (x, y, z, w)
//                            X, Y, Z            of a pose member (position, orientation)
//                            EAST, NORTH, UP    of a sensor_msgs/NavSatFix (any of its members:
//                                               the whole fix is read; config/gps_inputs.hpp)
//                            and the quantities of the other extractor kinds registered in
//                            extractors/kinds.hpp (e.g. MAGNETIC_YAW of a MagneticField)
//                   mode     ABSOLUTE           the value itself
//                            DIFFERENTIAL       the change since the previous message of the
//                                               topic, in the frame of the previous pose
#pragma once

#include <string_view>

#include "sf_filter/config/detail/preprocessor.hpp"
#include "sf_filter/config/extractors/kinds.hpp"

// clang-format off
#define SF_DI_FORMAT "((input index)(quantity)(mode)), e.g. ((0)(YAW)(ABSOLUTE)) with quantity " \
  "one of X Y Z ROLL PITCH YAW and mode ABSOLUTE or DIFFERENTIAL"

#if defined(DERIVED_INPUTS)
SF_PP_CHECK_LIST("DERIVED_INPUTS", 3, 3, SF_DI_FORMAT, DERIVED_INPUTS)
#define SF_DI_OK SF_PP_IS_LIST(3, 3, DERIVED_INPUTS)
#else
#define SF_DI_OK 0
#endif

#define SF_DI_TABLE_OP(r, data, k, entry)                                                          \
  BOOST_PP_COMMA_IF(k) DerivedEntry{static_cast<int>(BOOST_PP_SEQ_ELEM(0, entry)),                 \
                                    quantityOf(SF_PP_STR(BOOST_PP_SEQ_ELEM(1, entry))),            \
                                    modeOf(SF_PP_STR(BOOST_PP_SEQ_ELEM(2, entry)))}
// clang-format on

namespace sf_config {
namespace derived_detail {

/// DERIVED_INPUTS quantities; Unknown for a name that is none of them.
enum Quantity : int {
  X = 0,
  Y = 1,
  Z = 2,
  Roll = 3,
  Pitch = 4,
  Yaw = 5,
  East = 6,
  North = 7,
  Up = 8,
  UnknownQuantity = -1
};
enum Mode : int { Absolute = 0, Differential = 1, UnknownMode = -1 };

/// The quantity named `s` (extractors/kinds.hpp numbers them across the extractor kinds).
constexpr int quantityOf(std::string_view s) { return extractors::quantityNumber(s); }
static_assert(extractors::quantityNumber("X") == X && extractors::quantityNumber("YAW") == Yaw &&
                  extractors::quantityNumber("EAST") == East &&
                  extractors::quantityNumber("UP") == Up,
              "extractors/kinds.hpp: the pose and GPS quantities keep their numbers");
constexpr int modeOf(std::string_view s) {
  return s == "ABSOLUTE" ? Absolute : s == "DIFFERENTIAL" ? Differential : UnknownMode;
}
/// An angle quantity (ROLL, PITCH, YAW, MAGNETIC_YAW, ...): an angle input.
constexpr bool isAngleQuantity(int q) { return extractors::quantityEntry(q).angle; }
/// A GPS quantity: the position of a sensor_msgs/NavSatFix in the odom frame.
constexpr bool isGpsQuantity(int q) { return q == East || q == North || q == Up; }

struct DerivedEntry {
  int input;
  int quantity;
  int mode;
};

#if SF_DI_OK
inline constexpr DerivedEntry kDerivedEntries[] = {
    BOOST_PP_SEQ_FOR_EACH_I(SF_DI_TABLE_OP, ~, DERIVED_INPUTS)};
inline constexpr int kDerivedCount = sizeof(kDerivedEntries) / sizeof(kDerivedEntries[0]);
#else
inline constexpr DerivedEntry kDerivedEntries[] = {{-1, UnknownQuantity, UnknownMode}};
inline constexpr int kDerivedCount = 0;
#endif

/// The first DERIVED_INPUTS entry of TOPICS_IN entry `input`, -1 if none.
constexpr int entryOf(int input) {
  for (int k = 0; k < kDerivedCount; ++k) {
    if (kDerivedEntries[k].input == input) return k;
  }
  return -1;
}

/// TOPICS_IN entry `input` is derived: its field is a member, not a number.
constexpr bool isDerived(int input) { return entryOf(input) >= 0; }

/// DERIVED_INPUTS is malformed or lists an input index out of range: which fields are members
/// is unknown, and the DERIVED_INPUTS error is the one to report.
constexpr bool derivedTableBroken() {
#if defined(DERIVED_INPUTS)
  if (!SF_DI_OK) return true;
  for (int k = 0; k < kDerivedCount; ++k) {
    if (kDerivedEntries[k].input < 0 || kDerivedEntries[k].input >= SF_CFG_M) return true;
  }
#endif
  return false;
}

/// The TOPICS_IN field of `input` need not be a number (see the two functions above).
constexpr bool fieldMayBeMember(int input) { return isDerived(input) || derivedTableBroken(); }

/// TOPICS_IN entry `input` is a derived ROLL, PITCH or YAW (an angle input).
constexpr bool isDerivedAngle(int input) {
  return isDerived(input) && isAngleQuantity(kDerivedEntries[entryOf(input)].quantity);
}

/// TOPICS_IN entry `input` is a derived EAST, NORTH or UP (a GPS input).
constexpr bool isDerivedGps(int input) {
  return isDerived(input) && isGpsQuantity(kDerivedEntries[entryOf(input)].quantity);
}

}  // namespace derived_detail
}  // namespace sf_config
