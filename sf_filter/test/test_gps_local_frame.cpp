// The GPS inputs' geodesy (sf_filter/gps/local_frame.hpp, GeographicLib) against independent
// references to the millimetre: points 100 m north along a meridian and 100 m east along a
// parallel, whose east/north/up follow in closed form from the WGS84 ellipse (semi-major axis
// a = 6378137 m, flattening 1/298.257223563, NIMA TR8350.2) and its published radii of
// curvature M (meridian) and N (prime vertical); the yaw offset and the covariance turned into
// the odom frame against hand-computed rotations.
#include <array>
#include <cmath>
#include <cstddef>

#include <gtest/gtest.h>

#include "sf_filter/gps/local_frame.hpp"

namespace {

using sf_filter::gps::Datum;
using sf_filter::gps::LocalFrame;

constexpr double kPi = 3.14159265358979323846;
constexpr double kA = 6378137.0;
constexpr double kF = 1.0 / 298.257223563;
constexpr double kE2 = kF * (2.0 - kF);
constexpr double kMm = 1e-3;

double rad(double deg) { return deg * kPi / 180.0; }
double deg(double rad) { return rad * 180.0 / kPi; }
/// Radius of curvature in the prime vertical, N = a / sqrt(1 - e^2 sin^2 lat).
double primeVertical(double lat) {
  return kA / std::sqrt(1.0 - kE2 * std::sin(lat) * std::sin(lat));
}
/// Meridian radius of curvature, M = a (1 - e^2) / (1 - e^2 sin^2 lat)^(3/2).
double meridian(double lat) {
  return kA * (1.0 - kE2) / std::pow(1.0 - kE2 * std::sin(lat) * std::sin(lat), 1.5);
}

class LocalFrameAtLatitude : public ::testing::TestWithParam<double> {};

// 100 m north along the meridian: latitude step 100 m / M. In the meridian plane a point on the
// ellipse is at (p, z) = (N cos lat, N (1 - e^2) sin lat); the tangent frame's north and up are
// (-sin lat, cos lat) and (cos lat, sin lat) there. North is then M dlat to 1e-5 m and up
// -d^2 / (2 M) (the ellipse falls away below the tangent plane), about -0.8 mm.
TEST_P(LocalFrameAtLatitude, HundredMetresNorthAlongTheMeridian) {
  const double lat0 = rad(GetParam()), lon0 = 11.0, d = 100.0;
  const double lat1 = lat0 + d / meridian(lat0);
  const LocalFrame frame(Datum{deg(lat0), lon0, 0.0}, 0.0);
  const auto enu = frame.enu(deg(lat1), lon0, 0.0);

  const double n0 = primeVertical(lat0), n1 = primeVertical(lat1);
  const double dp = n1 * std::cos(lat1) - n0 * std::cos(lat0);
  const double dz = n1 * (1 - kE2) * std::sin(lat1) - n0 * (1 - kE2) * std::sin(lat0);
  EXPECT_NEAR(enu[0], 0.0, kMm);
  EXPECT_NEAR(enu[1], -std::sin(lat0) * dp + std::cos(lat0) * dz, kMm);
  EXPECT_NEAR(enu[2], std::cos(lat0) * dp + std::sin(lat0) * dz, kMm);
  // The published radius of curvature alone, independent of the ellipse's coordinates.
  EXPECT_NEAR(enu[1], d, kMm);
  EXPECT_NEAR(enu[2], -d * d / (2 * meridian(lat0)), kMm);
}

// 100 m east along the parallel: longitude step 100 m / r with r = N cos lat the parallel's
// radius. The chord to it is r sin dlon east and r (1 - cos dlon) towards the earth's axis,
// which is sin lat north and -cos lat up in the tangent frame (exact on the ellipsoid).
TEST_P(LocalFrameAtLatitude, HundredMetresEastAlongTheParallel) {
  const double lat0 = rad(GetParam()), lon0 = -3.5, d = 100.0;
  const double r = primeVertical(lat0) * std::cos(lat0);
  const double dlon = d / r;
  const LocalFrame frame(Datum{deg(lat0), lon0, 0.0}, 0.0);
  const auto enu = frame.enu(deg(lat0), lon0 + deg(dlon), 0.0);
  const double inward = r * (1.0 - std::cos(dlon));
  EXPECT_NEAR(enu[0], r * std::sin(dlon), kMm);
  EXPECT_NEAR(enu[1], std::sin(lat0) * inward, kMm);
  EXPECT_NEAR(enu[2], -std::cos(lat0) * inward, kMm);
  EXPECT_NEAR(enu[0], d, kMm);
}

INSTANTIATE_TEST_SUITE_P(Latitudes, LocalFrameAtLatitude,
                         ::testing::Values(0.0, 33.9, -33.9, 45.0, 49.9, 60.0, -71.0));

TEST(LocalFrame, HeightIsUp) {
  const LocalFrame frame(Datum{43.5, 7.25, 272.4}, 0.0);
  const auto enu = frame.enu(43.5, 7.25, 282.4);
  EXPECT_NEAR(enu[0], 0.0, 1e-9);
  EXPECT_NEAR(enu[1], 0.0, 1e-9);
  EXPECT_NEAR(enu[2], 10.0, 1e-9);
  const auto at = frame.enu(43.5, 7.25, 272.4);
  EXPECT_NEAR(std::hypot(at[0], std::hypot(at[1], at[2])), 0.0, 1e-9);
}

// The yaw offset a is the odom x axis' heading in ENU, counter-clockwise from east.
TEST(LocalFrame, YawOffsetTurnsEastNorthIntoOdom) {
  const LocalFrame quarter(Datum{}, kPi / 2);  // odom x points north
  auto odom = quarter.toOdom({0.0, 100.0, 2.0});
  EXPECT_NEAR(odom[0], 100.0, 1e-9);
  EXPECT_NEAR(odom[1], 0.0, 1e-9);
  EXPECT_NEAR(odom[2], 2.0, 1e-9);
  odom = quarter.toOdom({100.0, 0.0, 0.0});  // east is to the right of north: odom -y
  EXPECT_NEAR(odom[0], 0.0, 1e-9);
  EXPECT_NEAR(odom[1], -100.0, 1e-9);

  const LocalFrame thirty(Datum{}, rad(30));  // x = cos a e + sin a n, y = -sin a e + cos a n
  odom = thirty.toOdom({3.0, 4.0, 0.0});
  EXPECT_NEAR(odom[0], 3.0 * std::sqrt(3.0) / 2 + 4.0 * 0.5, 1e-12);
  EXPECT_NEAR(odom[1], -3.0 * 0.5 + 4.0 * std::sqrt(3.0) / 2, 1e-12);
  EXPECT_NEAR(std::hypot(odom[0], odom[1]), 5.0, 1e-12);
}

TEST(LocalFrame, CovarianceTurnsWithTheYawOffset) {
  // Rot S Rot^T with Rot = ((c, s, 0), (-s, c, 0), (0, 0, 1)), written out by hand per case.
  // East variance 1, north 4, up 9, no correlation: a quarter turn swaps x and y.
  const std::array<double, 9> diagonal{1, 0, 0, 0, 4, 0, 0, 0, 9};
  auto v = LocalFrame(Datum{}, kPi / 2).odomCovariance(diagonal);
  EXPECT_NEAR(v[0], 4.0, 1e-12);
  EXPECT_NEAR(v[4], 1.0, 1e-12);
  EXPECT_NEAR(v[8], 9.0, 1e-12);
  EXPECT_NEAR(v[1], 0.0, 1e-12);
  // Without an offset the matrix is kept.
  v = LocalFrame(Datum{}, 0.0).odomCovariance(diagonal);
  for (std::size_t k = 0; k < 9; ++k) EXPECT_NEAR(v[k], diagonal[k], 1e-12) << k;
  // 30 degrees (c = sqrt 3 / 2, s = 1 / 2): a diagonal with unequal variances gets a
  // covariance of x and y: xx = c^2 1 + s^2 4 = 1.75, yy = s^2 1 + c^2 4 = 3.25,
  // xy = -c s 1 + s c 4 = 3 sqrt 3 / 4.
  v = LocalFrame(Datum{}, rad(30)).odomCovariance(diagonal);
  EXPECT_NEAR(v[0], 1.75, 1e-12);
  EXPECT_NEAR(v[4], 3.25, 1e-12);
  EXPECT_NEAR(v[1], 3.0 * std::sqrt(3.0) / 4, 1e-12);
  EXPECT_EQ(v[1], v[3]);  // exactly symmetric: the fusion core checks it
  EXPECT_NEAR(v[2], 0.0, 1e-12);
  EXPECT_NEAR(v[5], 0.0, 1e-12);
  // Equal variances stay uncorrelated at any offset.
  v = LocalFrame(Datum{}, rad(30)).odomCovariance({2, 0, 0, 0, 2, 0, 0, 0, 9});
  EXPECT_NEAR(v[0], 2.0, 1e-12);
  EXPECT_NEAR(v[1], 0.0, 1e-12);
  // Correlated east/north at 45 degrees: the variance along (1, 1) / sqrt 2 is
  // (1 + 2 * 1.5 + 4) / 2 = 4, across it (1 - 3 + 4) / 2 = 1, and their covariance
  // c s (4 - 1) + (c^2 - s^2) 1.5 = 1.5.
  const std::array<double, 9> correlated{1, 1.5, 0, 1.5, 4, 0, 0, 0, 9};
  v = LocalFrame(Datum{}, kPi / 4).odomCovariance(correlated);
  EXPECT_NEAR(v[0], 4.0, 1e-12);
  EXPECT_NEAR(v[4], 1.0, 1e-12);
  EXPECT_NEAR(v[1], 1.5, 1e-12);
  // Up's covariances turn with the horizontal axes: at a quarter turn x = north, y = -east.
  // An input asymmetric by rounding (east-north 1.5 against nextafter(1.5)) is taken as its
  // symmetric part, exactly symmetric.
  const double rounded = std::nextafter(1.5, 2.0);
  const std::array<double, 9> withUp{1, 1.5, 0.3, rounded, 4, 0.6, 0.3, 0.6, 9};
  v = LocalFrame(Datum{}, kPi / 2).odomCovariance(withUp);
  EXPECT_NEAR(v[2], 0.6, 1e-12);   // x z = north up
  EXPECT_NEAR(v[5], -0.3, 1e-12);  // y z = -east up
  EXPECT_NEAR(v[1], -1.5, 1e-12);  // x y = -north east
  EXPECT_EQ(v[1], v[3]);
  EXPECT_EQ(v[2], v[6]);
  EXPECT_EQ(v[5], v[7]);
  // Beyond the one relative tolerance (estimation::kSymmetryTolerance) an asymmetric input is
  // a fault, not rounding: turned as it is (east-north 1, north-east 2), so that the fusion
  // core refuses it as not symmetric (issue 38: it was symmetrised silently).
  const std::array<double, 9> asymmetric{1, 1, 0.3, 2, 4, 0.6, 0.3, 0.6, 9};
  v = LocalFrame(Datum{}, kPi / 2).odomCovariance(asymmetric);
  EXPECT_NEAR(v[1], -2.0, 1e-12);  // x y = cov(north, -east)
  EXPECT_NEAR(v[3], -1.0, 1e-12);  // y x = cov(-east, north)
}

}  // namespace
