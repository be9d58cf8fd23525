// WGS84 geodesy through GeographicLib (Debian's libgeographiclib-dev): the exact
// geodetic -> ECEF -> ENU conversion, not a flat-earth approximation; see local_frame.hpp.
#include "sf_filter/gps/local_frame.hpp"

#include <cmath>
#include <cstddef>

#include <Eigen/Core>
#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/LocalCartesian.hpp>
#include <sf_estimation/parameter_checks.hpp>

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

std::array<double, 9> LocalFrame::odomCovariance(const std::array<double, 9>& cov) const {
  const double c = std::cos(yawOffset_), s = std::sin(yawOffset_);
  const double rot[3][3] = {{c, s, 0.0}, {-s, c, 0.0}, {0.0, 0.0, 1.0}};
  // Rounding is made exact (S = (C + C^T) / 2); a fault is kept for the fusion core to refuse
  // (estimation::kSymmetryTolerance, the one rule of every covariance the node reads).
  const bool symmetric = estimation::nearlySymmetric(Eigen::Map<const Eigen::Matrix3d>(cov.data()));
  std::array<double, 9> out{};
  for (std::size_t a = 0; a < 3; ++a) {
    for (std::size_t b = symmetric ? a : 0; b < 3; ++b) {
      double sum = 0.0;
      for (std::size_t k = 0; k < 3; ++k) {
        for (std::size_t l = 0; l < 3; ++l) {
          const double entry = symmetric ? 0.5 * (cov[k * 3 + l] + cov[l * 3 + k]) : cov[k * 3 + l];
          sum += rot[a][k] * entry * rot[b][l];
        }
      }
      out[a * 3 + b] = sum;
      if (symmetric) out[b * 3 + a] = sum;  // one value for both: the core wants symmetry
    }
  }
  return out;
}

}  // namespace gps
}  // namespace sf_filter
