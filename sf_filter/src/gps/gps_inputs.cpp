// The GPS inputs' handling of a fix; see gps_inputs.hpp.
#include "sf_filter/gps/gps_inputs.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace sf_filter {
namespace gps {

namespace {

std::string outside(const char* what, double value, const char* band) {
  char text[96];
  std::snprintf(text, sizeof text, "%s %g outside %s", what, value, band);
  return text;
}

}  // namespace

std::string implausible(double latitude, double longitude, double altitude) {
  if (!(std::abs(latitude) <= 90.0)) return outside("latitude", latitude, "[-90, 90] degrees");
  if (!(std::abs(longitude) <= 180.0)) {
    return outside("longitude", longitude, "[-180, 180] degrees");
  }
  if (std::isnan(altitude) || (altitude >= kMinAltitude && altitude <= kMaxAltitude)) return {};
  return outside("altitude", altitude, "[-1e4, 1e5] m");
}

std::optional<GpsSample> GpsInputs::sample(std::size_t input, int axis, const Fix& fix) {
  if (noFix_.size() <= input) {
    noFix_.resize(input + 1, 0);
    received_.resize(input + 1, false);
    implausible_.resize(input + 1, 0);
    implausibleReason_.resize(input + 1);
  }
  received_[input] = true;
  if (fix.status < kStatusFix) {
    ++noFix_[input];
    return std::nullopt;
  }
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (!std::isfinite(fix.latitude) || !std::isfinite(fix.longitude)) {
    return GpsSample{kNaN, std::nullopt, false};  // dropped by the core as not finite
  }
  std::string reason = implausible(fix.latitude, fix.longitude, fix.altitude);
  if (!reason.empty()) {
    ++implausible_[input];
    implausibleReason_[input] = std::move(reason);
    return std::nullopt;  // nor the datum: the next plausible fix is
  }
  if (!frame_) {
    Datum datum;
    if (options_.datum) {
      datum = *options_.datum;
    } else {
      datum = {fix.latitude, fix.longitude, std::isfinite(fix.altitude) ? fix.altitude : 0.0};
    }
    frame_.emplace(datum, options_.yawOffset);
  }
  // Without an altitude the fix is taken at the datum's height: east and north barely depend
  // on it (1 m of height changes them by about 1e-7 of their size), up is unknown.
  const bool hasAltitude = std::isfinite(fix.altitude);
  const double altitude = hasAltitude ? fix.altitude : frame_->datum().altitude;
  const std::array<double, 3> odom =
      frame_->toOdom(frame_->enu(fix.latitude, fix.longitude, altitude));
  const double value = (axis == 2 && !hasAltitude) ? kNaN : odom[static_cast<std::size_t>(axis)];
  const std::optional<std::array<double, 9>> covariance = odomCovariance(fix);
  if (!covariance) return GpsSample{value, std::nullopt, true};
  const auto a = static_cast<std::size_t>(axis);
  return GpsSample{value, (*covariance)[a * 3 + a], false};
}

std::optional<std::array<double, 9>> GpsInputs::odomCovariance(const Fix& fix) const {
  if (fix.covarianceType == kCovarianceTypeUnknown) return std::nullopt;
  std::array<double, 9> enu = fix.covariance;
  if (fix.covarianceType != kCovarianceTypeKnown) {
    // APPROXIMATED, DIAGONAL_KNOWN: only the variances are meant, whatever is off the diagonal.
    enu = {fix.covariance[0], 0.0, 0.0, 0.0, fix.covariance[4], 0.0, 0.0, 0.0, fix.covariance[8]};
  }
  return LocalFrame(Datum{}, options_.yawOffset).odomCovariance(enu);
}

}  // namespace gps
}  // namespace sf_filter
