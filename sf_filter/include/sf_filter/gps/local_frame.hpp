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

  /// The variances of x, y, z in the odom frame of an ENU covariance (row-major 3x3, the
  /// order of sensor_msgs/NavSatFix's position_covariance): the diagonal of R C R^T.
  std::array<double, 3> odomVariances(const std::array<double, 9>& enuCovariance) const;

 private:
  Datum datum_;
  double yawOffset_;
};

}  // namespace gps
}  // namespace sf_filter
