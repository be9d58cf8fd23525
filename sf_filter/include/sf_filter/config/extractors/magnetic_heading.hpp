// Input extractor: the heading of a magnetometer (DERIVED_INPUTS MAGNETIC_YAW), e.g.
//
//   TOPICS_IN ((imu/mag)(sensor_msgs::MagneticField)(magnetic_field))
//   DERIVED_INPUTS ((2)(MAGNETIC_YAW)(ABSOLUTE))
//
// The field names the measured vector (x, y, z); its frame is taken to be the base frame
// (a level sensor, x forward: the horizontal components are x and y). The Earth's horizontal
// field points to magnetic north, so a robot at yaw psi (ENU, counter-clockwise from east)
// measures b = (B sin psi', B cos psi') with psi' its yaw from magnetic east, and
//   yaw = atan2(b.x, b.y) - declination,  wrapped to (-pi, pi]
// with ~magnetic_declination the angle of magnetic north east of true north (radians, east
// positive as the NOAA/IGRF tables give it; default 0). An angle input (ANGLE_INPUTS implied).
//
// Variance: the input's INPUT_COVARIANCE entry or variance field if configured; otherwise the
// message's magnetic_field_covariance (row-major 3x3) carried through the heading,
//   var = (b.y^2 Sxx - 2 b.x b.y Sxy + b.x^2 Syy) / (b.x^2 + b.y^2)^2
// (first order); an unknown covariance (all zero, -1 first) gives the header's R, counted. A
// vector without a horizontal part (b.x = b.y = 0) or not finite gives NaN (dropped and counted
// by the fusion core). Stateless. ROS-free and header-only; unit-tested in
// test_magnetic_heading.cpp.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string_view>
#include <type_traits>
#include <utility>

#include "sf_filter/config/extractors/extractor.hpp"
#include "sf_filter/config/extractors/message_covariance.hpp"

namespace sf_config {
namespace extractors {

/// The heading of horizontal field (bx, by) in the base frame with `declination` [rad]
/// (see above), in (-pi, pi]; NaN without a horizontal field.
inline double magneticYaw(double bx, double by, double declination) {
  if (!(bx * bx + by * by > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  double yaw = std::remainder(std::atan2(bx, by) - declination, 2.0 * M_PI);
  if (yaw <= -M_PI) yaw += 2.0 * M_PI;
  return yaw;
}

/// The variance of magneticYaw from the field's covariance (row-major 3x3), first order.
template <class Array>
double magneticYawVariance(double bx, double by, const Array& c) {
  const double h2 = bx * bx + by * by;
  const double sxx = static_cast<double>(c[0]), sxy = static_cast<double>(c[1]),
               syy = static_cast<double>(c[4]);
  return (by * by * sxx - 2.0 * bx * by * sxy + bx * bx * syy) / (h2 * h2);
}

template <class T, class = void>
struct IsVector3 : std::false_type {};
template <class T>
struct IsVector3<
    T, std::void_t<decltype(std::declval<const T&>().x), decltype(std::declval<const T&>().y),
                   decltype(std::declval<const T&>().z)>>
    : std::bool_constant<std::is_convertible_v<decltype(std::declval<const T&>().x), double> &&
                         std::is_convertible_v<decltype(std::declval<const T&>().y), double>> {};

template <class M, class = void>
struct HasFieldCovariance : std::false_type {};
template <class M>
struct HasFieldCovariance<
    M, std::void_t<decltype(std::declval<const M&>().magnetic_field_covariance[8])>>
    : std::true_type {};

/// Extractor kind MAGNETIC_YAW of a sensor_msgs/MagneticField's vector (see above).
class MagneticHeading : public ExtractorState {
 public:
  static constexpr std::array<std::string_view, 1> kQuantities{"MAGNETIC_YAW"};
  static constexpr std::array<bool, 1> kAngle{true};
  static constexpr ExtractorParameter kDeclination{
      "magnetic_declination", 0.0, -M_PI, M_PI,
      "radians in [-pi, pi], magnetic north east of true north positive"};
  static constexpr std::array<ExtractorParameter, 1> kParameters{kDeclination};
  static constexpr bool kAbsoluteOnly = true;  // a heading about magnetic north

  template <class Member>
  static constexpr bool fits(int) {
    return IsVector3<Member>::value;
  }

  template <int Quantity, bool Differential, class Message, class Member>
  std::optional<Sample> sample(const Message& msg, const Member& b, const SampleContext& c) {
    static_assert(!Differential, "refused by the configuration (kAbsoluteOnly)");
    const double bx = static_cast<double>(b.x), by = static_cast<double>(b.y);
    Sample s{magneticYaw(bx, by, c.parameters.value(kDeclination)), c.variance};
    if constexpr (HasFieldCovariance<Message>::value) {
      if (!s.variance && std::isfinite(s.value)) {
        s.covarianceUnknown = covarianceUnknown(msg.magnetic_field_covariance);
        if (!s.covarianceUnknown)
          s.variance = magneticYawVariance(bx, by, msg.magnetic_field_covariance);
      }
    }
    return s;
  }
};

}  // namespace extractors
}  // namespace sf_config
