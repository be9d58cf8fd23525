// Input extractor: an input's variance from an entry of its message's covariance array
// (INPUT_COVARIANCE), e.g. orientation_covariance[8] (yaw) of sensor_msgs/Imu or
// pose.covariance[35] (yaw) of nav_msgs/Odometry and geometry_msgs/PoseWithCovarianceStamped.
//
// ROS marks a covariance it does not know by -1 in the first entry (sensor_msgs/Imu) or by an
// all-zero matrix (many drivers); such a message gives no variance, the header's
// MEASUREMENT_NOISE_COVARIANCE entry is used for it and the fallback is counted (the sink's
// covarianceFallbacks). A known covariance whose entry is zero, negative or not finite is
// passed on as it is: the fusion core drops the value and counts a bad variance.
// ROS-free and header-only (C arrays, std::array, boost::array, std::vector); unit-tested in
// test_extractors.cpp.
#pragma once

#include <cstddef>
#include <iterator>
#include <optional>

namespace sf_config {
namespace extractors {

/// True when the covariance array says "unknown": -1 first, or all zero (or empty).
template <class Array>
bool covarianceUnknown(const Array& covariance) {
  const std::size_t size = std::size(covariance);
  if (size == 0 || covariance[0] == -1.0) return true;
  for (std::size_t k = 0; k < size; ++k) {
    if (covariance[k] != 0.0) return false;
  }
  return true;
}

/// covariance[entry], or nullopt when the array is unknown (see above) or too short.
template <class Array>
std::optional<double> covarianceEntry(const Array& covariance, std::size_t entry) {
  if (covarianceUnknown(covariance) || entry >= std::size(covariance)) return std::nullopt;
  return static_cast<double>(covariance[entry]);
}

}  // namespace extractors
}  // namespace sf_config
