// Stand-in for sensor_msgs/NavSatFix (see fake_msgs.h): the members a GPS input reads, with
// the real message's numeric types.
#pragma once

#include <cstdint>

#include "fake_msgs.h"

namespace sensor_msgs {
struct NavSatStatus {
  std::int8_t status = 0;
  std::uint16_t service = 0;
};
struct NavSatFix {
  std_msgs::Header header;
  NavSatStatus status;
  double latitude = 0.0;
  double longitude = 0.0;
  double altitude = 0.0;
  double position_covariance[9] = {};
  std::uint8_t position_covariance_type = 0;
};
}  // namespace sensor_msgs
