// The local frame of a GPS input: WGS84 geodetic coordinates as east, north, up metres about a
// datum (GeographicLib::LocalCartesian, compiled once in sf_fusion_core), turned by a yaw offset
// into the odom frame the filter's state is in.
//
// The yaw offset a is the heading of the odom frame's x axis in ENU, counter-clockwise from
// east (the robot's heading in ENU when its odometry heading is 0):
//   x =  cos a * east + sin a * north,   y = -sin a * east + cos a * north,   z = up
// The odom frame's origin is the datum. ROS-free; unit-tested in test_gps_local_frame.cpp.
#pragma once

#include <array>

namespace sf_filter {
namespace gps {

/// A geodetic point: latitude, longitude [deg], height above the WGS84 ellipsoid [m].
struct Datum {
  double latitude = 0.0;
  double longitude = 0.0;
  double altitude = 0.0;
};

class LocalFrame {
 public:
  LocalFrame(const Datum& datum, double yawOffset) : datum_(datum), yawOffset_(yawOffset) {}

  const Datum& datum() const { return datum_; }
  double yawOffset() const { return yawOffset_; }

  /// (east, north, up) [m] of a geodetic point about the datum (WGS84, exact).
  std::array<double, 3> enu(double latitude, double longitude, double altitude) const;

  /// (x, y, z) in the odom frame of an ENU vector (see above).
  std::array<double, 3> toOdom(const std::array<double, 3>& enu) const;

  /// The covariance in the odom frame (x, y, z; row-major 3x3) of an ENU covariance C (the
  /// order of sensor_msgs/NavSatFix's position_covariance): Rot S Rot^T with S = (C + C^T) / 2
  /// and Rot the rotation of toOdom. The result is exactly symmetric. A C asymmetric beyond
  /// estimation::kSymmetryTolerance is a fault, not rounding: Rot C Rot^T, asymmetric alike
  /// (the rotation keeps the relative asymmetry), which the fusion core refuses as not
  /// symmetric like any other covariance block. Unequal east and north
  /// variances get a covariance of x and y from any offset that is not a multiple of pi / 2.
  std::array<double, 9> odomCovariance(const std::array<double, 9>& enuCovariance) const;

 private:
  Datum datum_;
  double yawOffset_;
};

}  // namespace gps
}  // namespace sf_filter
