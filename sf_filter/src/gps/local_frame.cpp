// WGS84 geodesy through GeographicLib (Debian's libgeographiclib-dev): the exact
// geodetic -> ECEF -> ENU conversion, not a flat-earth approximation; see local_frame.hpp.
#include "sf_filter/gps/local_frame.hpp"

#include <cmath>

#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/LocalCartesian.hpp>

namespace sf_filter {
namespace gps {

std::array<double, 3> LocalFrame::enu(double latitude, double longitude, double altitude) const {
  // Constructing the converter costs a few trigonometric functions: cheaper than keeping
  // GeographicLib's types out of this header in a pointer, and a GPS gives a few fixes a second.
  const GeographicLib::LocalCartesian frame(datum_.latitude, datum_.longitude, datum_.altitude,
                                            GeographicLib::Geocentric::WGS84());
  std::array<double, 3> out{};
  frame.Forward(latitude, longitude, altitude, out[0], out[1], out[2]);
  return out;
}

std::array<double, 3> LocalFrame::toOdom(const std::array<double, 3>& enu) const {
  const double c = std::cos(yawOffset_), s = std::sin(yawOffset_);
  return {c * enu[0] + s * enu[1], -s * enu[0] + c * enu[1], enu[2]};
}

std::array<double, 3> LocalFrame::odomVariances(const std::array<double, 9>& cov) const {
  const double c = std::cos(yawOffset_), s = std::sin(yawOffset_);
  const double ee = cov[0], en = 0.5 * (cov[1] + cov[3]), nn = cov[4];
  return {c * c * ee + 2.0 * c * s * en + s * s * nn, s * s * ee - 2.0 * c * s * en + c * c * nn,
          cov[8]};
}

}  // namespace gps
}  // namespace sf_filter
