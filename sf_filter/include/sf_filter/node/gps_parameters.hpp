// The GPS inputs' private parameters (doc/configuration.md, "GPS"), read through a
// ParameterSource like the node's other parameters (ros_parameters.hpp):
//   ~datum           [latitude deg, longitude deg, altitude m]: the origin of the local frame;
//                    not set: the first valid fix. Checked like every fix
//                    (gps::implausible: latitude, longitude and altitude band).
//                    (robot_localization's navsat_transform takes [latitude, longitude, heading]
//                    under the same name.)
//   ~gps_yaw_offset  rad, the heading of the odom frame's x axis in ENU, counter-clockwise
//                    from east (0: x points east); in (-2 pi, 2 pi).
#pragma once

#include <cmath>
#include <string>

#include "sf_filter/gps/gps_inputs.hpp"
#include "sf_filter/io/ros_parameters.hpp"

namespace sf_filter {

inline gps::GpsOptions loadGpsParameters(const ParameterSource& pnh) {
  gps::GpsOptions options;
  XmlRpc::XmlRpcValue value;
  if (pnh.get("datum", value)) {
    if (value.getType() != XmlRpc::XmlRpcValue::TypeArray || value.size() != 3) {
      throw ParameterOverrideError(
          "parameter ~datum: expected [latitude, longitude, altitude] (degrees, degrees, "
          "metres), found " +
          detail::describe(value));
    }
    const double lat = detail::toDouble(value[0], "parameter ~datum latitude");
    const double lon = detail::toDouble(value[1], "parameter ~datum longitude");
    const double alt = detail::toDouble(value[2], "parameter ~datum altitude");
    const std::string reason = std::isnan(alt) ? std::string("altitude nan is not finite")
                                               : gps::implausible(lat, lon, alt);
    if (!reason.empty()) {
      throw ParameterOverrideError(
          "parameter ~datum: " + reason +
          " (a datum is a place on the Earth: latitude in [-90, 90], longitude in [-180, 180] "
          "degrees, altitude in [-1e4, 1e5] m)");
    }
    options.datum = gps::Datum{lat, lon, alt};
  }
  if (readScalarParameter(pnh, "gps_yaw_offset", options.yawOffset) &&
      !(std::abs(options.yawOffset) < 4.0 * std::acos(0.0))) {
    throw ParameterOverrideError(
        "parameter ~gps_yaw_offset: expected radians in (-2 pi, 2 pi), found " +
        std::to_string(options.yawOffset));
  }
  return options;
}

}  // namespace sf_filter
