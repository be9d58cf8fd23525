// What a fusion node does with the sensor_msgs/NavSatFix of its GPS inputs (DERIVED_INPUTS
// EAST, NORTH, UP; doc/configuration.md, "GPS"): the status check, the datum, the conversion
// to the odom frame (local_frame.hpp) and the variance from the fix's position_covariance.
//
// - A fix whose status is below STATUS_FIX (-1, STATUS_NO_FIX) gives no value: it is dropped
//   and counted per input (noFix(), shown in the input's diagnostics). A fix whose latitude or
//   longitude is not finite gives a NaN value, which the fusion core drops and counts as not
//   finite; a NaN altitude ("no altitude" in NavSatFix) is taken as the datum's for EAST and
//   NORTH and gives a NaN UP.
// - A fix whose finite position is not on the Earth (implausible(): latitude outside
//   [-90, 90], longitude outside [-180, 180] degrees, altitude outside [kMinAltitude,
//   kMaxAltitude]) gives no value either: dropped and counted per input with the reason
//   (implausibleFixes(), implausibleReason()). Wrapping longitude 500 to 140 would fuse a
//   place on the other side of the Earth; an altitude of 1e30 m overflows the geodesy.
// - The datum is the ~datum parameter if given (checked by the same implausible()), else the
//   first fix with a valid status and a plausible finite position (its NaN altitude taken as
//   0), kept until new settings (setOptions). A first fix that fails the checks is dropped,
//   not taken as the datum: the next plausible one is.
// - position_covariance_type COVARIANCE_TYPE_UNKNOWN (0) gives no variance: the header's R
//   is used and the caller counts the fallback. KNOWN (3) gives the whole ENU covariance,
//   APPROXIMATED (1) and DIAGONAL_KNOWN (2) its diagonal only (the type says the rest is not
//   known), turned into the odom frame (odomCovariance): the node hands the covariances
//   between a fix's GPS inputs to the fusion core with their values (a covariance block).
// ROS-free; compiled once in sf_fusion_core and unit-tested in test_gps_inputs.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sf_filter/gps/local_frame.hpp"

namespace sf_filter {
namespace gps {

/// The GPS inputs' settings (private parameters ~datum and ~gps_yaw_offset).
struct GpsOptions {
  std::optional<Datum> datum;  ///< nullopt: the first valid fix
  double yawOffset = 0.0;      ///< [rad], see local_frame.hpp
};

/// The members of a sensor_msgs/NavSatFix that a GPS input reads.
struct Fix {
  int status = -1;  ///< status.status: -1 no fix, 0 fix, 1 SBAS, 2 GBAS
  double latitude = 0.0;
  double longitude = 0.0;
  double altitude = 0.0;
  std::array<double, 9> covariance{};  ///< position_covariance, ENU, row-major
  int covarianceType = 0;              ///< position_covariance_type
};

inline constexpr int kStatusFix = 0;              ///< sensor_msgs/NavSatStatus STATUS_FIX
inline constexpr int kCovarianceTypeUnknown = 0;  ///< NavSatFix COVARIANCE_TYPE_UNKNOWN
inline constexpr int kCovarianceTypeKnown = 3;    ///< NavSatFix COVARIANCE_TYPE_KNOWN

/// The band of plausible altitudes [m] above the WGS84 ellipsoid of a fix or datum. The
/// lowest land (the Dead Sea shore, -430 m) lies above -600 m of ellipsoidal height anywhere
/// (the geoid is within -106 to +85 m of the ellipsoid); -1e4 m leaves room for a mine or a
/// receiver in a deep valley with a bad vertical solution. 1e5 m is the Karman line, far above
/// any robot (civil receivers stop reporting at 18 km). Outside the band a fix is a fault.
inline constexpr double kMinAltitude = -1e4, kMaxAltitude = 1e5;

/// Why the geodetic position (latitude, longitude [deg], altitude [m]) is not on the Earth
/// (latitude in [-90, 90], longitude in [-180, 180], altitude in [kMinAltitude,
/// kMaxAltitude]), e.g. "latitude 91 outside [-90, 90] degrees"; empty when it is. A NaN
/// altitude ("no altitude" in NavSatFix) passes: the caller decides what it means. The one
/// check of every fix and of the datum, from a fix or from ~datum (gps_parameters.hpp).
std::string implausible(double latitude, double longitude, double altitude);

/// One value of a GPS input and its variance.
struct GpsSample {
  double value;
  std::optional<double> variance;  ///< nullopt: the header's R
  bool covarianceUnknown;          ///< the fix's covariance type is unknown
};

class GpsInputs {
 public:
  /// New settings; forgets the datum of the previous ones.
  void setOptions(const GpsOptions& options) {
    options_ = options;
    frame_.reset();
  }
  const GpsOptions& options() const { return options_; }

  /// The value of axis `axis` of GPS input `input` from `fix` in the odom frame (0: x, EAST
  /// turned by the yaw offset; 1: y, NORTH turned; 2: z, UP); nullopt for a fix without a
  /// valid status or with an implausible position (each counted). See above.
  std::optional<GpsSample> sample(std::size_t input, int axis, const Fix& fix);

  /// The covariance of (x, y, z) in the odom frame (row-major 3x3) of a fix whose covariance
  /// type is known, from the settings' yaw offset; nullopt for COVARIANCE_TYPE_UNKNOWN. The
  /// variances of sample() are its diagonal.
  std::optional<std::array<double, 9>> odomCovariance(const Fix& fix) const;

  /// Fixes of `input` dropped because their status was below STATUS_FIX.
  std::uint64_t noFix(std::size_t input) const { return input < noFix_.size() ? noFix_[input] : 0; }
  /// Fixes of `input` dropped because their position is not on the Earth (implausible()).
  std::uint64_t implausibleFixes(std::size_t input) const {
    return input < implausible_.size() ? implausible_[input] : 0;
  }
  /// Why the newest of them was dropped ("" if none was).
  std::string implausibleReason(std::size_t input) const {
    return input < implausibleReason_.size() ? implausibleReason_[input] : std::string();
  }
  /// Whether `input` was given a fix (a GPS input that has received a message).
  bool receivedFix(std::size_t input) const { return input < noFix_.size() && received_[input]; }
  /// The datum in use, nullopt before the first valid fix (without ~datum).
  std::optional<Datum> datum() const {
    return frame_ ? std::optional<Datum>(frame_->datum()) : options_.datum;
  }

 private:
  GpsOptions options_;
  std::optional<LocalFrame> frame_;
  std::vector<std::uint64_t> noFix_;  ///< per input; all four sized together (sample())
  std::vector<bool> received_;
  std::vector<std::uint64_t> implausible_;
  std::vector<std::string> implausibleReason_;
};

}  // namespace gps
}  // namespace sf_filter
