// The magnetometer's heading (config/extractors/magnetic_heading.hpp, DERIVED_INPUTS
// MAGNETIC_YAW) against headings and variances computed by hand from the field a level robot
// measures at a known yaw: b = (B sin psi', B cos psi'), psi' its yaw from magnetic east.
#include <array>
#include <cmath>
#include <optional>

#include <gtest/gtest.h>

#include "sf_filter/config/extractors/kinds.hpp"
#include "sf_filter/config/extractors/magnetic_heading.hpp"

namespace {

using sf_config::extractors::MagneticHeading;
using sf_config::extractors::magneticYaw;
using sf_config::extractors::magneticYawVariance;
using sf_config::extractors::ParameterValues;
using sf_config::extractors::Sample;
using sf_config::extractors::SampleContext;

constexpr double kTol = 1e-12;
constexpr double kDeg = M_PI / 180.0;

// A stand-in for sensor_msgs/MagneticField (same member names and types).
struct Vector3 {
  double x = 0.0, y = 0.0, z = 0.0;
};
struct MagneticField {
  Vector3 magnetic_field;
  std::array<double, 9> magnetic_field_covariance{};
};

MagneticField field(double bx, double by) {
  MagneticField m;
  m.magnetic_field = {bx, by, -4e-5};  // a vertical part, which the heading ignores
  return m;
}

std::optional<Sample> read(MagneticHeading& kind, const MagneticField& m, const ParameterValues& p,
                           std::optional<double> variance = {}) {
  return kind.sample<0, false>(m, m.magnetic_field, SampleContext{variance, 1.0, p});
}

TEST(MagneticHeading, CompassPointsWithoutDeclination) {
  const double b = 2e-5;                                    // 20 uT horizontal
  EXPECT_NEAR(magneticYaw(0.0, b, 0.0), 0.0, kTol);         // facing east: field along +y
  EXPECT_NEAR(magneticYaw(b, 0.0, 0.0), M_PI / 2, kTol);    // facing north: field along +x
  EXPECT_NEAR(magneticYaw(0.0, -b, 0.0), M_PI, kTol);       // facing west: pi, not -pi
  EXPECT_NEAR(magneticYaw(-b, 0.0, 0.0), -M_PI / 2, kTol);  // facing south
  EXPECT_NEAR(magneticYaw(b, b, 0.0), M_PI / 4, kTol);      // facing north-east
  EXPECT_NEAR(magneticYaw(3.0, -4.0, 0.0), std::atan2(3.0, -4.0), kTol);
}

TEST(MagneticHeading, DeclinationTurnsMagneticIntoTrueHeading) {
  // Magnetic north 10 deg east of true north; the robot faces true north (yaw 90 deg): magnetic
  // north lies 10 deg to its right, at -10 deg in the robot's frame.
  const double bx = std::cos(-10 * kDeg), by = std::sin(-10 * kDeg);
  EXPECT_NEAR(magneticYaw(bx, by, 10 * kDeg), 90 * kDeg, kTol);
  // Facing true west (yaw 180 deg) with declination -5 deg (magnetic north 5 deg west): the
  // field (ENU direction 95 deg) points 85 deg to the robot's right, at -85 deg; the heading
  // stays in (-pi, pi].
  EXPECT_NEAR(magneticYaw(std::cos(-85 * kDeg), std::sin(-85 * kDeg), -5 * kDeg), M_PI, 1e-12);
  // Across the seam: magnetic heading 179 deg, declination -2 deg: 181 deg = -179 deg.
  EXPECT_NEAR(magneticYaw(std::sin(179 * kDeg), std::cos(179 * kDeg), -2 * kDeg), -179 * kDeg,
              1e-12);
}

TEST(MagneticHeading, NoHorizontalFieldIsNaN) {
  EXPECT_TRUE(std::isnan(magneticYaw(0.0, 0.0, 0.0)));
  EXPECT_TRUE(std::isnan(magneticYaw(std::nan(""), 1.0, 0.0)));
}

TEST(MagneticHeading, VarianceFromTheFieldCovariance) {
  // b = (3, 4): d yaw / d(bx, by) = (by, -bx) / |b|^2 = (4, -3) / 25, so
  // var = (16 Sxx - 24 Sxy + 9 Syy) / 625.
  const std::array<double, 9> c{1e-2, 2e-3, 0.0, 2e-3, 4e-3, 0.0, 0.0, 0.0, 1.0};
  EXPECT_NEAR(magneticYawVariance(3.0, 4.0, c), (0.16 - 0.048 + 0.036) / 625.0, 1e-15);
}

TEST(MagneticHeading, KindReadsTheMessageWithItsParameter) {
  MagneticHeading kind;
  ParameterValues p;
  MagneticField m = field(std::cos(-10 * kDeg), std::sin(-10 * kDeg));
  // Unknown (all-zero) covariance: the header's R, flagged for the sink's counter.
  std::optional<Sample> s = read(kind, m, p);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->value, 100 * kDeg, kTol);  // declination 0 by default
  EXPECT_FALSE(s->variance);
  EXPECT_TRUE(s->covarianceUnknown);
  p.set("magnetic_declination", 10 * kDeg);
  m.magnetic_field_covariance = {4e-3, 0.0, 0.0, 0.0, 1e-2, 0.0, 0.0, 0.0, 1e-2};
  s = read(kind, m, p);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->value, 90 * kDeg, kTol);
  // |b| = 1: var = by^2 Sxx + bx^2 Syy.
  const double sn = std::sin(-10 * kDeg), cs = std::cos(-10 * kDeg);
  EXPECT_NEAR(*s->variance, sn * sn * 4e-3 + cs * cs * 1e-2, 1e-15);
  EXPECT_FALSE(s->covarianceUnknown);
  // A configured variance (INPUT_COVARIANCE, variance field) is the input's.
  s = read(kind, m, p, 0.5);
  EXPECT_EQ(s->variance, 0.5);
  // ROS's "unknown" (-1 first) as well.
  m.magnetic_field_covariance[0] = -1.0;
  s = read(kind, m, p);
  EXPECT_FALSE(s->variance);
  EXPECT_TRUE(s->covarianceUnknown);
}

TEST(MagneticHeading, RegisteredAsAnAngleQuantity) {
  using sf_config::extractors::quantityEntry;
  using sf_config::extractors::quantityNumber;
  const int q = quantityNumber("MAGNETIC_YAW");
  ASSERT_EQ(q, 9);  // after X ... YAW (0-5) and EAST, NORTH, UP (6-8)
  EXPECT_TRUE(quantityEntry(q).angle);
  EXPECT_TRUE((std::is_same_v<sf_config::extractors::KindOf<9>, MagneticHeading>));
  EXPECT_EQ(MagneticHeading::kParameters[0].name, "magnetic_declination");
  EXPECT_EQ(quantityNumber("HEADING"), -1);
}

}  // namespace
