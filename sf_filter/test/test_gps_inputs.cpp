// The GPS inputs' handling of a fix (sf_filter/gps/gps_inputs.hpp): status check and its
// counter, datum from the first valid fix or from the parameter, the fix's covariance by its
// type (unknown: the header's R), a missing altitude. Positions are checked against the
// published WGS84 radius of curvature (a point 100 m north: latitude step 100 m / M).
#include <array>
#include <cmath>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "sf_filter/gps/gps_inputs.hpp"

namespace {

using sf_filter::gps::Datum;
using sf_filter::gps::Fix;
using sf_filter::gps::GpsInputs;
using sf_filter::gps::GpsOptions;
using sf_filter::gps::GpsSample;

constexpr double kPi = 3.14159265358979323846;
constexpr double kLat = 43.5, kLon = 7.25, kAlt = 272.4;
constexpr int kEast = 0, kNorth = 1, kUp = 2;

/// Latitude [deg] of the point `metres` north of latitude `lat` [deg] at height `height` [m]:
/// at that height the meridian's radius of curvature is M + height (WGS84 M).
double north(double lat, double metres, double height) {
  const double a = 6378137.0, f = 1.0 / 298.257223563, e2 = f * (2 - f);
  const double s = std::sin(lat * kPi / 180);
  const double m = a * (1 - e2) / std::pow(1 - e2 * s * s, 1.5);
  return lat + metres / (m + height) * 180 / kPi;
}

Fix fix(double lat, double lon, double alt, int status = 1, int covarianceType = 1) {
  Fix f;
  f.status = status;
  f.latitude = lat;
  f.longitude = lon;
  f.altitude = alt;
  f.covariance = {0.81, 0, 0, 0, 1.21, 0, 0, 0, 3.24};
  f.covarianceType = covarianceType;
  return f;
}

TEST(GpsInputs, NoFixIsDroppedAndCountedPerInput) {
  GpsInputs gps;
  EXPECT_FALSE(gps.sample(3, kEast, fix(kLat, kLon, kAlt, -1)));
  EXPECT_FALSE(gps.sample(4, kNorth, fix(kLat, kLon, kAlt, -1)));
  EXPECT_FALSE(gps.sample(4, kNorth, fix(kLat, kLon, kAlt, -2)));
  EXPECT_EQ(gps.noFix(3), 1u);
  EXPECT_EQ(gps.noFix(4), 2u);
  EXPECT_EQ(gps.noFix(0), 0u);
  EXPECT_TRUE(gps.receivedFix(3));
  EXPECT_FALSE(gps.receivedFix(0));
  // A dropped fix does not become the datum.
  EXPECT_FALSE(gps.datum());
  // STATUS_FIX, SBAS and GBAS fixes are used.
  for (int status : {0, 1, 2}) EXPECT_TRUE(gps.sample(3, kEast, fix(kLat, kLon, kAlt, status)));
  EXPECT_EQ(gps.noFix(3), 1u);
}

TEST(GpsInputs, DatumIsTheFirstValidFix) {
  GpsInputs gps;
  gps.sample(0, kEast, fix(10.0, 10.0, 0.0, -1));  // no fix: not the datum
  const std::optional<GpsSample> first = gps.sample(0, kEast, fix(kLat, kLon, kAlt));
  ASSERT_TRUE(first);
  EXPECT_NEAR(first->value, 0.0, 1e-9);
  ASSERT_TRUE(gps.datum());
  EXPECT_EQ(gps.datum()->latitude, kLat);
  EXPECT_EQ(gps.datum()->altitude, kAlt);
  const Fix later = fix(north(kLat, 100.0, kAlt), kLon, kAlt);
  EXPECT_NEAR(gps.sample(1, kNorth, later)->value, 100.0, 1e-3);
  EXPECT_NEAR(gps.sample(0, kEast, later)->value, 0.0, 1e-3);
  EXPECT_NEAR(gps.sample(2, kUp, later)->value, -100.0 * 100.0 / (2 * 6.3675e6), 1e-4);
  // New settings forget it: the next valid fix is the datum.
  gps.setOptions(GpsOptions{});
  EXPECT_NEAR(gps.sample(1, kNorth, later)->value, 0.0, 1e-9);
}

TEST(GpsInputs, DatumParameter) {
  GpsInputs gps;
  GpsOptions options;
  options.datum = Datum{north(kLat, -250.0, kAlt), kLon, kAlt};
  gps.setOptions(options);
  EXPECT_NEAR(gps.sample(0, kNorth, fix(kLat, kLon, kAlt))->value, 250.0, 1e-3);
  // 3 m above a datum at the same latitude and longitude.
  GpsInputs below;
  below.setOptions(GpsOptions{Datum{kLat, kLon, kAlt - 3.0}, 0.0});
  EXPECT_NEAR(below.sample(1, kUp, fix(kLat, kLon, kAlt))->value, 3.0, 1e-9);
  // New settings forget the previous datum.
  gps.setOptions(GpsOptions{});
  EXPECT_NEAR(gps.sample(0, kNorth, fix(kLat, kLon, kAlt))->value, 0.0, 1e-9);
}

TEST(GpsInputs, YawOffsetTurnsTheFixAndItsCovariance) {
  GpsInputs gps;
  GpsOptions options;
  options.yawOffset = kPi / 2;  // odom x points north
  gps.setOptions(options);
  gps.sample(0, kEast, fix(kLat, kLon, kAlt));
  const Fix later = fix(north(kLat, 100.0, kAlt), kLon, kAlt);
  const GpsSample x = *gps.sample(0, kEast, later);
  const GpsSample y = *gps.sample(1, kNorth, later);
  EXPECT_NEAR(x.value, 100.0, 1e-3);
  EXPECT_NEAR(y.value, 0.0, 1e-3);
  EXPECT_NEAR(*x.variance, 1.21, 1e-12);  // the north variance
  EXPECT_NEAR(*y.variance, 0.81, 1e-12);
}

TEST(GpsInputs, CovarianceByType) {
  GpsInputs gps;
  // APPROXIMATED (1), DIAGONAL_KNOWN (2), KNOWN (3): the fix's own variances.
  for (int type : {1, 2, 3}) {
    const GpsSample s = *gps.sample(0, kUp, fix(kLat, kLon, kAlt, 1, type));
    ASSERT_TRUE(s.variance);
    EXPECT_EQ(*s.variance, 3.24);
    EXPECT_FALSE(s.covarianceUnknown);
  }
  // UNKNOWN (0): no variance (the header's R), and the caller is told so to count it.
  const GpsSample unknown = *gps.sample(0, kEast, fix(kLat, kLon, kAlt, 1, 0));
  EXPECT_FALSE(unknown.variance);
  EXPECT_TRUE(unknown.covarianceUnknown);
  EXPECT_FALSE(gps.odomCovariance(fix(kLat, kLon, kAlt, 1, 0)));
}

TEST(GpsInputs, CovarianceBetweenAxesByType) {
  GpsInputs gps;
  GpsOptions options;
  options.yawOffset = kPi / 6;  // c = sqrt 3 / 2, s = 1 / 2
  gps.setOptions(options);
  Fix f = fix(kLat, kLon, kAlt, 1, 3);
  f.covariance = {1.0, 0.5, 0.0, 0.5, 2.0, 0.0, 0.0, 0.0, 3.24};
  // KNOWN (3): the whole ENU covariance turned (local_frame.hpp):
  //   xx = c^2 1 + 2 c s 0.5 + s^2 2 = 0.75 + 0.4330127 + 0.5
  //   yy = s^2 1 - 2 c s 0.5 + c^2 2 = 0.25 - 0.4330127 + 1.5
  //   xy = -c s 1 + (c^2 - s^2) 0.5 + c s 2 = c s + 0.25
  const double c = std::sqrt(3.0) / 2, s = 0.5;
  std::array<double, 9> odom = *gps.odomCovariance(f);
  EXPECT_NEAR(odom[0], 1.25 + c * s, 1e-12);
  EXPECT_NEAR(odom[4], 1.75 - c * s, 1e-12);
  EXPECT_NEAR(odom[1], c * s + 0.25, 1e-12);
  EXPECT_EQ(odom[3], odom[1]);
  EXPECT_NEAR(odom[8], 3.24, 1e-12);
  // The samples' variances are its diagonal.
  EXPECT_NEAR(*gps.sample(0, kEast, f)->variance, odom[0], 1e-15);
  EXPECT_NEAR(*gps.sample(1, kNorth, f)->variance, odom[4], 1e-15);
  // APPROXIMATED (1), DIAGONAL_KNOWN (2): the off-diagonal entries are not meant; the
  // diagonal alone turned still correlates x and y: xy = c s (2 - 1).
  for (int type : {1, 2}) {
    f.covarianceType = type;
    odom = *gps.odomCovariance(f);
    EXPECT_NEAR(odom[0], 0.75 + 0.5, 1e-12) << type;
    EXPECT_NEAR(odom[4], 0.25 + 1.5, 1e-12) << type;
    EXPECT_NEAR(odom[1], c * s, 1e-12) << type;
  }
}

TEST(GpsInputs, MissingAltitudeAndPosition) {
  GpsInputs gps;
  const double nan = std::nan("");
  // The first fix has no altitude: the datum is at height 0, east and north still work.
  gps.sample(0, kEast, fix(kLat, kLon, nan));
  EXPECT_EQ(gps.datum()->altitude, 0.0);
  EXPECT_NEAR(gps.sample(1, kNorth, fix(north(kLat, 100.0, 0.0), kLon, nan))->value, 100.0, 1e-3);
  EXPECT_TRUE(std::isnan(gps.sample(2, kUp, fix(kLat, kLon, nan))->value));
  // A position that is not finite gives NaN (the fusion core drops and counts it).
  EXPECT_TRUE(std::isnan(gps.sample(0, kEast, fix(nan, kLon, kAlt))->value));
  EXPECT_TRUE(std::isnan(gps.sample(0, kEast, fix(kLat, INFINITY, kAlt))->value));
}

TEST(GpsInputs, PositionsNotOnTheEarthAreNamed) {
  using sf_filter::gps::implausible;
  // The bounds belong to the ranges; a NaN altitude ("no altitude") is the caller's.
  EXPECT_EQ(implausible(90.0, -180.0, -1e4), "");
  EXPECT_EQ(implausible(-90.0, 180.0, 1e5), "");
  EXPECT_EQ(implausible(kLat, kLon, std::nan("")), "");
  EXPECT_EQ(implausible(91.0, kLon, kAlt), "latitude 91 outside [-90, 90] degrees");
  EXPECT_EQ(implausible(-100.0, 500.0, kAlt), "latitude -100 outside [-90, 90] degrees");
  EXPECT_EQ(implausible(kLat, 500.0, kAlt), "longitude 500 outside [-180, 180] degrees");
  EXPECT_EQ(implausible(kLat, kLon, 1e30), "altitude 1e+30 outside [-1e4, 1e5] m");
  EXPECT_EQ(implausible(kLat, kLon, -2e4), "altitude -20000 outside [-1e4, 1e5] m");
  EXPECT_EQ(implausible(std::nan(""), kLon, kAlt), "latitude nan outside [-90, 90] degrees");
}

TEST(GpsInputs, AFirstFixNotOnTheEarthIsDroppedAndTheNextIsTheDatum) {
  // Issue 38 D2: latitude 91 became the datum, and every later fix was then "not finite".
  for (const Fix& bad : {fix(91.0, kLon, kAlt), fix(-100.0, 500.0, kAlt), fix(kLat, 500.0, kAlt),
                         fix(kLat, kLon, 1e30)}) {
    GpsInputs gps;
    EXPECT_FALSE(gps.sample(3, kEast, bad));
    EXPECT_FALSE(gps.sample(4, kNorth, bad));
    EXPECT_FALSE(gps.datum());
    EXPECT_EQ(gps.implausibleFixes(3), 1u);
    EXPECT_EQ(gps.implausibleFixes(4), 1u);
    EXPECT_EQ(gps.implausibleReason(4),
              sf_filter::gps::implausible(bad.latitude, bad.longitude, bad.altitude));
    EXPECT_EQ(gps.noFix(3), 0u);
    // The next plausible fix is the datum: 0 there, 100 m north of it 100 m.
    EXPECT_NEAR(gps.sample(4, kNorth, fix(kLat, kLon, kAlt))->value, 0.0, 1e-9);
    ASSERT_TRUE(gps.datum());
    EXPECT_EQ(gps.datum()->latitude, kLat);
    EXPECT_EQ(gps.datum()->altitude, kAlt);
    EXPECT_NEAR(gps.sample(4, kNorth, fix(north(kLat, 100.0, kAlt), kLon, kAlt))->value, 100.0,
                1e-3);
  }
}

TEST(GpsInputs, LaterFixesNotOnTheEarthAreDroppedAndCounted) {
  // Issue 38 D3: longitude 500 was wrapped to 140 (5.6e6 m away) and used, altitude 1e30
  // drove the pose to 1e38 m. Each is dropped and counted; a plausible fix still works.
  GpsInputs gps;
  gps.sample(0, kEast, fix(kLat, kLon, kAlt));
  EXPECT_FALSE(gps.sample(0, kEast, fix(kLat, 500.0, kAlt)));
  EXPECT_FALSE(gps.sample(0, kEast, fix(kLat, kLon, 1e30)));
  EXPECT_FALSE(gps.sample(0, kEast, fix(kLat, kLon, -1e30)));
  EXPECT_EQ(gps.implausibleFixes(0), 3u);
  EXPECT_EQ(gps.implausibleReason(0), "altitude -1e+30 outside [-1e4, 1e5] m");
  EXPECT_EQ(gps.datum()->longitude, kLon);
  EXPECT_NEAR(gps.sample(0, kEast, fix(kLat, kLon, kAlt))->value, 0.0, 1e-9);
}

TEST(GpsInputs, KnownCovarianceAsymmetricByRoundingIsSymmetrisedAFaultIsKept) {
  // One rule for every covariance the node reads (estimation::kSymmetryTolerance): an
  // asymmetry in the last bit is rounding, made exact; 0.5 against 0.4 is a fault, kept
  // (turned alike) so that the fusion core refuses the fix's block as not symmetric.
  GpsInputs gps;
  GpsOptions options;
  options.yawOffset = kPi / 6;
  gps.setOptions(options);
  Fix f = fix(kLat, kLon, kAlt, 1, 3);
  f.covariance = {1.0, 0.5, 0.0, std::nextafter(0.5, 1.0), 2.0, 0.0, 0.0, 0.0, 3.24};
  std::array<double, 9> odom = *gps.odomCovariance(f);
  EXPECT_EQ(odom[1], odom[3]);
  const double c = std::sqrt(3.0) / 2, s = 0.5;
  EXPECT_NEAR(odom[1], c * s + 0.25, 1e-12);  // as CovarianceBetweenAxesByType
  f.covariance[3] = 0.4;
  odom = *gps.odomCovariance(f);
  // Rot C Rot^T of the asymmetric C: the antisymmetric part (0.05 [[0, 1], [-1, 0]]) is
  // unchanged by a rotation, so xy - yx = 0.5 - 0.4.
  EXPECT_NEAR(odom[1] - odom[3], 0.1, 1e-12);
  EXPECT_NEAR(odom[1] + odom[3], 2 * (c * s + 0.225), 1e-12);
}

TEST(GpsInputs, AnUndefinedCovarianceTypeGetsItsDiagonal) {
  // NavSatFix defines types 0 to 3; any other (255, say) is treated as DIAGONAL_KNOWN: the
  // variances are used, the entries off the diagonal are not (doc/configuration.md, "GPS").
  GpsInputs gps;
  Fix f = fix(kLat, kLon, kAlt, 1, 255);
  f.covariance = {1.0, 0.5, 0.0, 0.5, 2.0, 0.0, 0.0, 0.0, 3.24};
  const std::array<double, 9> odom = *gps.odomCovariance(f);
  EXPECT_EQ(odom, (std::array<double, 9>{1.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 3.24}));
  const GpsSample x = *gps.sample(0, kEast, f);
  EXPECT_EQ(*x.variance, 1.0);
  EXPECT_FALSE(x.covarianceUnknown);
}

}  // namespace
